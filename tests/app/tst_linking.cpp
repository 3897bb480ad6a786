// Issue 38 in the editor's widgets: the Properties dock's Linking section shows a loaded rig's links (mixed
// for several lights, unmatched names greyed and kept) and a click edits the document as one undo step; the
// Model dock counts each mesh's lights and shadows as the rig changes; the linking matrix dialog edits
// through the same command; Alt+click's pick toggles the part under the cursor for the selected lights.
#include "app/linkingsection.h"
#include "app/linkmatrixdialog.h"
#include "app/linktools.h"
#include "app/modeldock.h"
#include "app/modeltreemodel.h"
#include "app/propertiesdock.h"
#include "app/scene.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "editor/linkmatrixmodel.h"
#include "pickingcamera.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTreeWidget>

using namespace lr;

namespace {

// Two spheres seen by test::frontCamera: "Left" at x = -3 (screen x 85), "Right" at x = 3 (screen x 115).
Model twoSpheres() {
    Model model = makeSphere(1.0, 16, 8, glm::dvec3(-3.0, 0.0, 0.0));
    Model right = makeSphere(1.0, 16, 8, glm::dvec3(3.0, 0.0, 0.0));
    // Both relative to the first model's origin.
    for (Vertex& v : right.meshes[0].vertices)
        v.position += glm::vec3(right.origin - model.origin);
    model.meshes.push_back(right.meshes[0]);
    model.meshes[0].node = QStringLiteral("Left");
    model.meshes[0].name = QStringLiteral("left_mesh");
    model.meshes[1].node = QStringLiteral("Right");
    model.meshes[1].name = QStringLiteral("right_mesh");
    return model;
}

std::vector<PartNames> threeParts() {
    PartNames a, b, c;
    a.node = QStringLiteral("Body");
    a.mesh = QStringLiteral("body");
    a.material = QStringLiteral("Metal");
    b.node = QStringLiteral("Body");
    b.mesh = QStringLiteral("body_glass");
    b.material = QStringLiteral("Glass");
    c.node = QStringLiteral("Stand");
    c.mesh = QStringLiteral("stand");
    c.material = QStringLiteral("Metal");
    return {a, b, c};
}

// A rig file (format version 3, with links): Key lights Body only and Stand casts no shadow of it; Fill
// excludes Stand and a part this model lacks; Rim links nothing.
QString writeRig(const QTemporaryDir& dir) {
    Rig rig;
    Light key = makeLight(LightType::Spot, QStringLiteral("Key"));
    key.shadow.enabled = true;
    key.link.lit.include = {QStringLiteral("Body")};
    key.link.shadow.exclude = {QStringLiteral("Stand")};
    Light fill = makeLight(LightType::Point, QStringLiteral("Fill"));
    fill.link.lit.exclude = {QStringLiteral("Stand"), QStringLiteral("Visor")};
    rig.lights = {key, fill, makeLight(LightType::Rim, QStringLiteral("Rim"))};
    const QString path = dir.filePath(QStringLiteral("linked.json"));
    QString error;
    return saveRigFile(rig, path, &error) && writeRigJson(rig).contains("\"link\"") ? path : QString();
}

Qt::CheckState state(QTreeWidgetItem* item, int column) {
    return Qt::CheckState(item->data(column, Qt::CheckStateRole).toInt());
}

} // namespace

