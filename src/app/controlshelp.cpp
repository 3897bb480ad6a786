#include "controlshelp.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QMenu>
#include <QMenuBar>
#include <QSet>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QWidget>

namespace lr {

QList<ControlBinding> mouseBindings() {
    // viewport.cpp (mouse*Event, wheelEvent, keyPressEvent) and gizmointeraction.cpp.
    return {
        {QObject::tr("Left drag on empty space"), QObject::tr("Orbit the camera around its target")},
        {QObject::tr("Middle drag, or Shift+left drag"), QObject::tr("Pan the camera")},
        {QObject::tr("Wheel"), QObject::tr("Dolly towards or away from the target")},
        {QObject::tr("Click a light"), QObject::tr("Select it")},
        {QObject::tr("Ctrl+click a light"), QObject::tr("Add it to the selection, or take it out")},
        {QObject::tr("Click the background"),
         QObject::tr("Clear the selection (not the click that moves the keyboard focus to the viewport)")},
        {QObject::tr("Click the model"), QObject::tr("Nothing: no light moves, the selection stays")},
        {QObject::tr("Ctrl+click the model"),
         QObject::tr("Place the highlight: move each selected light, keeping its distance, so its mirror "
                     "reflection lands on that point (spot, rect and disk lights also turn to face it; "
                     "directional and rim lights only turn). One undo step; with no light selected it "
                     "changes nothing")},
        {QObject::tr("Click an area light's outline or inside it"), QObject::tr("Select it")},
        {QObject::tr("Left drag a selected rect or disk light's handle"),
         QObject::tr("Change its width, height or radius, symmetric about its centre")},
        {QObject::tr("Left drag a light"),
         QObject::tr("Move the selected lights in the view plane (directional and rim lights turn "
                     "around the scene)")},
        {QObject::tr("Ctrl or Alt + left drag a light"), QObject::tr("Move it along the view axis")},
        {QObject::tr("Left drag a selected spot's cone edge"),
         QObject::tr("Change its outer angle (in 0.5° steps)")},
        {QObject::tr("Shift+click the model"),
         QObject::tr("Aim the selected spot, rect, disk, directional and rim lights at that point "
                     "(nothing moves)")},
        {QObject::tr("Alt+click the model"),
         QObject::tr("Light linking: switch whether the selected lights light the part under the cursor (one "
                     "undo step; Properties › Linking lists the parts)")},
        {QObject::tr("Ctrl+Alt+click the background"),
         QObject::tr("Add a directional light from the environment's bright spot there (also Edit › Light "
                     "from environment, then a click)")},
        {QObject::tr("Esc while dragging a light"), QObject::tr("Cancel the drag (nothing is left to redo)")},
        {QObject::tr("Left drag the A/B line"),
         QObject::tr("Move the wipe between A and B (View › Compare A/B)")},
    };
}

namespace {
QString cleanText(QString text) {
    text.remove(QLatin1Char('&'));
    text.remove(QChar(0x2026)); // …
    return text.trimmed();
}

void collect(const QList<QAction*>& actions, const QString& prefix, QList<ControlBinding>* out,
             QSet<const QAction*>* seen) {
    for (QAction* a : actions) {
        if (seen->contains(a)) continue;
        if (a->menu()) {
            collect(a->menu()->actions(), prefix + cleanText(a->text()) + QStringLiteral(" › "), out, seen);
            continue;
        }
        seen->insert(a);
        if (a->shortcut().isEmpty() || a->isSeparator()) continue;
        out->append({a->shortcut().toString(QKeySequence::NativeText), prefix + cleanText(a->text())});
    }
}
} // namespace

QList<ControlBinding> keyBindings(const QWidget* window) {
    QList<ControlBinding> out;
    QSet<const QAction*> seen;
    // Menus first (in menu order, "File › Save"), then actions of docks and views not in a menu.
    if (const auto* menuBar = window->findChild<QMenuBar*>())
        collect(menuBar->actions(), QString(), &out, &seen);
    collect(window->findChildren<QAction*>(), QString(), &out, &seen);
    return out;
}

QString controlsHtml(const QWidget* window) {
    auto table = [](const QString& title, const QList<ControlBinding>& rows) {
        QString html = QStringLiteral("<h3>%1</h3><table cellspacing='2' cellpadding='3'>").arg(title);
        for (const ControlBinding& b : rows)
            html += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                        .arg(b.input.toHtmlEscaped(), b.effect.toHtmlEscaped());
        return html + QStringLiteral("</table>");
    };
    return table(QObject::tr("Viewport (mouse)"), mouseBindings()) +
           table(QObject::tr("Keyboard"), keyBindings(window)) +
           QObject::tr(
               "<p>Intensity slider: drag to change the value relative to where it is (40 px doubles "
               "it), Shift for finer, Ctrl for whole EV steps; type an exact value in its field.</p>");
}

QDialog* showControls(QWidget* window) {
    if (auto* open = window->findChild<QDialog*>(QStringLiteral("ControlsDialog"))) {
        open->raise();
        open->activateWindow();
        return open;
    }
    auto* dialog = new QDialog(window);
    dialog->setObjectName(QStringLiteral("ControlsDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(QObject::tr("Controls"));
    auto* layout = new QVBoxLayout(dialog);
    auto* text = new QTextBrowser(dialog);
    text->setObjectName(QStringLiteral("controlsText"));
    text->setHtml(controlsHtml(window));
    layout->addWidget(text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(560, 640);
    dialog->show();
    return dialog;
}

} // namespace lr
