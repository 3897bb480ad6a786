#include "isolatedimport.h"

#include "importprotocol.h"
#include "isolatedworker.h"
#include "modelcodec.h"

#include <QElapsedTimer>
#include <QProcess>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lr {

namespace {

namespace ip = importprotocol;

// The worker writes the encoded model into a memfd created here (fewer copies and page faults than the
// pipe for a large model: ~44 MB for 1M triangles). After the worker has exited, the memfd is sealed
// against any change before it is mapped, so the bytes cannot change or shrink (SIGBUS) under the decoder
// or under the texture images, which keep their pages of the mapping instead of copying them.
class SharedReply {
  public:
    SharedReply() {
#ifdef __linux__
        m_fd = ::memfd_create("lightrig-import", MFD_CLOEXEC | MFD_ALLOW_SEALING);
#endif
    }
    ~SharedReply() {
        if (m_fd >= 0) ::close(m_fd);
    }
    SharedReply(const SharedReply&) = delete;
    SharedReply& operator=(const SharedReply&) = delete;
    int fd() const {
        return m_fd;
    }

#ifdef __linux__
    // Seals the memfd against every change. Linux refuses F_SEAL_WRITE (EBUSY) while a page still has an
    // extra reference, which a page the worker has just written can hold for a moment on another CPU (the
    // kernel waits only briefly): then it is tried again, for up to kSealRetries × kSealRetryMs.
    bool seal() const {
        constexpr int kSealRetries = 20, kSealRetryMs = 10;
        for (int attempt = 0;; ++attempt) {
            if (::fcntl(m_fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL) == 0)
                return true;
            if (errno != EBUSY || attempt == kSealRetries) return false;
            ::usleep(kSealRetryMs * 1000);
        }
    }
#endif

    // Decodes the `size` bytes the worker announced. Sealing comes first, so a worker still running can
    // no longer change what is decoded.
    std::shared_ptr<Model> decode(quint64 size, qint64 maxBytes, QString* why) const {
#ifdef __linux__
        if (m_fd < 0) return fail(why, QStringLiteral("a shared reply that was not offered"));
        if (size < quint64(kModelCodecHeaderSize) || size > quint64(maxBytes))
            return fail(why, QStringLiteral("a shared reply of %1 bytes").arg(size));
        if (!seal())
            return fail(
                why,
                QStringLiteral("the shared reply is still open for writing (%1)").arg(qt_error_string()));
        struct stat st {};
        if (::fstat(m_fd, &st) != 0 || quint64(st.st_size) < size)
            return fail(why, QStringLiteral("the shared reply is shorter than announced"));
        void* mapped = ::mmap(nullptr, size_t(size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, m_fd, 0);
        if (mapped == MAP_FAILED)
            return fail(why, QStringLiteral("cannot map the shared reply (%1)").arg(qt_error_string()));
        // Texture images keep their own pages of the mapping (no copy); everything else is unmapped below.
        const auto* base = static_cast<const char*>(mapped);
        const std::size_t page = std::size_t(::sysconf(_SC_PAGESIZE));
        const auto pageEnd = [page](std::size_t offset) { return (offset + page - 1) / page * page; };
        std::vector<std::pair<std::size_t, std::size_t>> lent; // page ranges [begin, end) of texture images
        const ImageLender lend = [&](const char* pixels, std::size_t bytes, QImageCleanupFunction* cleanup,
                                     void** info) {
            const auto offset = std::size_t(pixels - base);
            if (offset % page != 0 || (!lent.empty() && offset < lent.back().second)) return false;
            auto* region = new Region{const_cast<char*>(pixels), pageEnd(offset + bytes) - offset};
            try {
                lent.emplace_back(offset, offset + region->length);
            } catch (...) {
                delete region;
                throw;
            }
            *cleanup = unmapRegion;
            *info = region;
            return true;
        };
        std::shared_ptr<Model> model = decodeModel(QByteArrayView(base, qsizetype(size)), why, {}, lend);
        std::size_t cursor = 0;
        for (const auto& [begin, end] : lent) {
            if (begin > cursor) ::munmap(const_cast<char*>(base) + cursor, begin - cursor);
            cursor = end;
        }
        if (cursor < pageEnd(size)) ::munmap(const_cast<char*>(base) + cursor, pageEnd(size) - cursor);
        return model;
#else
        Q_UNUSED(size);
        Q_UNUSED(maxBytes);
        return fail(why, QStringLiteral("a shared reply that was not offered"));
#endif
    }

  private:
    struct Region {
        char* start;
        std::size_t length;
    };
    static void unmapRegion(void* info) {
        const auto* region = static_cast<Region*>(info);
        ::munmap(region->start, region->length);
        delete region;
    }
    static std::shared_ptr<Model> fail(QString* why, const QString& text) {
        *why = text;
        return {};
    }
    int m_fd = -1;
};

} // namespace

ModelLoadResult importModelIsolated(const QString& path, const ModelLoadOptions& options,
                                    const ImportLimits& limits) {
    QElapsedTimer timer;
    timer.start();
    const auto failure = [&](const QString& reason, bool cancelled = false) {
        ModelLoadResult r;
        r.error = QStringLiteral("could not import %1: %2").arg(path, reason); // the path as given
        r.cancelled = cancelled;
        return r;
    };
    double reported = 0.0;
    const auto keepGoing = [&](double fraction) {
        reported = std::max(reported, fraction);
        if (limits.cancel && limits.cancel->load()) return false;
        return !options.progress || options.progress(reported);
    };
    const SharedReply shared;
    QJsonObject request;
    request.insert(QStringLiteral("path"), path);
    request.insert(QStringLiteral("allowTexturesOutsideFolder"), options.allowTexturesOutsideFolder);
    request.insert(QStringLiteral("maxDataUriBytes"), double(options.maxDataUriBytes));
    const qint64 maxBytes = limits.memoryBytes > 0 ? limits.memoryBytes : (1ll << 40);
    isolated::WorkerOutcome run =
        isolated::runWorker(request, limits, limits.sharedMemory ? shared.fd() : -1, keepGoing, maxBytes);
    if (!run.ok()) {
        if (!run.fromWorker) return failure(run.failure, run.cancelled);
        ModelLoadResult r;
        r.error = run.failure;
        r.cancelled = run.cancelled;
        return r;
    }
    QString why;
    std::shared_ptr<Model> model;
    if (run.type == ip::kModel) {
        model = decodeModel(run.payload, &why);
    } else if (run.type == ip::kShared) {
        quint64 size = 0;
        std::memcpy(&size, run.payload.constData(), sizeof size);
        model = shared.decode(size, maxBytes, &why); // sealed first: the worker may live on
    } else {
        why = QStringLiteral("a reply of type '%1' to a model request").arg(QLatin1Char(run.type));
    }
    if (!model) return failure(QStringLiteral("the importer sent a malformed reply (%1)").arg(why));
    if (!keepGoing(1.0)) return failure(QStringLiteral("cancelled"), true);
    model->loadMs = double(timer.nsecsElapsed()) / 1e6;
    ModelLoadResult r;
    r.model = std::move(model);
    return r;
}

} // namespace lr
