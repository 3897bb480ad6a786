// The "Recent files" list (rigs and models together), kept in QSettings under "recentFiles".
#pragma once

#include <QObject>
#include <QStringList>

class QMenu;

namespace lr {

class RecentFiles : public QObject {
    Q_OBJECT
  public:
    static constexpr int kMaxEntries = 10;

    explicit RecentFiles(QObject* parent = nullptr);
    QStringList files() const { return m_files; }
    void add(const QString& path); // moves it to the front
    void remove(const QString& path);
    void clear();
    // Keeps `menu` listing the files (numbered, with a "Clear" entry); triggers openRequested.
    void attachMenu(QMenu* menu);

  signals:
    void changed();
    void openRequested(const QString& path);

  private:
    void store();
    void rebuild(QMenu* menu);
    QStringList m_files;
};

} // namespace lr
