// The editor's tables: the falloff rows of the light-property table read core/fallofftraits.h (limits,
// when they are shown, what a model switch fills in), and every rig property is one row of
// rigProperties(). Editing each falloff field and each rig property through the document is one undo step
// that changes what the rig says, and undo and redo give back the exact bytes.
#include "core/fallofftraits.h"
#include "editor/rigproperty.h"
#include "rigfixture.h"

#include <QSize>
#include <QTest>

using namespace lr;
using lrtest::bytes;
using lrtest::checkDoUndoRedo;

namespace {

// The light-property row that edits a falloff field (by its JSON field, "falloff.range").
const LightPropertyInfo* rowOf(const FalloffField& field) {
    const QByteArray json = "falloff." + QByteArray(field.json);
    for (const LightPropertyInfo& row : lightProperties())
        if (json == row.jsonField) return &row;
    return nullptr;
}

} // namespace

class TestTables : public QObject {
    Q_OBJECT
  private slots:
    void falloffRowsReadTheTraits() {
        for (const FalloffField& field : kFalloffFields) {
            const LightPropertyInfo* row = rowOf(field);
            QVERIFY2(row, field.json);
            QCOMPARE(row->min, field.min);
            QCOMPARE(row->max, field.max);
            QCOMPARE(row->minExclusive, field.minExclusive);
            for (const FalloffTraits& t : kFalloffTraits) {
                Light l = makeLight(LightType::Point, QStringLiteral("p"));
                l.falloff.model = t.model;
                QCOMPARE(row->isShown(l), falloffUses(t.model, field.key));
            }
            // The row refuses what the reader refuses.
            QVERIFY(!validateLightValue(row->id, field.max * 2.0).isEmpty());
            QVERIFY(!validateLightValue(row->id, field.minExclusive ? field.min : field.min - 1.0).isEmpty());
            QVERIFY(validateLightValue(row->id, field.max).isEmpty());
        }
    }

    // Switching to a model fills in what its row requires: a range where it is required, a positive term
    // where one is needed; the light is then valid.
    void modelSwitchFillsTheRule() {
        for (const FalloffTraits& from : kFalloffTraits) {
            for (const FalloffTraits& to : kFalloffTraits) {
                Light l = makeLight(LightType::Point, QStringLiteral("p"));
                l.falloff = Falloff{};
                l.falloff.model = from.model;
                l.falloff.constant = 0.0; // no positive term, no range
                const QVariant value = QVariant::fromValue(to.model);
                QVERIFY(validateLightValue(l, LightProperty::FalloffModel, value).isEmpty());
                const Light after = withLightValue(l, LightProperty::FalloffModel, value);
                QCOMPARE(after.falloff.hasRange(), to.range == RangeRule::Required);
                QCOMPARE(after.falloff.constant > 0.0, to.needsPositiveTerm);
                QVERIFY2(validateLight(after).isEmpty(), qPrintable(validateLight(after)));
                if (to.range == RangeRule::Required) {
                    Light noRange = after;
                    noRange.falloff.range = -1.0;
                    QVERIFY(!validateLight(noRange).isEmpty());
                }
            }
        }
    }

    // Every falloff field of every model that has it, edited in a document: one undo step, the light
    // says the new value, undo and redo restore the bytes, and the step is named for the field.
    void editEachFalloffField() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (int k = 0; k < t.keyCount; ++k) {
                const FalloffField& field = falloffField(t.keys[size_t(k)]);
                const LightPropertyInfo* row = rowOf(field);
                QVERIFY(row);
                Rig rig;
                Light l = makeLight(LightType::Point, QStringLiteral("p"));
                l.falloff.model = t.model;
                l.falloff.range = 5.0;
                rig.lights.push_back(l);
                Document doc;
                doc.newRig(rig);
                const double value = std::min(field.max, l.falloff.*field.member + 0.75);
                checkDoUndoRedo(doc, [&] { return doc.setLightValue({0}, row->id, value); });
                QCOMPARE(doc.rig().lights[0].falloff.*field.member, value);
                QCOMPARE(lightValue(doc.rig().lights[0], row->id).toDouble(), value);
                QVERIFY2(doc.undoStack()->undoText().contains(row->displayName()),
                         qPrintable(doc.undoStack()->undoText()));
                QVERIFY(!doc.setLightValue({0}, row->id, field.max * 2.0));
            }
        }
    }

    void rigRowsInOrder() {
        QCOMPARE(int(rigProperties().size()), kRigPropertyCount);
        for (int i = 0; i < kRigPropertyCount; ++i) {
            QCOMPARE(rigProperties()[size_t(i)].id, RigProperty(i));
            QCOMPARE(rigPropertyInfo(RigProperty(i)), &rigProperties()[size_t(i)]);
            QVERIFY(!rigPropertyName(RigProperty(i)).isEmpty());
        }
        QVERIFY(!rigPropertyInfo(RigProperty::Any));
        QVERIFY(validateRigValue(RigProperty::Any, 1).contains(QStringLiteral("not an editable")));
    }

    // Every rig property edited in a document: one undo step, the rig says the new value, undo and redo
    // restore the bytes, the step is named for the property, and a value of the wrong kind is refused.
    void editEachRigProperty() {
        Environment studio;
        studio.source = EnvironmentSource::Studio;
        const std::pair<RigProperty, QVariant> edits[] = {
            {RigProperty::Name, QStringLiteral("Renamed")},
            {RigProperty::Space, QVariant::fromValue(RigSpace::Model)},
            {RigProperty::Ambient, QVariant::fromValue(glm::dvec3(0.25, 0.5, 0.125))},
            {RigProperty::SpecularModel, QVariant::fromValue(SpecularModel::Phong)},
            {RigProperty::ViewerModel, QVariant::fromValue(ViewerModel::Infinite)},
            {RigProperty::Shininess, 17.0},
            {RigProperty::ShadingModel, QVariant::fromValue(ShadingModel::Pbr)},
            {RigProperty::GroundMode, QVariant::fromValue(GroundMode::Catcher)},
            {RigProperty::GroundColor, QVariant::fromValue(glm::dvec3(0.5, 0.25, 0.75))},
            {RigProperty::Environment, QVariant::fromValue(studio)},
        };
        QCOMPARE(int(std::size(edits)), kRigPropertyCount);
        for (const auto& [p, value] : edits) {
            Rig rig = lrtest::sampleRig();
            rig.space = RigSpace::World;
            rig.shading.specular = SpecularModel::BlinnPhong;
            rig.shading.viewer = ViewerModel::Local;
            rig.shading.model = ShadingModel::Classic;
            rig.ground.mode = GroundMode::Off;
            Document doc;
            doc.newRig(rig);
            QVERIFY2(rigValue(doc.rig(), p) != value, qPrintable(rigPropertyName(p)));
            QVERIFY2(validateRigValue(p, value).isEmpty(), qPrintable(validateRigValue(p, value)));
            checkDoUndoRedo(doc, [&] { return doc.setRigValue(p, value); });
            QVERIFY2(rigValue(doc.rig(), p) == value, qPrintable(rigPropertyName(p)));
            if (p != RigProperty::Environment) // the environment's steps name its fields
                QVERIFY2(doc.undoStack()->undoText().contains(rigPropertyName(p)),
                         qPrintable(doc.undoStack()->undoText()));
            QString error;
            QVERIFY(!doc.setRigValue(p, QVariant::fromValue(QSize(1, 2)), &error));
            QVERIFY2(!error.isEmpty(), qPrintable(rigPropertyName(p)));
        }
    }
};

QTEST_GUILESS_MAIN(TestTables)
#include "tst_tables.moc"
