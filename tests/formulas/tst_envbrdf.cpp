// The split-sum environment BRDF (src/core/envbrdf.h): the lookup table the renderer shades environments
// with, checked against what it must be (a mirror at normal incidence reflects everything; the specular
// lobe never reflects more than arrives, A + B <= 1; the diffuse weight W <= 1 and falls towards grazing)
// and against an independent brute-force quadrature of the same integrals at a few points.
#include "core/envbrdf.h"

#include <QFile>
#include <QTest>
#include <cmath>
#include <cstdio>

using namespace lr;

namespace {

// The generated source of src/core/envbrdf_table.cpp: hex floats, so the file holds the floats exactly.
bool writeTable(const QString& path, const std::vector<glm::vec3>& lut) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) return false;
    QByteArray text =
        "// The split-sum table the renderer uploads (envbrdf.h dfgTable): dfgLut(kDfgTableSize) with its "
        "default\n// 1024 samples, precomputed so that no frame waits for it (computing it took 0.2-0.6 s of "
        "the first frame\n// with an environment). Generated; formulas_envbrdf checks it is still exactly "
        "what "
        "dfgLut computes and,\n// with LIGHTRIG_WRITE_DFG_TABLE=PATH, writes this file anew. (A, B, W) per "
        "texel, row-major.\n#include \"envbrdf.h\"\n\nnamespace lr::envbrdf {\n\nnamespace {\n// "
        "clang-format off\nconst float kTable[kDfgTableSize * kDfgTableSize * 3] = {\n";
    char line[160];
    for (const glm::vec3& t : lut) {
        std::snprintf(line, sizeof line, "    %af, %af, %af,\n", double(t.x), double(t.y), double(t.z));
        text += line;
    }
    text += "};\n// clang-format on\n} // namespace\n\nconst float* dfgTable() {\n    return kTable;\n}\n\n} "
            "// namespace lr::envbrdf\n";
    return f.write(text) == text.size();
}

} // namespace

class TestEnvBrdf : public QObject {
    Q_OBJECT
  private slots:
    void mirrorAtNormalIncidence() {
        // Roughness 0 (clamped to the shaders' minimum 0.0525), n·v = 1: F = F0 exactly (v·h = 1, w = 0)
        // and the GGX lobe integrates to 1, so A = 1 and B = 0.
        const envbrdf::Dfg d = envbrdf::integrate(1.0, 0.0, 4096);
        QVERIFY2(std::abs(d.scale - 1.0) < 2e-3, qPrintable(QString::number(d.scale)));
        QVERIFY2(d.bias < 1e-4, qPrintable(QString::number(d.bias)));
        QVERIFY(d.diffuse > 0.999 && d.diffuse <= 1.0);
    }

    void tableIsBoundedAndFinite() {
        const int size = 32;
        const auto lut = envbrdf::dfgLut(size, 512);
        QCOMPARE(int(lut.size()), size * size);
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                const glm::vec3 t = lut[size_t(j * size + i)];
                QVERIFY(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
                QVERIFY(t.x >= 0.0f && t.y >= 0.0f && t.z > 0.0f);
                // F = 1 (A + B) is the lobe's directional albedo: at most 1 (energy is lost, never made).
                QVERIFY2(t.x + t.y <= 1.0f + 2e-3f,
                         qPrintable(
                             QStringLiteral("A + B = %1 at (%2, %3)").arg(double(t.x + t.y)).arg(i).arg(j)));
                QVERIFY(t.z <= 1.0f);
                // W does not depend on the roughness (v·h is fixed by l and v).
                if (j > 0) QVERIFY(std::abs(t.z - lut[size_t((j - 1) * size + i)].z) < 2e-3f);
            }
        // Texel (i, j) is the integral at its centre.
        const envbrdf::Dfg d = envbrdf::integrate((5 + 0.5) / size, (20 + 0.5) / size, 512);
        QCOMPARE(lut[size_t(20 * size + 5)].x, float(d.scale));
        QCOMPARE(lut[size_t(20 * size + 5)].y, float(d.bias));
        // Fresnel grows towards grazing: B rises and W falls as n·v -> 0 (roughness 0.5).
        QVERIFY(lut[size_t(16 * size)].y > lut[size_t(16 * size + size - 1)].y + 0.05f);
        QVERIFY(lut[size_t(16 * size)].z < lut[size_t(16 * size + size - 1)].z - 0.01f);
    }

    // The table the renderer uploads is the one dfgLut computes (within float rounding of the same
    // arithmetic). LIGHTRIG_WRITE_DFG_TABLE=PATH writes src/core/envbrdf_table.cpp anew from dfgLut.
    void precomputedTableIsCurrent() {
        const auto lut = envbrdf::dfgLut(envbrdf::kDfgTableSize);
        const QString path = qEnvironmentVariable("LIGHTRIG_WRITE_DFG_TABLE");
        if (!path.isEmpty()) QVERIFY2(writeTable(path, lut), qPrintable(path));
        const float* table = envbrdf::dfgTable();
        for (size_t i = 0; i < lut.size(); ++i)
            for (int c = 0; c < 3; ++c)
                QVERIFY2(
                    std::abs(table[3 * i + size_t(c)] - lut[i][c]) <= 2e-6f,
                    qPrintable(QStringLiteral("texel %1 channel %2: table %3, dfgLut %4 (regenerate with "
                                              "LIGHTRIG_WRITE_DFG_TABLE=src/core/envbrdf_table.cpp)")
                                   .arg(i)
                                   .arg(c)
                                   .arg(double(table[3 * i + size_t(c)]))
                                   .arg(double(lut[i][c]))));
    }

    void matchesQuadrature_data() {
        QTest::addColumn<double>("nDotV");
        QTest::addColumn<double>("roughness");
        for (double r : {0.25, 0.5, 0.75, 1.0})
            for (double nv : {0.1, 0.5, 0.9})
                QTest::addRow("r%g nv%g", r, nv) << nv << r;
    }
    void matchesQuadrature() {
        QFETCH(double, nDotV);
        QFETCH(double, roughness);
        const envbrdf::Dfg s = envbrdf::integrate(nDotV, roughness, 4096);
        const envbrdf::Dfg q = envbrdf::quadrature(nDotV, roughness, 300);
        const double tol = 2e-3; // visible-normal sampling converges at grazing angles too
        QVERIFY2(std::abs(s.scale - q.scale) < tol,
                 qPrintable(QStringLiteral("A %1 vs %2").arg(s.scale).arg(q.scale)));
        QVERIFY2(std::abs(s.bias - q.bias) < tol,
                 qPrintable(QStringLiteral("B %1 vs %2").arg(s.bias).arg(q.bias)));
        QVERIFY2(std::abs(s.diffuse - q.diffuse) < 2e-3,
                 qPrintable(QStringLiteral("W %1 vs %2").arg(s.diffuse).arg(q.diffuse)));
    }
};

QTEST_APPLESS_MAIN(TestEnvBrdf)
#include "tst_envbrdf.moc"
