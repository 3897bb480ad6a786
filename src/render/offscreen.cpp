#include "offscreen.h"

#include "core/colour.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace lr {

namespace {

QSurfaceFormat contextFormat() {
    QSurfaceFormat f;
    f.setRenderableType(QSurfaceFormat::OpenGL);
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(0);
    f.setStencilBufferSize(0);
    f.setSamples(0);
    return f;
}

bool fail(QString* error, const QString& message) {
    if (error) *error = message;
    return false;
}

} // namespace

OffscreenRenderer::OffscreenRenderer() = default;

OffscreenRenderer::~OffscreenRenderer() {
    if (m_context && m_surface && m_context->makeCurrent(m_surface.get())) {
        releaseTarget();
        m_renderer.releaseResources();
        m_context->doneCurrent();
    }
}

bool OffscreenRenderer::initialize(QString* error) {
    if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return fail(error, QStringLiteral("offscreen rendering needs a QGuiApplication"));
    const QString platform = QGuiApplication::platformName();
    m_surface = std::make_unique<QOffscreenSurface>();
    m_surface->setFormat(contextFormat());
    m_surface->create();
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(contextFormat());
    if (!m_surface->isValid() || !m_context->create() || !m_context->makeCurrent(m_surface.get()))
        return fail(
            error,
            QStringLiteral("could not create an OpenGL 3.3 core profile context on the '%1' platform "
                           "(LightRig renders with OpenGL: run it with a display, e.g. under xvfb-run -a)")
                .arg(platform));
    const QSurfaceFormat got = m_context->format();
    if (m_context->isOpenGLES() || got.version() < qMakePair(3, 3) ||
        got.profile() != QSurfaceFormat::CoreProfile)
        return fail(
            error, QStringLiteral("OpenGL 3.3 core profile is not available (got %1 %2.%3%4)")
                       .arg(m_context->isOpenGLES() ? QStringLiteral("OpenGL ES") : QStringLiteral("OpenGL"))
                       .arg(got.majorVersion())
                       .arg(got.minorVersion())
                       .arg(got.profile() == QSurfaceFormat::CoreProfile ? QString()
                                                                         : QStringLiteral(" compatibility")));
    if (!m_gl.initializeOpenGLFunctions())
        return fail(error, QStringLiteral("cannot resolve the OpenGL 3.3 core functions"));
    return m_renderer.initialize(error);
}

bool OffscreenRenderer::makeCurrent() {
    return m_context && m_context->makeCurrent(m_surface.get());
}

QString OffscreenRenderer::glDescription() const {
    if (!m_context || QOpenGLContext::currentContext() != m_context.get()) return {};
    auto* gl = const_cast<QOpenGLFunctions_3_3_Core*>(&m_gl);
    const QSurfaceFormat f = m_context->format();
    return QStringLiteral("%1, OpenGL %2.%3 %4")
        .arg(QString::fromLatin1(reinterpret_cast<const char*>(gl->glGetString(GL_RENDERER))))
        .arg(f.majorVersion())
        .arg(f.minorVersion())
        .arg(f.profile() == QSurfaceFormat::CoreProfile ? QStringLiteral("core")
                                                        : QStringLiteral("compatibility"));
}

bool OffscreenRenderer::setModel(std::shared_ptr<const Model> model, QString* error) {
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context"));
    if (m_renderer.setModel(std::move(model))) return true;
    return fail(error, m_renderer.lastError());
}

int OffscreenRenderer::maxTileSize() const {
    int limit = m_renderer.maxTargetSize() > 0 ? std::min(m_renderer.maxTargetSize(), 4096) : 4096;
    return std::max(16, std::min(limit, m_tileLimit));
}

