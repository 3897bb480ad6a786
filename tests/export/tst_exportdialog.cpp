// File › Export glTF… on a real main window (app/gltfexportdialog.h): the dialog lists every lossy conversion
// of the open rig before writing, the export lands where asked with the viewport's view as camera 0, "Lights
// only" writes no meshes, and a failure is an error box that names the reason with nothing written.
#include "app/errordialog.h"
#include "app/gltfexportdialog.h"
#include "app/scene.h"
#include "app/startwindow.h"
#include "app/viewport.h"
#include "core/gltfrewrite.h"
#include "support/files.h"

#include <QAction>
#include <QCheckBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <functional>

using namespace lr;

class TestExportDialog : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    QAction* exportAction() {
        for (QAction* a : m_window->menuBar()->findChildren<QAction*>())
            if (a->text() == QStringLiteral("Export &glTF…")) return a;
        return nullptr;
    }
    // Triggers the action; `fill` gets the dialog once it is shown, then it is accepted.
    int runExport(const std::function<void(GltfExportDialog*)>& fill) {
        int rows = -1;
        QTimer::singleShot(0, this, [&] {
            auto* dialog = qobject_cast<GltfExportDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            rows = dialog->lossList()->count();
            fill(dialog);
            dialog->accept();
        });
        exportAction()->trigger();
        return rows;
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test"));
        QVERIFY(m_dir.isValid());
        setErrorPresenter([this](const ErrorReport& r) { m_errors.append(r); });
        m_window = std::make_unique<MainWindow>();
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        // A copy of Suzanne on disk, so the export can be written beside it.
        const QString suzanne = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/");
        for (const QString& f : QDir(suzanne).entryList(QDir::Files))
            QVERIFY(lrtest::copyWritable(suzanne + f, m_dir.filePath(f)));
        QSignalSpy loaded(m_window->files(), &DocumentFiles::modelLoadFinished);
        QVERIFY(m_window->files()->openModel(m_dir.filePath(QStringLiteral("Suzanne.gltf"))));
        QVERIFY(loaded.wait(60000));
        QCOMPARE(m_window->scene()->path(), m_dir.filePath(QStringLiteral("Suzanne.gltf")));
        QVERIFY(exportAction());
    }
    void cleanupTestCase() {
        m_window->document()->undoStack()->setClean();
        m_window.reset();
        setErrorPresenter({});
    }

    // Issue 41: the path's label is a mnemonic (a buddy), not "&File:" with the ampersand shown.
    void fileLabelIsAMnemonic() {
        GltfExportDialog dialog({}, QStringLiteral("/tmp/x.glb"));
        QLabel* label = nullptr;
        for (QLabel* l : dialog.findChildren<QLabel*>())
            if (l->text() == QStringLiteral("&File:")) label = l;
        QVERIFY(label);
        QCOMPARE(label->buddy(), dialog.pathEdit());
    }

    // Issue 41: the export is not proposed inside the model's folder; once exported somewhere, that folder
    // is proposed next time (QSettings "export/lastGltfDir").
    void proposesTheLastExportFolderNotTheModels() {
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("exports")));
        const QString out = m_dir.filePath(QStringLiteral("exports/first.glb"));
        QString first, second;
        runExport([&](GltfExportDialog* d) {
            first = d->path();
            d->pathEdit()->setText(out);
        });
        QVERIFY2(m_errors.isEmpty(), qPrintable(m_errors.value(0).details.join(QLatin1Char('\n'))));
        QVERIFY(QFile::exists(out));
        QVERIFY(first.endsWith(QStringLiteral("/Suzanne-lightrig.glb")));
        QVERIFY2(QFileInfo(first).absolutePath() != QFileInfo(m_window->scene()->path()).absolutePath(),
                 qPrintable(first));
        runExport([&](GltfExportDialog* d) {
            second = d->path();
            d->pathEdit()->setText(m_dir.filePath(QStringLiteral("exports/second.glb")));
        });
        QCOMPARE(QFileInfo(second).absolutePath(), m_dir.filePath(QStringLiteral("exports")));
    }

    // Issue 41: the exported view camera's planes enclose the model's bounding sphere with half its radius
    // to spare (planes at depth ± 1.02 r clipped it in three.js), the near plane no closer than 1/10,000
    // of the far one.
    void exportedCameraEnclosesTheModel() {
        const QString out = m_dir.filePath(QStringLiteral("exports/camera.gltf"));
        runExport([&](GltfExportDialog* d) { d->pathEdit()->setText(out); });
        QVERIFY(m_errors.isEmpty());
        const QJsonObject root = QJsonDocument::fromJson(lrtest::readFile(out)).object();
        const QJsonObject p = root[QStringLiteral("cameras")][0][QStringLiteral("perspective")].toObject();
        const double znear = p[QStringLiteral("znear")].toDouble(),
                     zfar = p[QStringLiteral("zfar")].toDouble();
        const ViewCamera view = m_window->viewport()->camera();
        const SceneFrame frame = m_window->scene()->frame();
        const double depth = glm::dot(frame.center - view.eye, view.forward());
        QVERIFY2(zfar >= depth + 1.4 * frame.radius,
                 qPrintable(QStringLiteral("%1 %2").arg(zfar).arg(depth)));
        QVERIFY2(znear <= std::max(depth - 1.4 * frame.radius, zfar * 1.01e-4),
                 qPrintable(QStringLiteral("%1 %2").arg(znear).arg(depth)));
        QVERIFY(znear >= zfar * 0.99e-4);
    }

    void listsLossesAndWritesTheModel() {
        const QString out = m_dir.filePath(QStringLiteral("out.glb"));
        const Rig& rig = m_window->document()->rig();
        const size_t losses = convertRigToGltf(rig, m_window->scene()->frame()).losses.size();
        QVERIFY(losses > 0); // the rig the model got (pbr-three-point: its ambient at least)
        const int rows = runExport([&](GltfExportDialog* d) { d->pathEdit()->setText(out); });
        QCOMPARE(rows, int(losses));
        QVERIFY2(m_errors.isEmpty(), qPrintable(m_errors.value(0).details.join(QLatin1Char('\n'))));
        QString error;
        const auto glb = parseGlb(lrtest::readFile(out), &error);
        QVERIFY2(glb, qPrintable(error));
        const QJsonObject root = QJsonDocument::fromJson(glb->json).object();
        QCOMPARE(root[QStringLiteral("cameras")][0][QStringLiteral("name")].toString(),
                 QStringLiteral("LightRig view"));
        QVERIFY(root.contains(QStringLiteral("meshes")));
        QVERIFY(!root[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                     [QStringLiteral("lights")]
                         .toArray()
                         .isEmpty());
        QVERIFY(m_window->statusBar()->currentMessage().contains(QStringLiteral("lossy conversions")));
    }

    void lightsOnly() {
        const QString out = m_dir.filePath(QStringLiteral("lights.gltf"));
        runExport([&](GltfExportDialog* d) {
            d->pathEdit()->setText(out);
            d->lightsOnlyBox()->setChecked(true);
        });
        QVERIFY(m_errors.isEmpty());
        const QJsonObject root = QJsonDocument::fromJson(lrtest::readFile(out)).object();
        QVERIFY(root.contains(QStringLiteral("nodes")));
        QVERIFY(!root.contains(QStringLiteral("meshes")));
    }

    void failureIsAnErrorBoxAndWritesNothing() {
        const QString out = m_dir.filePath(QStringLiteral("no-such-folder/out.glb"));
        runExport([&](GltfExportDialog* d) { d->pathEdit()->setText(out); });
        QCOMPARE(m_errors.size(), 1);
        QVERIFY2(m_errors[0].details.join(QString()).contains(QStringLiteral("cannot write")),
                 qPrintable(m_errors[0].details.join(QString())));
        QVERIFY(!QFile::exists(out));
        m_errors.clear();
    }
};

QTEST_MAIN(TestExportDialog)
#include "tst_exportdialog.moc"
