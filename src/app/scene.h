// The model the rig is designed on: shared, immutable once loaded (the renderer, the picking code and
// background loads hold it by shared_ptr). Never null: an empty model until the first load finishes.
// The model is shown with its up axis (model/upaxis.h), remembered per file in QSettings (keyed by the
// canonical path): model() is the rotated model everything draws and picks on; the rig is not touched.
#pragma once

#include "core/prepare.h"
#include "model/model.h"
#include "model/upaxis.h"

#include <QObject>
#include <memory>

namespace lr {

struct LoadedEnvironment;

class Scene : public QObject {
    Q_OBJECT
  public:
    explicit Scene(QObject* parent = nullptr);

    const std::shared_ptr<const Model>& model() const { return m_model; }
    QString path() const { return m_path; } // empty until a model is loaded
    bool isEmpty() const { return m_model->meshes.empty(); }
    // Where a rig in model space is anchored (bounding sphere of the model; unit sphere when empty).
    SceneFrame frame() const;
    // Shows the model with the up axis remembered for path (+Y when none).
    void setModel(std::shared_ptr<const Model> model, const QString& path);

    ModelUpAxis upAxis() const { return m_upAxis; }
    // Rotates the model to this up axis (relative to the file as imported) and remembers it for the file.
    void setUpAxis(ModelUpAxis axis);
    static ModelUpAxis rememberedUpAxis(const QString& path);

    // The rig's environment as loaded (environmentloading.h), shared by the viewport and every snapshot so
    // they render the same; null: none (or not loaded yet, or failed).
    const std::shared_ptr<const LoadedEnvironment>& environment() const { return m_environment; }
    void setEnvironment(std::shared_ptr<const LoadedEnvironment> environment);

  signals:
    void modelChanged();
    void environmentChanged();

  private:
    std::shared_ptr<const Model> m_model;
    ModelUpAxis m_upAxis = ModelUpAxis::YUp;
    QString m_path;
    std::shared_ptr<const LoadedEnvironment> m_environment;
};

} // namespace lr
