#include "rendersettingsdock.h"

#include "colorbutton.h"
#include "editor/changerigspace.h"
#include "editor/document.h"
#include "environmentbox.h"
#include "modeltooltips.h"
#include "numberedit.h"
#include "scene.h"
#include "tracedsettingsbox.h"
#include "ui_rendersettings.h"
#include "viewsettings.h"

#include <QColorDialog>
#include <QPainter>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <cmath>

namespace lr {

namespace {
template <typename E> void fillCombo(QComboBox* combo) {
    for (int i = 0; i < enumCount<E>(); ++i)
        combo->addItem(toString(E(i)));
}

QIcon swatch(const QColor& c) {
    QPixmap pm(28, 16);
    pm.fill(c);
    QPainter p(&pm);
    p.setPen(Qt::darkGray);
    p.drawRect(pm.rect().adjusted(0, 0, -1, -1));
    return QIcon(pm);
}
} // namespace

RenderSettingsDock::RenderSettingsDock(Document* document, ViewSettings* settings, QWidget* parent)
    : QDockWidget(tr("Render settings"), parent), m_ui(std::make_unique<Ui::RenderSettingsForm>()),
      m_doc(document), m_settings(settings) {
    setObjectName(QStringLiteral("RenderSettingsDock"));
    auto* body = new QWidget;
    m_ui->setupUi(body);
    m_environment = new EnvironmentBox(m_doc, body); // below the Ground box
    m_ui->mainLayout->insertWidget(m_ui->mainLayout->indexOf(m_ui->groundGroup) + 1, m_environment);
    // The path-traced view's targets (issue 36), below the Environment box.
    m_ui->mainLayout->insertWidget(m_ui->mainLayout->indexOf(m_environment) + 1,
                                   new TracedSettingsBox(m_settings, body));
    // Scrolled like the Properties dock it shares a tab with, so its boxes (Ground made it taller) never set
    // a minimum height on the main window.
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(body);
    setWidget(scroll);
    fillCombo<ToneMap>(m_ui->toneMap);
    fillCombo<Quality>(m_ui->quality);
    m_ui->quality->addItem(tr("path traced")); // after the raster tiers: ViewOptions::pathTraced
    m_ui->quality->setItemData(
        enumCount<Quality>(),
        tr("Once the view is still, path-traced samples accumulate (the targets are in "
           "the Path traced box); while it changes, the raster tier chosen last is shown"),
        Qt::ToolTipRole);
    // How the view draws while it moves (DynamicResolution): a frame rate to keep, or full size.
    m_moving = new QComboBox(body);
    m_moving->setObjectName(QStringLiteral("movingFrameRate"));
    m_moving->addItem(tr("full size"), 0);
    for (int fps : {15, 30, 60})
        m_moving->addItem(tr("%1 fps").arg(fps), fps);
    m_moving->setToolTip(tr("While the view moves or a light is dragged, frames are drawn smaller so that "
                            "this many fit a second; the still view is always drawn at full size. "
                            "\"full size\": every frame at full size, however long it takes."));
    auto* movingLabel = new QLabel(tr("&While moving"), body);
    movingLabel->setBuddy(m_moving);
    int qualityRow = 0;
    m_ui->viewLayout->getWidgetPosition(m_ui->quality, &qualityRow, nullptr);
    m_ui->viewLayout->insertRow(qualityRow + 1, movingLabel, m_moving);
    connect(m_moving, &QComboBox::activated, this,
            [this](int i) { m_settings->setMovingFrameRate(m_moving->itemData(i).toInt()); });
    fillCombo<SpecularModel>(m_ui->specularModel);
    fillCombo<ViewerModel>(m_ui->viewerModel);
    installModelTooltips<SpecularModel>(m_ui->specularModel);
    installModelTooltips<ViewerModel>(m_ui->viewerModel);
    for (const QString& axis : modelUpAxisNames())
        m_ui->modelUp->addItem(axis == QLatin1String("+Y") ? tr("+Y (as the file)") : axis);
    m_ui->modelUp->setEnabled(false);
    m_ui->shininess->setLimits(0.0, kMaxShininess, true);
    m_ui->shininess->setWhat(rigPropertyName(RigProperty::Shininess));

    // View settings: immediate, not undoable.
    connect(m_ui->exposure, &QDoubleSpinBox::valueChanged, m_settings, &ViewSettings::setExposure);
    connect(m_ui->exposureSlider, &QSlider::valueChanged, this,
            [this](int v) { m_settings->setExposure(v / 10.0); });
    connect(m_ui->toneMap, &QComboBox::activated, this,
            [this](int i) { m_settings->setToneMap(ToneMap(i)); });
    connect(m_ui->quality, &QComboBox::activated, this, [this](int i) {
        ViewOptions o = m_settings->options();
        o.pathTraced = i == enumCount<Quality>();
        if (!o.pathTraced) o.quality = Quality(i);
        m_settings->setOptions(o);
    });
    connect(m_ui->grid, &QCheckBox::toggled, m_settings, &ViewSettings::setGrid);
    connect(m_ui->gizmos, &QCheckBox::toggled, m_settings, &ViewSettings::setGizmos);
    connect(m_ui->background, &QToolButton::clicked, this, [this] {
        const QColor c =
            QColorDialog::getColor(m_settings->options().background, this, tr("Background colour"));
        if (c.isValid()) m_settings->setBackground(c);
    });
    connect(m_settings, &ViewSettings::changed, this, &RenderSettingsDock::loadView);

    // Rig shading: undoable document edits.
    connect(m_ui->shadingModel, &QComboBox::activated, this, [this](int i) {
        if (ShadingModel(i) != m_doc->rig().shading.model)
            setRigValue(int(RigProperty::ShadingModel), toString(ShadingModel(i)), false);
    });
    for (QWidget* w : classicOnlyWidgets())
        m_classicToolTips.append(w->toolTip());
    connect(m_ui->specularModel, &QComboBox::activated, this, [this](int i) {
        setRigValue(int(RigProperty::SpecularModel), toString(SpecularModel(i)), false);
    });
    connect(m_ui->viewerModel, &QComboBox::activated, this,
            [this](int i) { setRigValue(int(RigProperty::ViewerModel), toString(ViewerModel(i)), false); });
    connect(m_ui->shininess, &NumberEdit::valueEdited, this,
            [this](double v) { setRigValue(int(RigProperty::Shininess), v, true); });
    connect(m_ui->shininess, &QAbstractSpinBox::editingFinished, this, &RenderSettingsDock::finishGesture);
    connect(m_ui->shininess, &NumberEdit::rejected, m_ui->message, &QLabel::setText);
    connect(m_ui->ambient, &ColorButton::colorPicked, this, [this](const glm::dvec3& c) {
        setRigValue(int(RigProperty::Ambient), QVariant::fromValue(c), false);
    });
    // The ground (issue 14): the combo's items are GroundMode's, in order.
    static_assert(enumCount<GroundMode>() == 3, "ui/rendersettings.ui's groundMode lists one item per mode");
    connect(m_ui->groundMode, &QComboBox::activated, this, [this](int i) {
        if (GroundMode(i) != m_doc->rig().ground.mode)
            setRigValue(int(RigProperty::GroundMode), toString(GroundMode(i)), false);
    });
    connect(m_ui->groundColor, &ColorButton::colorPicked, this, [this](const glm::dvec3& c) {
        // The button keeps HDR scale; an albedo is at most 1 (a brighter pick is refused with the reason).
        setRigValue(int(RigProperty::GroundColor), QVariant::fromValue(c), false);
    });
    connect(m_ui->rigName, &QLineEdit::editingFinished, this, [this] {
        if (m_ui->rigName->text() != m_doc->rig().name)
            setRigValue(int(RigProperty::Name), m_ui->rigName->text(), false);
    });
    connect(m_ui->rigSpace, &QComboBox::activated, this, [this](int i) {
        if (RigSpace(i) == m_doc->rig().space) return;
        QString error;
        if (!changeRigSpace(m_doc, RigSpace(i), m_frame ? m_frame() : SceneFrame{}, &error)) {
            m_ui->message->setText(error);
            loadRig();
        } else {
            m_ui->message->clear();
        }
    });
    connect(m_doc, &Document::rigChanged, this, [this](const RigChange& change) {
        if (change.kind == RigChange::RigValues || change.kind == RigChange::Reset) loadRig();
    });
    loadView();
    loadRig();
}

void RenderSettingsDock::setScene(Scene* scene) {
    m_scene = scene;
    auto sync = [this] {
        const QSignalBlocker block(m_ui->modelUp);
        m_ui->modelUp->setCurrentIndex(int(m_scene->upAxis()));
        m_ui->modelUp->setEnabled(!m_scene->isEmpty());
    };
    connect(m_scene, &Scene::modelChanged, this, sync);
    connect(m_ui->modelUp, &QComboBox::activated, this,
            [this](int i) { m_scene->setUpAxis(ModelUpAxis(i)); });
    sync();
}

RenderSettingsDock::~RenderSettingsDock() {
    finishGesture();
}

void RenderSettingsDock::setTierOffers(const TierOffers& offers) {
    auto* items = qobject_cast<QStandardItemModel*>(m_ui->quality->model());
    for (int q = 0; q < enumCount<Quality>() && items; ++q) {
        const TierOffer& offer = offers[size_t(q)];
        if (QStandardItem* item = items->item(q)) item->setEnabled(offer.offered);
        m_ui->quality->setItemData(q, offer.offered ? QVariant() : QVariant(offer.why), Qt::ToolTipRole);
    }
}

void RenderSettingsDock::loadView() {
    const ViewOptions& o = m_settings->options();
    const QSignalBlocker b1(m_ui->exposure), b2(m_ui->exposureSlider), b3(m_ui->grid), b4(m_ui->gizmos);
    m_ui->exposure->setValue(o.exposure);
    m_ui->exposureSlider->setValue(int(std::lround(o.exposure * 10.0)));
    m_ui->toneMap->setCurrentIndex(int(o.toneMap));
    m_ui->quality->setCurrentIndex(o.pathTraced ? enumCount<Quality>() : int(o.quality));
    int moving = m_moving->findData(o.movingFrameRate);
    if (moving < 0) { // a rate from the settings file that the list lacks: shown as it is
        m_moving->addItem(tr("%1 fps").arg(o.movingFrameRate), o.movingFrameRate);
        moving = m_moving->count() - 1;
    }
    m_moving->setCurrentIndex(moving);
    m_ui->grid->setChecked(o.grid);
    m_ui->gizmos->setChecked(o.gizmos);
    m_ui->background->setIcon(swatch(o.background));
    m_ui->background->setText(o.background.name());
}

void RenderSettingsDock::loadRig() {
    const Rig& rig = m_doc->rig();
    if (m_ui->rigName->text() != rig.name) {
        const QSignalBlocker block(m_ui->rigName);
        m_ui->rigName->setText(rig.name);
    }
    m_ui->rigSpace->setCurrentIndex(int(rig.space));
    m_ui->shadingModel->setCurrentIndex(int(rig.shading.model));
    // Under physically based shading the classic-only values are kept (switching back restores them) but
    // mean nothing: disabled, and the tooltip says why.
    const bool classic = rig.shading.model == ShadingModel::Classic;
    const QList<QWidget*> classicOnly = classicOnlyWidgets();
    for (qsizetype i = 0; i < classicOnly.size(); ++i) {
        classicOnly[i]->setEnabled(classic);
        classicOnly[i]->setToolTip(classic ? m_classicToolTips.value(i) : classicOnlyToolTip());
    }
    m_ui->specularModel->setCurrentIndex(int(rig.shading.specular));
    m_ui->viewerModel->setCurrentIndex(int(rig.shading.viewer));
    m_ui->shininess->setValueQuietly(rig.shading.shininess);
    m_ui->ambient->setColor(rig.ambient);
    // Its unit (issue 41): an irradiance in lux on the diffuse lobe under physically based shading.
    m_ui->ambientLabel->setText(classic ? tr("&Ambient") : tr("&Ambient (lux)"));
    m_ui->groundMode->setCurrentIndex(int(rig.ground.mode));
    m_ui->groundColor->setColor(rig.ground.color);
    // A catcher shows only shadows: its colour means nothing then, nor with no ground.
    const bool visible = rig.ground.mode == GroundMode::Visible;
    m_ui->groundColor->setEnabled(visible);
    m_ui->groundColorLabel->setEnabled(visible);
}

QList<QWidget*> RenderSettingsDock::classicOnlyWidgets() const {
    return {m_ui->specularModel, m_ui->viewerModel, m_ui->shininess,
            m_ui->specularLabel, m_ui->viewerLabel, m_ui->shininessLabel};
}

QString RenderSettingsDock::classicOnlyToolTip() {
    return tr("Classic shading only: physically based shading uses each material's metallic and roughness "
              "(the glTF BRDF) and always the local viewer. Switch Shading to Classic to use it.");
}

void RenderSettingsDock::setRigValue(int property, const QVariant& value, bool continuous) {
    if (continuous && !m_editToken) m_editToken = m_doc->beginContinuousEdit();
    QString error;
    if (!m_doc->setRigValue(RigProperty(property), value, &error)) {
        m_ui->message->setText(error);
        loadRig();
    } else {
        m_ui->message->clear();
    }
    if (!continuous) finishGesture();
}

void RenderSettingsDock::finishGesture() {
    if (m_editToken) m_doc->endContinuousEdit(*std::exchange(m_editToken, std::nullopt));
}

} // namespace lr
