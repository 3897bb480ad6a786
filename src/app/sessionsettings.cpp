#include "sessionsettings.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QMainWindow>
#include <QScreen>
#include <QSettings>

namespace lr {

namespace {
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kLastModel = QStringLiteral("session/model");
const QString kLastRig = QStringLiteral("session/rig");
const QString kNormalGeometry = QStringLiteral("window/normalGeometry");
const QString kMaximized = QStringLiteral("window/maximized");

// `r` when its title area is on a screen, else moved (and shrunk) onto the primary screen: a screen that
// is gone must not leave the window out of reach.
QRect onAScreen(QRect r) {
    const QPoint grip(r.center().x(), r.top() + 10);
    for (const QScreen* screen : QGuiApplication::screens())
        if (screen->availableGeometry().contains(grip)) return r;
    const QScreen* primary = QGuiApplication::primaryScreen();
    if (!primary) return r;
    const QRect avail = primary->availableGeometry();
    r.setSize(r.size().boundedTo(avail.size()));
    r.moveCenter(avail.center());
    return r;
}

QString existing(const QString& key) {
    const QString p = QSettings().value(key).toString();
    return !p.isEmpty() && (p.startsWith(QLatin1String(":/")) || QFileInfo(p).isFile()) ? p : QString();
}
} // namespace

void SessionSettings::saveWindow(const QMainWindow* window) {
    QSettings s;
    // The client rectangle (without the frame) and whether the window was maximized. saveGeometry() stores
    // the frame's position, which restoreGeometry() could only place right where the window manager's frame
    // extents were known: under a window manager that reports none, the frame position came back as the
    // client position and the window reopened a title bar lower at each start.
    s.setValue(kNormalGeometry, window->isVisible() ? window->normalGeometry() : window->geometry());
    s.setValue(kMaximized, window->isMaximized());
    s.remove(kGeometry); // the old frame-based record
    s.setValue(kState, window->saveState(kStateVersion));
}

bool SessionSettings::restoreWindow(QMainWindow* window) {
    QSettings s;
    const QRect normal = s.value(kNormalGeometry).toRect();
    const QByteArray geometry = s.value(kGeometry).toByteArray();
    const QByteArray state = s.value(kState).toByteArray();
    bool restored = false;
    if (normal.isValid()) {
        window->setGeometry(onAScreen(normal));
        if (s.value(kMaximized).toBool()) window->setWindowState(window->windowState() | Qt::WindowMaximized);
        restored = true;
    } else if (!geometry.isEmpty()) {
        restored = window->restoreGeometry(geometry); // written by an older LightRig
    }
    if (!state.isEmpty()) restored = window->restoreState(state, kStateVersion) || restored;
    return restored;
}

void SessionSettings::setLastModel(const QString& path) {
    QSettings().setValue(kLastModel, path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath());
}

void SessionSettings::setLastRig(const QString& path) {
    QSettings().setValue(kLastRig, path.isEmpty() || path.startsWith(QLatin1String(":/"))
                                       ? QString()
                                       : QFileInfo(path).absoluteFilePath());
}

QString SessionSettings::lastModel() {
    return existing(kLastModel);
}
QString SessionSettings::lastRig() {
    return existing(kLastRig);
}

} // namespace lr
