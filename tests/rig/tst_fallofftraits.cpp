// The falloff-model traits table (core/fallofftraits.h) against the rig reader and writer, the reach test
// (culling) and the unit-of-length rescaling: every row round-trips through a file, the reader refuses a
// value beyond a field's limits and a key the model has not got, and a rescaled falloff lights every point
// as before (checked with the formulas of lighting.h, which do not read the table).
#include "core/fallofftraits.h"
#include "core/prepare.h"
#include "core/rigjson.h"
#include "core/shade.h"
#include "rigtest.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

namespace {

// A value of each field inside its limits, different for each field so that a swap would show.
double sampleValue(FalloffKey key) {
    const FalloffField& f = falloffField(key);
    return std::min(f.max, 1.5 + 2.0 * int(key));
}

// A point light with `model` and every field the model has set to its sample value.
Falloff sampleFalloff(FalloffModel model, bool withRange = true) {
    Falloff f;
    f.model = model;
    for (const FalloffField& field : kFalloffFields)
        if (falloffUses(model, field.key)) f.*field.member = sampleValue(field.key);
    if (!withRange && falloffTraitsOf(model).range == RangeRule::Optional) f.range = -1.0;
    return f;
}

QByteArray pointRig(const QByteArray& falloff) {
    return rigJson(pointWithFalloff(falloff));
}

QByteArray falloffObject(FalloffModel model, const QByteArray& members) {
    QByteArray out = R"({"model": ")" + toString(model).toLatin1() + '"';
    if (!members.isEmpty()) out += ", " + members;
    return out + '}';
}

QByteArray member(const FalloffField& field, double value) {
    return '"' + QByteArray(field.json) + "\": " + QByteArray::number(value, 'g', 17);
}

// The members of a valid falloff object of the model, all but `skip`.
QByteArray validMembers(FalloffModel model, std::optional<FalloffKey> skip = std::nullopt) {
    QByteArrayList parts;
    for (const FalloffField& field : kFalloffFields)
        if (falloffUses(model, field.key) && field.key != skip)
            parts << member(field, sampleValue(field.key));
    return parts.join(", ");
}

} // namespace

