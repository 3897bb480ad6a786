#include "viewport.h"

#include "abcompare.h"
#include "abcompareframe.h"
#include "editor/document.h"
#include "gizmointeraction.h"
#include "render/renderer.h"
#include "scene.h"
#include "screenshotdialog.h"
#include "screenshotexport.h"
#include "snapshotrenderer.h"
#include "tracedview.h"
#include "viewsettings.h"

#include <QElapsedTimer>
#include <QFocusEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr {

// Everything tied to the widget's GL context, recreated when the context is.
struct ViewportRenderer {
    Renderer renderer;
    CompareFrame compare;
    bool ok = false;
};

namespace {
constexpr double kOrbitDegreesPerPixel = 0.4;
constexpr double kWheelStep = 0.85; // distance factor per wheel notch (towards the target)
} // namespace

Viewport::Viewport(Document* document, Scene* scene, ViewSettings* settings, QWidget* parent)
    : QOpenGLWidget(parent), m_doc(document), m_scene(scene), m_settings(settings),
      m_interaction(std::make_unique<GizmoInteraction>(document, scene)),
      m_snapshots(std::make_unique<SnapshotRenderer>(scene)),
      m_traced(new TracedView(this, document, scene, settings)) {
    setObjectName(QStringLiteral("Viewport"));
    setMinimumSize(200, 150);
    setFocusPolicy(Qt::StrongFocus); // a click takes the keyboard focus; the wheel too (wheelEvent)
    setMouseTracking(true);
    if (auto c = standardView(QStringLiteral("three-quarter"), Bounds{glm::dvec3(-1), glm::dvec3(1)}, 1.5))
        m_camera = *c;
    connect(m_doc, &Document::rigChanged, this, [this] {
        m_rigDirty = true;
        update();
    });
    connect(m_doc, &Document::soloChanged, this, [this] {
        m_rigDirty = true;
        update();
    });
    connect(m_doc, &Document::selectionChanged, this, qOverload<>(&QWidget::update));
    connect(m_settings, &ViewSettings::changed, this, qOverload<>(&QWidget::update));
    connect(m_scene, &Scene::modelChanged, this, &Viewport::onModelChanged);
    connect(m_scene, &Scene::environmentChanged, this, qOverload<>(&QWidget::update));
    m_settle = new QTimer(this);
    m_settle->setSingleShot(true);
    m_settle->setInterval(250);
    connect(m_settle, &QTimer::timeout, this, [this] {
        if (m_nav == Navigation::None) setNavigating(false);
    });
}

void Viewport::setNavigating(bool on) {
    if (m_navigating == on) return;
    m_navigating = on;
    if (!on) update(); // the full-quality frame
}

Viewport::~Viewport() {
    delete std::exchange(m_traced, nullptr); // cancels its job and waits for the worker's tile
    m_snapshots.reset();
    releaseGL();
    // ~QOpenGLWidget destroys the context, whose aboutToBeDestroyed would call releaseGL on a Viewport that
    // is already destroyed (UBSan: "downcast ... does not point to an object of type 'Viewport'").
    if (context()) disconnect(context(), nullptr, this, nullptr);
}

void Viewport::setDefaultSurfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(0); // the renderer has its own MSAA target
    QSurfaceFormat::setDefaultFormat(format);
}

void Viewport::releaseGL() {
    if (!m_gl) return;
    if (context()) {
        makeCurrent();
        m_gl->compare.release();
        m_gl->renderer.releaseResources();
        m_gl.reset();
        doneCurrent();
    } else {
        m_gl.reset();
    }
}

void Viewport::initializeGL() {
    // A new context (first show, or the widget was reparented): start over with fresh GL objects.
    m_gl = std::make_unique<ViewportRenderer>();
    m_modelDirty = m_rigDirty = true;
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGL, Qt::UniqueConnection);
    QString error;
    m_gl->ok = m_gl->renderer.initialize(&error);
    if (!m_gl->ok) {
        m_error = tr("OpenGL 3.3 core is not available: %1").arg(error);
        emit statusMessage(m_error);
    }
}

