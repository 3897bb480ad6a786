// The editor's model loading (DocumentFiles::openModel) goes through the import worker: an importer that
// crashes or hangs costs the editor nothing. The model and rig that were open stay, the failure is reported
// with the worker's message, a hung import is cancelled (its worker killed), and the GUI thread keeps
// running its event loop while a load is in flight.
#include "app/documentfiles.h"
#include "app/errordialog.h"
#include "app/recentfiles.h"
#include "app/scene.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "model/importprotocol.h"
#include "model/isolatedimport.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QThreadPool>
#include <QTimer>

using namespace lr;

namespace {
const QString kData = QStringLiteral(LIGHTRIG_TEST_DATA "/model");
}

class TestEditorImport : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
        setErrorPresenter([this](const ErrorReport& r) { m_errors << r; });
    }
    void cleanup() {
        qunsetenv(importprotocol::kTestCrashVariable);
        m_errors.clear();
    }
    void crashKeepsTheOpenModelAndRig();
    void hangIsCancelledAndTheWindowStaysResponsive();

  private:
    QList<ErrorReport> m_errors;
};

void TestEditorImport::crashKeepsTheOpenModelAndRig() {
    Document doc;
    Scene scene;
    RecentFiles recent;
    DocumentFiles files(&doc, &scene, &recent, nullptr);
    QSignalSpy loaded(&files, &DocumentFiles::modelLoaded);
    QVERIFY(files.openModel(kData + QStringLiteral("/quad.obj")));
    QVERIFY(loaded.wait(60'000));
    const std::shared_ptr<const Model> before = scene.model();
    const QString pathBefore = scene.path();
    const QByteArray rigBefore = writeRigJson(doc.rig());
    QVERIFY(pathBefore.endsWith(QLatin1String("quad.obj")));

    qputenv(importprotocol::kTestCrashVariable, "segv");
    QSignalSpy failed(&files, &DocumentFiles::modelLoadFailed);
    QVERIFY(files.openModel(kData + QStringLiteral("/scene.gltf")));
    QVERIFY(failed.wait(60'000));
    QCOMPARE(failed.at(0).at(1).toString(),
             QStringLiteral("could not import %1/scene.gltf: the importer crashed (signal 11)").arg(kData));
    QCOMPARE(m_errors.size(), 1);
    QVERIFY(m_errors.at(0).details.contains(failed.at(0).at(1).toString()));
    QCOMPARE(scene.model(), before); // the very same model object
    QCOMPARE(scene.path(), pathBefore);
    QCOMPARE(writeRigJson(doc.rig()), rigBefore);
    QVERIFY(!files.isLoadingModel());
}

void TestEditorImport::hangIsCancelledAndTheWindowStaysResponsive() {
    Document doc;
    Scene scene;
    RecentFiles recent;
    DocumentFiles files(&doc, &scene, &recent, nullptr);
    const std::shared_ptr<const Model> before = scene.model();

    qputenv(importprotocol::kTestCrashVariable, "hang");
    int ticks = 0;
    QTimer timer;
    connect(&timer, &QTimer::timeout, this, [&ticks] { ++ticks; });
    timer.start(10);
    QSignalSpy finished(&files, &DocumentFiles::modelLoadFinished);
    QVERIFY(files.openModel(kData + QStringLiteral("/quad.obj")));
    QTRY_VERIFY_WITH_TIMEOUT(ticks >= 20, 10'000); // the event loop runs while the worker hangs
    QVERIFY(files.isLoadingModel());
    files.cancelModelLoad();
    QCOMPARE(finished.size(), 1);
    QVERIFY(!files.isLoadingModel());
    // The worker is killed within the import's 50 ms poll, so its thread comes back soon.
    QVERIFY(QThreadPool::globalInstance()->waitForDone(10'000));
    QCoreApplication::processEvents();
    QCOMPARE(scene.model(), before);
    QVERIFY(m_errors.isEmpty()); // cancelling is not an error
}

QTEST_MAIN(TestEditorImport)
#include "tst_editorimport.moc"
