#include "scene.h"

namespace lr {

Scene::Scene(QObject* parent) : QObject(parent), m_model(std::make_shared<Model>()) {}

SceneFrame Scene::frame() const {
    if (isEmpty()) return {};
    return {m_model->bounds.center(), m_model->bounds.radius()};
}

void Scene::setModel(std::shared_ptr<const Model> model, const QString& path) {
    m_model = model ? std::move(model) : std::make_shared<Model>();
    m_path = path;
    emit modelChanged();
}

} // namespace lr
