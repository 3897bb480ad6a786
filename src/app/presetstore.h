// Rig presets: the built-in ones (resources/presets, read-only) and the user's own, saved as rig files
// with a PNG thumbnail beside them in <AppDataLocation>/presets (QStandardPaths).
#pragma once

#include "core/rigjson.h"

#include <QImage>
#include <QList>
#include <QObject>
#include <optional>

namespace lr {

struct PresetEntry {
    QString name;      // display name (file base name)
    QString path;      // rig file (":/resources/presets/NAME.json" for built-ins)
    QString thumbnail; // PNG path, empty when none
    bool builtin = false;
    std::optional<ShadingModel>
        shading; // the preset's shading (issue 13: shown as a badge); unset: unreadable
};

class PresetStore : public QObject {
    Q_OBJECT
  public:
    // userDir empty: <AppDataLocation>/presets.
    explicit PresetStore(const QString& userDir = QString(), QObject* parent = nullptr);

    QString userDir() const { return m_userDir; }
    QList<PresetEntry> presets() const; // built-ins first, then the user's, each sorted by name
    RigReadResult read(const PresetEntry& entry) const;
    // Saves rig (named `name`) as a user preset, with the thumbnail when not null. Overwrites a user preset
    // of that name. Returns the error text (naming the file), empty on success.
    QString save(const QString& name, const Rig& rig, const QImage& thumbnail);
    QString remove(const PresetEntry& entry);
    // A file name for `name` without characters that are unsafe in file names.
    static QString fileBaseName(const QString& name);

  signals:
    void changed();

  private:
    QString m_userDir;
};

} // namespace lr
