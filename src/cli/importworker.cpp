// `lightrig import-worker` (hidden): imports one model (model/isolatedimport.h), decodes one environment
// image (model/environmentdecode.h) or one multi-layer OpenEXR file (model/exrdecode.h) for a parent process
// so that an importer crash, hang or allocation bomb ends this process, not the editor or `lightrig render`.
// Reads the request from stdin and writes frames to stdout (model/importprotocol.h). The parent sets the
// memory limit (RLIMIT_AS) before this starts; a failed allocation is remembered so that a crash that
// follows it can be reported as the memory limit rather than as a plain crash.
#include "cli.h"

#include "model/environmentdecode.h"
#include "model/exrdecode.h"
#include "model/gltfexport.h"
#include "model/gobodecode.h"
#include "model/importbudget.h"
#include "model/importprotocol.h"
#include "model/modelcodec.h"
#include "model/modelloader.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <QThread>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <mutex>
#include <new>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lr::cli {

namespace {

namespace ip = importprotocol;

int g_replyFd = -1;
volatile std::sig_atomic_t g_allocationFailed = 0;

bool writeFd(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

bool writeAll(const char* data, std::size_t size) {
    return writeFd(g_replyFd, data, size);
}

bool writeFrame(char type, const char* payload, std::size_t size) {
    char header[ip::kFrameHeaderSize];
    header[0] = type;
    const quint64 length = size;
    std::memcpy(header + 1, &length, sizeof length);
    return writeAll(header, sizeof header) && writeAll(payload, size);
}

// Every file the import reads raises this worker's address-space limit (soft, up to the hard limit its
// parent set) to the budget for all of them, and tells the parent, which moves its deadline
// (model/importbudget.h).
void followInputBudget(BudgetKind kind, std::mutex& writing) {
    setImportInputListener([kind, &writing](qint64 total) {
        const std::lock_guard lock(writing);
        static qint64 largest = 0;
        if (total <= largest) return;
        largest = total;
        rlimit as{};
        if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_max != RLIM_INFINITY) {
            const qint64 wanted = importBudget(kind, total, qint64(as.rlim_max), 0).memoryBytes;
            if (wanted > 0 && rlim_t(wanted) > as.rlim_cur) {
                as.rlim_cur = rlim_t(wanted);
                ::setrlimit(RLIMIT_AS, &as);
            }
        }
        const quint64 n = quint64(total);
        writeFrame(ip::kInputBytes, reinterpret_cast<const char*>(&n), sizeof n);
    });
}

// Async-signal-safe: only write(2) and re-raising with the default action (SA_RESETHAND).
void crashHandler(int sig) {
    if (g_allocationFailed && g_replyFd >= 0) {
        const char frame[ip::kFrameHeaderSize] = {ip::kOutOfMemory, 0, 0, 0, 0, 0, 0, 0, 0};
        [[maybe_unused]] const ssize_t n = ::write(g_replyFd, frame, sizeof frame);
    }
    ::raise(sig);
}

// Called by operator new when an allocation fails: remember it, then let new throw std::bad_alloc.
void onAllocationFailure() {
    g_allocationFailed = 1;
    std::set_new_handler(nullptr);
}

void installCrashReporting() {
    std::set_new_handler(onAllocationFailure);
    struct sigaction sa {};
    sa.sa_handler = crashHandler;
    sa.sa_flags = SA_RESETHAND | SA_NODEFER;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGILL, SIGFPE})
        sigaction(sig, &sa, nullptr);
}

// Moves the reply channel off fd 1, and points fd 1 at stderr: library chatter on stdout cannot reach
// the parent's frame reader.
bool takeStdout() {
    g_replyFd = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
    if (g_replyFd < 0) return false;
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
#ifdef F_SETPIPE_SZ
    ::fcntl(g_replyFd, F_SETPIPE_SZ, 1 << 20); // fewer round trips for large models; best effort
#endif
    return true;
}

// stdin up to its end (the parent closes it after the request), at most kMaxRequestBytes.
QByteArray readRequest() {
    QByteArray request;
    char buffer[4096];
    while (request.size() < ip::kMaxRequestBytes) {
        const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        request.append(buffer, qsizetype(n));
    }
    return request;
}

// The parent's memfd (a sealable file: F_GET_SEALS works on nothing else), empty, at offset 0.
bool sharedUsable(int fd) {
#ifdef F_GET_SEALS
    struct stat st {};
    return fd >= 0 && ::fcntl(fd, F_GET_SEALS) >= 0 && ::fstat(fd, &st) == 0 && st.st_size == 0 &&
           ::lseek(fd, 0, SEEK_CUR) == 0;
#else
    Q_UNUSED(fd);
    return false;
#endif
}

