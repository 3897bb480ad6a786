// What `lightrig render` will need, said before it allocates (issue 41, item 10: `--size 32768x32768
// --supersample 4` started with no estimate of time or memory).
//
// The renderer draws W·N × H·N pixels (N = --supersample) in tiles of at most 4096×4096 (offscreen.h): per
// tile its targets (targets.h: the RGBA8 output, colour and depth, MSAA samples of both, or the deferred
// path's G-buffer and kept surfaces, never both) and the tile's read-back; the W×H image is whole in memory,
// and once more while it is encoded.
#pragma once

#include <QSize>
#include <QString>
#include <QTextStream>
#include <cstdint>

namespace lr::cli {

struct RenderEstimate {
    QSize size;                                            // the image
    int supersample = 1;                                   // samples a side
    int tile = 0;                                          // the tile side, in rendered pixels
    int tiles = 0;                                         // tiles per image
    std::int64_t imageBytes = 0, tileBytes = 0, bytes = 0; // bytes: the whole process, about
};

RenderEstimate estimateRender(QSize size, int supersample, int msaaSamples);

// Memory this process can have: the physical memory (sysconf), or the address-space limit when lower.
// 0 when unknown. *what says which ("the machine's physical memory", "its address-space limit, ulimit -v").
std::int64_t availableMemory(QString* what);

// Beyond 1 GiB, prints the estimate on `err`. Returns false, having said why naming --size and
// --supersample, when it exceeds availableMemory() and `unchecked` (--no-memory-check) is false.
bool checkRenderMemory(const RenderEstimate& estimate, bool unchecked, QTextStream& err);

} // namespace lr::cli
