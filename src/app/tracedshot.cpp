#include "tracedshot.h"

#include "core/colour.h"
#include "scene/scenedescription.h"
#include "trace/pathtracer.h"
#include "trace/progressive.h"
#include "trace/tracescene.h"

#include <QCoreApplication>
#include <QPainter>
#include <algorithm>

namespace lr {

QImage tracedDisplay(const trace::PathTracer& tracer, const ViewOptions& options, bool transparent) {
    const QImage traced = tracer.display(options.exposure, options.toneMap);
    if (transparent || traced.isNull()) return traced;
    QImage image(traced.size(), QImage::Format_RGB32);
    image.fill(options.background);
    QPainter(&image).drawImage(0, 0, traced); // straight alpha over the colour
    return image;
}

trace::TraceSettings viewTraceSettings(const ViewOptions& options, const trace::TraceScene& scene) {
    trace::TraceSettings settings;
    const QColor bg = options.background.toRgb();
    settings.background = colour::srgbToLinear(glm::dvec3(bg.redF(), bg.greenF(), bg.blueF()));
    // Escaped rays go to alpha where no environment is seen: transparent, or laid over the background
    // colour as it is (tracedDisplay), untouched by exposure and tone map, as the raster draws it.
    settings.transparent = !scene.environmentVisible();
    return settings;
}

TracedShot::TracedShot(TracedInputs inputs, QSize size, int samples, bool transparent)
    : m_inputs(std::move(inputs)), m_size(size), m_samples(std::max(1, samples)), m_transparent(transparent) {
}

TracedShot::~TracedShot() = default;

void TracedShot::cancel() {
    QMutexLocker locker(&m_lock);
    m_cancelled.store(true);
    if (m_tracer) m_tracer->cancel();
}

QImage TracedShot::render(QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return QImage();
    };
    const QString cancelled = QCoreApplication::translate("lr::TracedShot", "cancelled");
    if (m_cancelled.load()) return fail(cancelled);
    if (!m_inputs.model || m_inputs.model->meshes.empty())
        return fail(QCoreApplication::translate("lr::TracedShot", "no model is loaded"));
    SceneDescription description;
    description.setModel(m_inputs.model);
    description.setRig(m_inputs.rig);
    description.setEnvironment(m_inputs.environment);
    QString why;
    const std::shared_ptr<const trace::TraceScene> scene = trace::TraceScene::build(description, &why);
    if (!scene) return fail(QCoreApplication::translate("lr::TracedShot", "not path traced: %1").arg(why));
    const trace::TraceSettings settings = viewTraceSettings(m_inputs.options, *scene);
    {
        QMutexLocker locker(&m_lock);
        if (m_cancelled.load()) return fail(cancelled);
        m_tracer = std::make_unique<trace::PathTracer>(scene, m_inputs.camera, m_size, settings);
    }
    // Passes of a few samples: progress between them.
    const trace::RenderOutcome outcome =
        trace::renderToTarget(*m_tracer, {m_samples, 0.0, 0.0, [this](int done) { m_done.store(done); }});
    if (outcome.reason == trace::StopReason::Cancelled) return fail(cancelled);
    return tracedDisplay(*m_tracer, m_inputs.options, m_transparent && settings.transparent);
}

} // namespace lr