class TestFalloffTraits : public QObject {
    Q_OBJECT
  private slots:
    // Every model's light, with and without an optional range, is written with exactly the row's keys in the
    // row's order and read back as the same falloff.
    void everyRowRoundTrips() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (const bool withRange : {true, false}) {
                Rig rig;
                Light l = makeLight(LightType::Point, QStringLiteral("p"));
                l.falloff = sampleFalloff(t.model, withRange);
                rig.lights.push_back(l);
                const QByteArray text = writeRigJson(rig);
                const RigReadResult back = readRigJson(text, QStringLiteral("falloff.json"));
                LR_VERIFY_OK(back);
                LR_COMPARE(back.rig->lights[0].falloff, l.falloff);
                // The keys in the written object, in order.
                const qsizetype from = text.indexOf("\"falloff\": {");
                QVERIFY(from >= 0);
                const QByteArray object = text.mid(from, text.indexOf('}', from) - from);
                QByteArrayList expected{"model"};
                for (int k = 0; k < t.keyCount; ++k) {
                    const FalloffField& field = falloffField(t.keys[size_t(k)]);
                    if (field.key == FalloffKey::Range && !l.falloff.hasRange()) continue;
                    expected << field.json;
                }
                QByteArrayList written;
                for (qsizetype at = object.indexOf('"', 12); at >= 0;) {
                    const qsizetype end = object.indexOf('"', at + 1);
                    const QByteArray word = object.mid(at + 1, end - at - 1);
                    if (object.mid(end + 1, 1) == ":") written << word;
                    at = object.indexOf('"', end + 1);
                }
                QVERIFY2(written == expected, text.constData());
            }
        }
    }

    // A value just outside a field's limits is refused at its path, the limit itself accepted.
    void readerRefusesBeyondTheLimits() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (int k = 0; k < t.keyCount; ++k) {
                const FalloffField& field = falloffField(t.keys[size_t(k)]);
                const QString path = QStringLiteral("lights[0].falloff.%1: ").arg(QLatin1String(field.json));
                const QByteArray others = validMembers(t.model, field.key);
                const auto read = [&](double value) {
                    QByteArray members = member(field, value);
                    if (!others.isEmpty()) members += ", " + others;
                    return readRigJson(pointRig(falloffObject(t.model, members)), QStringLiteral("f.json"));
                };
                const RigReadResult atMax = read(field.max);
                LR_VERIFY_OK(atMax);
                QCOMPARE(atMax.rig->lights[0].falloff.*field.member, field.max);
                const RigReadResult above = read(field.max * 2.0);
                QVERIFY2(hasMessage(above.errors, QStringLiteral("f.json"), path),
                         qPrintable(describe(above)));
                const RigReadResult below = read(field.minExclusive ? field.min : field.min - 1.0);
                QVERIFY2(hasMessage(below.errors, QStringLiteral("f.json"), path),
                         qPrintable(describe(below)));
                if (!field.minExclusive) LR_VERIFY_OK(read(field.min));
            }
        }
    }

    // A key the model has not got is refused at its path; a required range may not be left out.
    void readerRefusesOtherKeys() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (const FalloffField& field : kFalloffFields) {
                if (falloffUses(t.model, field.key)) continue;
                QByteArray members = member(field, sampleValue(field.key));
                if (const QByteArray valid = validMembers(t.model); !valid.isEmpty()) members += ", " + valid;
                const RigReadResult r =
                    readRigJson(pointRig(falloffObject(t.model, members)), QStringLiteral("f.json"));
                QVERIFY2(hasMessage(r.errors, QStringLiteral("f.json"),
                                    QStringLiteral("lights[0].falloff.%1: ").arg(QLatin1String(field.json))),
                         qPrintable(describe(r)));
            }
            const RigReadResult noRange =
                readRigJson(pointRig(falloffObject(t.model, validMembers(t.model, FalloffKey::Range))),
                            QStringLiteral("f.json"));
            QCOMPARE(noRange.ok(), t.range != RangeRule::Required);
            if (t.range == RangeRule::Required)
                QVERIFY(hasMessage(noRange.errors, QStringLiteral("f.json"),
                                   QStringLiteral("lights[0].falloff.range: missing")));
        }
    }

    // A bounded falloff is zero at and beyond its range (lighting.h's formulas), and lightReaches culls a
    // light whose range ends short of the object; an unbounded one reaches everywhere.
    void boundedMeansZeroBeyondTheRange() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (const bool withRange : {true, false}) {
                const Falloff f = sampleFalloff(t.model, withRange);
                lighting::ShadeLight<double> sl;
                sl.falloff = f.model;
                sl.range = f.range, sl.falloffExponent = f.exponent;
                sl.constant = f.constant, sl.linear = f.linear, sl.quadratic = f.quadratic;
                const double beyond = f.hasRange() ? f.range * 1.5 : 1e3;
                QCOMPARE(falloffBounded(f), lighting::evalFalloff(sl, beyond) == 0.0);
                Rig rig;
                rig.space = RigSpace::World;
                Light l = makeLight(LightType::Point, QStringLiteral("p"));
                l.position = glm::dvec3(0.0);
                l.falloff = f;
                QCOMPARE(lightReaches(rig, SceneFrame{}, l, glm::dvec3(beyond + 1.0, 0.0, 0.0), 0.5),
                         !falloffBounded(f));
            }
        }
    }

    // scaleFalloffLengths (rig space switches, imported lights): with distances k times larger the light
    // is as bright at every point (intensity × a(d) before = intensity' × a'(k d)).
    void rescalingKeepsTheLight() {
        for (const FalloffTraits& t : kFalloffTraits) {
            for (const double k : {0.25, 4.0}) {
                const Falloff before = sampleFalloff(t.model);
                Falloff after = before;
                double intensity = 3.0;
                scaleFalloffLengths(after, intensity, k);
                const auto eval = [](const Falloff& f, double d) {
                    lighting::ShadeLight<double> sl;
                    sl.falloff = f.model;
                    sl.range = f.range, sl.falloffExponent = f.exponent;
                    sl.constant = f.constant, sl.linear = f.linear, sl.quadratic = f.quadratic;
                    return lighting::evalFalloff(sl, d);
                };
                for (const double d : {0.3, 1.0, 2.5, 4.0}) {
                    const double a = 3.0 * eval(before, d), b = intensity * eval(after, k * d);
                    QVERIFY2(std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(a)),
                             qPrintable(QStringLiteral("%1 k=%2 d=%3: %4 vs %5")
                                            .arg(toString(t.model))
                                            .arg(k)
                                            .arg(d)
                                            .arg(a)
                                            .arg(b)));
                }
            }
        }
    }

    // The messages name the models that have a key, from the table.
    void modelsWithAKey() {
        QCOMPARE(falloffModelsWith(FalloffKey::Exponent), QStringLiteral("\"range-power\""));
        for (const FalloffField& field : kFalloffFields)
            for (const FalloffTraits& t : kFalloffTraits)
                QCOMPARE(falloffModelsWith(field.key).contains(QLatin1Char('"') + toString(t.model) +
                                                               QLatin1Char('"')),
                         falloffUses(t.model, field.key));
    }
};

QTEST_GUILESS_MAIN(TestFalloffTraits)
#include "tst_fallofftraits.moc"
