// Issue 38, the editor's side of light linking: the part rows (one per node name, "node:" only where the bare
// name would name other parts), the include/exclude toggles (minimal lists; every other part keeps its
// state; names this model lacks are kept), the Link property through ChangeLightValue (one undo step over
// several lights, undo gives the exact bytes back, what the rig reader refuses is refused), and the linking
// matrix under QAbstractItemModelTester.
#include "editor/linkedit.h"
#include "editor/linkmatrixmodel.h"
#include "rigfixture.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>

using namespace lr;
using lrtest::bytes;
using lrtest::checkDoUndoRedo;

namespace {

PartNames part(const QString& node, const QString& mesh, const QString& material) {
    return PartNames::of(node, mesh, material);
}

PartNames groundPart() {
    return PartNames::theGround();
}

// Body: two meshes (metal, glass); Stand: metal; Lamp: a node named like a material of Body.
std::vector<PartNames> sampleParts(bool ground = false) {
    std::vector<PartNames> parts = {part("Body", "body_0", "Metal"), part("Body", "body_1", "Glass"),
                                    part("Stand", "stand", "Metal"), part("Glass", "lamp", "Bulb")};
    if (ground) parts.push_back(groundPart());
    return parts;
}

const LinkPartRow& rowNamed(const std::vector<LinkPartRow>& rows, const QString& label) {
    for (const LinkPartRow& r : rows)
        if (r.label == label && !r.ground) return r;
    for (const LinkPartRow& r : rows)
        if (r.label == label) return r;
    qFatal("no row %s", qPrintable(label));
}

PartSet set(QStringList include, QStringList exclude = {}) {
    return PartSet{std::move(include), std::move(exclude)};
}

} // namespace

class TestLinkEdit : public QObject {
    Q_OBJECT
  private slots:
    void rowsGroupByNode() {
        const auto parts = sampleParts(true);
        const auto rows = linkPartRows(parts);
        QCOMPARE(int(rows.size()), 4);
        QCOMPARE(rows[0].label, QStringLiteral("Body"));
        QCOMPARE(rows[0].parts, (std::vector<std::size_t>{0, 1}));
        QCOMPARE(rows[0].name, QStringLiteral("Body"));
        QVERIFY(rows[0].toolTip.contains(QLatin1String("body_1")) &&
                rows[0].toolTip.contains(QLatin1String("Glass")));
        QCOMPARE(rows[1].name, QStringLiteral("Stand"));
        // "Glass" alone would also name Body's glass mesh (its material): the node's name is prefixed.
        QCOMPARE(rows[2].label, QStringLiteral("Glass"));
        QCOMPARE(rows[2].name, QStringLiteral("node:Glass"));
        QVERIFY(rows[3].ground);
        QCOMPARE(rows[3].name, QStringLiteral("ground"));
        QCOMPARE(rows[3].parts, (std::vector<std::size_t>{4}));
    }

