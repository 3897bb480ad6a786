#include "environmentbox.h"

#include "colorbutton.h"
#include "editor/document.h"
#include "editor/environmentvalue.h"
#include "environmentloading.h"
#include "logslider.h"
#include "model/environmentdecode.h"
#include "numberedit.h"
#include "softboxeditor.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QToolButton>
#include <algorithm>
#include <cmath>

namespace lr {

QStringList bundledEnvironmentFiles() {
    // The studio first: what switching to an image environment starts with.
    QStringList names = builtinEnvironmentNames();
    if (names.removeOne(QStringLiteral("studio"))) names.prepend(QStringLiteral("studio"));
    QStringList files;
    for (const QString& name : names)
        files << QLatin1String(kBuiltinEnvironmentPrefix) + name;
    return files;
}

namespace {
// The classic diffuse model of the environment (Environment::diffuse, core/environment.h's definition),
// where the rig format has it; templates so this compiles before and after the field exists.
template <typename E> std::optional<DiffuseModel> diffuseOf(const E& e) {
    if constexpr (requires { DiffuseModel(e.diffuse); })
        return e.diffuse;
    else
        return std::nullopt;
}
template <typename E> void setDiffuse(E& e, DiffuseModel m) {
    if constexpr (requires { e.diffuse = m; }) e.diffuse = m;
}

template <typename E> void fill(QComboBox* combo, const QStringList& labels) {
    Q_ASSERT(labels.size() == enumCount<E>());
    for (int i = 0; i < enumCount<E>(); ++i)
        combo->addItem(labels[i], toString(E(i)));
}

constexpr int kEvSteps = 10; // intensity slider steps per EV
} // namespace

bool EnvironmentBox::hasClassicDiffuse() {
    return diffuseOf(Environment{}).has_value();
}

EnvironmentBox::EnvironmentBox(Document* document, QWidget* parent)
    : QGroupBox(tr("Environment"), parent), m_doc(document) {
    setObjectName(QStringLiteral("environmentGroup"));
    auto* form = new QFormLayout(this);
    auto named = [](auto* w, const char* name) {
        w->setObjectName(QLatin1String(name));
        return w;
    };
    m_source = named(new QComboBox, "environmentSource");
    fill<EnvironmentSource>(m_source, {tr("None"), tr("HDR image"), tr("Studio (procedural)")});
    form->addRow(tr("&Source"), m_source);

    m_imageRow = new QWidget;
    auto* imageLayout = new QHBoxLayout(m_imageRow);
    imageLayout->setContentsMargins(0, 0, 0, 0);
    m_file = named(new QComboBox, "environmentFile");
    m_file->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_file->setMinimumContentsLength(12);
    m_browse = named(new QToolButton, "environmentBrowse");
    m_browse->setText(tr("…"));
    m_browse->setToolTip(tr("Choose an equirectangular HDR image (.hdr, .exr)"));
    imageLayout->addWidget(m_file, 1);
    imageLayout->addWidget(m_browse);
    form->addRow(tr("&Image"), m_imageRow);

    auto numberRow = [&](const char* name, const char* sliderName, const QString& label, double lo, double hi,
                         int sliderLo, int sliderHi, NumberEdit** edit, QSlider** slider) {
        auto* row = new QWidget;
        auto* l = new QHBoxLayout(row);
        l->setContentsMargins(0, 0, 0, 0);
        *edit = named(new NumberEdit, name);
        (*edit)->setLimits(lo, hi);
        (*edit)->setWhat(label.toLower().remove(QLatin1Char('&')));
        l->addWidget(*edit);
        if (slider) {
            *slider = named(new QSlider(Qt::Horizontal), sliderName);
            (*slider)->setRange(sliderLo, sliderHi);
            l->addWidget(*slider, 1);
        }
        form->addRow(label, row);
        return row;
    };
    QWidget* intensityRow = numberRow("environmentIntensity", nullptr, tr("In&tensity"), -envlimits::kMaxEv,
                                      envlimits::kMaxEv, 0, 0, &m_intensity, nullptr);
    // The intensity's slider drags in EV like the lights' (logslider.h): 40 px per EV, arrows ±⅓ EV (issue
    // 41: an absolute slider over ±20 EV moved several EV per few pixels). The handle shows where the value
    // lies in the range.
    m_intensitySlider = named(new EvDragSlider, "environmentIntensitySlider");
    m_intensitySlider->setRange(int(-envlimits::kMaxEv * kEvSteps), int(envlimits::kMaxEv * kEvSteps));
    m_intensitySlider->setToolTip(tr("Drag to change the intensity: %1 px per EV; Shift: finer, Ctrl: whole "
                                     "EV. Arrow keys: ±⅓ EV. Type an exact value in the field.")
                                      .arg(EvDragSlider::kPixelsPerEv));
    static_cast<QHBoxLayout*>(intensityRow->layout())->addWidget(m_intensitySlider, 1);
    m_intensity->setSuffix(tr(" EV"));
    m_intensity->setToolTip(tr("Radiance × 2^EV: +1 doubles the environment's light"));
    QWidget* rotationRow = numberRow("environmentRotation", "environmentRotationSlider", tr("&Rotation"), 0.0,
                                     360.0, 0, 360, &m_rotation, &m_rotationSlider);
    m_rotation->setSuffix(QStringLiteral("°"));
    m_rotation->setToolTip(tr("Turns the environment about the up axis (counter-clockwise seen from above)"));
    m_background = named(new QComboBox, "environmentBackground");
    fill<EnvironmentBackground>(m_background, {tr("Visible"), tr("Blurred"), tr("Background colour")});
    m_background->setToolTip(tr("What shows behind the model"));
    form->addRow(tr("&Background"), m_background);
    QWidget* blurRow = numberRow("environmentBlur", nullptr, tr("B&lur"), 0.0, 1.0, 0, 0, &m_blur, nullptr);
    m_blur->setSingleStep(0.05);
    m_blur->setToolTip(tr("The blurred background's blur, as a roughness (0 sharp ... 1 only colours)"));
    m_diffuse = named(new QComboBox, "environmentDiffuse");
    fill<DiffuseModel>(m_diffuse, {tr("Lambert"), tr("Half-Lambert")});
    form->addRow(tr("Classic &diffuse"), m_diffuse);

    m_studio = new QWidget;
    auto* studioLayout = new QFormLayout(m_studio);
    studioLayout->setContentsMargins(0, 0, 0, 0);
    auto colour = [&](const char* name, const QString& label, const QString& tip) {
        auto* b = named(new ColorButton, name);
        b->setToolTip(tip);
        studioLayout->addRow(label, b);
        return b;
    };
    m_zenith = colour("studioZenith", tr("Zenith"), tr("The sky straight up (linear radiance)"));
    m_horizon = colour("studioHorizon", tr("Horizon"), tr("The sky at the horizon (linear radiance)"));
    m_floor = colour("studioFloor", tr("Floor"), tr("Everything below the horizon (linear radiance)"));
    m_softboxes = new SoftboxEditor;
    studioLayout->addRow(m_softboxes);
    form->addRow(m_studio);

    m_status = named(new QLabel, "environmentStatus");
    m_status->setWordWrap(true);
    m_message = named(new QLabel, "environmentMessage");
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #c03030"));
    form->addRow(m_status);
    form->addRow(m_message);
    m_imageOnly = {m_imageRow};
    m_studioOnly = {m_studio};
    m_anySource = {intensityRow, rotationRow, m_background, blurRow, m_diffuse};

    // Every control proposes an edited copy of the rig's environment: one undo step.
    connect(m_source, &QComboBox::activated, this, [this](int i) {
        edit([i](Environment& e) {
            e.source = EnvironmentSource(i);
            if (e.source == EnvironmentSource::Image && e.file.isEmpty())
                e.file = bundledEnvironmentFiles().first();
            if (e.source == EnvironmentSource::Studio && e.studio.softboxes.empty())
                e.studio.softboxes.push_back(Softbox{}); // a key softbox to start from
        });
    });
    connect(m_file, &QComboBox::activated, this, [this](int i) {
        const QString file = m_file->itemData(i).toString();
        setImage(file);
    });
    connect(m_browse, &QToolButton::clicked, this, &EnvironmentBox::browse);
    auto continuous = [this](NumberEdit* field, QSlider* slider, double scale,
                             void (*apply)(Environment&, double)) {
        connect(field, &NumberEdit::valueEdited, this,
                [this, apply](double v) { edit([&](Environment& e) { apply(e, v); }, true); });
        connect(field, &QAbstractSpinBox::editingFinished, this, &EnvironmentBox::finishGesture);
        connect(field, &NumberEdit::rejected, m_message, &QLabel::setText);
        if (!slider) return;
        connect(slider, &QSlider::valueChanged, this, [this, slider, scale, apply](int v) {
            edit([&](Environment& e) { apply(e, v / scale); }, slider->isSliderDown());
        });
        connect(slider, &QSlider::sliderReleased, this, &EnvironmentBox::finishGesture);
    };
    continuous(m_intensity, nullptr, kEvSteps, [](Environment& e, double v) { e.intensity = v; });
    const auto setEv = [](Environment& e, double ev) {
        e.intensity = std::clamp(std::round(ev * 100.0) / 100.0, -envlimits::kMaxEv, envlimits::kMaxEv);
    };
    connect(m_intensitySlider, &EvDragSlider::dragStarted, this,
            [this] { m_dragStartEv = m_doc->rig().environment.intensity; });
    connect(m_intensitySlider, &EvDragSlider::dragged, this,
            [this, setEv](double ev) { edit([&](Environment& e) { setEv(e, m_dragStartEv + ev); }, true); });
    connect(m_intensitySlider, &EvDragSlider::dragFinished, this, &EnvironmentBox::finishGesture);
    connect(m_intensitySlider, &EvDragSlider::stepped, this,
            [this, setEv](double ev) { edit([&](Environment& e) { setEv(e, e.intensity + ev); }); });
    continuous(m_rotation, m_rotationSlider, 1.0, [](Environment& e, double v) { e.rotation = v; });
    continuous(m_blur, nullptr, 1.0, [](Environment& e, double v) { e.blur = v; });
    connect(m_background, &QComboBox::activated, this,
            [this](int i) { edit([i](Environment& e) { e.background = EnvironmentBackground(i); }); });
    connect(m_diffuse, &QComboBox::activated, this,
            [this](int i) { edit([i](Environment& e) { setDiffuse(e, DiffuseModel(i)); }); });
    connect(m_zenith, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { edit([&](Environment& e) { e.studio.zenith = c; }); });
    connect(m_horizon, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { edit([&](Environment& e) { e.studio.horizon = c; }); });
    connect(m_floor, &ColorButton::colorPicked, this,
            [this](const glm::dvec3& c) { edit([&](Environment& e) { e.studio.floor = c; }); });
    connect(m_softboxes, &SoftboxEditor::edited, this, [this](const std::vector<Softbox>& boxes, bool cont) {
        edit([&](Environment& e) { e.studio.softboxes = boxes; }, cont);
    });
    connect(m_softboxes, &SoftboxEditor::gestureFinished, this, &EnvironmentBox::finishGesture);
    connect(m_softboxes, &SoftboxEditor::rejected, m_message, &QLabel::setText);

    connect(m_doc, &Document::rigChanged, this, [this](const RigChange& c) {
        if (c.kind == RigChange::RigValues || c.kind == RigChange::Reset) load();
    });
    connect(m_doc, &Document::fileChanged, this, &EnvironmentBox::load);
    load();
}

EnvironmentBox::~EnvironmentBox() {
    finishGesture();
}

void EnvironmentBox::setLoading(EnvironmentLoading* loading) {
    m_loading = loading;
    connect(loading, &EnvironmentLoading::loadingChanged, this, &EnvironmentBox::showStatus);
    connect(loading, &EnvironmentLoading::loaded, this, &EnvironmentBox::showStatus);
    connect(loading, &EnvironmentLoading::refused, this, [this](const QString& error) {
        m_message->setText(tr("Kept the environment: %1").arg(error));
        showStatus();
    });
    showStatus();
}

void EnvironmentBox::showStatus() {
    if (!m_loading || m_doc->rig().environment.isNone()) {
        m_status->clear();
    } else if (m_loading->isLoading()) {
        m_status->setText(tr("Loading environment…"));
    } else if (!m_loading->lastError().isEmpty()) {
        m_status->setText(tr("Not drawn: %1").arg(m_loading->lastError()));
    } else {
        m_status->clear();
    }
}

void EnvironmentBox::load() {
    const Environment& e = m_doc->rig().environment;
    const QSignalBlocker b1(m_intensitySlider), b2(m_rotationSlider);
    m_source->setCurrentIndex(int(e.source));
    {
        const QSignalBlocker block(m_file);
        m_file->clear();
        QStringList files = bundledEnvironmentFiles();
        if (!e.file.isEmpty() && !files.contains(e.file)) files.prepend(e.file);
        for (const QString& f : files)
            m_file->addItem(f.startsWith(QLatin1String(kBuiltinEnvironmentPrefix))
                                ? tr("%1 (bundled)").arg(f.mid(int(qstrlen(kBuiltinEnvironmentPrefix))))
                                : QDir::toNativeSeparators(f),
                            f);
        m_file->setCurrentIndex(files.indexOf(e.file));
        m_file->setToolTip(e.file);
    }
    m_intensity->setValueQuietly(e.intensity);
    m_intensitySlider->setValue(int(std::lround(e.intensity * kEvSteps)));
    const double rotation = std::fmod(std::fmod(e.rotation, 360.0) + 360.0, 360.0);
    m_rotation->setValueQuietly(rotation);
    m_rotationSlider->setValue(int(std::lround(rotation)));
    m_background->setCurrentIndex(int(e.background));
    m_blur->setValueQuietly(e.blur);
    m_zenith->setColor(e.studio.zenith);
    m_horizon->setColor(e.studio.horizon);
    m_floor->setColor(e.studio.floor);
    m_softboxes->setSoftboxes(e.studio.softboxes);

    const bool any = !e.isNone();
    for (QWidget* w : m_anySource)
        w->setEnabled(any);
    auto* form = static_cast<QFormLayout*>(layout());
    form->setRowVisible(m_imageRow, e.source == EnvironmentSource::Image);
    form->setRowVisible(m_studio, e.source == EnvironmentSource::Studio);
    m_blur->setEnabled(any && e.background == EnvironmentBackground::Blurred);
    const bool classic = m_doc->rig().shading.model == ShadingModel::Classic;
    const std::optional<DiffuseModel> diffuse = diffuseOf(e);
    m_diffuse->setCurrentIndex(int(diffuse.value_or(DiffuseModel::Lambert)));
    m_diffuse->setEnabled(any && classic && diffuse.has_value());
    m_diffuse->setToolTip(!diffuse ? tr("Not in the rig format yet: the environment is shaded with Lambert")
                          : classic
                              ? tr("How the environment's light wraps around classic surfaces")
                              : tr("Classic shading only: physically based shading uses the glTF BRDF"));
    showStatus();
}

void EnvironmentBox::edit(const std::function<void(Environment&)>& change, bool continuous) {
    Environment e = m_doc->rig().environment;
    change(e);
    if (e == m_doc->rig().environment) return;
    if (continuous && !m_editToken) m_editToken = m_doc->beginContinuousEdit();
    QString error;
    if (!m_doc->setRigValue(RigProperty::Environment, QVariant::fromValue(e), &error)) {
        m_message->setText(error);
        load();
    } else {
        m_message->clear();
    }
    if (!continuous) finishGesture();
}

void EnvironmentBox::finishGesture() {
    if (m_editToken) m_doc->endContinuousEdit(*std::exchange(m_editToken, std::nullopt));
}

void EnvironmentBox::chooseImageFile(const QString& absolutePath) {
    QString file = QDir::cleanPath(absolutePath);
    if (!m_doc->filePath().isEmpty())
        file = QFileInfo(m_doc->filePath())
                   .absoluteDir()
                   .relativeFilePath(QFileInfo(absolutePath).absoluteFilePath());
    setImage(file);
}

void EnvironmentBox::setImage(const QString& file) {
    auto change = [file](Environment& e) {
        e.source = EnvironmentSource::Image;
        e.file = file;
    };
    Environment tried = m_doc->rig().environment;
    change(tried);
    if (!m_loading || tried == m_doc->rig().environment) {
        edit(change);
        return;
    }
    // Tried first: the rig (and the view) take the image only once it has loaded (issue 41).
    m_message->clear();
    m_loading->tryEnvironment(tried, [this, change] { edit(change); });
    load(); // the list shows the rig's file until then
}

void EnvironmentBox::browse() {
    const QString current = m_doc->rig().environment.file;
    QString dir = EnvironmentLoading::rigFolder(m_doc);
    if (!current.isEmpty() && !current.startsWith(QLatin1String(kBuiltinEnvironmentPrefix)))
        dir = QFileInfo(QDir(dir), current).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Environment image"), dir,
                                                      tr("HDR images (*.hdr *.exr);;All files (*)"));
    if (!path.isEmpty()) chooseImageFile(path);
}

} // namespace lr
