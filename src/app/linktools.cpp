#include "linktools.h"

#include "editor/document.h"
#include "editor/linkedit.h"
#include "linkingsection.h"
#include "linkmatrixdialog.h"
#include "mainwindow.h"
#include "propertiesdock.h"
#include "scene.h"
#include "scene/linkparts.h"
#include "viewport.h"

#include <QAction>
#include <QStatusBar>

namespace lr {

std::vector<PartNames> modelLinkParts(const Model& model) {
    return linkParts(&model, nullptr);
}

LinkPick toggleLitPartAt(Document* doc, const Model& model, const ScreenProjector& projector,
                         const QPointF& screen, QString* message) {
    const auto say = [&](LinkPick result, const QString& text) {
        if (message) *message = text;
        return result;
    };
    const auto hit = intersectModelWithNormal(model, projector.ray(screen));
    if (!hit) return say(LinkPick::Missed, QString());
    const std::vector<PartNames> parts = linkParts(model, doc->rig()); // the ground's too, while it is on
    const std::vector<LinkPartRow> rows = linkPartRows(parts);
    const LinkPartRow* row = nullptr;
    for (const LinkPartRow& r : rows)
        for (std::size_t p : r.parts)
            if (p == hit->mesh) row = &r;
    if (!row) return say(LinkPick::Missed, QString());
    const QList<int> lights = doc->selectedRows();
    if (lights.isEmpty())
        return say(LinkPick::NothingSelected,
                   QObject::tr("Select a light, then Alt+click a part of the model to link it (%1)")
                       .arg(row->label));
    const bool on = !rowLinkedForAll(*doc, lights, LinkKind::Lit, parts, *row);
    QString error;
    if (!setRowLinked(doc, lights, LinkKind::Lit, parts, *row, on, &error))
        return say(LinkPick::Refused,
                   error.isEmpty() ? QObject::tr("Nothing to change for %1").arg(row->label) : error);
    const QString who =
        lights.size() == 1 ? doc->light(lights.front()).name : QObject::tr("%1 lights").arg(lights.size());
    return on ? say(LinkPick::Linked,
                    QObject::tr("%1 now lights %2 (Alt+click again to switch it back)").arg(who, row->label))
              : say(LinkPick::Unlinked, QObject::tr("%1 no longer lights %2").arg(who, row->label));
}

LinkTools::LinkTools(MainWindow* window)
    : QObject(window), m_window(window), m_matrixAction(new QAction(tr("Light &linking…"), this)) {
    m_matrixAction->setToolTip(tr("Which parts each light lights and which cast its shadow, as a matrix"));
    connect(m_matrixAction, &QAction::triggered, this, &LinkTools::showMatrix);
    connect(window->scene(), &Scene::modelChanged, this, &LinkTools::modelChanged);
    LinkingSection* section = window->propertiesDock()->linking();
    connect(section, &LinkingSection::highlightChanged, this, &LinkTools::updateHighlight);
    Viewport* viewport = window->viewport();
    connect(viewport, &Viewport::linkClicked, this, [this, viewport](const QPointF& screen) {
        QString message;
        toggleLitPartAt(m_window->document(), *m_window->scene()->model(), viewport->projector(), screen,
                        &message);
        if (!message.isEmpty()) m_window->statusBar()->showMessage(message, 8000);
    });
    modelChanged();
}

LinkMatrixDialog* LinkTools::matrixDialog() {
    if (!m_matrix) {
        m_matrix = new LinkMatrixDialog(m_window->document(), m_window);
        m_matrix->setModelParts(modelLinkParts(*m_window->scene()->model()));
    }
    return m_matrix;
}

void LinkTools::showMatrix() {
    LinkMatrixDialog* dialog = matrixDialog();
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void LinkTools::modelChanged() {
    const std::vector<PartNames> parts = modelLinkParts(*m_window->scene()->model());
    m_window->propertiesDock()->linking()->setModelParts(parts);
    if (m_matrix) m_matrix->setModelParts(parts);
}

void LinkTools::updateHighlight() {
    const std::vector<std::size_t> parts = m_window->propertiesDock()->linking()->highlightedParts();
    m_window->viewport()->setHighlightedParts(std::vector<int>(parts.begin(), parts.end()));
}

} // namespace lr