    void togglesMakeMinimalLists() {
        const auto parts = sampleParts(true);
        const auto rows = linkPartRows(parts);
        const LinkPartRow& body = rowNamed(rows, "Body");
        const LinkPartRow& stand = rowNamed(rows, "Stand");
        const LinkPartRow& lamp = rowNamed(rows, "Glass");
        // Off in everything: one exclusion; on again: everything.
        const PartSet noBody = withRowLinked(PartSet{}, parts, body, false);
        QCOMPARE(noBody, set({}, {"Body"}));
        QVERIFY(withRowLinked(noBody, parts, body, true).isEverything());
        QCOMPARE(withRowLinked(PartSet{}, parts, lamp, false), set({}, {"node:Glass"}));
        // On in an include-set: added to the include; off: taken out of it.
        QCOMPARE(withRowLinked(set({"Body"}), parts, stand, true), set({"Body", "Stand"}));
        QCOMPARE(withRowLinked(set({"Body", "Stand"}), parts, body, false), set({"Stand"}));
        // The last include is never removed (an empty include is everything): excluded instead.
        QCOMPARE(withRowLinked(set({"Body"}), parts, body, false), set({"Body"}, {"Body"}));
        // Already so: unchanged.
        QCOMPARE(withRowLinked(set({"Body"}), parts, body, true), set({"Body"}));
        QCOMPARE(withRowLinked(set({}, {"Stand"}), parts, stand, false), set({}, {"Stand"}));
        // An include that ends up naming every part is no include.
        const auto noGround = sampleParts(false);
        const auto rows2 = linkPartRows(noGround);
        QVERIFY(
            withRowLinked(set({"Body", "Stand"}), noGround, rowNamed(rows2, "Glass"), true).isEverything());
        // ... unless it also holds a name for another model.
        QCOMPARE(withRowLinked(set({"Body", "Stand", "Visor"}), noGround, rowNamed(rows2, "Glass"), true),
                 set({"Body", "Stand", "Visor", "node:Glass"}));
        // Part of an include by material: on covers the rest of the row; off keeps the material, excludes.
        QCOMPARE(withRowLinked(set({"material:Metal"}), parts, body, true), set({"material:Metal", "Body"}));
        QCOMPARE(withRowLinked(set({"material:Metal"}), parts, body, false),
                 set({"material:Metal"}, {"Body"}));
        // A broader exclusion is replaced by the other parts it named.
        QCOMPARE(withRowLinked(set({}, {"material:Metal"}), parts, body, true), set({}, {"Stand"}));
        // Names matching nothing here stay where they were.
        QCOMPARE(withRowLinked(set({"Visor", "Body"}), parts, body, false), set({"Visor"}));
        QCOMPARE(withRowLinked(set({}, {"Visor"}), parts, stand, false), set({}, {"Visor", "Stand"}));
        QCOMPARE(unmatchedNames(set({"Visor", "Body"}, {"node:Helmet"}), parts),
                 (QStringList{"Visor", "node:Helmet"}));
        // The ground has no other name.
        QCOMPARE(withRowLinked(PartSet{}, parts, rowNamed(rows, "ground"), false), set({}, {"ground"}));
    }

    // Whatever the starting lists, a toggle puts the row where it was asked and every other part where it
    // was, and a toggle back to the first state leaves an everything-set everything.
    void togglesKeepEveryOtherPart() {
        const auto parts = sampleParts(true);
        const auto rows = linkPartRows(parts);
        const QStringList names = {"Body",           "Stand",  "node:Glass", "Glass",
                                   "material:Metal", "ground", "Visor"};
        std::vector<PartSet> starts = {PartSet{}};
        for (const QString& a : names) {
            starts.push_back(set({a}));
            starts.push_back(set({}, {a}));
            for (const QString& b : names)
                if (a != b) {
                    starts.push_back(set({a, b}));
                    starts.push_back(set({a}, {b}));
                }
        }
        int checked = 0;
        for (const PartSet& start : starts)
            for (const LinkPartRow& row : rows)
                for (bool on : {false, true}) {
                    const PartSet after = withRowLinked(start, parts, row, on);
                    for (std::size_t p = 0; p < parts.size(); ++p) {
                        const bool inRow =
                            std::find(row.parts.begin(), row.parts.end(), p) != row.parts.end();
                        const bool want = inRow ? on : partSetContains(start, parts[p]);
                        QVERIFY2(
                            partSetContains(after, parts[p]) == want,
                            qPrintable(QStringLiteral("[%1 | %2] %3 %4: part %5")
                                           .arg(start.include.join(','), start.exclude.join(','), row.label)
                                           .arg(on)
                                           .arg(p)));
                    }
                    // Unmatched names are never dropped.
                    for (const QString& n : unmatchedNames(start, parts))
                        QVERIFY(after.include.contains(n) || after.exclude.contains(n));
                    // No list grows by more than one name for a row that a single name can say.
                    QVERIFY(after.include.size() <= start.include.size() + 1);
                    ++checked;
                }
        QVERIFY(checked > 500);
    }

