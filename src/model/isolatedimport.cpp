#include "isolatedimport.h"

#include "importprotocol.h"
#include "modelcodec.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMutex>
#include <QProcess>
#include <algorithm>
#include <csignal>
#include <cstring>
#include <new>
#include <sys/resource.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define LIGHTRIG_ISOLATED_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIGHTRIG_ISOLATED_ASAN 1
#endif
#endif

namespace lr {

namespace {

namespace ip = importprotocol;

constexpr int kPollMs = 50;
constexpr double kImportShare = 0.9; // of the progress bar; the rest is receiving the model
constexpr qsizetype kStderrTail = 8192;

QMutex g_executableMutex;
QString g_executable;

// Reads the worker's frames as they arrive. Never trusts a length before checking it.
class FrameReader {
  public:
    explicit FrameReader(qint64 maxModelBytes) : m_maxModelBytes(maxModelBytes) {}

    enum class State { Reading, Model, Error, Malformed };
    State state() const { return m_state; }
    bool done() const { return m_state != State::Reading; }
    double fraction() const {
        double f = kImportShare * m_childFraction;
        if (m_inPayload && m_type == ip::kModel && m_length > 0)
            f = kImportShare + (1.0 - kImportShare) * double(m_payload.size()) / double(m_length);
        return f;
    }
    bool sawOutOfMemory() const { return m_outOfMemory; }
    bool midFrame() const { return m_inPayload || !m_header.isEmpty(); }
    const QByteArray& payload() const { return m_payload; }
    const QString& problem() const { return m_problem; }

    void consume(QProcess& p) {
        while (!done() && p.bytesAvailable() > 0) {
            if (!m_inPayload) {
                m_header += p.read(ip::kFrameHeaderSize - m_header.size());
                if (m_header.size() == ip::kFrameHeaderSize) startFrame();
            } else {
                const qint64 want = qint64(m_length) - m_payload.size();
                const qint64 take = std::min(want, p.bytesAvailable());
                const qsizetype old = m_payload.size();
                m_payload.resize(old + qsizetype(take));
                const qint64 got = p.read(m_payload.data() + old, take);
                m_payload.resize(old + qsizetype(std::max<qint64>(got, 0)));
                if (got <= 0) return;
                if (quint64(m_payload.size()) == m_length) endFrame();
            }
        }
    }

  private:
    void malformed(const QString& why) {
        m_state = State::Malformed;
        m_problem = why;
    }
    void startFrame() {
        m_type = m_header[0];
        std::memcpy(&m_length, m_header.constData() + 1, sizeof m_length);
        m_header.clear();
        bool ok = false;
        switch (m_type) {
        case ip::kProgress:
            ok = m_length == sizeof(double);
            break;
        case ip::kOutOfMemory:
            ok = m_length == 0;
            break;
        case ip::kError:
            ok = m_length >= 1 && m_length <= quint64(1 + ip::kMaxErrorBytes);
            break;
        case ip::kModel:
            ok = m_length >= quint64(kModelCodecHeaderSize) && m_length <= quint64(m_maxModelBytes);
            break;
        default:
            return malformed(QStringLiteral("unknown frame type %1").arg(int(quint8(m_type))));
        }
        if (!ok)
            return malformed(QStringLiteral("frame '%1' of %2 bytes").arg(QLatin1Char(m_type)).arg(m_length));
        m_payload.clear();
        try {
            m_payload.reserve(qsizetype(m_length));
        } catch (const std::bad_alloc&) {
            return malformed(QStringLiteral("no memory for a reply of %1 bytes").arg(m_length));
        }
        m_inPayload = true;
        if (m_length == 0) endFrame();
    }
    void endFrame() {
        m_inPayload = false;
        switch (m_type) {
        case ip::kProgress: {
            double f;
            std::memcpy(&f, m_payload.constData(), sizeof f);
            if (f >= 0.0 && f <= 1.0) m_childFraction = std::max(m_childFraction, f); // NaN fails both
            break;
        }
        case ip::kOutOfMemory:
            m_outOfMemory = true;
            break;
        case ip::kError:
            m_state = State::Error;
            break;
        case ip::kModel:
            m_state = State::Model;
            break;
        }
    }

