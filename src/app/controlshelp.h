// Help > Controls: how to drive the editor. The viewport's mouse bindings are a table here (they are
// handled in viewport.cpp and gizmointeraction.cpp: keep them in step); the keyboard shortcuts are read from
// the window's actions themselves (menus and docks), so that list cannot go stale.
#pragma once

#include <QList>
#include <QString>

class QDialog;
class QWidget;

namespace lr {

struct ControlBinding {
    QString input;  // "Shift+left drag", "Ctrl+Shift+S"
    QString effect; // what it does
};

QList<ControlBinding> mouseBindings();
// Every action under `window` with a shortcut, in menu order where it has one; the ampersands and the
// ellipses of the action texts are dropped.
QList<ControlBinding> keyBindings(const QWidget* window);
// Both tables as HTML (the dialog's text).
QString controlsHtml(const QWidget* window);
// Shows the Controls dialog (non-modal, object name "ControlsDialog"; one at a time) and returns it.
QDialog* showControls(QWidget* window);

} // namespace lr