// The model into the shared memfd, then the 'S' frame with its size; false (and the memfd emptied)
// when it could not be written, so that the pipe can carry it instead.
bool sendShared(int fd, const Model& model) {
    if (!sharedUsable(fd)) return false;
    const quint64 size = encodedModelSize(model);
    const bool written =
        writeModel(model, [fd](const char* data, std::size_t n) { return writeFd(fd, data, n); });
    if (!written) {
        [[maybe_unused]] const int ignored = ::ftruncate(fd, 0);
        ::lseek(fd, 0, SEEK_SET);
        return false;
    }
    return writeFrame(ip::kShared, reinterpret_cast<const char*>(&size), sizeof size);
}

// An environment image: the 'V' frame (importprotocol.h) or the decoder's error. The texels go out
// from the image itself (encodeEnvironmentReply's layout without its copy: half the worker's memory).
// A gobo's image (model/gobodecode.h) goes back the same way.
[[noreturn]] void sendEnvironment(const EnvironmentDecodeResult& result) {
    bool sent;
    if (result.ok()) {
        EnvironmentImage empty;
        empty.width = result.image.width;
        empty.height = result.image.height;
        const QByteArray head = encodeEnvironmentReply(empty, result.warnings);
        const auto* texels = reinterpret_cast<const char*>(result.image.texels.data());
        const std::size_t texelBytes = result.image.texels.size() * sizeof(glm::vec3);
        char header[ip::kFrameHeaderSize] = {ip::kEnvironment};
        const quint64 length = quint64(head.size()) + texelBytes;
        std::memcpy(header + 1, &length, sizeof length);
        sent = writeAll(header, sizeof header) && writeAll(head.constData(), std::size_t(head.size())) &&
               writeAll(texels, texelBytes);
    } else {
        QByteArray payload(1, char(g_allocationFailed ? ip::kErrorOutOfMemory : 0));
        payload += result.error.toUtf8().left(ip::kMaxErrorBytes);
        sent = writeFrame(ip::kError, payload.constData(), std::size_t(payload.size()));
    }
    std::_Exit(sent ? Ok : Failed);
}

// A multi-layer OpenEXR file (model/exrdecode.h): the 'L' frame, its pixels written from the decoded
// layers themselves (no copy), or the decoder's error.
[[noreturn]] void sendExrLayers(const QString& path) {
    QString error;
    const std::optional<ExrFile> file = decodeExrLayersFile(path, &error);
    bool sent;
    if (file) {
        const QByteArray head = exrLayersReplyHead(*file);
        quint64 length = quint64(head.size());
        for (const ExrLayer& layer : file->layers)
            length += layer.pixels.size() * sizeof(float);
        char header[ip::kFrameHeaderSize] = {ip::kExrLayers};
        std::memcpy(header + 1, &length, sizeof length);
        sent = writeAll(header, sizeof header) && writeAll(head.constData(), std::size_t(head.size()));
        for (const ExrLayer& layer : file->layers)
            sent = sent && writeAll(reinterpret_cast<const char*>(layer.pixels.data()),
                                    layer.pixels.size() * sizeof(float));
    } else {
        QByteArray payload(1, char(g_allocationFailed ? ip::kErrorOutOfMemory : 0));
        payload += error.toUtf8().left(ip::kMaxErrorBytes);
        sent = writeFrame(ip::kError, payload.constData(), std::size_t(payload.size()));
    }
    std::_Exit(sent ? Ok : Failed);
}

// An Assimp export of a model to GLB (model/gltfexport.h), or the error.
[[noreturn]] void sendGltf(const QString& path) {
    QString error;
    const QByteArray glb = assimpGlb(path, &error);
    bool sent;
    if (!glb.isEmpty()) {
        sent = writeFrame(ip::kGltf, glb.constData(), std::size_t(glb.size()));
    } else {
        QByteArray payload(1, char(g_allocationFailed ? ip::kErrorOutOfMemory : 0));
        payload += error.toUtf8().left(ip::kMaxErrorBytes);
        sent = writeFrame(ip::kError, payload.constData(), std::size_t(payload.size()));
    }
    std::_Exit(sent ? Ok : Failed);
}