bool OffscreenRenderer::ensureTarget(QSize size, QString* error) {
    if (m_fbo && m_targetSize == size) return true;
    releaseTarget();
    while (m_gl.glGetError() != GL_NO_ERROR) {
    }
    m_gl.glGenFramebuffers(1, &m_fbo);
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    m_gl.glGenRenderbuffers(1, &m_color);
    m_gl.glBindRenderbuffer(GL_RENDERBUFFER, m_color);
    m_gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.width(), size.height());
    m_gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
    const bool ok = m_gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE &&
                    m_gl.glGetError() == GL_NO_ERROR;
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) {
        releaseTarget();
        return fail(
            error,
            QStringLiteral("cannot create a %1x%2 output framebuffer").arg(size.width()).arg(size.height()));
    }
    m_targetSize = size;
    return true;
}

void OffscreenRenderer::releaseTarget() {
    if (m_fbo) m_gl.glDeleteFramebuffers(1, &m_fbo);
    if (m_color) m_gl.glDeleteRenderbuffers(1, &m_color);
    m_fbo = m_color = 0;
    m_targetSize = QSize();
}

bool OffscreenRenderer::beginImage(TiledImage* job, const ViewCamera& camera, QSize size,
                                   const RenderSettings& settings, int supersample, QString* error) {
    if (size.isEmpty() || size.width() > 65536 || size.height() > 65536)
        return fail(error,
                    QStringLiteral("image size %1x%2 is out of range").arg(size.width()).arg(size.height()));
    job->camera = camera;
    job->settings = settings;
    job->size = size;
    job->supersample = std::clamp(supersample, 1, 4);
    job->full = size * job->supersample;
    job->image = QImage(size, QImage::Format_RGBA8888);
    if (job->image.isNull())
        return fail(
            error,
            QStringLiteral("not enough memory for a %1x%2 image").arg(size.width()).arg(size.height()));
    const int ss = job->supersample;
    job->tile = std::max(ss, maxTileSize() / ss * ss); // tiles map to whole output pixels
    job->tilesTotal = ((job->full.width() + job->tile - 1) / job->tile) *
                      ((job->full.height() + job->tile - 1) / job->tile);
    job->tilesDone = 0;
    job->pixelsTotal = qint64(job->full.width()) * job->full.height();
    job->pixelsDone = 0;
    return true;
}

bool OffscreenRenderer::renderNextTile(TiledImage* job, QString* error) {
    if (job->finished()) return true;
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context"));
    const int columns = (job->full.width() + job->tile - 1) / job->tile;
    const int tx = (job->tilesDone % columns) * job->tile, ty = (job->tilesDone / columns) * job->tile;
    const QRect rect(tx, ty, std::min(job->tile, job->full.width() - tx),
                     std::min(job->tile, job->full.height() - ty));
    if (!ensureTarget(rect.size(), error)) return false;
    const bool whole = rect.size() == job->full;
    if (!m_renderer.render(job->camera, job->full, job->settings, m_fbo, whole ? QRect() : rect))
        return fail(error, m_renderer.lastError());
    QImage part(rect.size(), QImage::Format_RGBA8888);
    m_gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m_fbo);
    m_gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    m_gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    m_gl.glPixelStorei(GL_PACK_ROW_LENGTH, int(part.bytesPerLine() / 4));
    m_gl.glReadPixels(0, 0, rect.width(), rect.height(), GL_RGBA, GL_UNSIGNED_BYTE, part.bits());
    m_gl.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    m_gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    part = downsampleLinear(std::move(part).mirrored(), job->supersample); // GL rows run bottom-up
    const QPoint at(tx / job->supersample, ty / job->supersample);
    for (int y = 0; y < part.height(); ++y)
        std::memcpy(job->image.scanLine(at.y() + y) + size_t(at.x()) * 4, part.constScanLine(y),
                    size_t(part.width()) * 4);
    ++job->tilesDone;
    job->pixelsDone += qint64(rect.width()) * rect.height();
    return true;
}

QImage OffscreenRenderer::renderImage(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                      int supersample, QString* error, const TileProgress& progress) {
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context")), QImage();
    TiledImage job;
    if (!beginImage(&job, camera, size, settings, supersample, error)) return QImage();
    const auto keepGoing = [&] {
        if (!progress) return true;
        if (!progress(job.tilesDone, job.tilesTotal)) return fail(error, QStringLiteral("cancelled"));
        return makeCurrent() || fail(error, QStringLiteral("no OpenGL context")); // it may have switched
    };
    if (!keepGoing()) return QImage();
    while (!job.finished())
        if (!renderNextTile(&job, error) || !keepGoing()) return QImage();
    return std::move(job.image);
}

