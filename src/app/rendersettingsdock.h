// The Render settings dock (form ui/rendersettings.ui): view settings (exposure, tone mapping, quality,
// background, grid, gizmos; ViewSettings, kept in QSettings) and the rig's shading values (specular model,
// viewer, shininess, ambient; undoable Document edits).
#pragma once

#include <QDockWidget>
#include <memory>
#include <optional>

namespace Ui {
class RenderSettingsForm;
}

namespace lr {

class Document;
class ViewSettings;

class RenderSettingsDock : public QDockWidget {
    Q_OBJECT
  public:
    RenderSettingsDock(Document* document, ViewSettings* settings, QWidget* parent = nullptr);
    ~RenderSettingsDock() override;

    Ui::RenderSettingsForm* form() const { return m_ui.get(); }

  private:
    void loadView();
    void loadRig();
    void setRigValue(int property, const QVariant& value, bool continuous);
    void finishGesture();

    std::unique_ptr<Ui::RenderSettingsForm> m_ui;
    Document* m_doc;
    ViewSettings* m_settings;
    std::optional<int> m_editToken;
};

} // namespace lr
