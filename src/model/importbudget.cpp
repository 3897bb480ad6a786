#include "importbudget.h"

#include "environmentdecode.h"
#include "exrdecode.h"

#include <QFileInfo>
#include <QSet>
#include <algorithm>
#include <mutex>

namespace lr {

namespace {

constexpr qint64 MiB = 1ll << 20;
constexpr qint64 kModelBaseBytes = 1ll << 30;
constexpr qint64 kModelBytesPerInputByte = 64;
constexpr qint64 kEnvironmentBaseBytes = 512 * MiB;
constexpr qint64 kBaseMs = 9'000; // a file under 1 MiB: under 10 s
constexpr qint64 kMsPerMiB = 1'000;

std::mutex g_mutex;
QSet<QString> g_seen;
qint64 g_total = 0;
std::function<void(qint64)> g_listener;

} // namespace

ImportBudget importBudget(BudgetKind kind, qint64 inputBytes, qint64 hardMemoryBytes, int hardTimeoutMs) {
    const qint64 input = std::clamp<qint64>(inputBytes, 0, 1ll << 40);
    qint64 memory = kModelBaseBytes + kModelBytesPerInputByte * input;
    if (kind == BudgetKind::Environment)
        memory = kEnvironmentBaseBytes + 2 * maxEnvironmentDecodedBytes(input);
    if (kind == BudgetKind::ExrLayers) memory = kEnvironmentBaseBytes + input + maxExrDecodedBytes(input);
    const qint64 ms = kBaseMs + kMsPerMiB * input / MiB;
    ImportBudget b; // no limit stays no limit
    b.memoryBytes = hardMemoryBytes > 0 ? std::min((memory + MiB - 1) / MiB * MiB, hardMemoryBytes) : 0;
    b.timeoutMs = hardTimeoutMs > 0 ? int(std::min<qint64>(ms, hardTimeoutMs)) : 0;
    return b;
}

QString formatInputBytes(qint64 bytes) {
    if (bytes < 1000) return QStringLiteral("%1 bytes").arg(bytes);
    if (bytes < 1000 * 1000) return QStringLiteral("%1 KB").arg(double(bytes) / 1e3, 0, 'f', 1);
    return QStringLiteral("%1 MB").arg(double(bytes) / 1e6, 0, 'f', 1);
}

void noteImportInput(const QString& path) {
    const QFileInfo info(path);
    if (!info.isFile()) return;
    const QString key = info.absoluteFilePath();
    std::function<void(qint64)> listener;
    qint64 total = 0;
    {
        const std::lock_guard lock(g_mutex);
        if (g_seen.contains(key)) return;
        g_seen.insert(key);
        g_total += info.size();
        total = g_total;
        listener = g_listener;
    }
    if (listener) listener(total);
}

void setImportInputListener(std::function<void(qint64)> listener) {
    const std::lock_guard lock(g_mutex);
    g_listener = std::move(listener);
}

} // namespace lr
