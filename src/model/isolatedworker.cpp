#include "isolatedworker.h"

#include "importprotocol.h"
#include "modelcodec.h"

#include "core/hugepages.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QMutex>
#include <QProcess>
#include <algorithm>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <new>
#include <sys/resource.h>
#include <unistd.h>
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
constexpr double kImportShare = 0.9; // of the progress bar; the rest is receiving the reply
constexpr qsizetype kStderrTail = 8192;

QMutex g_executableMutex;
QString g_executable;

// Reads the worker's frames as they arrive. Never trusts a length before checking it.
class FrameReader {
  public:
    explicit FrameReader(qint64 maxReplyBytes) : m_maxReplyBytes(maxReplyBytes) {}

    enum class State { Reading, Reply, Error, Malformed };
    State state() const { return m_state; }
    bool done() const { return m_state != State::Reading; }
    double fraction() const {
        double f = kImportShare * m_childFraction;
        if (m_inPayload && (m_type == ip::kModel || m_type == ip::kEnvironment || m_type == ip::kExrLayers) &&
            m_length > 0)
            f = kImportShare + (1.0 - kImportShare) * double(m_payload.size()) / double(m_length);
        return f;
    }
    bool sawOutOfMemory() const { return m_outOfMemory; }
    qint64 inputBytes() const { return m_inputBytes; }
    bool midFrame() const { return m_inPayload || !m_header.isEmpty(); }
    QByteArray& payload() { return m_payload; }
    char type() const { return m_type; }
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
            ok = m_length >= quint64(kModelCodecHeaderSize) && m_length <= quint64(m_maxReplyBytes);
            break;
        case ip::kEnvironment:
            ok = m_length >= quint64(ip::kEnvironmentHeaderSize) && m_length <= quint64(m_maxReplyBytes);
            break;
        case ip::kGltf:
            ok = m_length >= 12 && m_length <= quint64(m_maxReplyBytes);
            break;
        case ip::kExrLayers: // width, height and two counts at least
            ok = m_length >= 16 && m_length <= quint64(m_maxReplyBytes);
            break;
        case ip::kShared:
        case ip::kInputBytes:
            ok = m_length == sizeof(quint64);
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
        case ip::kInputBytes: {
            quint64 n;
            std::memcpy(&n, m_payload.constData(), sizeof n);
            m_inputBytes = std::max(m_inputBytes, qint64(std::min<quint64>(n, 1ull << 40)));
            break;
        }
        case ip::kError:
            m_state = State::Error;
            break;
        case ip::kModel:
        case ip::kShared:
        case ip::kEnvironment:
        case ip::kGltf:
        case ip::kExrLayers:
            m_state = State::Reply;
            break;
        }
    }

    qint64 m_maxReplyBytes;
    State m_state = State::Reading;
    QByteArray m_header, m_payload;
    char m_type = 0;
    quint64 m_length = 0;
    bool m_inPayload = false;
    double m_childFraction = 0.0;
    bool m_outOfMemory = false;
    qint64 m_inputBytes = 0;
    QString m_problem;
};

QString seconds(int ms) {
    return QString::number(ms / 1000.0, 'g', 4);
}

// " (its limit for 221 bytes of input)" when the limit was scaled down to the input, else nothing.
QString ofInput(const ImportLimits& limits, bool scaled, const QString& what, qint64 input) {
    if (!limits.scaleWithInput || !scaled) return {};
    return QStringLiteral(" (%1for %2 of input)")
        .arg(what.isEmpty() ? QString() : what + QLatin1Char(' '), formatInputBytes(input));
}

QString lastLine(const QByteArray& text) {
    const QList<QByteArray> lines = text.trimmed().split('\n');
    return lines.isEmpty() ? QString() : QString::fromUtf8(lines.last().trimmed()).left(300);
}

// The worker decodes every texture into fresh buffers (16 MiB for a 2048² RGBA image, several times
// over), so it runs with malloc on transparent huge pages (core/hugepages.h): importing DamagedHelmet
// (five 2048² JPEGs) took 490-610 ms before and 227-352 ms after, four runs each on the 2-core VM.
// The worker's glibc tunables: huge pages as the editor has them, and at most two malloc arenas. Each
// thread that allocates would otherwise get an arena of its own, and with huge pages each reserves 64 MiB
// or more of address space: the texture decoders of a 16-core machine (one thread per texture) then ran
// out of the worker's address-space budget (RLIMIT_AS, importbudget.h) for the 3.8 MB DamagedHelmet,
// and a thread could not start. Two arenas keep the decoders' contention low and the budget machine-free.
QProcessEnvironment workerEnvironment() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    QString tunables = env.value(QStringLiteral("GLIBC_TUNABLES"));
    if (const std::string huge = withHugePageTunable(tunables.toStdString()); !huge.empty())
        tunables = QString::fromStdString(huge);
    if (!tunables.contains(QLatin1String("glibc.malloc.arena_max")))
        tunables += QLatin1String(tunables.isEmpty() ? "" : ":") + QLatin1String("glibc.malloc.arena_max=2");
    env.insert(QStringLiteral("GLIBC_TUNABLES"), tunables);
    return env;
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
    // Only lightrig itself has the import-worker subcommand (a test executable, say, does not).
    if (!QCoreApplication::instance() || QCoreApplication::applicationName() != QLatin1String("lightrig"))
        return {};
    return QCoreApplication::applicationFilePath();
}

QString formatMemoryLimit(qint64 bytes) {
    constexpr qint64 MiB = 1ll << 20, GiB = 1ll << 30;
    if (bytes >= GiB && bytes % GiB == 0) return QStringLiteral("%1 GiB").arg(bytes / GiB);
    if (bytes >= GiB) return QStringLiteral("%1 GiB").arg(double(bytes) / double(GiB), 0, 'f', 1);
    if (bytes % MiB == 0) return QStringLiteral("%1 MiB").arg(bytes / MiB);
    return QStringLiteral("%1 bytes").arg(bytes);
}

