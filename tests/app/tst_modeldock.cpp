// Issue 13 in the editor's docks: the Model dock (ModelTreeModel under QAbstractItemModelTester: every value
// of a material, its textures and transforms, the warnings in full, following model reloads, copyable), the
// Render settings dock's Shading switch (one undo step, the classic-only controls disabled under PBR, saved
// and read back), and the Presets dock's shading badges.
#include "app/modeldock.h"
#include "app/modeltreemodel.h"
#include "app/presetsdock.h"
#include "app/presetstore.h"
#include "app/rendersettingsdock.h"
#include "app/scene.h"
#include "app/viewsettings.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "model/modelloader.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QFileInfo>
#include <QListWidget>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>

using namespace lr;

namespace {
const QString kWarningA = QStringLiteral(
    "spider.fbx: texture 'Spinnen_Bein_tex_COLOR_.jpg' not found (looked in /models/spider/textures and "
    "/models/spider); the part using it is drawn untextured");
const QString kWarningB = QStringLiteral("spider.fbx: 12 degenerate triangles dropped");

QImage image(int w, int h) {
    QImage i(w, h, QImage::Format_RGBA8888);
    i.fill(Qt::gray);
    return i;
}

// A sphere with one fully specified physically based material, a classic one, two textures and warnings.
std::shared_ptr<Model> detailedModel() {
    auto model = std::make_shared<Model>(makeSphere(1.0, 8, 6));
    model->meshes[0].name = QStringLiteral("Body");
    model->textures = {{QStringLiteral("albedo.png"), image(4, 2)}, {QStringLiteral("*1"), image(8, 8)}};
    Material m;
    m.name = QStringLiteral("painted metal");
    m.pbr = true;
    m.baseColor = glm::vec4(0.25f, 0.5f, 0.75f, 0.5f);
    m.metallic = 0.8f;
    m.roughness = 0.3f;
    m.baseColorTexture = 0;
    m.metallicRoughnessTexture = 1;
    m.occlusionTexture = 1;
    m.occlusionStrength = 0.7f;
    m.normalScale = 0.5f;
    m.emissive = glm::vec3(0.1f, 0.2f, 0.3f);
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.4f;
    m.doubleSided = true;
    m.baseColorTransform.offset = glm::vec2(0.5f, 0.0f);
    m.baseColorTransform.scale = glm::vec2(2.0f, 2.0f);
    m.metallicRoughnessSampling = {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, true};
    m.extensions = {
        {QStringLiteral("KHR_materials_clearcoat"), QStringLiteral("{\"clearcoatFactor\":1}")},
        {QStringLiteral("KHR_materials_emissive_strength"), QStringLiteral("{\"emissiveStrength\":4}")}};
    Material classic;
    classic.name = QStringLiteral("old plastic");
    classic.shininess = 40.0f;
    model->materials = {m, classic};
    model->meshes[0].material = 0;
    model->warnings = {kWarningA, kWarningB};
    return model;
}

// name -> value of the rows under `parent`.
QHash<QString, QString> rows(const QAbstractItemModel& m, const QModelIndex& parent) {
    QHash<QString, QString> out;
    for (int r = 0; r < m.rowCount(parent); ++r)
        out.insert(m.index(r, 0, parent).data().toString(), m.index(r, 1, parent).data().toString());
    return out;
}
} // namespace

