#include "mixerdock.h"

#include "core/lightmixfile.h"
#include "editor/applylightmix.h"
#include "errordialog.h"
#include "mixergrouprow.h"
#include "mixerpreview.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace lr {

namespace {
QString mixFilter() {
    return QObject::tr("Light mixes (*.json);;All files (*)");
}

QHBoxLayout* buttonRow(std::initializer_list<QPushButton*> buttons) {
    auto* row = new QHBoxLayout;
    for (QPushButton* b : buttons)
        row->addWidget(b);
    row->addStretch(1);
    return row;
}
} // namespace

MixerDock::MixerDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Mixer"), parent), m_doc(document) {
    setObjectName(QStringLiteral("MixerDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    auto button = [&](const QString& text, const char* name, const QString& tip) {
        auto* b = new QPushButton(text, body);
        b->setObjectName(QLatin1String(name));
        b->setToolTip(tip);
        return b;
    };
    m_capture = button(tr("Capture"), "mixerCapture", tr("Render the scene split into its light groups"));
    m_ab = button(tr("A/B"), "mixerAB",
                  tr("Show the render as it was, unmixed (also while the mouse is held "
                     "on the image)"));
    m_ab->setCheckable(true);
    m_reset = button(tr("Reset"), "mixerReset", tr("Every group on, 0 EV, no tint"));
    m_open = button(tr("Open mix…"), "mixerOpen", tr("Read a mix file"));
    m_save = button(tr("Save mix…"), "mixerSave", tr("Write the mix to a mix file"));
    m_apply = button(tr("Apply to rig"), "mixerApply",
                     tr("Write the mix into the rig's lights (one undo step): a new render then looks like "
                        "the mix"));
    m_caption = new QLabel(body);
    m_caption->setObjectName(QStringLiteral("mixerCaption"));
    m_caption->setWordWrap(true);
    m_staleLabel =
        new QLabel(tr("These layers are from an earlier rig (it changed since they were rendered): "
                      "the mix still works on them. Capture again to see the rig as it is."),
                   body);
    m_staleLabel->setObjectName(QStringLiteral("mixerStale"));
    m_staleLabel->setWordWrap(true);
    m_staleLabel->setStyleSheet(QStringLiteral("color: #b7791f"));
    m_staleLabel->hide();
    m_preview = new MixerPreview(body);
    m_preview->setObjectName(QStringLiteral("mixerPreview"));
    m_rowsBox = new QWidget;
    m_rowsLayout = new QVBoxLayout(m_rowsBox);
    m_rowsLayout->setContentsMargins(0, 0, 0, 0);
    m_rowsLayout->addStretch(1);
    auto* scroll = new QScrollArea(body);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_rowsBox);
    m_notesLabel = new QLabel(body);
    m_notesLabel->setObjectName(QStringLiteral("mixerNotes"));
    m_notesLabel->setWordWrap(true);
    m_notesLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notesLabel->hide();

    layout->addLayout(buttonRow({m_capture, m_ab, m_reset}));
    layout->addWidget(m_caption);
    layout->addWidget(m_staleLabel);
    layout->addWidget(m_preview, 2);
    layout->addWidget(scroll, 1);
    layout->addLayout(buttonRow({m_open, m_save, m_apply}));
    layout->addWidget(m_notesLabel);
    setWidget(body);

    askOpenPath = [this](const QString& title, const QString& filter) {
        return QFileDialog::getOpenFileName(this, title, QString(), filter);
    };
    askSavePath = [this](const QString& title, const QString& suggested, const QString& filter) {
        return QFileDialog::getSaveFileName(this, title, suggested, filter);
    };
    connect(m_capture, &QPushButton::clicked, this, &MixerDock::captureRequested);
    connect(m_ab, &QPushButton::toggled, this, &MixerDock::setShowUnmixed);
    connect(m_reset, &QPushButton::clicked, this, &MixerDock::resetMix);
    connect(m_open, &QPushButton::clicked, this, [this] { openMix(); });
    connect(m_save, &QPushButton::clicked, this, [this] { saveMix(); });
    connect(m_apply, &QPushButton::clicked, this, &MixerDock::applyToRig);
    connect(m_preview, &MixerPreview::held, this, [this](bool down) {
        m_held = down && hasLayers();
        redraw();
    });
    connect(m_preview, &MixerPreview::resized, this, [this] {
        rebuildPreviewLayers();
        redraw();
    });
    connect(m_doc, &Document::rigChanged, this, &MixerDock::updateStale);
    clearLayers();
}

MixerDock::~MixerDock() = default;

void MixerDock::setLayers(RenderLayers layers, const QString& what) {
    setLayers(std::move(layers), what, m_doc->rig(), m_doc->lightIds());
}