void Viewport::resizeGL(int, int) {}

double Viewport::aspect() const {
    return height() > 0 ? double(width()) / double(height()) : 1.0;
}

RenderSettings Viewport::renderSettings(bool gizmos) const {
    const ViewOptions& o = m_settings->options();
    RenderSettings s;
    s.exposureEV = o.exposure;
    s.toneMap = o.toneMap;
    s.background = o.background;
    s.quality = o.quality;
    s.showGizmos = gizmos && o.gizmos;
    s.showGrid = gizmos && o.grid;
    s.msaaSamples = o.quality == Quality::Fast || m_navigating ? 0 : 4;
    s.interactive = m_navigating;
    for (int row : m_doc->selectedRows())
        s.selectedLights.push_back(row);
    if (gizmos) s.highlightedParts = m_highlightedParts; // an overlay, as the gizmos: never in a final image
    return s;
}

void Viewport::paintGL() {
    if (!m_gl || !m_gl->ok) {
        glClearColor(0.15f, 0.15f, 0.16f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    Renderer& r = m_gl->renderer;
    if (m_modelDirty) {
        m_modelDirty = false;
        if (!r.setModel(m_scene->model())) {
            m_error = r.lastError();
            emit statusMessage(tr("Could not upload the model: %1").arg(m_error));
        }
    }
    if (m_rigDirty) {
        m_rigDirty = false;
        r.setRig(m_doc->renderRig());
    }
    if (r.environment() != m_scene->environment()) r.setEnvironment(m_scene->environment());
    const qreal dpr = devicePixelRatioF();
    const QSize size(qMax(1, int(std::lround(width() * dpr))), qMax(1, int(std::lround(height() * dpr))));
    // A moving frame is drawn at the scale that keeps the chosen frame rate (dynamicresolution.h), and
    // finished here so that its time is known: the window waits for the frame to compose it anyway.
    const int fps = m_settings->options().movingFrameRate;
    m_moving.setBudgetMs(fps > 0 ? 1000.0 / fps : 0.0);
    RenderSettings settings = renderSettings(true);
    const bool timed = m_navigating && m_moving.enabled() && !(m_compare && m_compare->isActive());
    if (timed) settings.renderScale = m_moving.scale();
    QElapsedTimer clock;
    clock.start();
    if (m_compare && m_compare->isActive()
            ? !paintCompare(size)
            : !r.render(renderCamera(), size, settings, defaultFramebufferObject())) {
        if (m_error != r.lastError()) {
            m_error = r.lastError();
            emit statusMessage(tr("Rendering failed: %1").arg(m_error));
        }
        return;
    }
    // Path traced (tracedview.h): accumulates once this camera and size hold still.
    m_traced->viewDrawn(renderCamera(), size, m_navigating || (m_compare && m_compare->isActive()));
    const RenderStats& st = r.stats();
    m_lastDrawnSize = st.drawnSize;
    if (timed) {
        glFinish();
        m_moving.frameDrawn(double(clock.nsecsElapsed()) * 1e-6, settings.renderScale);
    }
    emit frameRendered(st.lastGpuMs, st.lastCpuMs);
    if (m_framesRendered++ == 0) emit firstFrame();
}

std::shared_ptr<const LoadedEnvironment> Viewport::renderedEnvironment() const {
    return m_gl ? m_gl->renderer.environment() : nullptr;
}

void Viewport::onModelChanged() {
    m_modelDirty = true;
    m_rigDirty = true;                        // a model-space rig moves with the model's bounds
    if (std::exchange(m_holdCamera, false)) { // a rig's saved view came first (openInitial)
        m_cameraFramed = true;
        update();
        return;
    }
    const Bounds& b = m_scene->model()->bounds;
    if (!m_cameraFramed) {
        if (auto c = standardView(QStringLiteral("three-quarter"), b, aspect())) m_camera = *c;
        m_cameraFramed = true;
    }
    frameAllLights(); // the model and the rig's lights around it, from the current direction
    update();
}

void Viewport::setCamera(const ViewCamera& camera) {
    m_camera = camera;
    update();
}

void Viewport::showSavedView(const ViewCamera& camera, bool holdForModel) {
    m_camera = camera;
    m_holdCamera = holdForModel;
    if (!holdForModel) m_cameraFramed = true;
    update();
}

ViewCamera Viewport::renderCamera() const {
    const SceneFrame f = m_scene->frame();
    double radius = f.radius;
    for (const Light& l : m_doc->rig().lights) {
        const double d = glm::length(lightAnchor(m_doc->rig(), f, l) - f.center) * 1.05;
        if (std::isfinite(d)) radius = std::max(radius, d);
    }
    // Far-away lights must not cost the model its depth precision: they are clipped past 100 radii.
    radius = std::min(radius, 100.0 * f.radius);
    return m_camera.withClipPlanes(f.center, radius);
}

ScreenProjector Viewport::projector() const {
    const ViewCamera c = renderCamera();
    const QRectF r = documentRect();
    return ScreenProjector(c.view(), c.projection(r.width() / std::max(1.0, r.height())), r.size());
}

std::optional<QPointF> Viewport::lightScreenPosition(int row) const {
    if (row < 0 || row >= m_doc->lightCount()) return std::nullopt;
    return projector().project(lightAnchor(m_doc->rig(), m_scene->frame(), m_doc->light(row)));
}

void Viewport::frameAll() {
    m_camera.znear = m_camera.zfar = 0.0;
    m_camera.frameAll(m_scene->model()->bounds, aspect());
    update();
}

namespace {
void include(Bounds& b, const glm::dvec3& p) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
}
} // namespace

void Viewport::frameSelectionOrAll() {
    const QList<int> rows = m_doc->selectedRows();
    if (rows.isEmpty()) {
        frameAll();
        return;
    }
    frameModelAndLights(rows); // the light and what it lights: flying to the light alone lost the model
}

void Viewport::frameAllLights() {
    const SceneFrame f = m_scene->frame();
    QList<int> rows;
    for (int row = 0; row < m_doc->lightCount(); ++row) {
        const double d = glm::length(lightAnchor(m_doc->rig(), f, m_doc->light(row)) - f.center);
        if (std::isfinite(d) && d <= kFramedLightRadii * f.radius) rows.append(row);
    }
    frameModelAndLights(rows);
}

bool Viewport::onScreen(int row) const {
    const auto p = lightScreenPosition(row);
    return p && QRectF(rect()).contains(*p);
}

void Viewport::reportLightsOutOfView(const QList<int>& rows) {
    for (int row : rows)
        if (row >= 0 && row < m_doc->lightCount() && !onScreen(row))
            return emit statusMessage(
                tr("%1 is outside the view: press F to frame it, or Shift+F for all lights")
                    .arg(m_doc->light(row).name));
}

void Viewport::frameModelAndLights(const QList<int>& rows) {
    const SceneFrame f = m_scene->frame();
    Bounds b = m_scene->model()->bounds;
    std::vector<glm::dvec3> points;
    for (int row : rows) {
        if (row < 0 || row >= m_doc->lightCount()) continue;
        points.push_back(lightAnchor(m_doc->rig(), f, m_doc->light(row)));
        include(b, points.back());
    }
    const Bounds& m = m_scene->model()->bounds;
    for (int i = 0; i < 8; ++i)
        points.emplace_back(i & 1 ? m.max.x : m.min.x, i & 2 ? m.max.y : m.min.y, i & 4 ? m.max.z : m.min.z);
    m_camera.znear = m_camera.zfar = 0.0;
    m_camera.frameAll(b, aspect());
    // frameAll fits a bounding sphere, which leaves the model small: move in while everything stays in view.
    const QRectF inside =
        QRectF(rect()).adjusted(width() * 0.06, height() * 0.06, -width() * 0.06, -height() * 0.06);
    auto fits = [&] {
        const ScreenProjector p = projector();
        for (const glm::dvec3& q : points) {
            const auto s = p.project(q);
            if (!s || !inside.contains(*s)) return false;
        }
        return true;
    };
    for (int i = 0; i < 40 && fits(); ++i) {
        const ViewCamera previous = m_camera;
        m_camera.dolly(0.95);
        if (!fits()) {
            m_camera = previous;
            break;
        }
    }
    update();
}

void Viewport::setStandardView(const QString& name) {
    if (auto c = standardView(name, m_scene->model()->bounds, aspect())) setCamera(*c);
}

void Viewport::setModelCamera(int index) {
    const auto& cameras = m_scene->model()->cameras;
    if (index < 0 || index >= int(cameras.size())) return;
    const Camera& cam = cameras[size_t(index)];
    const double focus = glm::length(m_scene->frame().center - cam.position);
    setCamera(fromModelCamera(cam, focus));
}

void Viewport::lookThroughLight(int row) {
    if (row < 0 || row >= m_doc->lightCount() || m_doc->light(row).type != LightType::Spot) {
        emit statusMessage(tr("Select a spot light to look through it."));
        return;
    }
    const Light& l = m_doc->light(row);
    const SceneFrame f = m_scene->frame();
    ViewCamera c;
    c.eye = lightAnchor(m_doc->rig(), f, l);
    const glm::dvec3 dir = glm::normalize(l.direction);
    const double focus = std::max(glm::length(f.center - c.eye), 1e-3 * f.radius);
    c.target = c.eye + dir * focus;
    c.up = std::abs(dir.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    c.yfovDeg = std::clamp(2.0 * l.cone.outer, 1.0, 150.0); // the cone fills the view vertically
    setCamera(c);
    emit statusMessage(tr("Looking through %1").arg(l.name));
}

void Viewport::focusInEvent(QFocusEvent* event) {
    // Qt gives the focus before it delivers the press that caused it (mousePressEvent reads this).
    m_focusedByClick = event->reason() == Qt::MouseFocusReason;
    QOpenGLWidget::focusInEvent(event);
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    m_pressFocused = std::exchange(m_focusedByClick, false);
    m_pressPos = m_lastPos = event->position() - documentRect().topLeft();
    m_moved = false;
    m_shiftPress = false;
    if (event->button() == Qt::LeftButton) {
        if (m_compare && m_compare->onWipeHandle(event->position(), QSizeF(size()))) {
            m_nav = Navigation::Wipe;
        } else if (event->modifiers() & Qt::ShiftModifier) {
            m_nav = Navigation::Pan; // a Shift+click without motion aims (see release)
            m_shiftPress = true;
        } else if (m_interaction->press(projector(), m_pressPos, event->modifiers())) {
            m_nav = Navigation::Gizmo;
        } else {
            m_nav = Navigation::Orbit;
        }
    } else if (event->button() == Qt::MiddleButton) {
        m_nav = Navigation::Pan;
    } else {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF pos = event->position() - documentRect().topLeft();
    const QPointF delta = pos - m_lastPos;
    m_lastPos = pos;
    if (QLineF(pos, m_pressPos).length() >= GizmoInteraction::kDragThreshold) m_moved = true;
    const double h = std::max(1, height());
    switch (m_nav) {
    case Navigation::None: {
        // Hover feedback: a hand over a light, a selected spot's cone edge or an area light's size handle.
        const ScreenProjector p = projector();
        const bool over = m_interaction->pickSizeHandle(p, pos).row >= 0 ||
                          m_interaction->pickConeEdge(p, pos) >= 0 || m_interaction->pickLight(p, pos) >= 0;
        const bool wipe = m_compare && m_compare->onWipeHandle(event->position(), QSizeF(size()));
        setCursor(wipe ? Qt::SplitHCursor : over ? Qt::PointingHandCursor : Qt::ArrowCursor);
        return;
    }
    case Navigation::Wipe:
        m_compare->setSplit(event->position().x() / std::max(1, width()));
        break;
    case Navigation::Gizmo:
        if (m_moved) setNavigating(true);
        m_interaction->move(projector(), pos, event->modifiers());
        break;
    case Navigation::Orbit:
        if (!m_moved) return;
        setNavigating(true);
        m_camera.orbit(-delta.x() * kOrbitDegreesPerPixel, delta.y() * kOrbitDegreesPerPixel);
        update();
        break;
    case Navigation::Pan:
        if (!m_moved) return;
        setNavigating(true);
        m_camera.pan(-delta.x() / h, delta.y() / h);
        update();
        break;
    }
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    const Navigation nav = std::exchange(m_nav, Navigation::None);
    const QPointF pos = event->position() - documentRect().topLeft();
    setNavigating(false);
    if (nav == Navigation::Gizmo) {
        m_interaction->release();
    } else if (nav == Navigation::Pan && m_shiftPress && !m_moved) {
        QString message;
        if (m_interaction->aimSelectedAt(projector(), pos, &message))
            emit statusMessage(tr("Aimed the selected light(s) at the clicked point"));
        else if (!message.isEmpty())
            emit statusMessage(message);
    } else if (nav == Navigation::Orbit && !m_moved &&
               (m_pickEnvironment || event->modifiers().testFlags(Qt::ControlModifier | Qt::AltModifier))) {
        emit environmentClicked(pos); // the background (a light would have been a gizmo press)
    } else if (nav == Navigation::Orbit && !m_moved && (event->modifiers() & Qt::AltModifier)) {
        emit linkClicked(pos); // issue 38: Alt+click the model (linktools.h)
    } else if (nav == Navigation::Orbit && !m_moved && (event->modifiers() & Qt::ControlModifier)) {
        // Ctrl+click that hit no gizmo: on the model with lights selected it places their highlight there
        // (one undo step); with nothing selected it only says so; on the background nothing.
        QString message;
        switch (m_interaction->placeHighlight(projector(), pos, &message)) {
        case GizmoInteraction::Highlight::Placed:
            emit statusMessage(tr("Moved the selected light(s) so their highlight lands on the clicked point "
                                  "(Shift+click aims instead)"));
            break;
        case GizmoInteraction::Highlight::Refused:
            emit statusMessage(message);
            break;
        case GizmoInteraction::Highlight::NothingSelected:
            emit statusMessage(tr("Select a light, then Ctrl+click the model to place its highlight there "
                                  "(Shift+click aims it instead)"));
            break;
        case GizmoInteraction::Highlight::Missed:
            break;
        }
    } else if (nav == Navigation::Orbit && !m_moved && !m_pressFocused) {
        // A plain click that hit no gizmo never moves a light. On the background it clears the selection,
        // unless it was the click that gave the viewport the keyboard focus (from a dock's field, say).
        if (!intersectModel(*m_scene->model(), projector().ray(pos))) m_doc->setSelection({});
    }
    event->accept();
}

void Viewport::setHighlightedParts(std::vector<int> parts) {
    if (parts == m_highlightedParts) return;
    m_highlightedParts = std::move(parts);
    update(); // drawn by the renderer's overlay pass once it takes the list (issue 38)
}

void Viewport::wheelEvent(QWheelEvent* event) {
    // Issue 41: after an edit in a dock, the number keys went on typing into that field while the user
    // dollied the view. Qt gives a wheel focus only to spontaneous events of WheelFocus widgets: take it.
    if (!hasFocus()) setFocus(Qt::OtherFocusReason);
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        setNavigating(true);
        m_settle->start();
        m_camera.dolly(std::pow(kWheelStep, notches));
        update();
    }
    event->accept();
}

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_nav == Navigation::Gizmo) {
        m_interaction->cancel(); // takes back what the drag did so far (one merged step)
        m_nav = Navigation::None;
        setNavigating(false);
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

void Viewport::setCompare(AbCompare* compare) {
    if (m_compare) disconnect(m_compare, nullptr, this, nullptr);
    m_compare = compare;
    if (!m_compare) return update();
    connect(m_compare, &AbCompare::changed, this, qOverload<>(&QWidget::update));
    m_compare->attachLabels(this); // "A · the rig", "B · ..." over the two sides
    update();
}

QRectF Viewport::documentRect() const {
    return m_compare ? m_compare->documentRect(QSizeF(size())) : QRectF(rect());
}

bool Viewport::paintCompare(const QSize& size) {
    CompareFrame::Side a{&m_gl->renderer.rig(), m_scene->environment(), renderSettings(true)};
    CompareFrame::Side b{&m_compare->rigB(), m_compare->environmentB(), renderSettings(true)};
    b.settings.selectedLights.clear(); // the selection is the document's
    const Rig rigA = *a.rig;           // the renderer's rig changes while B renders
    a.rig = &rigA;
    QString error;
    if (!m_gl->compare.render(m_gl->renderer, *m_compare, a, b, renderCamera(), size, devicePixelRatioF(),
                              defaultFramebufferObject(), &error)) {
        if (m_error != error) emit statusMessage(tr("Compare view failed: %1").arg(error));
        m_error = error; // the normal frame instead
        return m_gl->renderer.render(renderCamera(), size, renderSettings(true), defaultFramebufferObject());
    }
    return true;
}

QImage Viewport::renderThumbnail(const Rig& rig, const QSize& size) {
    ViewCamera c = m_camera;
    c.znear = c.zfar = 0.0;
    c.frameAll(m_scene->model()->bounds, size.height() > 0 ? double(size.width()) / size.height() : 1.0);
    QString error;
    const QImage image = m_snapshots->render(rig, c, size, renderSettings(false), 2, &error);
    if (image.isNull()) emit statusMessage(tr("No thumbnail: %1").arg(error));
    return image;
}

QImage Viewport::renderScreenshot(const ScreenshotOptions& options, QString* error,
                                  const std::function<bool(int, int)>& progress) {
    return renderScreenshot(options, m_doc->renderRig(), renderCamera(), error, progress);
}

QImage Viewport::renderScreenshot(const ScreenshotOptions& options, const Rig& rig, const ViewCamera& camera,
                                  QString* error, const std::function<bool(int, int)>& progress) {
    RenderSettings s = renderSettings(options.gizmos);
    s.transparentBackground = options.transparent;
    if (!options.gizmos) s.selectedLights.clear();
    QImage image = m_snapshots->render(rig, camera, options.size, s, options.supersample, error, progress,
                                       progress ? options.tileSize : 0);
    if (image.isNull() && error && error->isEmpty()) *error = tr("rendering failed");
    return image;
}

std::unique_ptr<SnapshotJob> Viewport::beginScreenshot(const ScreenshotOptions& options, QString* error) {
    RenderSettings s = renderSettings(options.gizmos);
    s.transparentBackground = options.transparent;
    if (!options.gizmos) s.selectedLights.clear();
    return m_snapshots->begin(m_doc->renderRig(), renderCamera(), options.size, s, options.supersample,
                              options.tileSize, error);
}

std::optional<RenderLayers> Viewport::renderLayers(QSize size, QString* error) {
    RenderSettings s = renderSettings(false);
    s.selectedLights.clear();
    const QSize view = this->size() * devicePixelRatioF();
    if (!view.isEmpty()) size = view.scaled(size, Qt::KeepAspectRatio).boundedTo(view);
    return m_snapshots->renderLayers(m_doc->renderRig(), renderCamera(), size, s, error);
}

bool Viewport::renderScreenshotTile(SnapshotJob* job, QString* error) {
    return m_snapshots->renderNext(job, error);
}

QString Viewport::exportScreenshot(const ScreenshotOptions& options) {
    QString error;
    const QImage image = renderScreenshot(options, &error);
    if (image.isNull()) return error;
    return saveImageAtomically(image, options.path, options.format);
}

} // namespace lr