bool OffscreenRenderer::renderFrame(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                    QString* error) {
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context"));
    if (size.isEmpty() || size.width() > maxTileSize() || size.height() > maxTileSize())
        return fail(error, QStringLiteral("frame size %1x%2 must be within one tile (%3)")
                               .arg(size.width())
                               .arg(size.height())
                               .arg(maxTileSize()));
    if (!ensureTarget(size, error)) return false;
    if (!m_renderer.render(camera, size, settings, m_fbo)) return fail(error, m_renderer.lastError());
    m_gl.glFinish();
    return true;
}

bool OffscreenRenderer::renderRadiance(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                       FloatImage* out, QString* error) {
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context"));
    if (size.isEmpty() || size.width() > maxTileSize() || size.height() > maxTileSize())
        return fail(error, QStringLiteral("float read-back size %1x%2 must be within one tile (%3)")
                               .arg(size.width())
                               .arg(size.height())
                               .arg(maxTileSize()));
    RenderSettings s = settings;
    s.hdrTarget = true;
    s.hdrFloat32 = true;
    s.showGizmos = s.showGrid = false;
    if (!ensureTarget(size, error)) return false;
    if (!m_renderer.render(camera, size, s, m_fbo) || !m_renderer.readRadiance(out))
        return fail(error, m_renderer.lastError());
    return true;
}

bool OffscreenRenderer::renderGBuffer(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                      GBuffer* out, QString* error) {
    if (!makeCurrent()) return fail(error, QStringLiteral("no OpenGL context"));
    if (size.isEmpty() || size.width() > maxTileSize() || size.height() > maxTileSize())
        return fail(error, QStringLiteral("G-buffer size %1x%2 must be within one tile (%3)")
                               .arg(size.width())
                               .arg(size.height())
                               .arg(maxTileSize()));
    if (!m_renderer.renderGBuffer(camera, size, settings, out)) return fail(error, m_renderer.lastError());
    return true;
}

QImage downsampleLinear(const QImage& image, int factor) {
    if (factor <= 1 || image.isNull()) return image;
    static const std::array<float, 256> toLinear = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[size_t(i)] = float(colour::srgbToLinear(i / 255.0));
        return t;
    }();
    const QImage src =
        image.format() == QImage::Format_RGBA8888 ? image : image.convertToFormat(QImage::Format_RGBA8888);
    const int w = src.width() / factor, h = src.height() / factor;
    QImage out(w, h, QImage::Format_RGBA8888);
    const float n = float(factor * factor);
    auto encode = [](double v) {
        return uchar(std::lround(std::clamp(colour::linearToSrgb(v), 0.0, 1.0) * 255.0));
    };
    for (int y = 0; y < h; ++y) {
        uchar* o = out.scanLine(y);
        for (int x = 0; x < w; ++x) {
            double r = 0, g = 0, b = 0, a = 0;
            for (int sy = 0; sy < factor; ++sy) {
                const uchar* p = src.constScanLine(y * factor + sy) + size_t(x * factor) * 4;
                for (int sx = 0; sx < factor; ++sx, p += 4) {
                    const double alpha = p[3] / 255.0;
                    r += toLinear[p[0]] * alpha;
                    g += toLinear[p[1]] * alpha;
                    b += toLinear[p[2]] * alpha;
                    a += alpha;
                }
            }
            o[4 * x + 0] = a > 0 ? encode(r / a) : 0;
            o[4 * x + 1] = a > 0 ? encode(g / a) : 0;
            o[4 * x + 2] = a > 0 ? encode(b / a) : 0;
            o[4 * x + 3] = uchar(std::lround(a / n * 255.0));
        }
    }
    return out;
}

} // namespace lr
