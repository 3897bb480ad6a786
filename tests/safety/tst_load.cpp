// Load (issue 6): 4096 lights and 10,000 undo steps with the light table model attached, and a 1,000-light
// multi-edit through the Properties dock as one undo step. tests/editor/tst_document.cpp checks the
// Document alone (value edits, setIndex round trips); this adds the views: the model (checked by
// QAbstractItemModelTester) follows every kind of step — values, renames, toggles, inserts, removals,
// moves — through undoing and redoing all of them, and the autosave copes with the largest rig.
// Functional asserts only; the times printed (qInfo) are for the report, not checked.
#include "app/autosave.h"
#include "app/numberedit.h"
#include "app/propertiesdock.h"
#include "editor/lighttablemodel.h"
#include "editor/rigfixture.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <memory>

using namespace lr;
using lrtest::bytes;

namespace {

// The table shows what the document holds: names, on/off and intensity of every row.
bool modelMatches(const LightTableModel& model, const Document& doc) {
    if (model.rowCount() != doc.lightCount()) return false;
    for (int row = 0; row < doc.lightCount(); ++row) {
        const Light& l = doc.light(row);
        if (model.index(row, LightTableModel::NameColumn).data(Qt::EditRole).toString() != l.name)
            return false;
        if (model.index(row, LightTableModel::IntensityColumn).data(Qt::EditRole).toDouble() != l.intensity)
            return false;
        const bool on =
            model.index(row, LightTableModel::OnColumn).data(Qt::CheckStateRole).toInt() == Qt::Checked;
        if (on != l.enabled) return false;
        if (model.index(row, 0).data(LightTableModel::LightIdRole).toULongLong() != doc.lightId(row))
            return false;
    }
    return true;
}

} // namespace

