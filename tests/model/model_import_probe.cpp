// Imports each file named on the command line with lr::loadModel and prints one line per file:
//   OK <file> triangles=N meshes=N materials=N textures=N lights=N cameras=N ms=T warnings=N
//   ERROR <message>
//   BAD <file>: <invariant broken>      (exit code 3)
// Used by tst_model_shared to import every third-party file in a child process, so that an importer
// crash is reported for that file instead of ending the test.
#include "model/modelloader.h"
#include "modelchecks.h"

#include <QCoreApplication>
#include <cstdio>
#include <sys/resource.h>

#if defined(__SANITIZE_ADDRESS__)
#define LIGHTRIG_PROBE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIGHTRIG_PROBE_ASAN 1
#endif
#endif

int main(int argc, char** argv) {
    // An allocation bomb must end in std::bad_alloc (a message), not in swapping or the OOM killer.
    // AddressSanitizer reserves terabytes of address space, so it keeps the default.
#ifndef LIGHTRIG_PROBE_ASAN
    const rlimit limit{rlim_t(4) << 30, rlim_t(4) << 30};
    setrlimit(RLIMIT_AS, &limit);
#endif
    QCoreApplication app(argc, argv);
    int status = 0;
    for (const QString& path : app.arguments().mid(1)) {
        const lr::ModelLoadResult r = lr::loadModel(path);
        if (!r.ok()) {
            std::printf("ERROR %s\n", qPrintable(r.error));
        } else if (const QString problem = lr::test::modelProblems(*r.model); !problem.isEmpty()) {
            std::printf("BAD %s: %s\n", qPrintable(path), qPrintable(problem));
            status = 3;
        } else {
            const lr::Model& m = *r.model;
            std::printf(
                "OK %s triangles=%zu meshes=%zu materials=%zu textures=%zu lights=%zu cameras=%zu ms=%.1f "
                "warnings=%lld\n",
                qPrintable(path), m.triangleCount(), m.meshes.size(), m.materials.size(), m.textures.size(),
                m.lights.lights.size(), m.cameras.size(), m.loadMs, qlonglong(m.warnings.size()));
        }
        std::fflush(stdout);
    }
    return status;
}
