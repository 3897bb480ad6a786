// Helpers shared by the model import tests (tst_model, tst_modelmaterials, tst_modelhostile): test data
// paths, small files written and read, and loading that prints the error.
#pragma once

#include "model/modelloader.h"

#include <QByteArray>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QTemporaryDir>
#include <glm/geometric.hpp>
#include <memory>

namespace lr::test {

inline QString dataFile(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/model/") + name;
}

inline bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

inline QJsonObject readJson(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

inline bool near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    return glm::length(a - b) <= tol;
}

inline std::shared_ptr<Model> mustLoad(const QString& path, const ModelLoadOptions& options = {}) {
    ModelLoadResult r = loadModel(path, options);
    if (!r.ok()) qWarning("%s", qPrintable(r.error));
    return r.model;
}

// `gltf` written as `name` in `dir` and loaded; null (with the reason logged) when either fails.
inline std::shared_ptr<Model> loadGltfJson(const QJsonObject& gltf, const QTemporaryDir& dir,
                                           const QString& name) {
    const QString path = dir.filePath(name);
    if (!writeFile(path, QJsonDocument(gltf).toJson())) {
        qWarning("cannot write %s", qPrintable(path));
        return nullptr;
    }
    return mustLoad(path);
}

} // namespace lr::test
