// The editor's "Light from environment" (issue 15, part 7): Edit › Light from environment arms it, and the
// next click on the viewport's background (or any Ctrl+Alt+click there) is turned into a world direction
// through the viewport's camera (picking.h ScreenProjector::ray) and handed to addLightFromEnvironment
// (editor/environmentlight.h): a directional light from the bright spot there, and — with "Dim the spot in
// the environment" checked (the default) — that spot dimmed, in one undo step.
#pragma once

#include <QObject>
#include <QPointF>
#include <glm/vec3.hpp>

class QAction;
class QMenu;

namespace lr {

class Document;
class Scene;
class Viewport;
struct EnvironmentLightResult;

class EnvironmentLightTool : public QObject {
    Q_OBJECT
  public:
    EnvironmentLightTool(Document* document, Scene* scene, Viewport* viewport, QObject* parent = nullptr);

    QAction* pickAction() const { return m_pick; } // checkable: the next background click takes a light
    QAction* dimAction() const { return m_dim; }   // checkable, on by default
    void addActions(QMenu* menu) const;

    // A click at a viewport position: the background gives a light, the model a message.
    void clickedAt(const QPointF& position);
    // The same for a world direction (tests, and what a click comes to).
    EnvironmentLightResult addFromDirection(const glm::dvec3& direction);

  signals:
    void statusMessage(const QString& text);

  private:
    Document* m_doc;
    Scene* m_scene;
    Viewport* m_viewport;
    QAction *m_pick, *m_dim;
};

} // namespace lr
