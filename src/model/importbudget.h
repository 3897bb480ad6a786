// The import worker's limits scaled to its input (issue 41): a file is refused or loaded in time and
// memory proportional to the bytes it brings, not after the fixed 120 s and 8 GiB (a 221-byte SMD kept
// the importer busy 120 s, a 36.7 KB COB took 5 GB). The input is every file the import reads: the model,
// its buffers and material libraries, its textures; the worker notes each as it is opened (noteImportInput)
// and tells its parent, which moves the deadline, while the worker raises its own address-space limit
// (RLIMIT_AS, soft) up to the hard limit the parent set (ImportLimits::memoryBytes).
#pragma once

#include <QString>
#include <QtGlobal>
#include <functional>

namespace lr {

enum class BudgetKind { Model, Environment, ExrLayers };

struct ImportBudget {
    qint64 memoryBytes = 0; // the worker's address space (RLIMIT_AS); <= 0: none
    int timeoutMs = 0;      // the whole import; <= 0: none
};

// Model: 1 GiB + 64 bytes per byte of input; environment: 512 MiB + twice the largest image a file of
// that size may decode to (maxEnvironmentDecodedBytes); multi-layer OpenEXR: 512 MiB + the file (mapped) +
// the most it may decode to (maxExrDecodedBytes, sent from where it was decoded); all 9 s + 1 s per MiB of
// input (under 10 s for a file under 1 MiB). Memory is rounded up to whole MiB; each is capped by the hard
// limit (a hard limit <= 0, none, stays none: 0).
ImportBudget importBudget(BudgetKind kind, qint64 inputBytes, qint64 hardMemoryBytes, int hardTimeoutMs);

// "12 KB", "3.4 MB": an input size as the messages write it.
QString formatInputBytes(qint64 bytes);

// In the worker: `path` (a file the import opened) counts towards the input, once per path. The listener
// (set by the worker, may be none) is called with the new total whenever it grows; thread-safe.
void noteImportInput(const QString& path);
void setImportInputListener(std::function<void(qint64 totalBytes)> listener);

} // namespace lr
