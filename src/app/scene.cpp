#include "scene.h"

#include "scene/environmentloader.h"

#include <QCryptographicHash>
#include <QFileInfo>
#include <QSettings>
#include <glm/matrix.hpp>

namespace lr {

namespace {
// One QSettings key per model file: "modelUpAxis/<sha1 of the canonical path>" = "+Z".
QString upAxisKey(const QString& path) {
    const QString canonical = QFileInfo(path).canonicalFilePath();
    const QByteArray hash =
        QCryptographicHash::hash((canonical.isEmpty() ? path : canonical).toUtf8(), QCryptographicHash::Sha1);
    return QStringLiteral("modelUpAxis/") + QString::fromLatin1(hash.toHex());
}
} // namespace

Scene::Scene(QObject* parent) : QObject(parent), m_model(std::make_shared<Model>()) {}

SceneFrame Scene::frame() const {
    if (isEmpty()) return {};
    return {m_model->bounds.center(), m_model->bounds.radius()};
}

ModelUpAxis Scene::rememberedUpAxis(const QString& path) {
    if (path.isEmpty()) return ModelUpAxis::YUp;
    return modelUpAxisFromString(QSettings().value(upAxisKey(path)).toString());
}

void Scene::setModel(std::shared_ptr<const Model> model, const QString& path) {
    m_model = model ? std::move(model) : std::make_shared<Model>();
    m_path = path;
    m_upAxis = rememberedUpAxis(path);
    if (m_upAxis != ModelUpAxis::YUp)
        m_model = std::make_shared<const Model>(rotateModelUp(*m_model, m_upAxis));
    emit modelChanged();
}

void Scene::setUpAxis(ModelUpAxis axis) {
    if (axis == m_upAxis) return;
    // From the current axis back to the file's and on to the new one, in one exact rotation (the model is
    // kept once, not also as imported).
    const glm::dmat3 r = upAxisRotation(axis) * glm::transpose(upAxisRotation(m_upAxis));
    m_upAxis = axis;
    if (!m_path.isEmpty()) {
        QSettings settings;
        if (axis == ModelUpAxis::YUp)
            settings.remove(upAxisKey(m_path));
        else
            settings.setValue(upAxisKey(m_path), toString(axis));
    }
    m_model = std::make_shared<const Model>(rotateModel(*m_model, r));
    emit modelChanged();
}

void Scene::setEnvironment(std::shared_ptr<const LoadedEnvironment> environment) {
    if (environment == m_environment) return;
    m_environment = std::move(environment);
    emit environmentChanged();
}

} // namespace lr
