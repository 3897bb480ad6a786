// Not a test: measures what the import worker costs. For each file named on the command line, imports it
// directly (loadModel) and through the worker (importModelIsolated, LIGHTRIG_EXECUTABLE as the worker)
// alternately, N times each (--runs N, default 5), and prints the medians and the overhead:
//   import_timing [--runs N] [--only direct|isolated] [--transport memfd|pipe] FILE...
#include "model/isolatedimport.h"
#include "model/modelloader.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <algorithm>
#include <cstdio>
#include <sys/resource.h>
#include <vector>

namespace {
// CPU seconds of this process and its waited-for children (the workers), user + system.
double cpuMs() {
    double total = 0.0;
    for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage u{};
        getrusage(who, &u);
        total += double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
                 double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e3;
    }
    return total;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}
} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    lr::setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
    QStringList args = app.arguments().mid(1);
    int runs = 5;
    int only = -1;
    lr::ImportLimits limits; // --transport pipe: the model through the worker's stdout, not a memfd // --only
                             // direct|isolated: one kind of run (for profiling each alone)
    while (args.size() >= 2 && args[0].startsWith(QLatin1String("--"))) {
        if (args[0] == QLatin1String("--runs")) runs = std::max(1, args[1].toInt());
        if (args[0] == QLatin1String("--only")) only = args[1] == QLatin1String("isolated") ? 1 : 0;
        if (args[0] == QLatin1String("--transport")) limits.sharedMemory = args[1] != QLatin1String("pipe");
        args = args.mid(2);
    }
    int status = 0;
    for (const QString& path : args) {
        std::vector<double> direct, isolated, directCpu, isolatedCpu;
        std::size_t triangles = 0;
        for (int i = 0; i < runs; ++i) {
            for (int isolatedRun = 0; isolatedRun < 2; ++isolatedRun) {
                if (only >= 0 && isolatedRun != only) continue;
                QElapsedTimer t;
                const double cpu0 = cpuMs();
                t.start();
                const lr::ModelLoadResult r =
                    isolatedRun ? lr::importModelIsolated(path, {}, limits) : lr::loadModel(path);
                const double ms = double(t.nsecsElapsed()) / 1e6, cpu = cpuMs() - cpu0;
                if (!r.ok()) {
                    std::printf("%s: %s\n", qPrintable(path), qPrintable(r.error));
                    status = 1;
                    break;
                }
                triangles = r.model->triangleCount();
                (isolatedRun ? isolated : direct).push_back(ms);
                (isolatedRun ? isolatedCpu : directCpu).push_back(cpu);
            }
        }
        if (only >= 0) {
            const std::vector<double>& wall = only ? isolated : direct;
            const std::vector<double>& cpu = only ? isolatedCpu : directCpu;
            if (!wall.empty())
                std::printf("%s: %s %.1f ms, CPU %.1f ms (medians of %d)\n",
                            qPrintable(QFileInfo(path).fileName()), only ? "isolated" : "direct",
                            median(wall), median(cpu), runs);
            continue;
        }
        if (direct.empty() || isolated.empty()) continue;
        const double d = median(direct), s = median(isolated);
        std::printf("%s: %zu triangles, %d runs: direct %.1f ms, isolated %.1f ms (min %.1f / %.1f), "
                    "overhead %+.1f ms "
                    "(%+.1f%%); CPU (user+sys, worker included) %.1f vs %.1f ms (%+.1f%%)\n",
                    qPrintable(QFileInfo(path).fileName()), triangles, runs, d, s,
                    *std::min_element(direct.begin(), direct.end()),
                    *std::min_element(isolated.begin(), isolated.end()), s - d, 100.0 * (s - d) / d,
                    median(directCpu), median(isolatedCpu),
                    100.0 * (median(isolatedCpu) - median(directCpu)) / median(directCpu));
        std::fflush(stdout);
    }
    return status;
}
