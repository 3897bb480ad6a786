// View › Saved views (issue 41): named camera views kept in the rig (Rig::views, saved with it). "Save
// view…" asks for a name and stores the viewport's camera under it (an undo step; a name already used is
// replaced), each saved view's action recalls it (the camera moves: no undo step, as every camera move),
// "Remove saved view" takes one out (an undo step). The menu follows the rig (open, undo, preset).
#pragma once

#include "core/rig.h"

#include <QObject>
#include <functional>

class QMenu;

namespace lr {

class Document;
class Viewport;
struct ViewCamera;

class ViewBookmarks : public QObject {
    Q_OBJECT
  public:
    ViewBookmarks(Document* document, Viewport* viewport, QMenu* menu, QWidget* window);

    // The name for "Save view…" (a QInputDialog; tests replace it). Empty: cancelled.
    std::function<QString(const QString& suggested)> askName;

    bool saveCurrentView(const QString& name); // false (and a message) when refused
    bool recall(const QString& name);          // false when no view has that name

  signals:
    void statusMessage(const QString& text);

  private:
    void rebuild();

    Document* m_doc;
    Viewport* m_viewport;
    QMenu* m_menu;
    QWidget* m_window;
    std::vector<RigView> m_shown; // the views the menu lists
    bool m_built = false;
};

// The viewport camera as a saved view and back (the clip planes stay automatic).
RigView rigViewOf(const ViewCamera& camera, const QString& name = {});
ViewCamera viewCameraOf(const RigView& view);

} // namespace lr