class TestModelDock : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setApplicationName(QStringLiteral("lightrig-test-modeldock"));
        QSettings().clear();
    }

    void treeModel_showsEveryValue() {
        ModelTreeModel tree;
        QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(tree.rowCount(), 4);
        for (int b = 0; b < 4; ++b)
            QCOMPARE(tree.rowCount(tree.branchIndex(ModelTreeModel::Branch(b))), 0);
        tree.setModel(detailedModel());
        QCOMPARE(tree.index(0, 0).data().toString(), QStringLiteral("Meshes"));
        QCOMPARE(tree.index(3, 0).data().toString(), QStringLiteral("Warnings"));
        QCOMPARE(tree.index(3, 1).data().toString(), QStringLiteral("2"));

        const QModelIndex meshes = tree.branchIndex(ModelTreeModel::Meshes);
        QCOMPARE(tree.rowCount(meshes), 1);
        const QString mesh = tree.index(0, 1, meshes).data().toString();
        QCOMPARE(tree.index(0, 0, meshes).data().toString(), QStringLiteral("Body"));
        const Model& model = *tree.model();
        QVERIFY2(mesh.contains(QStringLiteral("%1 triangles").arg(model.triangleCount())) &&
                     mesh.contains(QStringLiteral("%1 vertices").arg(model.vertexCount())) &&
                     mesh.contains(QStringLiteral("painted metal")),
                 qPrintable(mesh));

        const QModelIndex materials = tree.branchIndex(ModelTreeModel::Materials);
        QCOMPARE(tree.rowCount(materials), 2);
        const QModelIndex metal = tree.index(0, 0, materials);
        QCOMPARE(metal.data().toString(), QStringLiteral("painted metal"));
        const auto v = rows(tree, metal);
        QCOMPARE(v.value(QStringLiteral("physically based values")), QStringLiteral("from the file"));
        QCOMPARE(v.value(QStringLiteral("base colour")), QStringLiteral("0.25, 0.5, 0.75; alpha 0.5"));
        QCOMPARE(v.value(QStringLiteral("metallic")), QStringLiteral("0.8"));
        QCOMPARE(v.value(QStringLiteral("roughness")), QStringLiteral("0.3"));
        QCOMPARE(v.value(QStringLiteral("occlusion strength")), QStringLiteral("0.7"));
        QCOMPARE(v.value(QStringLiteral("normal scale")), QStringLiteral("0.5"));
        QCOMPARE(v.value(QStringLiteral("emissive")), QStringLiteral("0.1, 0.2, 0.3"));
        QCOMPARE(v.value(QStringLiteral("alpha mode")), QStringLiteral("mask, cutoff 0.4"));
        QCOMPARE(v.value(QStringLiteral("double-sided")), QStringLiteral("yes"));
        QCOMPARE(v.value(QStringLiteral("base colour texture")), QStringLiteral("albedo.png (4×2)"));
        QCOMPARE(v.value(QStringLiteral("metallic-roughness texture")), QStringLiteral("*1 (8×8)"));
        QCOMPARE(v.value(QStringLiteral("occlusion texture")), QStringLiteral("*1 (8×8)"));
        QCOMPARE(v.value(QStringLiteral("normal texture")), QStringLiteral("none"));
        QCOMPARE(v.value(QStringLiteral("emissive texture")), QStringLiteral("none"));
        // The base colour texture's KHR_texture_transform, as a row under it; identity transforms have none.
        // The metallic-roughness texture's sampler likewise; glTF's default sampler has none.
        int extensionRows = 0;
        for (int r = 0; r < tree.rowCount(metal); ++r) {
            const QModelIndex row = tree.index(r, 0, metal);
            const QString name = row.data().toString();
            const bool base = name == QLatin1String("base colour texture");
            const bool metalRough = name == QLatin1String("metallic-roughness texture");
            if (name == QLatin1String("extensions")) {
                // Issue 42: every extension with its values; the ones not rendered are counted and say so.
                ++extensionRows;
                QCOMPARE(tree.index(r, 1, metal).data().toString(), QStringLiteral("1 not rendered"));
                QCOMPARE(tree.rowCount(row), 2);
                QCOMPARE(tree.index(0, 0, row).data().toString(), QStringLiteral("KHR_materials_clearcoat"));
                QCOMPARE(tree.index(0, 1, row).data().toString(), QStringLiteral("{\"clearcoatFactor\":1}"));
                QVERIFY(tree.index(0, 0, row)
                            .data(Qt::ToolTipRole)
                            .toString()
                            .contains(QLatin1String("Not rendered")));
                QCOMPARE(tree.index(1, 0, row).data(Qt::ToolTipRole).toString(), QStringLiteral("Rendered"));
                continue;
            }
            QCOMPARE(tree.rowCount(row), base || metalRough ? 1 : 0);
            if (base)
                QCOMPARE(tree.index(0, 1, row).data().toString(),
                         QStringLiteral("offset 0.5, 0; rotation 0°; scale 2, 2"));
            if (metalRough) {
                QCOMPARE(tree.index(0, 0, row).data().toString(), QStringLiteral("sampler"));
                QCOMPARE(tree.index(0, 1, row).data().toString(),
                         QStringLiteral("wrap S clamp-to-edge, T mirrored-repeat; magnified nearest"));
            }
        }
        QCOMPARE(extensionRows, 1);
        const auto classic = rows(tree, tree.index(1, 0, materials));
        QCOMPARE(classic.value(QStringLiteral("physically based values")),
                 QStringLiteral("converted from specular and shininess"));
        QCOMPARE(classic.value(QStringLiteral("shininess (classic)")), QStringLiteral("40"));
        QCOMPARE(classic.value(QStringLiteral("double-sided")), QStringLiteral("no"));
        QCOMPARE(classic.value(QStringLiteral("alpha mode")), QStringLiteral("opaque"));
        QVERIFY(!classic.contains(QStringLiteral("extensions"))); // none listed, no row

        const QModelIndex textures = tree.branchIndex(ModelTreeModel::Textures);
        QCOMPARE(rows(tree, textures).value(QStringLiteral("albedo.png")), QStringLiteral("4×2"));
        const QModelIndex warnings = tree.branchIndex(ModelTreeModel::Warnings);
        QCOMPARE(tree.index(0, 0, warnings).data().toString(), kWarningA); // in full
        QCOMPARE(tree.index(1, 0, warnings).data().toString(), kWarningB);

        // A bad texture index is reported, not read.
        auto broken = detailedModel();
        broken->materials[0].normalTexture = 7;
        tree.setModel(broken);
        QCOMPARE(rows(tree, tree.index(0, 0, tree.branchIndex(ModelTreeModel::Materials)))
                     .value(QStringLiteral("normal texture")),
                 QStringLiteral("missing (texture 7)"));
        tree.setModel(nullptr);
        QCOMPARE(tree.rowCount(tree.branchIndex(ModelTreeModel::Materials)), 0);
    }

    void treeModel_leavesOutAnImportersPlaceholderMaterial() {
        // Issue 41: DamagedHelmet's Model dock listed a spurious "material 1", the unnamed default material
        // Assimp adds to every glTF scene, which no mesh uses. A named material no mesh uses stays, marked.
        ModelTreeModel tree;
        auto model = detailedModel();
        model->materials.push_back(Material{}); // unnamed, unused
        tree.setModel(model);
        const QModelIndex materials = tree.branchIndex(ModelTreeModel::Materials);
        const auto listed = rows(tree, materials);
        QCOMPARE(tree.rowCount(materials), 2);
        QVERIFY(!listed.contains(QStringLiteral("material 2")));
        QCOMPARE(tree.index(int(ModelTreeModel::Materials), 1).data().toString(), QStringLiteral("2"));
        QVERIFY2(listed.value(QStringLiteral("old plastic")).contains(QLatin1String("no mesh uses it")),
                 qPrintable(listed.value(QStringLiteral("old plastic"))));
        QVERIFY(!listed.value(QStringLiteral("painted metal")).contains(QLatin1String("no mesh")));

        const QString helmet = QStringLiteral(LIGHTRIG_SHARED_MODELS
                                              "/gltf/khronos/DamagedHelmet/glTF-Binary/DamagedHelmet.glb");
        if (!QFileInfo::exists(helmet)) QSKIP("DamagedHelmet.glb is not in ../shared/models");
        const ModelLoadResult loaded = loadModel(helmet);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        tree.setModel(loaded.model);
        QStringList names;
        for (int r = 0; r < tree.rowCount(materials); ++r)
            names << tree.index(r, 0, materials).data().toString();
        QCOMPARE(names, QStringList{QStringLiteral("Material_MR")});
    }

    void dock_followsTheScene_opensOnWarnings_copies() {
        Scene scene;
        ModelDock dock;
        QAbstractItemModelTester tester(dock.treeModel(),
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        dock.setScene(&scene);
        dock.resize(600, 400);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        scene.setModel(detailedModel(), QStringLiteral("/models/spider.fbx"));
        ModelTreeModel* tree = dock.treeModel();
        const QModelIndex warnings = tree->branchIndex(ModelTreeModel::Warnings);
        QCOMPARE(tree->rowCount(warnings), 2);

        dock.view()->setCurrentIndex(tree->branchIndex(ModelTreeModel::Meshes));
        dock.view()->collapse(warnings);
        dock.showWarnings();
        QCOMPARE(dock.view()->currentIndex(), warnings);
        QVERIFY(dock.view()->isExpanded(warnings));

        // Both warnings selected and copied in full, in order.
        QItemSelectionModel* sel = dock.view()->selectionModel();
        sel->clearSelection();
        sel->select(tree->index(0, 0, warnings), QItemSelectionModel::Select | QItemSelectionModel::Rows);
        sel->select(tree->index(1, 0, warnings), QItemSelectionModel::Select | QItemSelectionModel::Rows);
        QCOMPARE(dock.selectedText(), kWarningA + QLatin1Char('\n') + kWarningB);
        QApplication::clipboard()->clear();
        dock.copyAction()->trigger();
        QCOMPARE(QApplication::clipboard()->text(), kWarningA + QLatin1Char('\n') + kWarningB);

        // A reload with other contents replaces the tree.
        auto clean = std::make_shared<Model>(makeSphere(1.0, 8, 6));
        scene.setModel(clean, QStringLiteral("/models/ball.obj"));
        QCOMPARE(tree->rowCount(tree->branchIndex(ModelTreeModel::Warnings)), 0);
        QCOMPARE(tree->rowCount(tree->branchIndex(ModelTreeModel::Materials)), int(clean->materials.size()));
    }

    void renderSettings_shadingSwitch_isOneUndoStep() {
        Document doc;
        doc.newRig(defaultRig());
        ViewSettings settings;
        RenderSettingsDock dock(&doc, &settings);
        struct {
            QComboBox *shadingModel, *specularModel, *viewerModel;
            QWidget* shininess;
        } const ui{dock.findChild<QComboBox*>(QStringLiteral("shadingModel")),
                   dock.findChild<QComboBox*>(QStringLiteral("specularModel")),
                   dock.findChild<QComboBox*>(QStringLiteral("viewerModel")),
                   dock.findChild<QWidget*>(QStringLiteral("shininess"))};
        const auto* form = &ui;
        QVERIFY(ui.shadingModel && ui.specularModel && ui.viewerModel && ui.shininess);
        QCOMPARE(form->shadingModel->count(), 2);
        QCOMPARE(form->shadingModel->currentIndex(), int(ShadingModel::Classic));
        const QList<QWidget*> classicOnly = dock.classicOnlyWidgets();
        QVERIFY(classicOnly.contains(form->specularModel) && classicOnly.contains(form->viewerModel) &&
                classicOnly.contains(form->shininess));
        const QString shininessTip = form->shininess->toolTip();
        for (QWidget* w : classicOnly)
            QVERIFY(w->isEnabled());
        const Rig before = doc.rig();

        form->shadingModel->setCurrentIndex(int(ShadingModel::Pbr));
        emit form->shadingModel->activated(int(ShadingModel::Pbr));
        QCOMPARE(int(doc.rig().shading.model), int(ShadingModel::Pbr));
        QCOMPARE(doc.undoStack()->count(), 1);
        for (QWidget* w : classicOnly) {
            QVERIFY2(!w->isEnabled(), qPrintable(w->objectName()));
            QCOMPARE(w->toolTip(), RenderSettingsDock::classicOnlyToolTip());
        }
        // The classic values are kept (switching back restores them).
        QCOMPARE(doc.rig().shading.shininess, before.shading.shininess);
        QCOMPARE(doc.rig().lights, before.lights);

        doc.undoStack()->undo();
        QVERIFY(doc.rig() == before);
        QCOMPARE(form->shadingModel->currentIndex(), int(ShadingModel::Classic));
        for (QWidget* w : classicOnly)
            QVERIFY(w->isEnabled());
        QCOMPARE(form->shininess->toolTip(), shininessTip);
        doc.undoStack()->redo();
        QCOMPARE(int(doc.rig().shading.model), int(ShadingModel::Pbr));
        QCOMPARE(form->shadingModel->currentIndex(), int(ShadingModel::Pbr));
        QVERIFY(!form->specularModel->isEnabled());

        // Saved as "shading": {"model": "pbr"} and read back physically based.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("pbr.json"));
        QCOMPARE(doc.saveAs(path), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains(R"("shading": {"model": "pbr"})"));
        Document reopened;
        RenderSettingsDock other(&reopened, &settings);
        QCOMPARE(reopened.load(path), QString());
        QCOMPARE(int(reopened.rig().shading.model), int(ShadingModel::Pbr));
        QCOMPARE(other.findChild<QComboBox*>(QStringLiteral("shadingModel"))->currentIndex(),
                 int(ShadingModel::Pbr));
        QVERIFY(!other.findChild<QWidget*>(QStringLiteral("shininess"))->isEnabled());
    }

    void presetsDock_marksEachPresetsShading() {
        QTemporaryDir dir;
        Document doc;
        PresetStore store(dir.path());
        PresetsDock dock(&doc, &store);
        int pbr = 0, classic = 0;
        for (int i = 0; i < dock.list()->count(); ++i) {
            const QListWidgetItem* item = dock.list()->item(i);
            const QString name = item->text().section(QLatin1Char('\n'), 0, 0);
            const RigReadResult r = readBuiltinPreset(name);
            QVERIFY2(r.ok(), qPrintable(name));
            const bool isPbr = r.rig->shading.model == ShadingModel::Pbr;
            QCOMPARE(item->data(PresetsDock::kShadingRole).toString(),
                     isPbr ? QStringLiteral("pbr") : QStringLiteral("classic"));
            QCOMPARE(item->text().section(QLatin1Char('\n'), 1),
                     isPbr ? QStringLiteral("PBR") : QStringLiteral("Classic"));
            (isPbr ? pbr : classic) += 1;
        }
        QVERIFY(pbr >= 3);
        QVERIFY(classic >= 9);
    }
};

QTEST_MAIN(TestModelDock)
#include "tst_modeldock.moc"
