// The Render settings dock (form ui/rendersettings.ui): view settings (exposure, tone mapping, quality,
// background, grid, gizmos; ViewSettings, kept in QSettings) and the rig's shading values (shading classic or
// physically based, specular model, viewer, shininess, ambient; undoable Document edits; the classic-only
// ones disabled, with a tooltip saying why, under physically based shading) and the rig's space (world or
// model; switching converts the lights so they stay where they are, one undo step), the rig's ground (off,
// visible or a shadow catcher, and its colour; each change one undo step), and the model's up axis (scene.h,
// per file).
#pragma once

#include "core/prepare.h"
#include "render/interactionbench.h"

#include <QComboBox>
#include <QDockWidget>
#include <QList>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>

namespace Ui {
class RenderSettingsForm;
}

namespace lr {

class Document;
class EnvironmentBox;
class Scene;
class ViewSettings;

class RenderSettingsDock : public QDockWidget {
    Q_OBJECT
  public:
    RenderSettingsDock(Document* document, ViewSettings* settings, QWidget* parent = nullptr);
    ~RenderSettingsDock() override;

    Ui::RenderSettingsForm* form() const { return m_ui.get(); }
    // The controls that mean something only under classic shading (disabled under Pbr) and their tooltip
    // then.
    QList<QWidget*> classicOnlyWidgets() const;
    static QString classicOnlyToolTip();
    // The model's bounding sphere, for the Space switch (editor/changerigspace.h converts the lights
    // through it). Unset: the unit sphere.
    void setSceneFrameProvider(std::function<SceneFrame()> frame) { m_frame = std::move(frame); }
    // The scene whose model's up axis the "Model up axis" box shows and sets (disabled without one).
    void setScene(Scene* scene);
    EnvironmentBox* environmentBox() const { return m_environment; } // issue 15 (environmentbox.h)
    // The tiers' promise for the current scene (core/tieroffer.h, measured by the Quality panel): a tier
    // not offered is greyed out in the Quality box, its tooltip the reason. Default: every tier offered.
    void setTierOffers(const TierOffers& offers);

  private:
    void loadView();
    void loadRig();
    void setRigValue(int property, const QVariant& value, bool continuous);
    void finishGesture();

    std::unique_ptr<Ui::RenderSettingsForm> m_ui;
    Document* m_doc;
    ViewSettings* m_settings;
    std::optional<int> m_editToken;
    std::function<SceneFrame()> m_frame;
    Scene* m_scene = nullptr;
    EnvironmentBox* m_environment;
    QComboBox* m_moving;           // "While moving": ViewOptions::movingFrameRate
    QStringList m_classicToolTips; // classicOnlyWidgets()' own tooltips, restored under classic shading
};

} // namespace lr