class TestLoad : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // lights: the rig's size; tester: attach QAbstractItemModelTester (it re-checks the whole model on each
    // reset, so it runs on a smaller rig to keep the test fast; the full-size run checks the data instead).
    void mixedSteps(int lights, int kSteps, bool tester) {
        Document doc;
        doc.newRig(lrtest::pointRig(lights));
        LightTableModel model(&doc);
        std::unique_ptr<QAbstractItemModelTester> check;
        if (tester)
            check = std::make_unique<QAbstractItemModelTester>(
                &model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        const int maxLights = lights + 64;
        doc.undoStack()->setUndoLimit(0);
        const QByteArray start = bytes(doc);
        QElapsedTimer timer;
        timer.start();
        int refused = 0;
        for (int i = 0; i < kSteps; ++i) {
            const int n = doc.lightCount();
            const int row = (i * 7919) % n;
            QString error;
            bool ok = false;
            switch (i % 10) {
            case 0:
                ok = doc.renameLight(row, QStringLiteral("renamed %1").arg(i), &error);
                break;
            case 1:
                ok = doc.setLightsEnabled({row, (row + 1) % n}, i % 4 == 1, &error);
                break;
            case 2:
                // Keep within the format's limit: add when there is room, else remove.
                ok = n < maxLights ? doc.addLight(LightType::Spot, &error) : doc.removeLights({row}, &error);
                break;
            case 3:
                ok = n > 2 ? doc.removeLights({row, (row + 5) % n}, &error) : true;
                break;
            case 4:
                ok = doc.moveLights({row, (row + 3) % n}, (row * 31) % (n + 1), &error);
                break;
            default:
                ok = doc.setLightValue({row}, LightProperty::Intensity, 1.0 + i * 1e-3, &error);
                break;
            }
            // A toggle to the state the lights already have, or a move that leaves them in place, may be
            // refused as a no-op; every other step must be taken.
            if (!ok) ++refused;
            QVERIFY2(ok || i % 10 == 1 || i % 10 == 4,
                     qPrintable(QStringLiteral("step %1: %2").arg(i).arg(error)));
        }
        const qint64 doMs = timer.restart();
        QVERIFY(doc.undoStack()->count() <= kSteps - refused); // a step with nothing to change may push none
        QVERIFY(refused < kSteps / 10);
        QVERIFY(doc.lightCount() <= maxLights);
        QVERIFY(modelMatches(model, doc));
        const QByteArray end = bytes(doc);

        doc.undoStack()->setIndex(0);
        const qint64 undoMs = timer.restart();
        QCOMPARE(bytes(doc), start);
        QVERIFY(modelMatches(model, doc));
        doc.undoStack()->setIndex(doc.undoStack()->count());
        const qint64 redoMs = timer.restart();
        QCOMPARE(bytes(doc), end);
        QVERIFY(modelMatches(model, doc));
        qInfo("%d steps on %d lights, model attached%s: do %lld ms, undo all %lld ms, redo all %lld ms",
              doc.undoStack()->count(), lights, tester ? " and tested" : "", doMs, undoMs, redoMs);
    }

    void model_followsTenThousandMixedSteps_on4096Lights() { mixedSteps(kMaxRigLights - 64, 10000, false); }
    void modelTester_mixedSteps() { mixedSteps(200, 2000, true); }

    void propertiesDock_multiEditOf1000SelectedLights_isOneStep() {
        Document doc;
        doc.newRig(lrtest::pointRig(kMaxRigLights));
        LightTableModel model(&doc); // the Lights dock's model follows the edit too
        PropertiesDock dock(&doc);
        dock.show();
        QList<int> rows;
        for (int i = 0; i < 1000; ++i)
            rows << i * 4 + 1;
        doc.setSelectedRows(rows, rows.first());
        QSignalSpy dataChanged(&model, &QAbstractItemModel::dataChanged);
        auto* intensity = dock.field(LightProperty::Intensity)->findChild<NumberEdit*>();
        QVERIFY(intensity);
        QVERIFY(intensity->isVisibleTo(&dock));
        const QByteArray before = bytes(doc);

        QElapsedTimer timer;
        timer.start();
        intensity->setFocus();
        intensity->selectAll();
        intensity->findChild<QLineEdit*>()->insert(QStringLiteral("3.25"));
        QTest::keyClick(intensity, Qt::Key_Return);
        intensity->clearFocus();
        const qint64 ms = timer.elapsed();

        QCOMPARE(doc.undoStack()->count(), 1);
        for (int i = 0; i < doc.lightCount(); ++i)
            QCOMPARE(doc.light(i).intensity, i % 4 == 1 && i < 4000 ? 3.25 : 1.0);
        QVERIFY(dataChanged.count() <= kMaxChangeRuns); // one span, not 1,000 signals
        QCOMPARE(model.index(4 * 999 + 1, LightTableModel::IntensityColumn).data(Qt::EditRole).toDouble(),
                 3.25);
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
        qInfo("1,000-light intensity edit through the Properties dock: %lld ms (one undo step)", ms);
    }

    void autosave_ofTheLargestRig_restoresExactly() {
        QTemporaryDir tmp;
        Document doc;
        doc.newRig(lrtest::pointRig(kMaxRigLights));
        QVERIFY(doc.setLightValue({0, 4095}, LightProperty::Intensity, 2.5));
        Autosave autosave(&doc, tmp.path());
        QElapsedTimer timer;
        timer.start();
        QVERIFY(autosave.saveNow());
        const qint64 ms = timer.elapsed();
        QFile copy(autosave.rigPath());
        QVERIFY(copy.copy(tmp.filePath(QStringLiteral("kept.rig.json"))));
        const RigReadResult read = readRigFile(tmp.filePath(QStringLiteral("kept.rig.json")));
        QVERIFY(read.ok());
        QCOMPARE(writeRigJson(*read.rig), bytes(doc));
        qInfo("autosave of 4096 lights (%lld bytes): %lld ms", static_cast<long long>(QFileInfo(copy).size()),
              ms);
    }
};

QTEST_MAIN(TestLoad)
#include "tst_load.moc"
