#include "turntabledialog.h"

#include "render/imagefile.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>

namespace lr {

namespace {
// "PNG" or "JPEG" (the screenshot options' spelling) by the suffix, or empty.
QByteArray formatOf(const QString& path) {
    return writableImageFormatOf(path).toUpper();
}
} // namespace

TurntableDialog::TurntableDialog(const QSize& viewportSize, const QString& suggestedPath, QWidget* parent)
    : QDialog(parent), m_path(new QLineEdit), m_frames(new QSpinBox), m_width(new QSpinBox),
      m_height(new QSpinBox), m_supersample(new QSpinBox), m_rotate(new QComboBox),
      m_transparent(new QCheckBox(tr("Transparent background (PNG)"))), m_message(new QLabel) {
    setWindowTitle(tr("Export turntable"));
    m_path->setObjectName(QStringLiteral("path"));
    m_path->setToolTip(tr("The frames' file name: the last run of # becomes the frame number"));
    auto* browse = new QToolButton;
    browse->setText(QStringLiteral("…"));
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(m_path);
    pathRow->addWidget(browse);
    m_frames->setObjectName(QStringLiteral("frames"));
    m_frames->setRange(1, 3600);
    m_rotate->setObjectName(QStringLiteral("rotate"));
    m_rotate->addItem(tr("Camera orbits the model"));
    m_rotate->addItem(tr("Lights turn, camera stays"));
    for (QSpinBox* side : {m_width, m_height}) {
        side->setRange(1, 16384);
        side->setSuffix(tr(" px"));
    }
    auto* viewportButton = new QToolButton;
    viewportButton->setText(tr("Viewport size"));
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(m_width);
    sizeRow->addWidget(new QLabel(QStringLiteral("×")));
    sizeRow->addWidget(m_height);
    sizeRow->addWidget(viewportButton);
    m_supersample->setRange(1, 4);
    m_supersample->setSuffix(QStringLiteral("×"));
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Files"), pathRow);
    form->addRow(tr("Frames"), m_frames);
    form->addRow(tr("Turn"), m_rotate);
    form->addRow(tr("Size"), sizeRow);
    form->addRow(tr("Supersampling"), m_supersample);
    form->addRow(QString(), m_transparent);
    form->addRow(m_message);
    form->addRow(buttons);

    QSettings s;
    s.beginGroup(QStringLiteral("turntable"));
    TurntableOptions o;
    o.frames = s.value(QStringLiteral("frames"), o.frames).toInt();
    o.rotate = s.value(QStringLiteral("rotate")).toString() == QLatin1String("lights")
                   ? TurntableRotation::Lights
                   : TurntableRotation::Camera;
    o.shot.size = s.value(QStringLiteral("size"), o.shot.size).toSize();
    o.shot.supersample = s.value(QStringLiteral("supersample"), o.shot.supersample).toInt();
    o.shot.transparent = s.value(QStringLiteral("transparent"), o.shot.transparent).toBool();
    s.endGroup();
    o.shot.path = suggestedPath;
    setOptions(o);

    connect(browse, &QToolButton::clicked, this, [this] {
        const QString p = QFileDialog::getSaveFileName(this, tr("Export turntable"), m_path->text(),
                                                       tr("PNG images (*.png);;JPEG images (*.jpg *.jpeg)"));
        if (!p.isEmpty()) m_path->setText(QDir::toNativeSeparators(p));
    });
    connect(viewportButton, &QToolButton::clicked, this, [this, viewportSize] {
        m_width->setValue(viewportSize.width());
        m_height->setValue(viewportSize.height());
    });
    connect(m_path, &QLineEdit::textChanged, this,
            [this](const QString& p) { m_transparent->setEnabled(formatOf(p) != "JPEG"); });
    connect(buttons, &QDialogButtonBox::accepted, this, &TurntableDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &TurntableDialog::reject);
}

TurntableOptions TurntableDialog::options() const {
    TurntableOptions o;
    o.shot.path = QDir::fromNativeSeparators(m_path->text().trimmed());
    o.shot.size = QSize(m_width->value(), m_height->value());
    o.shot.supersample = m_supersample->value();
    o.shot.format = formatOf(o.shot.path);
    if (o.shot.format.isEmpty()) o.shot.format = "PNG";
    o.shot.transparent = o.shot.format == "PNG" && m_transparent->isChecked();
    o.shot.gizmos = false;
    o.frames = m_frames->value();
    o.rotate = m_rotate->currentIndex() == 1 ? TurntableRotation::Lights : TurntableRotation::Camera;
    return o;
}

void TurntableDialog::setOptions(const TurntableOptions& o) {
    m_path->setText(QDir::toNativeSeparators(o.shot.path));
    m_frames->setValue(o.frames);
    m_rotate->setCurrentIndex(o.rotate == TurntableRotation::Lights ? 1 : 0);
    m_width->setValue(o.shot.size.width());
    m_height->setValue(o.shot.size.height());
    m_supersample->setValue(o.shot.supersample);
    m_transparent->setChecked(o.shot.transparent);
}

QString TurntableDialog::message() const {
    return m_message->text();
}

void TurntableDialog::accept() {
    const TurntableOptions o = options();
    const QFileInfo file(o.shot.path);
    if (o.shot.path.isEmpty()) {
        m_message->setText(tr("Choose the frames' file name."));
        return;
    }
    if (formatOf(o.shot.path).isEmpty()) {
        m_message->setText(tr("The file name must end in .png, .jpg or .jpeg."));
        return;
    }
    if (o.frames > 1 && !hasFrameField(o.shot.path)) {
        m_message->setText(tr("Put a run of # in the file name for the frame number, e.g. %1_####.%2")
                               .arg(file.completeBaseName(), file.suffix()));
        return;
    }
    // A folder that does not exist yet is created by the export (issue 41): its nearest existing parent
    // must be a writable folder.
    QString existing = file.absolutePath();
    while (!QFileInfo::exists(existing) && QFileInfo(existing).dir().path() != existing)
        existing = QFileInfo(existing).dir().path();
    const QFileInfo dir(existing);
    if (!dir.isDir() || !dir.isWritable()) {
        m_message->setText(tr("%1: not a writable folder").arg(dir.filePath()));
        return;
    }
    QSettings s;
    s.beginGroup(QStringLiteral("turntable"));
    s.setValue(QStringLiteral("frames"), o.frames);
    s.setValue(QStringLiteral("rotate"),
               o.rotate == TurntableRotation::Lights ? QStringLiteral("lights") : QStringLiteral("camera"));
    s.setValue(QStringLiteral("size"), o.shot.size);
    s.setValue(QStringLiteral("supersample"), o.shot.supersample);
    s.setValue(QStringLiteral("transparent"), o.shot.transparent);
    s.endGroup();
    QDialog::accept();
}

} // namespace lr
