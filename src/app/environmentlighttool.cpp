#include "environmentlighttool.h"

#include "editor/document.h"
#include "editor/environmentlight.h"
#include "scene.h"
#include "scene/environmentloader.h"
#include "viewport.h"

#include <QAction>
#include <QMenu>

namespace lr {

EnvironmentLightTool::EnvironmentLightTool(Document* document, Scene* scene, Viewport* viewport,
                                           QObject* parent)
    : QObject(parent), m_doc(document), m_scene(scene), m_viewport(viewport) {
    m_pick = new QAction(tr("Light from &environment"), this);
    m_pick->setObjectName(QStringLiteral("lightFromEnvironment"));
    m_pick->setCheckable(true);
    m_pick->setToolTip(tr("Click a bright spot of the environment in the viewport's background to add a "
                          "directional light of its direction, colour and strength (or Ctrl+Alt+click it)"));
    m_dim = new QAction(tr("&Dim the spot in the environment"), this);
    m_dim->setObjectName(QStringLiteral("dimEnvironmentSpot"));
    m_dim->setCheckable(true);
    m_dim->setChecked(true);
    m_dim->setToolTip(tr("Darken the spot a light was taken from, so the environment does not light the "
                         "model twice"));
    connect(m_pick, &QAction::toggled, this, [this](bool on) {
        m_viewport->setEnvironmentPicking(on);
        if (on) emit statusMessage(tr("Click a bright spot of the environment in the viewport's background"));
    });
    connect(m_viewport, &Viewport::environmentClicked, this, &EnvironmentLightTool::clickedAt);
}

void EnvironmentLightTool::addActions(QMenu* menu) const {
    menu->addAction(m_pick);
    menu->addAction(m_dim);
}

void EnvironmentLightTool::clickedAt(const QPointF& position) {
    m_pick->setChecked(false); // one light per arming; Ctrl+Alt+click needs no arming
    const ScreenProjector projector = m_viewport->projector();
    const Ray ray = projector.ray(position);
    if (!m_scene->isEmpty() && intersectModel(*m_scene->model(), ray)) {
        emit statusMessage(
            tr("That is the model: click the background to take a light from the environment"));
        return;
    }
    addFromDirection(ray.direction);
}

EnvironmentLightResult EnvironmentLightTool::addFromDirection(const glm::dvec3& direction) {
    EnvironmentLightResult result;
    const auto& loaded = m_scene->environment();
    const Environment& spec = m_doc->rig().environment;
    if (spec.isNone())
        result.message = tr("The rig has no environment: choose one in Render settings first");
    else if (!loaded || !loaded->spec.sameRadiance(spec))
        result.message = tr("The environment is not loaded yet (or could not be): try again when it shows");
    else
        result = addLightFromEnvironment(m_doc, loaded->image, direction, m_dim->isChecked());
    if (result.added) m_doc->setSelectedRows({result.row});
    emit statusMessage(result.message);
    return result;
}

} // namespace lr
