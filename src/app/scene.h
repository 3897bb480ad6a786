// The model the rig is designed on: shared, immutable once loaded (the renderer, the picking code and
// background loads hold it by shared_ptr). Never null: an empty model until the first load finishes.
#pragma once

#include "core/prepare.h"
#include "model/model.h"

#include <QObject>
#include <memory>

namespace lr {

class Scene : public QObject {
    Q_OBJECT
  public:
    explicit Scene(QObject* parent = nullptr);

    const std::shared_ptr<const Model>& model() const { return m_model; }
    QString path() const { return m_path; } // empty until a model is loaded
    bool isEmpty() const { return m_model->meshes.empty(); }
    // Where a rig in model space is anchored (bounding sphere of the model; unit sphere when empty).
    SceneFrame frame() const;
    void setModel(std::shared_ptr<const Model> model, const QString& path);

  signals:
    void modelChanged();

  private:
    std::shared_ptr<const Model> m_model;
    QString m_path;
};

} // namespace lr
