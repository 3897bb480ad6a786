#include "recentfiles.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace lr {

namespace {
const QString kKey = QStringLiteral("recentFiles");
}

RecentFiles::RecentFiles(QObject* parent) : QObject(parent) {
    m_files = QSettings().value(kKey).toStringList();
    while (m_files.size() > kMaxEntries)
        m_files.removeLast();
}

void RecentFiles::add(const QString& path) {
    const QString abs = QFileInfo(path).absoluteFilePath();
    m_files.removeAll(abs);
    m_files.prepend(abs);
    while (m_files.size() > kMaxEntries)
        m_files.removeLast();
    store();
}

void RecentFiles::remove(const QString& path) {
    if (m_files.removeAll(QFileInfo(path).absoluteFilePath()) > 0) store();
}

void RecentFiles::clear() {
    m_files.clear();
    store();
}

void RecentFiles::store() {
    QSettings().setValue(kKey, m_files);
    emit changed();
}

void RecentFiles::attachMenu(QMenu* menu) {
    rebuild(menu);
    connect(this, &RecentFiles::changed, menu, [this, menu] { rebuild(menu); });
}

void RecentFiles::rebuild(QMenu* menu) {
    menu->clear();
    int n = 0;
    for (const QString& f : m_files) {
        ++n;
        const QString label = QStringLiteral("&%1 %2").arg(n % 10).arg(QFileInfo(f).fileName());
        QAction* a = menu->addAction(label);
        a->setToolTip(QDir::toNativeSeparators(f));
        a->setStatusTip(QDir::toNativeSeparators(f));
        connect(a, &QAction::triggered, this, [this, f] { emit openRequested(f); });
    }
    menu->addSeparator();
    QAction* clearAction = menu->addAction(tr("Clear list"));
    clearAction->setEnabled(!m_files.isEmpty());
    connect(clearAction, &QAction::triggered, this, &RecentFiles::clear);
    menu->setEnabled(true);
}

} // namespace lr