class TestLinking : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setApplicationName(QStringLiteral("lightrig-test-linking"));
    }

    void propertiesSection_reflectsAndEdits() {
        QTemporaryDir dir;
        Document doc;
        const QString error = doc.load(writeRig(dir));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        PropertiesDock dock(&doc);
        dock.resize(400, 900);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QVERIFY(!dock.field(LightProperty::Link)); // a section of its own, not a form row
        LinkingSection* section = dock.linking();
        section->setModelParts(threeParts());
        QCOMPARE(int(section->rows().size()), 2); // Body (two meshes) and Stand
        QVERIFY(
            section->itemOfRow(0)->toolTip(LinkingSection::PartColumn).contains(QLatin1String("body_glass")));

        doc.setSelectedRows({0}, 0); // Key
        QVERIFY(section->isVisible());
        // Highlight: only while the section is open, the parts the current light lights.
        QSignalSpy highlight(section, &LinkingSection::highlightChanged);
        QVERIFY(section->highlightedParts().empty());
        QVERIFY(section->resetButton()->isEnabled());
        section->setOpen(true);
        QCOMPARE(section->highlightedParts(), (std::vector<std::size_t>{0, 1}));
        QCOMPARE(highlight.count(), 1);
        QCOMPARE(state(section->itemOfRow(0), LinkingSection::LitColumn), Qt::Checked);
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::LitColumn), Qt::Unchecked);
        QCOMPARE(state(section->itemOfRow(0), LinkingSection::ShadowColumn), Qt::Checked);
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::ShadowColumn), Qt::Unchecked);

        // A click on Stand's Lit box: Key lights Stand too (Body and Stand are every part: no include left),
        // one undo step, and the highlight follows.
        const int steps = doc.undoStack()->index();
        section->itemOfRow(1)->setCheckState(LinkingSection::LitColumn, Qt::Checked);
        QCOMPARE(doc.undoStack()->index(), steps + 1);
        QVERIFY(doc.light(0).link.lit.isEverything());
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::LitColumn), Qt::Checked);
        QCOMPARE(section->highlightedParts(), (std::vector<std::size_t>{0, 1, 2}));
        doc.undoStack()->undo();
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::LitColumn), Qt::Unchecked);

        // Several lights: all three light Body: checked; Stand is lit by Rim alone: mixed; Key and Fill keep
        // off Stand: unchecked. Rim casts no shadow, Key's Stand shadow is off and Fill's on: mixed.
        doc.setSelectedRows({0, 1, 2}, 0);
        QCOMPARE(state(section->itemOfRow(0), LinkingSection::LitColumn), Qt::Checked);
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::LitColumn), Qt::PartiallyChecked);
        doc.setSelectedRows({0, 1}, 0);
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::LitColumn), Qt::Unchecked);
        doc.setSelectedRows({0, 1, 2}, 0);
        QCOMPARE(state(section->itemOfRow(1), LinkingSection::ShadowColumn), Qt::PartiallyChecked);
        // Fill's "Visor" matches nothing here: listed, greyed, with its list.
        QTreeWidgetItem* visor = section->itemOfUnmatched(QStringLiteral("Visor"));
        QVERIFY(visor);
        QCOMPARE(visor->text(LinkingSection::LitColumn), QStringLiteral("exclude"));
        QVERIFY(visor->toolTip(LinkingSection::PartColumn).contains(QLatin1String("matches no part")));
        QVERIFY(!(visor->flags() & Qt::ItemIsUserCheckable));
        // Clicking the mixed box casts for all (Rim is skipped: it has no shadow): one step.
        const QByteArray beforeBytes = writeRigJson(doc.rig());
        const int before = doc.undoStack()->index();
        section->itemOfRow(1)->setCheckState(LinkingSection::ShadowColumn, Qt::Checked);
        QCOMPARE(doc.undoStack()->index(), before + 1);
        QVERIFY(doc.light(0).link.shadow.isEverything());
        QVERIFY(doc.light(2).link.isDefault());
        // Unmatched names survive edits of other rows.
        section->itemOfRow(0)->setCheckState(LinkingSection::LitColumn, Qt::Unchecked);
        QCOMPARE(doc.undoStack()->index(), before + 2);
        QVERIFY(doc.light(1).link.lit.exclude.contains(QStringLiteral("Visor")));
        QVERIFY(section->itemOfUnmatched(QStringLiteral("Visor")));
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(writeRigJson(doc.rig()), beforeBytes);

        // Reset linking: every selected light to the default, one step; the unmatched row goes with it.
        QVERIFY(section->resetButton()->isEnabled());
        QTest::mouseClick(section->resetButton(), Qt::LeftButton);
        QCOMPARE(doc.undoStack()->index(), before + 1);
        for (int r = 0; r < 3; ++r)
            QVERIFY(doc.light(r).link.isDefault());
        QVERIFY(!section->itemOfUnmatched(QStringLiteral("Visor")));
        QVERIFY(!section->resetButton()->isEnabled());
        doc.undoStack()->undo();
        QVERIFY(section->itemOfUnmatched(QStringLiteral("Visor")));

        // The ground's row while the ground is on.
        QVERIFY(doc.setRigValue(RigProperty::GroundMode, QVariant::fromValue(GroundMode::Catcher)));
        QCOMPARE(int(section->rows().size()), 3);
        QVERIFY(section->rows().back().ground);
        QCOMPARE(int(section->parts().size()), 4);

        // Nothing selected: the section goes with the fields.
        doc.setSelectedRows({});
        QVERIFY(!section->isVisible());
        QVERIFY(section->highlightedParts().empty());
    }

    void modelTree_countsLinkedLights() {
        auto model = std::make_shared<Model>(twoSpheres());
        ModelTreeModel tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        tree.setModel(model);
        Document doc;
        Rig rig;
        Light key = makeLight(LightType::Spot, QStringLiteral("Key"));
        key.shadow.enabled = true;
        Light fill = makeLight(LightType::Point, QStringLiteral("Fill"));
        rig.lights = {key, fill};
        doc.newRig(rig);
        tree.setLights(doc.rig().lights);
        QCOMPARE(tree.linkIndex(0, false).data().toString(), QStringLiteral("2 of 2 lights"));
        QCOMPARE(tree.linkIndex(1, true).data().toString(), QStringLiteral("1 of 1 shadow"));
        QCOMPARE(tree.linkIndex(0, false, ModelTreeModel::NameColumn).data().toString(),
                 QStringLiteral("lit by"));
        // Key keeps off Right: Right is lit by Fill alone; its tooltip names it. In place, not a reset.
        QSignalSpy changed(&tree, &QAbstractItemModel::dataChanged);
        QSignalSpy reset(&tree, &QAbstractItemModel::modelReset);
        LightLink link;
        link.lit.exclude = {QStringLiteral("Right")};
        link.shadow.include = {QStringLiteral("Left")};
        QVERIFY(doc.setLightValue({0}, LightProperty::Link, QVariant::fromValue(link)));
        tree.setLights(doc.rig().lights);
        QCOMPARE(tree.linkIndex(1, false).data().toString(), QStringLiteral("1 of 2 lights"));
        QCOMPARE(tree.linkIndex(1, false).data(Qt::ToolTipRole).toString(), QStringLiteral("Lit by: Fill"));
        QCOMPARE(tree.linkIndex(0, false).data().toString(), QStringLiteral("2 of 2 lights"));
        QCOMPARE(tree.linkIndex(1, true).data().toString(), QStringLiteral("0 of 1 shadow"));
        QCOMPARE(tree.linkIndex(0, true).data(Qt::ToolTipRole).toString(),
                 QStringLiteral("Casts the shadow of: Key"));
        QCOMPARE(changed.count(), 2); // Right's two rows
        QCOMPARE(reset.count(), 0);
        // A light switched off reaches nothing.
        QVERIFY(doc.setLightsEnabled({1}, false));
        tree.setLights(doc.rig().lights);
        QCOMPARE(tree.linkIndex(1, false).data().toString(), QStringLiteral("0 of 1 light"));
        // The dock follows the document by itself, undo included.
        Scene scene;
        scene.setModel(model, QString());
        ModelDock dock;
        dock.setScene(&scene);
        dock.setDocument(&doc);
        QCOMPARE(dock.treeModel()->linkIndex(1, false).data().toString(), QStringLiteral("0 of 1 light"));
        doc.undoStack()->undo();
        QCOMPARE(dock.treeModel()->linkIndex(1, false).data().toString(), QStringLiteral("1 of 2 lights"));
        doc.undoStack()->undo();
        QCOMPARE(dock.treeModel()->linkIndex(1, false).data().toString(), QStringLiteral("2 of 2 lights"));
    }

    void matrixDialog_editsThroughOneStep() {
        Document doc;
        Rig rig;
        rig.lights = {makeLight(LightType::Spot, QStringLiteral("Key")),
                      makeLight(LightType::Rim, QStringLiteral("Rim"))};
        doc.newRig(rig);
        LinkMatrixDialog dialog(&doc);
        dialog.setModelParts(threeParts());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        LinkMatrixModel* m = dialog.matrix();
        QCOMPARE(dialog.view()->model(), m);
        QCOMPARE(m->rowCount(), 2);
        QCOMPARE(m->columnCount(), 2);
        // A click in the Rim × Stand cell's box (Lit mode): Rim keeps off Stand, one step.
        const QRect cell = dialog.view()->visualRect(m->index(1, 1));
        QVERIFY(cell.isValid());
        const int steps = doc.undoStack()->index();
        QStyleOptionViewItem option;
        option.initFrom(dialog.view());
        option.rect = cell;
        option.features = QStyleOptionViewItem::HasCheckIndicator | QStyleOptionViewItem::HasDisplay;
        const QRect box = dialog.view()->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator,
                                                                 &option, dialog.view());
        QTest::mouseClick(dialog.view()->viewport(), Qt::LeftButton, {}, box.center());
        QCOMPARE(doc.undoStack()->index(), steps + 1);
        QCOMPARE(doc.light(1).link.lit.exclude, QStringList{"Stand"});
        QCOMPARE(m->index(1, 1).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        // Shadow mode: the rim light's cells have no box.
        dialog.shadowButton()->click();
        QCOMPARE(m->mode(), LinkKind::Shadow);
        QVERIFY(!m->index(1, 0).data(Qt::CheckStateRole).isValid());
        QCOMPARE(m->index(0, 0).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
    }

    void altClickPick_togglesThePart() {
        const Model model = twoSpheres();
        const ScreenProjector camera = test::frontCamera();
        Document doc;
        Rig rig;
        rig.lights = {makeLight(LightType::Spot, QStringLiteral("Key")),
                      makeLight(LightType::Point, QStringLiteral("Fill"))};
        doc.newRig(rig);
        QString message;
        // Nothing selected: says so, changes nothing.
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(115, 50), &message), LinkPick::NothingSelected);
        QCOMPARE(doc.undoStack()->index(), 0);
        // The background: nothing.
        doc.setSelectedRows({0, 1});
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(100, 50), &message), LinkPick::Missed);
        // Right, under x = 115: both lights keep off it, one step; again: both light it.
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(115, 50), &message), LinkPick::Unlinked);
        QCOMPARE(doc.undoStack()->index(), 1);
        QVERIFY2(message.contains(QLatin1String("Right")), qPrintable(message));
        for (int r = 0; r < 2; ++r)
            QCOMPARE(doc.light(r).link.lit.exclude, QStringList{"Right"});
        QVERIFY(doc.light(0).link.shadow.isEverything());
        // Left is a different part.
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(85, 50), &message), LinkPick::Unlinked);
        QCOMPARE(doc.light(0).link.lit.exclude, (QStringList{"Right", "Left"}));
        doc.undoStack()->undo();
        // Mixed (Key lights Right again, Fill does not): the click links it for all.
        doc.setSelectedRows({0});
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(115, 50), &message), LinkPick::Linked);
        doc.setSelectedRows({0, 1});
        QCOMPARE(toggleLitPartAt(&doc, model, camera, QPointF(115, 50), &message), LinkPick::Linked);
        QVERIFY(doc.light(0).link.isDefault() && doc.light(1).link.isDefault());
    }
};

QTEST_MAIN(TestLinking)
#include "tst_linking.moc"
