#include "sessionsettings.h"

#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>

namespace lr {

namespace {
const QString kGeometry = QStringLiteral("window/geometry");
const QString kState = QStringLiteral("window/state");
const QString kLastModel = QStringLiteral("session/model");
const QString kLastRig = QStringLiteral("session/rig");

QString existing(const QString& key) {
    const QString p = QSettings().value(key).toString();
    return !p.isEmpty() && (p.startsWith(QLatin1String(":/")) || QFileInfo(p).isFile()) ? p : QString();
}
} // namespace

void SessionSettings::saveWindow(const QMainWindow* window) {
    QSettings s;
    s.setValue(kGeometry, window->saveGeometry());
    s.setValue(kState, window->saveState(kStateVersion));
}

bool SessionSettings::restoreWindow(QMainWindow* window) {
    QSettings s;
    const QByteArray geometry = s.value(kGeometry).toByteArray();
    const QByteArray state = s.value(kState).toByteArray();
    bool restored = false;
    if (!geometry.isEmpty()) restored = window->restoreGeometry(geometry);
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
