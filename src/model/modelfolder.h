// Internal to lightrig_model. The folder a model file lives in, and the rule for the files it refers
// to (.bin buffers, .mtl libraries, textures): they must lie inside that folder unless the caller
// allows otherwise. Works for file-system paths and Qt resource paths (":/resources/models/...").
// Also the Assimp IOSystem that enforces the rule while Assimp reads, over QFile.
#pragma once

#include <QString>
#include <QStringList>
#include <assimp/IOSystem.hpp>
#include <mutex>

namespace lr::detail {

class ModelFolder {
  public:
    ModelFolder(const QString& modelPath, bool allowOutside);

    // The model file as handed to Assimp: absolute and clean (or a ":/" resource path).
    const QString& modelFile() const { return m_file; }
    const QString& folder() const { return m_folder; }
    // The file name for messages ("spider.fbx").
    const QString& displayName() const { return m_display; }

    // Resolves `reference` (absolute, or relative to the model's folder; '\' accepted as a separator)
    // to a clean path. Returns an empty string and sets *refusal when the path leaves the folder and
    // outside files are not allowed. The file need not exist.
    QString resolve(const QString& reference, QString* refusal) const;
    bool isInside(const QString& cleanPath) const;
    // The existing file `reference` names when it is refused only for lying outside the folder (so it
    // would be followed with permission); empty when it is inside, a Windows path, missing, or allowed.
    QString refusedOutsideFile(const QString& reference) const;

  private:
    QString m_file, m_folder, m_canonicalFolder, m_display;
    bool m_allowOutside = false;
};

// Assimp reads every file through this: QFile (so ":/" resources work), read-only, confined to the
// model's folder. Refused opens are remembered so the caller can report them.
class QtIOSystem : public Assimp::IOSystem {
  public:
    explicit QtIOSystem(const ModelFolder& folder) : m_folder(folder) {}
    bool Exists(const char* file) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override;
    void Close(Assimp::IOStream* stream) override;
    bool ComparePaths(const char* one, const char* second) const override;

    QStringList refusals() const;

  private:
    QString resolveForAssimp(const char* file) const;
    const ModelFolder& m_folder;
    mutable std::mutex m_mutex;
    mutable QStringList m_refusals;
};

} // namespace lr::detail