    void oneUndoStepOverSeveralLights() {
        Document doc;
        doc.newRig(lrtest::pointRig(3));
        const auto parts = sampleParts();
        const auto rows = linkPartRows(parts);
        const LinkPartRow& stand = rowNamed(rows, "Stand");
        QList<LightProperty> changed;
        connect(&doc, &Document::rigChanged, this, [&](const RigChange& c) { changed << c.lightProperty; });
        checkDoUndoRedo(doc, [&] { return setRowLinked(&doc, {0, 2}, LinkKind::Lit, parts, stand, false); });
        QCOMPARE(doc.light(0).link.lit, set({}, {"Stand"}));
        QCOMPARE(doc.light(2).link.lit, set({}, {"Stand"}));
        QVERIFY(doc.light(1).link.isDefault());
        QVERIFY(doc.light(0).link.shadow.isEverything());
        QVERIFY(!changed.isEmpty());
        for (LightProperty p : std::as_const(changed))
            QCOMPARE(p, LightProperty::Link);
        disconnect(&doc, nullptr, this, nullptr);
        QCOMPARE(doc.undoStack()->text(doc.undoStack()->index() - 1),
                 QStringLiteral("Keep 2 lights off Stand"));
        // Lights that differ each get their own minimal lists, still one step.
        QString error;
        QVERIFY2(setRowLinked(&doc, {0, 1}, LinkKind::Shadow, parts, rowNamed(rows, "Body"), false, &error),
                 qPrintable(error));
        const int steps = doc.undoStack()->count();
        checkDoUndoRedo(doc, [&] {
            return setRowLinked(&doc, {0, 1, 2}, LinkKind::Lit, parts, stand, true);
        });
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        for (int r = 0; r < 3; ++r)
            QVERIFY(doc.light(r).link.lit.isEverything());
        QCOMPARE(doc.light(0).link.shadow, set({}, {"Body"}));
        // Nothing to change: no step and no error.
        QVERIFY(!setRowLinked(&doc, {0, 1, 2}, LinkKind::Lit, parts, stand, true, &error));
        QVERIFY(error.isEmpty());
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        // Two toggles are two steps, even inside a gesture that merges other edits.
        {
            ContinuousEdit gesture(&doc);
            const int index = doc.undoStack()->index();
            QVERIFY(setRowLinked(&doc, {0}, LinkKind::Lit, parts, stand, false));
            QVERIFY(setRowLinked(&doc, {0}, LinkKind::Lit, parts, rowNamed(rows, "Body"), false));
            QCOMPARE(doc.undoStack()->index(), index + 2);
        }
        checkDoUndoRedo(doc, [&] { return resetLinks(&doc, {0, 1, 2}); });
        for (int r = 0; r < 3; ++r)
            QVERIFY(doc.light(r).link.isDefault());
        QCOMPARE(doc.undoStack()->text(doc.undoStack()->index() - 1),
                 QStringLiteral("Reset the linking of 3 lights"));
    }

    void savedAndReadBack() {
        Document doc;
        doc.newRig(lrtest::pointRig(2));
        const auto parts = sampleParts(true);
        const auto rows = linkPartRows(parts);
        QVERIFY(setRowLinked(&doc, {0}, LinkKind::Lit, parts, rowNamed(rows, "Glass"), false));
        QVERIFY(setRowLinked(&doc, {1}, LinkKind::Shadow, parts, rowNamed(rows, "ground"), false));
        const QByteArray json = bytes(doc);
        const RigReadResult read = readRigJson(json, QStringLiteral("linked.json"));
        QVERIFY2(read.ok(), qPrintable(read.errors.join('\n')));
        QCOMPARE(read.rig->lights[0].link, doc.light(0).link);
        QCOMPARE(read.rig->lights[1].link, doc.light(1).link);
        QCOMPARE(writeRigJson(*read.rig), json);
    }

