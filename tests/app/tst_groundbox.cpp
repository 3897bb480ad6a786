// Issue 14 in Render settings: the Ground box (Off / Visible / Shadow catcher and the ground colour) edits
// the rig's ground as undoable document steps, follows undo, redo and loaded rigs, enables the colour only
// where it shows, refuses a colour an albedo cannot have, and what it sets is saved and read back.
#include "app/colorbutton.h"
#include "app/rendersettingsdock.h"
#include "app/viewsettings.h"
#include "core/rigjson.h"
#include "editor/document.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;

class TestGroundBox : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void modeAndColourAreUndoSteps() {
        Document doc;
        doc.newRig(defaultRig());
        ViewSettings settings;
        RenderSettingsDock dock(&doc, &settings);
        auto* mode = dock.findChild<QComboBox*>(QStringLiteral("groundMode"));
        auto* colour = dock.findChild<ColorButton*>(QStringLiteral("groundColor"));
        auto* message = dock.findChild<QLabel*>(QStringLiteral("message"));
        QVERIFY(mode && colour && message);
        QCOMPARE(mode->count(), enumCount<GroundMode>());
        QCOMPARE(mode->itemText(int(GroundMode::Catcher)), QStringLiteral("Shadow catcher"));
        QCOMPARE(mode->currentIndex(), int(GroundMode::Off));
        QVERIFY(!colour->isEnabled()); // no ground: nothing to colour
        const Rig before = doc.rig();

        mode->setCurrentIndex(int(GroundMode::Visible));
        emit mode->activated(int(GroundMode::Visible));
        QCOMPARE(int(doc.rig().ground.mode), int(GroundMode::Visible));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Change ground"));
        QVERIFY(colour->isEnabled());
        QCOMPARE(doc.rig().lights, before.lights);

        emit colour->colorPicked(glm::dvec3(0.2, 0.4, 0.6));
        QCOMPARE(doc.rig().ground.color, glm::dvec3(0.2, 0.4, 0.6));
        QCOMPARE(doc.undoStack()->count(), 2);
        QCOMPARE(colour->color(), glm::dvec3(0.2, 0.4, 0.6));
        // Brighter than white is no albedo: refused with the reason, nothing stored.
        emit colour->colorPicked(glm::dvec3(2.0, 0.4, 0.6));
        QCOMPARE(doc.undoStack()->count(), 2);
        QVERIFY2(message->text().contains(QLatin1String("ground colour")), qPrintable(message->text()));
        QCOMPARE(colour->color(), glm::dvec3(0.2, 0.4, 0.6));

        mode->setCurrentIndex(int(GroundMode::Catcher));
        emit mode->activated(int(GroundMode::Catcher));
        QCOMPARE(int(doc.rig().ground.mode), int(GroundMode::Catcher));
        QVERIFY(!colour->isEnabled()); // a catcher shows only its shadows
        QCOMPARE(doc.undoStack()->count(), 3);
        // Choosing the mode it already has is no step.
        emit mode->activated(int(GroundMode::Catcher));
        QCOMPARE(doc.undoStack()->count(), 3);

        // The box follows undo and redo.
        doc.undoStack()->undo();
        QCOMPARE(mode->currentIndex(), int(GroundMode::Visible));
        QVERIFY(colour->isEnabled());
        doc.undoStack()->undo();
        QCOMPARE(colour->color(), Ground{}.color);
        doc.undoStack()->undo();
        QVERIFY(doc.rig() == before);
        QCOMPARE(mode->currentIndex(), int(GroundMode::Off));
        doc.undoStack()->redo();
        doc.undoStack()->redo();
        doc.undoStack()->redo();
        QCOMPARE(mode->currentIndex(), int(GroundMode::Catcher));

        // Saved in the rig and read back into another document's box.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("ground.json"));
        QCOMPARE(doc.saveAs(path), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains(R"("ground": {"mode": "catcher", "color": [0.2, 0.4, 0.6]})"));
        Document reopened;
        RenderSettingsDock other(&reopened, &settings);
        QCOMPARE(reopened.load(path), QString());
        QCOMPARE(other.findChild<QComboBox*>(QStringLiteral("groundMode"))->currentIndex(),
                 int(GroundMode::Catcher));
        QCOMPARE(other.findChild<ColorButton*>(QStringLiteral("groundColor"))->color(),
                 glm::dvec3(0.2, 0.4, 0.6));
    }
};

QTEST_MAIN(TestGroundBox)
#include "tst_groundbox.moc"
