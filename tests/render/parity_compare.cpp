// Not a test: `parity_compare OURS.png THREE.png` prints one JSON line of the figures of OURS against
// three.js's THREE over the pixels three.js covers (tests/render/parity.h), for scripts/perf/parity.sh.
#include "parity.h"

#include <QCoreApplication>
#include <QImage>
#include <cstdio>

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc != 3) {
        std::fprintf(stderr, "usage: parity_compare OURS.png THREE.png\n");
        return 2;
    }
    const QImage ours(QString::fromLocal8Bit(argv[1])), three(QString::fromLocal8Bit(argv[2]));
    if (ours.isNull() || three.isNull() || ours.size() != three.size()) {
        std::fprintf(stderr, "parity_compare: cannot read both images at one size (%s, %s)\n", argv[1],
                     argv[2]);
        return 1;
    }
    const lr::ErrorFigures f = lrtest::compareWithThree(ours, three);
    std::printf("{\"pixels\": %lld, \"psnrDb\": %.2f, \"meanLevels\": %.2f, \"maxLevels\": %d}\n",
                static_cast<long long>(f.pixels), f.psnrDb, f.meanLevels, f.maxLevels);
    return 0;
}