    void refusesWhatTheReaderRefuses() {
        Document doc;
        doc.newRig(lrtest::pointRig(2));
        const QByteArray before = bytes(doc);
        const auto refused = [&](const QVariant& v) {
            QString error;
            const bool ok = doc.setLightValue({0, 1}, LightProperty::Link, v, &error);
            return !ok && !error.isEmpty() && bytes(doc) == before;
        };
        LightLink empty;
        empty.lit.include = {QString()};
        QVERIFY(refused(QVariant::fromValue(empty)));
        LightLink twice;
        twice.shadow.exclude = {"Body", "Body"};
        QVERIFY(refused(QVariant::fromValue(twice)));
        LightLink prefixOnly;
        prefixOnly.lit.exclude = {"node:"};
        QVERIFY(refused(QVariant::fromValue(prefixOnly)));
        LightLink tooLong;
        tooLong.lit.include = {QString(kMaxRigNameLength + 1, QLatin1Char('x'))};
        QVERIFY(refused(QVariant::fromValue(tooLong)));
        QVERIFY(refused(QStringLiteral("Body")));
        QVERIFY(refused(QVariant()));
        LightLink fine;
        fine.lit.include = {"Visor"}; // names nothing here, and is kept
        QVERIFY(doc.setLightValue({0, 1}, LightProperty::Link, QVariant::fromValue(fine)));
        QCOMPARE(doc.light(1).link.lit.include, QStringList{"Visor"});
        QVERIFY(validateRig(doc.rig()).isEmpty());
    }

    void matrixModel() {
        Document doc;
        Rig rig = lrtest::sampleRig(); // L3 is a rim light: no shadow
        rig.lights[1].link.lit.include = {"Body"};
        doc.newRig(rig);
        LinkMatrixModel matrix(&doc);
        QAbstractItemModelTester tester(&matrix, QAbstractItemModelTester::FailureReportingMode::QtTest);
        matrix.setModelParts(sampleParts());
        QCOMPARE(matrix.rowCount(), doc.lightCount());
        QCOMPARE(matrix.columnCount(), 3); // Body, Stand, Glass
        QCOMPARE(matrix.headerData(0, Qt::Horizontal).toString(), QStringLiteral("Body"));
        QCOMPARE(matrix.headerData(1, Qt::Vertical).toString(), QStringLiteral("L1"));
        QCOMPARE(matrix.index(1, 0).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
        QCOMPARE(matrix.index(1, 1).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        QCOMPARE(matrix.index(0, 1).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));

        // A click on a cell: one undo step, that light only, the cell says so.
        QSignalSpy cells(&matrix, &QAbstractItemModel::dataChanged);
        checkDoUndoRedo(doc,
                        [&] { return matrix.setData(matrix.index(1, 1), Qt::Checked, Qt::CheckStateRole); });
        QCOMPARE(doc.light(1).link.lit, set({"Body", "Stand"}));
        QCOMPARE(matrix.index(1, 1).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
        QVERIFY(!cells.isEmpty());
        for (int r = 0; r < doc.lightCount(); ++r)
            if (r != 1) QVERIFY(doc.light(r).link.isDefault());

        // Shadow mode: the rim light has no box; a cell edits the shadow set.
        matrix.setMode(LinkKind::Shadow);
        QVERIFY(!matrix.index(3, 0).data(Qt::CheckStateRole).isValid());
        QVERIFY(!(matrix.flags(matrix.index(3, 0)) & Qt::ItemIsUserCheckable));
        QVERIFY(!matrix.setData(matrix.index(3, 0), Qt::Unchecked, Qt::CheckStateRole));
        checkDoUndoRedo(
            doc, [&] { return matrix.setData(matrix.index(0, 2), Qt::Unchecked, Qt::CheckStateRole); });
        QCOMPARE(doc.light(0).link.shadow, set({}, {"node:Glass"}));
        QVERIFY(doc.light(0).link.lit.isEverything());

        // Structural changes and the ground's column, under the tester.
        QVERIFY(doc.addLight(LightType::Spot));
        QCOMPARE(matrix.rowCount(), doc.lightCount());
        QVERIFY(doc.removeLights({0}));
        QCOMPARE(matrix.rowCount(), doc.lightCount());
        QVERIFY(doc.setRigValue(RigProperty::GroundMode, QVariant::fromValue(GroundMode::Visible)));
        QCOMPARE(matrix.columnCount(), 4);
        QCOMPARE(matrix.headerData(3, Qt::Horizontal).toString(), QStringLiteral("ground"));
        doc.undoStack()->undo();
        QCOMPARE(matrix.columnCount(), 3);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(matrix.rowCount(), doc.lightCount());
        doc.newRig(Rig{});
        QCOMPARE(matrix.rowCount(), 0);
    }
};

QTEST_GUILESS_MAIN(TestLinkEdit)
#include "tst_linkedit.moc"