void MixerDock::setLayers(RenderLayers layers, const QString& what, const Rig& rig,
                          const QList<LightId>& ids) {
    bool consistent = !layers.groupImages.empty() && layers.groupImages.size() == layers.groups.size();
    for (const FloatImage& g : layers.groupImages)
        consistent = consistent && !g.isNull() && g.width == layers.groupImages.front().width &&
                     g.height == layers.groupImages.front().height;
    if (!consistent) {
        emit statusMessage(tr("The render's layers are not usable for mixing (%1 groups, %2 images)")
                               .arg(layers.groups.size())
                               .arg(layers.groupImages.size()));
        clearLayers();
        return;
    }
    m_layers = std::move(layers);
    m_what = what;
    m_rigThen = rig;
    m_idsThen = ids;
    // The mix keeps its values for the groups these layers have.
    const QStringList names = groupNames(m_layers.groups);
    std::erase_if(m_mix.groups, [&](const auto& g) { return !names.contains(g.first); });
    showNotes({});
    buildRows();
    m_small = {};
    rebuildPreviewLayers();
    updateStale();
    redraw();
    emit mixChanged();
}

void MixerDock::clearLayers() {
    m_layers = {};
    m_small = {};
    m_what.clear();
    m_rigThen = {};
    m_idsThen.clear();
    m_held = false;
    buildRows();
    updateStale();
    redraw();
}

void MixerDock::setDisplay(double exposureEV, ToneMap toneMap) {
    if (exposureEV == m_exposure && toneMap == m_toneMap) return;
    m_exposure = exposureEV;
    m_toneMap = toneMap;
    redraw();
}

MixerGroupRow* MixerDock::row(const QString& group) const {
    const auto it = m_rows.find(group);
    return it == m_rows.end() ? nullptr : it->second;
}

void MixerDock::setMix(const LightMix& mix) {
    m_mix = mix;
    std::erase_if(m_mix.groups, [](const auto& g) { return g.second.isIdentity(); });
    for (const auto& [name, row] : m_rows)
        row->setMix(m_mix.of(name));
    redraw();
    emit mixChanged();
}

void MixerDock::resetMix() {
    setMix({});
}

void MixerDock::setShowUnmixed(bool unmixed) {
    m_unmixed = unmixed;
    if (m_ab->isChecked() != unmixed) m_ab->setChecked(unmixed); // toggled comes back here: no-op
    redraw();
}

FloatImage MixerDock::shownImage() const {
    return mixGroupImages(m_layers, showsUnmixed() ? LightMix{} : m_mix);
}

QImage MixerDock::previewImage() const {
    return m_preview->image();
}

void MixerDock::buildRows() {
    for (const auto& [name, row] : m_rows)
        delete row;
    m_rows.clear();
    for (const LightGroup& g : m_layers.groups) {
        auto* row = new MixerGroupRow(g.name, groupToolTip(g), m_rowsBox);
        row->setMix(m_mix.of(g.name));
        m_rowsLayout->insertWidget(m_rowsLayout->count() - 1, row); // above the stretch
        m_rows[g.name] = row;
        connect(row, &MixerGroupRow::mixEdited, this, [this](const QString& group, const GroupMix& mix) {
            if (mix.isIdentity())
                m_mix.groups.erase(group);
            else
                m_mix.groups[group] = mix;
            redraw();
            emit mixChanged();
        });
    }
}

void MixerDock::rebuildPreviewLayers() {
    if (!hasLayers()) {
        m_small = {};
        return;
    }
    const FloatImage& first = m_layers.groupImages.front();
    const QSize size = fitSize(QSize(first.width, first.height), m_preview->pixelSize());
    const bool same = m_small.groups == m_layers.groups && !m_small.groupImages.empty() &&
                      m_small.groupImages.front().width == size.width() &&
                      m_small.groupImages.front().height == size.height();
    if (same) return;
    m_small = {};
    m_small.groups = m_layers.groups;
    for (const FloatImage& g : m_layers.groupImages)
        m_small.groupImages.push_back(downscaleImage(g, size));
}

void MixerDock::redraw() {
    updateControls();
    if (!hasLayers()) {
        m_preview->setImage({});
        m_preview->setText(tr("No layers yet. Capture renders the scene split into its light groups; each "
                              "group then gets a row here."));
        return;
    }
    if (m_small.groupImages.empty()) rebuildPreviewLayers();
    m_preview->setImage(
        displayImage(mixGroupImages(m_small, showsUnmixed() ? LightMix{} : m_mix), m_exposure, m_toneMap));
}

void MixerDock::updateStale() {
    m_stale = hasLayers() && (m_doc->rig() != m_rigThen || m_doc->lightIds() != m_idsThen);
    m_staleLabel->setVisible(m_stale);
}

void MixerDock::updateControls() {
    const bool layers = hasLayers();
    if (layers) {
        const FloatImage& first = m_layers.groupImages.front();
        m_caption->setText(tr("%1 · %2×%3 · %n group(s)", nullptr, int(m_layers.groups.size()))
                               .arg(m_what.isEmpty() ? tr("render") : m_what)
                               .arg(first.width)
                               .arg(first.height));
    } else {
        m_caption->setText(tr("No layers"));
    }
    m_ab->setEnabled(layers);
    m_reset->setEnabled(!m_mix.isIdentity());
    m_apply->setEnabled(layers && !m_mix.isIdentity());
}

