// The double reference's light-group split (issue 37; render/referencelayers.h): in the same evaluation as
// its radiance, each covered pixel's radiance per group — lights with their traced shadows, an area light's
// Monte Carlo direct terms, the environment's integral, the scene ambient, the emission — summing to the
// radiance to double rounding; a group scaled equals the reference of the rig with those lights scaled; the
// exact tier's raster groups agree with the reference's group by group.
#include "glfixture.h"
#include "layerscenes.h"

#include "render/offscreen.h"
#include "render/rasterlayers.h"
#include "render/referencelayers.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

namespace {

const QSize kReferenceSize(48, 36);

class TestReferenceLayers : public QObject {
    Q_OBJECT

    std::unique_ptr<OffscreenRenderer> m_gl;

    struct Reference {
        RenderLayers layers;
        ReferenceImage image;
    };

    std::optional<Reference> reference(const Rig& rig, QSize size = kReferenceSize) {
        m_gl->setRig(rig);
        const RenderSettings s = layerSettings(Quality::Exact, 0);
        GBuffer g;
        QString error;
        if (!m_gl->renderGBuffer(groundCamera(), size, s, &g, &error))
            return qWarning("%s", qPrintable(error)), std::nullopt;
        Reference r;
        const glm::dmat4 view = m_gl->renderer().effectiveCamera(groundCamera()).view();
        std::optional<RenderLayers> layers =
            computeReferenceLayers(m_gl->renderer().scene(), g, view, s, &error, &r.image);
        if (!layers) return qWarning("%s", qPrintable(error)), std::nullopt;
        r.layers = std::move(*layers);
        return r;
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        QVERIFY2(m_gl->initialize(&error), qPrintable(error));
        QVERIFY2(m_gl->setModel(emittingSphere(), &error), qPrintable(error));
        m_gl->renderer().setEnvironment(layerEnvironment());
    }

    void groupsSumToRadiance_data() {
        QTest::addColumn<int>("shading");
        QTest::newRow("classic") << int(ShadingModel::Classic);
        QTest::newRow("pbr") << int(ShadingModel::Pbr);
    }
    void groupsSumToRadiance() {
        QFETCH(int, shading);
        const std::optional<Reference> r = reference(layerRig(ShadingModel(shading), true, true));
        QVERIFY(r);
        const ReferenceImage& image = r->image;
        QCOMPARE(groupNames(r->layers.groups),
                 QStringList({"key", "fill", "sun", "rim", "softbox", "environment", "emissive", "ambient",
                              "background"}));
        QVERIFY(image.casters == 3 && image.environment && image.area); // every kind of term is split
        const size_t n = r->layers.groups.size();
        QCOMPARE(image.groupCount, int(n));
        double worst = 0.0, peak = 0.0;
        std::vector<double> groupPeak(n, 0.0);
        for (size_t i = 0; i < image.radiance.size(); ++i) {
            glm::dvec3 sum(0.0);
            for (size_t g = 0; g < n; ++g) {
                const glm::dvec3 v = image.groupRadiance[i * n + g];
                sum += v;
                groupPeak[g] = std::max({groupPeak[g], v.r, v.g, v.b});
            }
            for (int c = 0; c < 3; ++c) {
                peak = std::max(peak, image.radiance[i][c]);
                worst = std::max(worst, std::abs(sum[c] - image.radiance[i][c]));
            }
        }
        qInfo("Σ groups − radiance: %.3g of the brightest channel (double)", worst / peak);
        QVERIFY2(worst <= 1e-13 * peak, qPrintable(QString::number(worst / peak)));
        for (size_t g = 0; g < n; ++g) {
            const bool background = r->layers.groups[g].kind == LightGroupKind::Background;
            QVERIFY2(background ? groupPeak[g] == 0.0 : groupPeak[g] > 1e-3,
                     qPrintable(r->layers.groups[g].name));
        }
        // The float layers: the same to float rounding.
        QVERIFY2(groupSumError(r->layers) <= 1e-6, qPrintable(QString::number(groupSumError(r->layers))));
        QCOMPARE(r->layers.albedo.width, kReferenceSize.width());
    }

    // Without Monte Carlo terms (no area light, no environment) the reference is deterministic: a group ×k
    // is the reference of the rig with its lights ×k, to the float layers' rounding.
    void scaledGroupEqualsScaledLights() {
        const Rig rig = layerRig(ShadingModel::Pbr, false);
        const std::optional<Reference> r = reference(rig);
        QVERIFY(r);
        for (const char* group : {"key", "fill"}) {
            const double k = 0.37;
            LightMix mix;
            mix.groups[QString::fromLatin1(group)].ev = std::log2(k);
            Rig scaled = rig;
            for (int i :
                 r->layers.groups[size_t(groupIndex(r->layers.groups, QString::fromLatin1(group)))].lights)
                scaled.lights[size_t(i)].intensity *= k;
            const std::optional<Reference> fresh = reference(scaled);
            QVERIFY(fresh);
            const Relative d = relativeDifference(mixGroupImages(r->layers, mix), fresh->layers.beauty);
            QVERIFY2(d.bright > 100 && d.mean <= 1e-6 && d.max <= 1e-6,
                     qPrintable(QStringLiteral("%1: mean %2, max %3").arg(group).arg(d.mean).arg(d.max)));
        }
    }

    // The exact tier's groups against the reference's, group by group (no shadows: the maps are the
    // raster's approximation; no environment: its prefiltering is), as tst_renderaccuracy compares the
    // whole image.
    void rasterGroupsMatchReferenceGroups() {
        Rig rig = layerRig(ShadingModel::Classic, false);
        for (Light& l : rig.lights)
            l.shadow.enabled = false;
        const std::optional<Reference> r = reference(rig);
        QVERIFY(r);
        QString error;
        const std::optional<RenderLayers> raster = renderRasterLayers(
            *m_gl, groundCamera(), kReferenceSize, layerSettings(Quality::Exact, 0), &error);
        QVERIFY2(raster, qPrintable(error));
        QCOMPARE(groupNames(raster->groups), groupNames(r->layers.groups));
        for (size_t g = 0; g < raster->groups.size(); ++g) {
            if (raster->groups[g].kind == LightGroupKind::Background) continue;
            const Relative d = relativeDifference(raster->groupImages[g], r->layers.groupImages[g]);
            qInfo("%s: raster against reference: mean %.3g, max %.3g", qPrintable(raster->groups[g].name),
                  d.mean, d.max);
            QVERIFY2(d.mean <= 1e-4 && d.max <= 1e-3, qPrintable(QStringLiteral("%1: mean %2, max %3")
                                                                     .arg(raster->groups[g].name)
                                                                     .arg(d.mean)
                                                                     .arg(d.max)));
        }
    }
};

} // namespace

LR_GL_TEST_MAIN(TestReferenceLayers)
#include "tst_referencelayers.moc"