namespace isolated {

ExitingWorker::ExitingWorker() = default;
ExitingWorker::ExitingWorker(ExitingWorker&&) noexcept = default;
ExitingWorker::~ExitingWorker() {
    QProcess* p = process.get();
    if (p && p->state() != QProcess::NotRunning && !p->waitForFinished(5'000)) {
        p->kill();
        p->waitForFinished(5'000);
    }
}

WorkerOutcome runWorker(const QJsonObject& request, const ImportLimits& limits, int sharedFd,
                        const std::function<bool(double)>& keepGoing, qint64 maxReplyBytes, BudgetKind kind) {
    QElapsedTimer timer;
    timer.start();
    WorkerOutcome out;
    const auto fail = [&out](const QString& reason, bool cancelled = false) {
        out.failure = reason;
        out.cancelled = cancelled;
        return std::move(out);
    };
    if (!keepGoing(0.0)) return fail(QStringLiteral("cancelled"), true);
    const QString executable = importWorkerExecutable();
    if (executable.isEmpty())
        return fail(QStringLiteral("no import worker: this is not lightrig, and neither "
                                   "setImportWorkerExecutable() nor LIGHTRIG_IMPORT_WORKER names one"));

    out.worker.process = std::make_unique<QProcess>();
    QProcess& worker = *out.worker.process;
    worker.setProgram(executable);
    worker.setArguments({QString::fromLatin1(ip::kSubcommand)});
    worker.setProcessEnvironment(workerEnvironment());
    // The budget for the request's file alone; the worker raises its own (soft) memory limit, and says
    // so, as it reads more files, up to limits.memoryBytes (the hard limit).
    const qint64 fileBytes = QFileInfo(request.value(QStringLiteral("path")).toString()).size();
    const auto budgetFor = [&](qint64 input) {
        return limits.scaleWithInput ? importBudget(kind, input, limits.memoryBytes, limits.timeoutMs)
                                     : ImportBudget{limits.memoryBytes, limits.timeoutMs};
    };
    ImportBudget budget = budgetFor(fileBytes);
    const qint64 memory = limits.memoryBytes, softMemory = budget.memoryBytes;
    worker.setChildProcessModifier([memory, softMemory, sharedFd] {
        // Runs in the child between fork and exec: async-signal-safe calls only.
        if (sharedFd >= 0) ::fcntl(sharedFd, F_SETFD, 0); // this child alone inherits the memfd
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
#ifndef LIGHTRIG_ISOLATED_ASAN // AddressSanitizer reserves terabytes of address space
        if (memory > 0) {
            const rlimit as{rlim_t(softMemory), rlim_t(memory)};
            ::setrlimit(RLIMIT_AS, &as);
        }
#endif
#ifdef __linux__
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // the worker never outlives this thread
#endif
    });
    worker.start(QIODevice::ReadWrite);
    if (!worker.waitForStarted(30'000))
        return fail(QStringLiteral("could not start the import worker %1 (%2)")
                        .arg(executable, worker.errorString()));
    QJsonObject full = request;
    if (sharedFd >= 0) full.insert(QStringLiteral("sharedFd"), sharedFd);
    worker.write(QJsonDocument(full).toJson(QJsonDocument::Compact));
    worker.closeWriteChannel();

    FrameReader reader(memory > 0 ? std::min(memory, maxReplyBytes) : maxReplyBytes);
    qint64 input = fileBytes;
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
        if (reader.inputBytes() > input) budget = budgetFor(input = reader.inputBytes());
        if (budget.timeoutMs > 0 && timer.elapsed() > budget.timeoutMs) {
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
        if (stop == Stop::Cancelled) return fail(QStringLiteral("cancelled"), true);
        if (stop == Stop::TimedOut)
            return fail(
                QStringLiteral("the importer did not finish within %1 s%2")
                    .arg(seconds(budget.timeoutMs), ofInput(limits, budget.timeoutMs != limits.timeoutMs,
                                                            QStringLiteral("its limit"), input)));
        return fail(QStringLiteral("the importer sent a malformed reply (%1)").arg(reader.problem()));
    }
    const qint64 softNow = budgetFor(std::max(input, reader.inputBytes())).memoryBytes;
    const QString outOfMemory =
        QStringLiteral("the importer ran out of its %1 memory limit%2")
            .arg(formatMemoryLimit(softNow), ofInput(limits, softNow != memory, QString(), input));
    if (reader.state() == FrameReader::State::Error) {
        const QByteArray& p = reader.payload();
        const auto flags = quint8(p.at(0));
        if (flags & ip::kErrorOutOfMemory && memory > 0) return fail(outOfMemory);
        const QString message = QString::fromUtf8(p.constData() + 1, p.size() - 1);
        if (message.isEmpty()) return fail(QStringLiteral("the importer gave no reason"));
        out.fromWorker = true;
        return fail(message, flags & ip::kErrorCancelled);
    }
    if (reader.state() == FrameReader::State::Reply) {
        out.type = reader.type();
        out.payload = std::move(reader.payload());
        return out;
    }
    // The worker ended without a complete reply.
    if (reader.sawOutOfMemory() && memory > 0) return fail(outOfMemory);
    if (worker.exitStatus() == QProcess::NormalExit && worker.exitCode() == 0 && reader.midFrame())
        return fail(QStringLiteral("the importer sent a malformed reply (truncated)"));
    return fail(describeExit(worker, stderrTail));
}

} // namespace isolated
} // namespace lr
