#include "screenshotdialog.h"

#include "ui_screenshotdialog.h"

#include <QCheckBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>

namespace lr {

ScreenshotDialog::ScreenshotDialog(const QSize& viewportSize, const QString& suggestedPath, QWidget* parent)
    : QDialog(parent), m_ui(std::make_unique<Ui::ScreenshotDialog>()), m_viewportSize(viewportSize),
      m_pathTraced(new QCheckBox(tr("&Path traced"))), m_traceSamples(new QSpinBox) {
    m_ui->setupUi(this);
    // Path traced (issue 36): the samples per pixel beside the box, enabled with it.
    m_pathTraced->setObjectName(QStringLiteral("pathTraced"));
    m_pathTraced->setToolTip(
        tr("Render the true image of the rig (every bounce, the environment's shadows) "
           "on the CPU instead of the raster tier; progress and Cancel in the status bar"));
    m_traceSamples->setObjectName(QStringLiteral("traceSamples"));
    m_traceSamples->setRange(1, 65536);
    m_traceSamples->setSuffix(tr(" samples"));
    m_traceSamples->setToolTip(tr("Samples per pixel: noise falls as one over their square root"));
    auto* traceRow = new QHBoxLayout;
    traceRow->addWidget(m_pathTraced);
    traceRow->addWidget(m_traceSamples, 1);
    m_ui->form->addRow(tr("Quality"), traceRow);
    connect(m_pathTraced, &QCheckBox::toggled, m_traceSamples, &QWidget::setEnabled);
    QSettings s;
    s.beginGroup(QStringLiteral("screenshot"));
    ScreenshotOptions o;
    o.size = s.value(QStringLiteral("size"), o.size).toSize();
    o.supersample = s.value(QStringLiteral("supersample"), o.supersample).toInt();
    o.transparent = s.value(QStringLiteral("transparent"), o.transparent).toBool();
    o.gizmos = s.value(QStringLiteral("gizmos"), o.gizmos).toBool();
    o.format = s.value(QStringLiteral("format"), o.format).toByteArray();
    o.pathTraced = s.value(QStringLiteral("pathTraced"), o.pathTraced).toBool();
    o.traceSamples = s.value(QStringLiteral("traceSamples"), o.traceSamples).toInt();
    // The file last exported to, while its folder is there (issue 41: the dialog forgot it); else the
    // suggestion (the rig's name beside the rig).
    const QString last = s.value(QStringLiteral("path")).toString();
    s.endGroup();
    o.path = !last.isEmpty() && QFileInfo(QFileInfo(last).absolutePath()).isDir() ? last : suggestedPath;
    setOptions(o);
    connect(m_ui->format, &QComboBox::currentIndexChanged, this, &ScreenshotDialog::syncFormat);
    connect(m_ui->path, &QLineEdit::textEdited, this, [this](const QString& p) {
        const QString suffix = QFileInfo(p).suffix().toLower();
        if (suffix == QLatin1String("jpg") || suffix == QLatin1String("jpeg"))
            m_ui->format->setCurrentIndex(1);
        else if (suffix == QLatin1String("png"))
            m_ui->format->setCurrentIndex(0);
    });
    connect(m_ui->browse, &QToolButton::clicked, this, &ScreenshotDialog::browse);
    connect(m_ui->viewportSize, &QToolButton::clicked, this, [this] {
        m_ui->width->setValue(m_viewportSize.width());
        m_ui->height->setValue(m_viewportSize.height());
    });
    connect(m_ui->buttons, &QDialogButtonBox::accepted, this, &ScreenshotDialog::accept);
}

ScreenshotDialog::~ScreenshotDialog() = default;

ScreenshotOptions ScreenshotDialog::options() const {
    ScreenshotOptions o;
    o.path = m_ui->path->text().trimmed();
    o.size = QSize(m_ui->width->value(), m_ui->height->value());
    o.supersample = m_ui->supersample->value();
    o.format = m_ui->format->currentIndex() == 1 ? QByteArray("JPEG") : QByteArray("PNG");
    o.transparent = o.format == "PNG" && m_ui->transparent->isChecked();
    o.gizmos = m_ui->gizmos->isChecked();
    o.pathTraced = m_pathTraced->isChecked();
    o.traceSamples = m_traceSamples->value();
    return o;
}

void ScreenshotDialog::setOptions(const ScreenshotOptions& o) {
    m_ui->path->setText(o.path);
    m_ui->width->setValue(o.size.width());
    m_ui->height->setValue(o.size.height());
    m_ui->supersample->setValue(o.supersample);
    m_ui->format->setCurrentIndex(o.format == "JPEG" ? 1 : 0);
    m_ui->transparent->setChecked(o.transparent);
    m_ui->gizmos->setChecked(o.gizmos);
    m_pathTraced->setChecked(o.pathTraced);
    m_traceSamples->setValue(o.traceSamples);
    m_traceSamples->setEnabled(o.pathTraced);
    syncFormat();
}

void ScreenshotDialog::syncFormat() {
    const bool jpeg = m_ui->format->currentIndex() == 1;
    m_ui->transparent->setEnabled(!jpeg);
    QString p = m_ui->path->text();
    const QFileInfo fi(p);
    if (!p.isEmpty()) {
        const QString want = jpeg ? QStringLiteral("jpg") : QStringLiteral("png");
        const QString suffix = fi.suffix().toLower();
        const bool matches = jpeg ? (suffix == QLatin1String("jpg") || suffix == QLatin1String("jpeg"))
                                  : suffix == QLatin1String("png");
        if (!matches) {
            p = fi.dir().filePath(fi.completeBaseName() + QLatin1Char('.') + want);
            m_ui->path->setText(QDir::toNativeSeparators(p));
        }
    }
}

void ScreenshotDialog::browse() {
    const QString p = QFileDialog::getSaveFileName(this, tr("Export screenshot"), m_ui->path->text(),
                                                   tr("PNG image (*.png);;JPEG image (*.jpg *.jpeg)"));
    if (p.isEmpty()) return;
    m_ui->path->setText(QDir::toNativeSeparators(p));
    const QString suffix = QFileInfo(p).suffix().toLower();
    m_ui->format->setCurrentIndex(suffix == QLatin1String("jpg") || suffix == QLatin1String("jpeg") ? 1 : 0);
}

void ScreenshotDialog::accept() {
    const ScreenshotOptions o = options();
    if (o.path.isEmpty()) {
        m_ui->message->setText(tr("Choose a file to write."));
        return;
    }
    const QFileInfo dir(QFileInfo(o.path).absolutePath());
    if (!dir.isDir() || !dir.isWritable()) {
        m_ui->message->setText(tr("%1: the folder does not exist or is not writable").arg(dir.filePath()));
        return;
    }
    QSettings s;
    s.beginGroup(QStringLiteral("screenshot"));
    s.setValue(QStringLiteral("size"), o.size);
    s.setValue(QStringLiteral("supersample"), o.supersample);
    s.setValue(QStringLiteral("transparent"), o.transparent);
    s.setValue(QStringLiteral("gizmos"), o.gizmos);
    s.setValue(QStringLiteral("format"), o.format);
    s.setValue(QStringLiteral("pathTraced"), o.pathTraced);
    s.setValue(QStringLiteral("traceSamples"), o.traceSamples);
    s.setValue(QStringLiteral("path"), QFileInfo(o.path).absoluteFilePath());
    s.endGroup();
    QDialog::accept();
}

} // namespace lr