    qint64 m_maxModelBytes;
    State m_state = State::Reading;
    QByteArray m_header, m_payload;
    char m_type = 0;
    quint64 m_length = 0;
    bool m_inPayload = false;
    double m_childFraction = 0.0;
    bool m_outOfMemory = false;
    QString m_problem;
};

QString seconds(int ms) {
    return QString::number(ms / 1000.0, 'g', 4);
}

QString lastLine(const QByteArray& text) {
    const QList<QByteArray> lines = text.trimmed().split('\n');
    return lines.isEmpty() ? QString() : QString::fromUtf8(lines.last().trimmed()).left(300);
}

QString describeExit(const QProcess& p, const QByteArray& stderrTail) {
    if (p.exitStatus() == QProcess::CrashExit) {
        const int sig = p.exitCode(); // Qt reports the signal number for a crash exit on Unix
        if (sig == SIGABRT) return QStringLiteral("the importer aborted (signal %1)").arg(sig);
        if (sig == SIGKILL) return QStringLiteral("the importer was killed (signal %1)").arg(sig);
        return QStringLiteral("the importer crashed (signal %1)").arg(sig);
    }
    QString why = QStringLiteral("the importer exited with code %1 without a result").arg(p.exitCode());
    if (const QString line = lastLine(stderrTail); !line.isEmpty()) why += QStringLiteral(" (%1)").arg(line);
    return why;
}

} // namespace

void setImportWorkerExecutable(const QString& path) {
    const QMutexLocker lock(&g_executableMutex);
    g_executable = path;
}

QString importWorkerExecutable() {
    {
        const QMutexLocker lock(&g_executableMutex);
        if (!g_executable.isEmpty()) return g_executable;
    }
    if (const QString fromEnvironment = qEnvironmentVariable("LIGHTRIG_IMPORT_WORKER");
        !fromEnvironment.isEmpty())
        return fromEnvironment;
    return QCoreApplication::instance() ? QCoreApplication::applicationFilePath() : QString();
}

QString formatMemoryLimit(qint64 bytes) {
    constexpr qint64 MiB = 1ll << 20, GiB = 1ll << 30;
    if (bytes >= GiB && bytes % GiB == 0) return QStringLiteral("%1 GiB").arg(bytes / GiB);
    if (bytes >= GiB) return QStringLiteral("%1 GiB").arg(double(bytes) / double(GiB), 0, 'f', 1);
    if (bytes % MiB == 0) return QStringLiteral("%1 MiB").arg(bytes / MiB);
    return QStringLiteral("%1 bytes").arg(bytes);
}

ModelLoadResult importModelIsolated(const QString& path, const ModelLoadOptions& options,
                                    const ImportLimits& limits) {
    QElapsedTimer timer;
    timer.start();
    const QString fileName = QFileInfo(path).fileName();
    const QString name = fileName.isEmpty() ? path : fileName;
    const auto failure = [&](const QString& reason, bool cancelled = false) {
        ModelLoadResult r;
        r.error = QStringLiteral("could not import %1: %2").arg(name, reason);
        r.cancelled = cancelled;
        return r;
    };
    double reported = 0.0;
    const auto keepGoing = [&](double fraction) {
        reported = std::max(reported, fraction);
        if (limits.cancel && limits.cancel->load()) return false;
        return !options.progress || options.progress(reported);
    };
    if (!keepGoing(0.0)) return failure(QStringLiteral("cancelled"), true);

    const QString executable = importWorkerExecutable();
    if (executable.isEmpty()) return failure(QStringLiteral("no import worker executable is set"));

    QProcess worker;
    worker.setProgram(executable);
    worker.setArguments({QString::fromLatin1(ip::kSubcommand)});
    const qint64 memory = limits.memoryBytes;
    worker.setChildProcessModifier([memory] {
        // Runs in the child between fork and exec: async-signal-safe calls only.
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
#ifndef LIGHTRIG_ISOLATED_ASAN // AddressSanitizer reserves terabytes of address space
        if (memory > 0) {
            const rlimit as{rlim_t(memory), rlim_t(memory)};
            ::setrlimit(RLIMIT_AS, &as);
        }
#endif
#ifdef __linux__
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // the worker never outlives this thread
#endif
    });
    worker.start(QIODevice::ReadWrite);
    if (!worker.waitForStarted(30'000))
        return failure(QStringLiteral("could not start the import worker %1 (%2)")
                           .arg(executable, worker.errorString()));

    QJsonObject request;
    request.insert(QStringLiteral("path"), path);
    request.insert(QStringLiteral("allowTexturesOutsideFolder"), options.allowTexturesOutsideFolder);
    request.insert(QStringLiteral("maxDataUriBytes"), double(options.maxDataUriBytes));
    worker.write(QJsonDocument(request).toJson(QJsonDocument::Compact));
    worker.closeWriteChannel();

    FrameReader reader(memory > 0 ? memory : (1ll << 40));
    QByteArray stderrTail;
    enum class Stop { None, TimedOut, Cancelled } stop = Stop::None;
    for (;;) {
        worker.waitForReadyRead(kPollMs);
        reader.consume(worker);
        stderrTail += worker.readAllStandardError();
        if (stderrTail.size() > kStderrTail) stderrTail = stderrTail.right(kStderrTail);
        if (reader.done()) break;
        if (worker.state() == QProcess::NotRunning) {
            reader.consume(worker); // whatever arrived with the exit
            break;
        }
        if (limits.timeoutMs > 0 && timer.elapsed() > limits.timeoutMs) {
            stop = Stop::TimedOut;
            break;
        }
        if (!keepGoing(reader.fraction())) {
            stop = Stop::Cancelled;
            break;
        }
    }
    if (stop != Stop::None || reader.state() == FrameReader::State::Malformed) {
        worker.kill();
        worker.waitForFinished(5'000);
        if (stop == Stop::Cancelled) return failure(QStringLiteral("cancelled"), true);
        if (stop == Stop::TimedOut)
            return failure(
                QStringLiteral("the importer did not finish within %1 s").arg(seconds(limits.timeoutMs)));
        return failure(QStringLiteral("the importer sent a malformed reply (%1)").arg(reader.problem()));
    }
    // A complete reply: the worker exits right after sending it.
    if (reader.done() && !worker.waitForFinished(5'000)) {
        worker.kill();
        worker.waitForFinished(5'000);
    }
    const QString outOfMemory =
        QStringLiteral("the importer ran out of its %1 memory limit").arg(formatMemoryLimit(memory));

    if (reader.state() == FrameReader::State::Error) {
        const QByteArray& p = reader.payload();
        const auto flags = quint8(p.at(0));
        if (flags & ip::kErrorOutOfMemory && memory > 0) return failure(outOfMemory);
        QString message = QString::fromUtf8(p.constData() + 1, p.size() - 1);
        if (message.isEmpty()) message = failure(QStringLiteral("the importer gave no reason")).error;
        ModelLoadResult r;
        r.error = message;
        r.cancelled = flags & ip::kErrorCancelled;
        return r;
    }
    if (reader.state() == FrameReader::State::Model) {
        QString why;
        std::shared_ptr<Model> model = decodeModel(reader.payload(), &why);
        if (!model) return failure(QStringLiteral("the importer sent a malformed reply (%1)").arg(why));
        if (!keepGoing(1.0)) return failure(QStringLiteral("cancelled"), true);
        model->loadMs = double(timer.nsecsElapsed()) / 1e6;
        ModelLoadResult r;
        r.model = std::move(model);
        return r;
    }
    // The worker ended without a complete reply.
    if (reader.sawOutOfMemory() && memory > 0) return failure(outOfMemory);
    if (worker.exitStatus() == QProcess::NormalExit && worker.exitCode() == 0 && reader.midFrame())
        return failure(QStringLiteral("the importer sent a malformed reply (truncated)"));
    return failure(describeExit(worker, stderrTail));
}

} // namespace lr
