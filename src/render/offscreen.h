// Rendering without a window: a QOffscreenSurface and an OpenGL 3.3 core context of its own driving a
// Renderer (the same one the viewport uses, so the pixels are the same). Screenshots at any size (tiled
// beyond the largest render target), supersampled 1–4×, transparent backgrounds; float read-backs of the
// linear radiance and of the G-buffer for tests and the accuracy benchmark.
//
// Create, initialize and use it on the GUI thread of a QGuiApplication (the platform must offer OpenGL:
// under X11 that means a display, e.g. xvfb-run).
#pragma once

#include "renderer.h"

#include <QImage>
#include <QOpenGLFunctions_3_3_Core>
#include <functional>
#include <memory>

class QOffscreenSurface;
class QOpenGLContext;

namespace lr {

// Progress of a tiled render: called with (0, total) before the first tile and (done, total) after each;
// returning false cancels. It may run the event loop (other contexts may be current when it returns).
using TileProgress = std::function<bool(int done, int total)>;

// A tiled image render in progress (OffscreenRenderer::beginImage / renderNextTile): what it draws, fixed at
// its start, the image so far and how much of the work is done. Progress is in rendered pixels (edge tiles
// are smaller), so a share of pixelsDone / pixelsTotal is a share of the work.
struct TiledImage {
    ViewCamera camera;
    RenderSettings settings;
    QSize size, full; // output pixels; rendered pixels (size × supersample)
    int supersample = 1, tile = 0;
    int tilesDone = 0, tilesTotal = 0;
    qint64 pixelsDone = 0, pixelsTotal = 0;
    QImage image; // RGBA8888, straight alpha; complete when tilesDone == tilesTotal
    bool finished() const { return tilesDone >= tilesTotal; }
};

class OffscreenRenderer {
  public:
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Creates the context (3.3 core profile; a clear error when the platform cannot give one).
    bool initialize(QString* error);
    bool makeCurrent(); // initialize() leaves the context current; call this if you switched away
    Renderer& renderer() { return m_renderer; }
    QString glDescription() const; // "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 core"

    bool setModel(std::shared_ptr<const Model> model, QString* error = nullptr);
    void setRig(const Rig& rig) { m_renderer.setRig(rig); }

    // An 8-bit image (QImage::Format_RGBA8888, straight alpha) of `size` pixels, rendered at
    // size × supersample (1–4; averaged in linear light) in tiles of at most maxTileSize() pixels.
    // A null image on failure, *error saying why ("cancelled" when progress returned false).
    QImage renderImage(const ViewCamera& camera, QSize size, const RenderSettings& settings, int supersample,
                       QString* error, const TileProgress& progress = {});
    // The same in steps a caller drives (from the event loop, say): beginImage checks the size and allocates
    // the image (tiles of at most maxTileSize() at the time), renderNextTile renders the next tile into it.
    // False and *error on failure. renderImage is these two in a loop.
    bool beginImage(TiledImage* job, const ViewCamera& camera, QSize size, const RenderSettings& settings,
                    int supersample, QString* error);
    bool renderNextTile(TiledImage* job, QString* error);
    // One frame into an internal target of `size` (one tile), waited for with glFinish: for timing.
    bool renderFrame(const ViewCamera& camera, QSize size, const RenderSettings& settings, QString* error);
    // Linear radiance before exposure and tone mapping (RGBA32F target, one tile: size <= maxTileSize()).
    bool renderRadiance(const ViewCamera& camera, QSize size, const RenderSettings& settings, FloatImage* out,
                        QString* error);
    bool renderGBuffer(const ViewCamera& camera, QSize size, const RenderSettings& settings, GBuffer* out,
                       QString* error);

    // The largest tile side: the driver's limit, at most 4096, or a smaller value set here (tests).
    int maxTileSize() const;
    void setMaxTileSize(int pixels) { m_tileLimit = pixels; }

  private:
    bool ensureTarget(QSize size, QString* error);
    void releaseTarget();

    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOpenGLContext> m_context;
    QOpenGLFunctions_3_3_Core m_gl;
    Renderer m_renderer;
    GLuint m_fbo = 0, m_color = 0;
    QSize m_targetSize;
    int m_tileLimit = 4096;
};

// Box-downsamples an RGBA8888 (straight alpha, sRGB) image by an integer factor, averaging in linear
// light weighted by alpha. factor 1 returns the image.
QImage downsampleLinear(const QImage& image, int factor);

} // namespace lr
