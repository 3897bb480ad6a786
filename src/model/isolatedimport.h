// Importing a model in a child process (`lightrig import-worker`), so that an Assimp crash, abort, hang
// or allocation bomb cannot take down the editor or `lightrig render`: the child imports with
// loadModel (modelloader.h) and sends the Model back in modelcodec.h's form, which is validated here
// before anything uses it. Whatever goes wrong becomes ModelLoadResult::error:
//   "could not import models/spider.fbx: the importer crashed (signal 11)" (the path as given)
//   "could not import models/spider.fbx: the importer aborted (signal 6)"
//   "could not import models/spider.fbx: the importer ran out of its 1.0 GiB memory limit (for 36.7 KB
//    of input)"
//   "could not import models/spider.fbx: the importer did not finish within 10 s (its limit for 221
//    bytes of input)"
//   "could not import models/spider.fbx: the importer sent a malformed reply (<reason>)"
// and the caller keeps whatever it had.
#pragma once

#include "modelloader.h"

#include <QString>
#include <atomic>

namespace lr {

struct ImportLimits {
    int timeoutMs = 120'000;        // wall-clock limit for the whole import; <= 0: none
    qint64 memoryBytes = 8ll << 30; // the worker's address-space limit (RLIMIT_AS); <= 0: none
    // Both limits above are the most any import gets; with this set (the default) the worker gets less,
    // in proportion to the bytes it reads (importbudget.h: 10 s and 1 GiB for a small model), so that a
    // small hostile file is refused in seconds, not minutes.
    bool scaleWithInput = true;
    // Set to true (from any thread) to stop the import; the worker is killed within ~50 ms.
    const std::atomic<bool>* cancel = nullptr;
    // The model comes back through a memfd (Linux) rather than the worker's stdout: fewer copies.
    bool sharedMemory = true;
};

// Imports `path` in a worker process. options.progress is called on the calling thread at least every
// 50 ms while the worker runs (with the last fraction when nothing new arrived), so returning false from
// it cancels even a hung import; result.cancelled is then set. Blocks the calling thread: call it from a
// worker thread in a GUI (DocumentFiles::openModel runs it on QtConcurrent). Thread-safe.
ModelLoadResult importModelIsolated(const QString& path, const ModelLoadOptions& options = {},
                                    const ImportLimits& limits = {});

// The executable run as `EXE import-worker`: the one set here, else the environment variable
// LIGHTRIG_IMPORT_WORKER, else QCoreApplication::applicationFilePath() when the application is lightrig
// itself (applicationName() "lightrig"), else none (imports then fail saying so). A test executable
// that imports (directly or through the editor) names lightrig one of the first two ways:
// setImportWorkerExecutable(LIGHTRIG_EXECUTABLE), or ctest's LIGHTRIG_IMPORT_WORKER (tests/CMakeLists.txt).
void setImportWorkerExecutable(const QString& path);
QString importWorkerExecutable();

// "8 GiB", "512 MiB": the memory limit as the error messages write it.
QString formatMemoryLimit(qint64 bytes);

} // namespace lr
