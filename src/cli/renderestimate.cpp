#include "renderestimate.h"

#include <algorithm>
#include <sys/resource.h>
#include <unistd.h>

namespace lr::cli {

namespace {

constexpr int kTileLimit = 4096;                    // OffscreenRenderer::maxTileSize() at most
constexpr std::int64_t kProcessBytes = 200ll << 20; // Qt, llvmpipe and a small model (measured: ~150 MB)
constexpr std::int64_t kReportFrom = 1ll << 30;     // smaller renders say nothing

QString gib(std::int64_t bytes) {
    return QStringLiteral("%1 GiB").arg(double(bytes) / double(1ll << 30), 0, 'f', 1);
}

} // namespace

RenderEstimate estimateRender(QSize size, int supersample, int msaaSamples) {
    RenderEstimate e;
    e.size = size;
    e.supersample = std::clamp(supersample, 1, 4);
    const std::int64_t w = std::int64_t(size.width()) * e.supersample;
    const std::int64_t h = std::int64_t(size.height()) * e.supersample;
    e.tile = int(std::max<std::int64_t>(e.supersample, kTileLimit / e.supersample * e.supersample));
    const std::int64_t tw = std::min<std::int64_t>(w, e.tile), th = std::min<std::int64_t>(h, e.tile);
    e.tiles = int(((w + e.tile - 1) / e.tile) * ((h + e.tile - 1) / e.tile));
    // Per tile pixel: the output framebuffer (4), read back and flipped (8), colour up to RGBA16F and depth
    // (12), then either MSAA (8 a sample: RGBA8 and depth-stencil) or the G-buffer and kept surfaces
    // (8 RGBA32F textures: 128). Measured at 4096x4096 with MSAA 4: ~850 MB over the process's own.
    const std::int64_t perPixel = 24 + std::max<std::int64_t>(8ll * std::max(0, msaaSamples), 128);
    e.tileBytes = tw * th * perPixel;
    e.imageBytes = std::int64_t(size.width()) * size.height() * 4;
    e.bytes = kProcessBytes + e.tileBytes + 2 * e.imageBytes; // the image, and its copy while encoded
    return e;
}

std::int64_t availableMemory(QString* what) {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    std::int64_t bytes = pages > 0 && pageSize > 0 ? std::int64_t(pages) * pageSize : 0;
    *what = QStringLiteral("the machine's physical memory");
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
        (bytes == 0 || std::int64_t(limit.rlim_cur) < bytes)) {
        bytes = std::int64_t(limit.rlim_cur);
        *what = QStringLiteral("its address-space limit, ulimit -v");
    }
    return bytes;
}

bool checkRenderMemory(const RenderEstimate& e, bool unchecked, QTextStream& err) {
    if (e.bytes < kReportFrom) return true;
    QString what;
    const std::int64_t available = availableMemory(&what);
    const QString options =
        QStringLiteral("--size %1x%2%3")
            .arg(e.size.width())
            .arg(e.size.height())
            .arg(e.supersample > 1 ? QStringLiteral(" --supersample %1").arg(e.supersample) : QString());
    err << QStringLiteral("lightrig render: %1 renders %2x%3 pixels in %4 tile(s) of at most %5x%5 and needs "
                          "about %6 (the image %7, twice while it is encoded; a tile's targets %8)\n")
               .arg(options)
               .arg(std::int64_t(e.size.width()) * e.supersample)
               .arg(std::int64_t(e.size.height()) * e.supersample)
               .arg(e.tiles)
               .arg(e.tile)
               .arg(gib(e.bytes), gib(e.imageBytes), gib(e.tileBytes));
    if (unchecked || available <= 0 || e.bytes <= available) {
        err.flush();
        return true;
    }
    err << QStringLiteral(
               "lightrig render: %1 needs about %2 of memory, more than the %3 this process may use (%4): "
               "use a smaller --size or --supersample, or --no-memory-check to try anyway\n")
               .arg(options, gib(e.bytes), gib(available), what);
    err.flush();
    return false;
}

} // namespace lr::cli
