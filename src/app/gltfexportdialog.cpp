#include "gltfexportdialog.h"

#include "core/atomicwrite.h"
#include "documentfiles.h"
#include "editor/document.h"
#include "errordialog.h"
#include "mainwindow.h"
#include "model/gltfexport.h"
#include "scene.h"
#include "scene/camera.h"
#include "viewport.h"

#include <QApplication>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtConcurrent>

namespace lr {

namespace {

const QString kLastExportFolder = QStringLiteral("export/lastGltfDir");

// Where an export is proposed (issue 41: it was the model's folder, often a download or a shared library):
// the folder of the last export, else the rig file's folder, else the folder rigs were last opened or
// saved in (DocumentFiles::lastFolder, the home folder at first).
QString exportFolder(const QString& rigPath) {
    const QString last = QSettings().value(kLastExportFolder).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir()) return last;
    if (!rigPath.isEmpty() && !rigPath.startsWith(QLatin1String(":/")))
        return QFileInfo(rigPath).absolutePath();
    return DocumentFiles::lastFolder(DocumentFiles::FileKind::Rig);
}

} // namespace

GltfExportDialog::GltfExportDialog(const std::vector<LossyConversion>& losses, const QString& suggestedPath,
                                   QWidget* parent)
    : QDialog(parent), m_path(new QLineEdit(suggestedPath, this)),
      m_lightsOnly(new QCheckBox(tr("&Lights only (no meshes, to merge into another scene)"), this)),
      m_losses(new QListWidget(this)) {
    setWindowTitle(tr("Export glTF"));
    auto* browse = new QToolButton(this);
    browse->setText(tr("…"));
    connect(browse, &QToolButton::clicked, this, [this] {
        const QString chosen = QFileDialog::getSaveFileName(this, tr("Export glTF"), m_path->text(),
                                                            tr("glTF binary (*.glb);;glTF (*.gltf)"));
        if (!chosen.isEmpty()) m_path->setText(chosen);
    });
    auto* file = new QHBoxLayout;
    file->addWidget(m_path);
    file->addWidget(browse);
    auto* form = new QFormLayout;
    auto* fileLabel = new QLabel(tr("&File:"), this); // a buddy: the & is a mnemonic, not shown
    fileLabel->setBuddy(m_path);
    form->addRow(fileLabel, file);
    form->addRow(QString(), m_lightsOnly);
    for (const LossyConversion& loss : losses)
        m_losses->addItem(describeLoss(loss));
    auto* heading =
        new QLabel(losses.empty() ? tr("Nothing is lost: glTF holds every light of this rig as it is.")
                                  : tr("%n conversion(s) glTF cannot hold exactly (docs/export.md):", nullptr,
                                       int(losses.size())),
                   this);
    heading->setWordWrap(true);
    m_losses->setVisible(!losses.empty());
    m_losses->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(heading);
    layout->addWidget(m_losses, 1);
    layout->addWidget(buttons);
    resize(720, losses.empty() ? 160 : 420);
}

QString GltfExportDialog::path() const {
    return m_path->text().trimmed();
}

bool GltfExportDialog::lightsOnly() const {
    return m_lightsOnly->isChecked();
}

void GltfExportDialog::accept() {
    const QString p = path();
    if (!p.endsWith(QLatin1String(".glb"), Qt::CaseInsensitive) &&
        !p.endsWith(QLatin1String(".gltf"), Qt::CaseInsensitive)) {
        QMessageBox::warning(this, windowTitle(), tr("The file must end in .glb or .gltf."));
        return;
    }
    QDialog::accept();
}

void exportGltfInteractive(MainWindow* window) {
    Scene* scene = window->scene();
    const Rig& rig = window->document()->rig();
    const QString title = QApplication::translate("lr::GltfExportDialog", "Export glTF");
    if (scene->path().isEmpty()) {
        showError(window,
                  {title, QApplication::translate("lr::GltfExportDialog", "Open a model first."), {}});
        return;
    }
    GltfExportRequest request;
    request.modelPath = scene->path();
    request.rig = rig;
    request.frame = scene->frame();
    request.fileFromWorld = glm::transpose(upAxisRotation(scene->upAxis()));
    const ViewCamera view =
        window->viewport()->camera().withExportClipPlanes(request.frame.center, request.frame.radius);
    request.camera = makeGltfCamera(QStringLiteral("LightRig view"), view.eye, view.forward(), view.trueUp(),
                                    view.yfovDeg, view.znear, view.zfar, request.fileFromWorld);
    const QString suggested =
        QDir(exportFolder(window->document()->filePath()))
            .filePath(QFileInfo(scene->path()).completeBaseName() + QStringLiteral("-lightrig.glb"));
    GltfExportDialog dialog(convertRigToGltf(rig, request.frame, request.fileFromWorld).losses, suggested,
                            window);
    if (dialog.exec() != QDialog::Accepted) return;
    request.outputPath = dialog.path();
    request.lightsOnly = dialog.lightsOnly();
    if (const QFileInfo out(request.outputPath), source(request.modelPath);
        out.exists() && out.canonicalFilePath() == source.canonicalFilePath()) {
        showError(window, {title,
                           QApplication::translate("lr::GltfExportDialog", "Nothing was exported."),
                           {QStringLiteral("cannot write %1: it is the open model, which the export reads")
                                .arg(request.outputPath)}});
        return;
    }

    // Off the GUI thread (an Assimp export runs the import worker); the window stays painted meanwhile.
    QApplication::setOverrideCursor(Qt::WaitCursor);
    QFutureWatcher<QString> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcher<QString>::finished, &loop, &QEventLoop::quit);
    GltfExportResult result;
    watcher.setFuture(QtConcurrent::run([&request, &result] {
        result = exportGltf(request);
        if (!result.ok()) return result.error;
        const QString why = writeFileAtomically(request.outputPath, result.bytes);
        return why.isEmpty() ? QString() : QStringLiteral("cannot write %1: %2").arg(request.outputPath, why);
    }));
    loop.exec();
    QApplication::restoreOverrideCursor();
    const QString error = watcher.result();
    if (!error.isEmpty()) {
        showError(window,
                  {title, QApplication::translate("lr::GltfExportDialog", "Nothing was exported."), {error}});
        return;
    }
    QSettings().setValue(kLastExportFolder, QFileInfo(request.outputPath).absolutePath());
    window->statusBar()->showMessage(
        QApplication::translate("lr::GltfExportDialog", "Wrote %1: %2 lights, %3 lossy conversions")
            .arg(QDir::toNativeSeparators(request.outputPath))
            .arg(result.lights)
            .arg(result.losses.size()),
        10000);
}

} // namespace lr