void MixerDock::showNotes(const QStringList& lines) {
    m_notes = lines;
    m_notesLabel->setText(lines.isEmpty() ? QString() : tr("Not applied to the rig:\n") + lines.join('\n'));
    m_notesLabel->setVisible(!lines.isEmpty());
}

QString MixerDock::groupToolTip(const LightGroup& g) const {
    switch (g.kind) {
    case LightGroupKind::Lights: {
        QStringList names;
        for (int i : g.lights)
            if (i >= 0 && size_t(i) < m_rigThen.lights.size()) {
                const QString& name = m_rigThen.lights[size_t(i)].name;
                names << (name.trimmed().isEmpty() ? tr("light %1").arg(i + 1) : name);
            }
        return tr("Light group: %1").arg(names.join(QStringLiteral(", ")));
    }
    case LightGroupKind::Environment:
        return tr("The environment's light and its visible background");
    case LightGroupKind::Emissive:
        return tr("The model's emissive surfaces");
    case LightGroupKind::Ambient:
        return tr("The rig's ambient term");
    case LightGroupKind::Background:
        return tr("What no light lit: the background colour and the shadow catcher");
    }
    return {};
}

bool MixerDock::saveMix(const QString& given) {
    QString path = given;
    if (path.isEmpty()) {
        const QString rig = m_doc->filePath();
        const QString suggested = rig.isEmpty()
                                      ? QDir::home().filePath(QStringLiteral("mix.json"))
                                      : QFileInfo(rig).dir().filePath(QFileInfo(rig).completeBaseName() +
                                                                      QStringLiteral(".mix.json"));
        path = askSavePath(tr("Save mix"), suggested, mixFilter());
        if (path.isEmpty()) return false;
    }
    if (const QString error = writeLightMixFile(path, m_mix); !error.isEmpty()) {
        showError(this, {tr("Save mix"), tr("Could not save the mix."), {error}});
        emit statusMessage(error);
        return false;
    }
    emit statusMessage(tr("Saved the mix to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool MixerDock::openMix(const QString& given) {
    const QString path = given.isEmpty() ? askOpenPath(tr("Open mix"), mixFilter()) : given;
    if (path.isEmpty()) return false;
    const LightMixReadResult read =
        readLightMixFile(path, hasLayers() ? groupNames(m_layers.groups) : QStringList());
    if (!read.mix) {
        const QString summary =
            tr("Could not open %1: %n error(s); the mix stays as it was.", nullptr, int(read.errors.size()))
                .arg(QFileInfo(path).fileName());
        showError(this, {tr("Open mix"), summary, read.errors});
        emit statusMessage(summary);
        return false;
    }
    setMix(*read.mix);
    emit statusMessage(read.warnings.isEmpty() ? tr("Opened the mix %1").arg(QDir::toNativeSeparators(path))
                                               : tr("Opened the mix %1; %2")
                                                     .arg(QDir::toNativeSeparators(path),
                                                          read.warnings.join(QStringLiteral("; "))));
    return true;
}

bool MixerDock::applyToRig() {
    if (!hasLayers()) {
        emit statusMessage(tr("Nothing to apply: capture layers first"));
        return false;
    }
    const bool wasCurrent = !m_stale;
    QStringList notes;
    const std::vector<LightGroup> groups = groupsAtRows(*m_doc, m_layers.groups, m_idsThen, &notes);
    QStringList notApplied;
    QString error;
    if (!applyLightMixToDocument(m_doc, groups, m_mix, &notApplied, &error)) {
        showNotes(notes + notApplied);
        emit statusMessage(tr("Mix not applied: %1").arg(error));
        return false;
    }
    notes += notApplied;
    if (wasCurrent && notes.isEmpty()) {
        // The rig now renders exactly the mixed image: the layers take the mix and stay current.
        const FloatImage mixed = mixGroupImages(m_layers, m_mix);
        for (size_t g = 0; g < m_layers.groups.size(); ++g) {
            const glm::vec3 k(m_mix.of(m_layers.groups[g].name).factor());
            for (glm::vec4& p : m_layers.groupImages[g].pixels)
                p = glm::vec4(k * glm::vec3(p), p.w);
        }
        m_layers.beauty = mixed;
        m_rigThen = m_doc->rig();
        m_idsThen = m_doc->lightIds();
        m_small = {};
        rebuildPreviewLayers();
    }
    setMix({}); // the rig holds it now
    updateStale();
    showNotes(notes);
    emit statusMessage(notes.isEmpty() ? tr("Applied the mix to the rig (Edit › Undo takes it back)")
                                       : tr("Applied the mix to the rig; %n change(s) not applied: see the "
                                            "Mixer",
                                            nullptr, int(notes.size())));
    return true;
}

} // namespace lr