[[noreturn]] void testCrash(const QByteArray& mode, int sharedFd) {
    if (mode == "segv") ::raise(SIGSEGV);
    if (mode == "abort") std::abort();
    if (mode == "hang")
        for (;;)
            QThread::sleep(1);
    if (mode == "oom") {
        static std::vector<char*> hoard; // keeps every block alive until new fails, uncaught
        for (;;) {
            char* block = new char[64 << 20];
            block[0] = 1;
            hoard.push_back(block);
        }
    }
    if (mode == "garbage") {
        const QByteArray junk(4096, '\x5a');
        writeFrame(ip::kModel, junk.constData(), std::size_t(junk.size()));
    }
    if (mode == "truncate") {
        const QByteArray encoded = encodeModel(makeSphere(1.0, 16, 8));
        char header[ip::kFrameHeaderSize] = {ip::kModel};
        const quint64 length = quint64(encoded.size());
        std::memcpy(header + 1, &length, sizeof length);
        writeAll(header, sizeof header);
        writeAll(encoded.constData(), std::size_t(encoded.size() / 2));
    }
    if (mode == "env-nan" || mode == "env-size") { // an environment reply the parent must refuse
        EnvironmentImage image;
        image.width = 2;
        image.height = 1;
        image.texels = {glm::vec3(1.0f), glm::vec3(std::numeric_limits<float>::quiet_NaN())};
        QByteArray reply = encodeEnvironmentReply(image, {});
        if (mode == "env-size") reply.chop(4);
        writeFrame(ip::kEnvironment, reply.constData(), std::size_t(reply.size()));
    }
    if (mode == "shared-garbage" || mode == "shared-short") {
        const QByteArray junk(4096, '\x5a');
        writeFd(sharedFd, junk.constData(), std::size_t(junk.size()));
        const quint64 size = mode == "shared-short" ? 8192 : 4096;
        writeFrame(ip::kShared, reinterpret_cast<const char*>(&size), sizeof size);
    }
    std::_Exit(mode == "exit" ? 3 : 0);
}

} // namespace

int runImportWorker(const QStringList&) {
    QTextStream err(stderr);
    installCrashReporting();
    if (!takeStdout()) {
        err << "lightrig import-worker: cannot take over stdout\n";
        return Failed;
    }
    const QJsonObject request = QJsonDocument::fromJson(readRequest()).object();
    const QString path = request.value(QStringLiteral("path")).toString();
    if (path.isEmpty()) {
        err << "lightrig import-worker: expects a JSON request with a path on stdin (used by lightrig "
               "itself)\n";
        return Usage;
    }
    const int sharedFd = request.value(QStringLiteral("sharedFd")).toInt(-1);
    std::mutex writing;
    const QString kind = request.value(QStringLiteral("kind")).toString();
    const bool environment =
        kind == QLatin1String("environment") || kind == QLatin1String(ip::kGoboKind); // the same budget
    const bool exrLayers = kind == QLatin1String(ip::kExrLayersKind);
    followInputBudget(environment ? BudgetKind::Environment
                      : exrLayers ? BudgetKind::ExrLayers
                                  : BudgetKind::Model,
                      writing);
    if (const QByteArray mode = qgetenv(ip::kTestCrashVariable); !mode.isEmpty()) testCrash(mode, sharedFd);
    if (kind == QLatin1String(ip::kGoboKind)) sendEnvironment(decodeGoboFile(path));
    if (environment) sendEnvironment(decodeEnvironmentFile(path));
    if (exrLayers) sendExrLayers(path);
    if (kind == QLatin1String("gltf-export")) sendGltf(path);

    ModelLoadOptions options;
    options.allowTexturesOutsideFolder =
        request.value(QStringLiteral("allowTexturesOutsideFolder")).toBool(false);
    options.maxDataUriBytes =
        qint64(request.value(QStringLiteral("maxDataUriBytes")).toDouble(double(options.maxDataUriBytes)));
    double lastSent = -1.0;
    options.progress = [&](double fraction) {
        const std::lock_guard lock(writing);
        if (fraction - lastSent >= 0.005 || (fraction >= 1.0 && lastSent < 1.0)) {
            lastSent = fraction;
            return writeFrame(ip::kProgress, reinterpret_cast<const char*>(&fraction), sizeof fraction);
        }
        return true; // the parent cancels by killing this process
    };

    const ModelLoadResult result = loadModel(path, options);
    const std::lock_guard lock(writing);
    bool sent;
    if (result.ok()) {
        sent = sendShared(sharedFd, *result.model);
        if (!sent) {
            char header[ip::kFrameHeaderSize] = {ip::kModel};
            const quint64 length = encodedModelSize(*result.model);
            std::memcpy(header + 1, &length, sizeof length);
            sent = writeAll(header, sizeof header) && writeModel(*result.model, writeAll);
        }
    } else {
        QByteArray payload(1, char((result.cancelled ? ip::kErrorCancelled : 0) |
                                   (g_allocationFailed ? ip::kErrorOutOfMemory : 0)));
        payload += result.error.toUtf8().left(ip::kMaxErrorBytes);
        sent = writeFrame(ip::kError, payload.constData(), std::size_t(payload.size()));
    }
    // The reply is out: skip freeing a possibly huge model and Qt's shutdown.
    std::_Exit(sent ? Ok : Failed);
}

} // namespace lr::cli
