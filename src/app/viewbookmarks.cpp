#include "viewbookmarks.h"

#include "editor/document.h"
#include "editor/rigviews.h"
#include "errordialog.h"
#include "viewport.h"

#include <QInputDialog>
#include <QMenu>

namespace lr {

RigView rigViewOf(const ViewCamera& camera, const QString& name) {
    RigView v;
    v.name = name;
    v.eye = camera.eye;
    v.target = camera.target;
    v.up = camera.trueUp();
    v.yfovDeg = camera.yfovDeg;
    return v;
}

ViewCamera viewCameraOf(const RigView& view) {
    ViewCamera c;
    c.eye = view.eye;
    c.target = view.target;
    c.up = view.up;
    c.yfovDeg = view.yfovDeg;
    return c;
}

ViewBookmarks::ViewBookmarks(Document* document, Viewport* viewport, QMenu* menu, QWidget* window)
    : QObject(window), m_doc(document), m_viewport(viewport), m_menu(menu), m_window(window) {
    askName = [this](const QString& suggested) {
        return QInputDialog::getText(m_window, tr("Save view"), tr("Name of the view:"), QLineEdit::Normal,
                                     suggested)
            .trimmed();
    };
    connect(m_doc, &Document::rigChanged, this, &ViewBookmarks::rebuild);
    rebuild();
}

bool ViewBookmarks::saveCurrentView(const QString& name) {
    QString error;
    if (!saveRigView(m_doc, rigViewOf(m_viewport->camera(), name.trimmed()), &error)) {
        showError(m_window, {tr("Save view"), tr("Could not save the view."), {error}});
        return false;
    }
    emit statusMessage(tr("Saved the view “%1” with the rig").arg(name.trimmed()));
    return true;
}

bool ViewBookmarks::recall(const QString& name) {
    for (const RigView& v : m_doc->rig().views)
        if (v.name == name) {
            m_viewport->setCamera(viewCameraOf(v));
            return true;
        }
    return false;
}

void ViewBookmarks::rebuild() {
    if (m_built && m_shown == m_doc->rig().views) return; // a light edit: the menu stays as it is
    m_built = true;
    m_shown = m_doc->rig().views;
    m_menu->clear();
    QAction* save = m_menu->addAction(tr("&Save view…"));
    save->setObjectName(QStringLiteral("saveView"));
    save->setToolTip(tr("Keep the current camera under a name, saved with the rig (an undo step)"));
    connect(save, &QAction::triggered, this, [this] {
        const QString name = askName(tr("View %1").arg(m_doc->rig().views.size() + 1));
        if (!name.isEmpty()) saveCurrentView(name);
    });
    const std::vector<RigView>& views = m_doc->rig().views;
    if (views.empty()) return;
    m_menu->addSeparator();
    for (const RigView& v : views) {
        QAction* a = m_menu->addAction(v.name);
        a->setObjectName(QStringLiteral("view:") + v.name);
        connect(a, &QAction::triggered, this, [this, name = v.name] { recall(name); });
    }
    m_menu->addSeparator();
    QMenu* remove = m_menu->addMenu(tr("&Remove saved view"));
    for (const RigView& v : views)
        connect(remove->addAction(v.name), &QAction::triggered, this, [this, name = v.name] {
            QString error;
            if (!removeRigView(m_doc, name, &error)) emit statusMessage(error);
        });
}

} // namespace lr
