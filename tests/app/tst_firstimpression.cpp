// Issue 41 item 18: with no arguments the editor opens on a physically based product look (the bundled
// Avocado, CC0, its licence beside it, on a ground in studio.exr with a soft key light and its shadow);
// Suzanne stays bundled as a sample (File › Open sample) and keeps its classic default rig.
#include "app/editoractions.h"
#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "startwindow.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QUndoStack>

using namespace lr;

class TestFirstImpression : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { test::prepareEditorTest(QStringLiteral("lightrig-firstimpression-test")); }

    void opensOnAProductLook_andSuzanneIsASample() {
        MainWindow w;
        QSignalSpy loaded(w.files(), &DocumentFiles::modelLoadFinished);
        EditorOptions options;
        options.restoreSession = false;
        w.openInitial(options);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(loaded.count() > 0 || loaded.wait(60000));
        const QString avocado = QStringLiteral(":/resources/models/avocado/Avocado.gltf");
        QCOMPARE(w.scene()->path(), avocado);
        QVERIFY(QFile::exists(QStringLiteral(":/resources/models/avocado/LICENSE.md")));
        QVERIFY(w.scene()->model()->hasPbrMaterials());
        const Rig& rig = w.document()->rig();
        QVERIFY(rig.shading.model == ShadingModel::Pbr);
        QVERIFY(rig.ground.mode != GroundMode::Off);
        QVERIFY(rig.environment.source == EnvironmentSource::Image);
        QCOMPARE(rig.environment.file, QStringLiteral("builtin:studio"));
        QCOMPARE(rig.lights.size(), size_t(1)); // one soft key
        QVERIFY(rig.lights[0].isArea());
        QVERIFY(rig.lights[0].shadow.enabled);
        const auto sample = sampleRig(avocado);
        QVERIFY(sample.has_value());
        QVERIFY(rig == *sample);
        QVERIFY(!w.document()->isModified());
        QVERIFY(w.files()->rigFollowsModel());
        QVERIFY(QTest::qWaitFor([&] { return w.viewport()->hasRenderedFrame(); }, 30000));
        test::shot(w, QStringLiteral("editor2-first-impression"));

        // File › Open sample › Suzanne: the classic showcase with the classic default rig.
        auto* samples = w.findChild<QMenu*>(QStringLiteral("samplesMenu"));
        QVERIFY(samples);
        QAction* suzanne = nullptr;
        for (QAction* a : samples->actions())
            if (a->text().contains(QStringLiteral("Suzanne"))) suzanne = a;
        QVERIFY(suzanne);
        QSignalSpy again(w.files(), &DocumentFiles::modelLoaded);
        suzanne->trigger();
        QVERIFY(again.wait(60000));
        QCOMPARE(w.scene()->path(), QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"));
        QVERIFY(w.document()->rig() == defaultRig());
        w.document()->undoStack()->setClean();
    }
};

QTEST_MAIN(TestFirstImpression)
#include "tst_firstimpression.moc"
