// The renderer's structure (issue 11): the pass chains and their declared reads and writes, the plan
// rebuilt only when the kind of frame changes, the one table of texture units, the G-buffer codec and the
// colour module. And the overlay (issue 12): the ground grid is depth-tested against the model and fades
// with distance.
#include "glfixture.h"
#include "scenes.h"

#include "core/colour.h"
#include "render/gbuffer.h"
#include "render/offscreen.h"
#include "render/renderplan.h"
#include "render/shadergen.h"
#include "render/targets.h"
#include "render/textureunits.h"

#include <QSet>
#include <QTest>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

class TestRenderPasses : public QObject {
    Q_OBJECT
    std::unique_ptr<OffscreenRenderer> m_gl;

    bool startGl() {
        if (!haveDisplay()) return false;
        if (m_gl) return true;
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
        return true;
    }

  private slots:
    void everyPlanIsConsistent() {
        RenderPlan plan;
        for (int bits = 0; bits < 16; ++bits) {
            PlanKey key;
            key.set(PlanBit::Deferred, bits & 1).set(PlanBit::Hdr, bits & 2).set(PlanBit::Msaa, bits & 4);
            key.set(PlanBit::Overlays, bits & 8);
            const bool deferred = key.has(PlanBit::Deferred), hdr = key.has(PlanBit::Hdr);
            const bool msaa = key.has(PlanBit::Msaa), overlays = key.has(PlanBit::Overlays);
            const auto& passes = plan.select(key);
            const QString where = plan.describe();
            QVERIFY2(RenderPlan::check(passes, msaa).isEmpty(),
                     qPrintable(where + ": " + RenderPlan::check(passes, msaa)));
            QCOMPARE(QString::fromLatin1(passes.front()->name()),
                     deferred ? QStringLiteral("geometry (G-buffer)") : QStringLiteral("geometry (shaded)"));
            QCOMPARE(where.contains(QLatin1String("deferred lighting")), deferred);
            QCOMPARE(where.contains(QLatin1String("tone map")), hdr);
            QCOMPARE(where.contains(QLatin1String("present")), !hdr);
            QCOMPARE(QString::fromLatin1(passes.back()->name()) == QLatin1String("overlay"), overlays);
            QCOMPARE(where.contains(QLatin1String("resolve")), msaa && (hdr || overlays));
        }
        QCOMPARE(plan.builds(), 16);
        const PlanKey twice = PlanKey().set(PlanBit::Deferred).set(PlanBit::Hdr).set(PlanBit::Overlays);
        plan.select(twice);
        plan.select(twice);
        QCOMPARE(plan.builds(), 17); // the same key twice: one build
    }

    // The tiers' approximations are named variant bits of the key (approximations.h), chosen through
    // RenderSettings, not environment variables: each compiles only into its own tier's shaders, and two
    // choices are two variants.
    void approximationsAreVariantBitsOfTheirTier() {
        FeatureKey balanced;
        balanced.quality = Quality::Balanced;
        balanced.approximations = approx::forTier(approx::kDefault, Quality::Balanced);
        const QByteArray shipped = shaderPrelude(balanced);
        QVERIFY(shipped.contains("#define LR_B1 1") && shipped.contains("#define LR_B4 1"));
        QVERIFY(!shipped.contains("LR_B3"));
        FeatureKey withB3 = balanced;
        withB3.approximations = approx::forTier(approx::kDefault | approx::kB3, Quality::Balanced);
        QVERIFY(shaderPrelude(withB3).contains("#define LR_B3 1"));
        QVERIFY(withB3.bits() != balanced.bits());
        FeatureKey exact;
        exact.approximations = approx::forTier(approx::kBalancedMask | approx::kF2, Quality::Exact);
        QCOMPARE(int(exact.approximations), 0);
        const QByteArray exactPrelude = shaderPrelude(exact);
        QVERIFY(!exactPrelude.contains("LR_B1") && !exactPrelude.contains("LR_FAST_INFINITE_VIEWER"));
        FeatureKey fast;
        fast.quality = Quality::Fast;
        fast.approximations = approx::forTier(approx::kDefault | approx::kF2, Quality::Fast);
        QCOMPARE(int(fast.approximations), int(approx::kF2));
        QVERIFY(shaderPrelude(fast).contains("#define LR_FAST_INFINITE_VIEWER 1"));
        QCOMPARE(int(RenderSettings().approximations), int(approx::kDefault));

        std::uint8_t set = 0;
        QString error;
        QVERIFY(approx::parseApproximations(QStringLiteral("B1, b3,f2"), &set, &error));
        QCOMPARE(int(set), int(approx::kB1 | approx::kB3 | approx::kF2));
        QVERIFY(approx::parseApproximations(QStringLiteral("none"), &set, &error));
        QCOMPARE(int(set), 0);
        QVERIFY(!approx::parseApproximations(QStringLiteral("b1,b9"), &set, &error));
        QVERIFY2(error.contains(QLatin1String("'b9'")), qPrintable(error));
        QCOMPARE(approx::approximationNames(approx::kDefault), QStringLiteral("b1,b2,b4"));
    }

    void checkNamesAMissingInput() {
        ToneMapPass toneMap;
        GeometryPass shaded(GeometryPass::Output::Shaded);
        OverlayPass overlay;
        // Multisampled radiance must be resolved before the tone-map pass can read it.
        const QString e = RenderPlan::check({&shaded, &toneMap}, true);
        QVERIFY2(e.contains(QLatin1String("tone map reads resolved")), qPrintable(e));
        QVERIFY(RenderPlan::check({&shaded, &toneMap}, false).isEmpty());
        QVERIFY(RenderPlan::check({&overlay}, false).contains(QLatin1String("overlay reads")));
        QVERIFY(RenderPlan::check({&shaded}, false).contains(QLatin1String("nothing writes the output")));
    }

    // The cross-pass dependencies are declared reads that check() verifies: the deferred lighting over a
    // background reads the colour the background left; a lit pass reads shadow maps only after the pass
    // that writes them, and a lit input the frame has not got (no caster, no environment) is no read.
    void crossPassDependenciesAreDeclared() {
        GeometryPass gbuffer(GeometryPass::Output::GBuffer), shaded(GeometryPass::Output::Shaded);
        DeferredLightingPass lighting;
        BackgroundPass background;
        ShadowPass shadow;
        PresentPass present;
        QVERIFY(RenderPlan::check({&gbuffer, &lighting, &present}, false).isEmpty());
        lighting.setOverBackground(true);
        const QString e = RenderPlan::check({&gbuffer, &lighting, &present}, false);
        QVERIFY2(e.contains(QLatin1String("deferred lighting reads scene-color")), qPrintable(e));
        QVERIFY(RenderPlan::check({&gbuffer, &background, &lighting, &present}, false).isEmpty());
        const QString late = RenderPlan::check({&shaded, &shadow, &present}, false);
        QVERIFY2(late.contains(QLatin1String("geometry (shaded) reads shadow-maps")), qPrintable(late));
        QVERIFY(RenderPlan::check({&shadow, &shaded, &present}, false).isEmpty());
        QVERIFY(
            RenderPlan::check({&shaded, &present}, false, resource::Lights | resource::Clusters).isEmpty());
        // The background reads the environment: without an input providing it, nothing does.
        const QString noEnvironment =
            RenderPlan::check({&gbuffer, &background, &lighting, &present}, false, resource::Lights);
        QVERIFY2(noEnvironment.isEmpty(), qPrintable(noEnvironment)); // void: no input has it this frame
        const QString noLights = RenderPlan::check({&shaded, &present}, false, 0);
        QVERIFY2(noLights.isEmpty(), qPrintable(noLights)); // a frame without lights reads none
    }

    // The G-buffer's revision is counted in one place, RenderPlan::runPass, from the declared writes: a
    // pass writing the G-buffer or the depth it shares counts one (and is the last writer) unless it kept
    // them; a pass writing neither counts none.
    void theDepthRevisionFollowsTheDeclaredWrites() {
        struct FakePass final : RenderPass {
            PassResources w = 0;
            bool keep = false;
            const char* name() const override { return "fake"; }
            PassResources reads() const override { return 0; }
            PassResources writes() const override { return w; }
            bool run(const FrameContext&, PassScene&) override { return true; }
            bool keptOutputs() const override { return keep; }
        };
        Targets targets;
        PassScene scene;
        scene.targets = &targets;
        const FrameContext frame;
        FakePass depth, colour, kept;
        depth.w = resource::GBuffer | resource::SceneDepth;
        colour.w = resource::SceneColor;
        kept.w = resource::SceneDepth;
        kept.keep = true;
        const int start = targets.gbufferRevision;
        QVERIFY(RenderPlan::runPass(depth, frame, scene));
        QCOMPARE(targets.gbufferRevision, start + 1);
        QCOMPARE(targets.gbufferWriter, static_cast<const void*>(&depth));
        RenderPlan::runPass(colour, frame, scene);
        RenderPlan::runPass(kept, frame, scene);
        QCOMPARE(targets.gbufferRevision, start + 1);
        QCOMPARE(targets.gbufferWriter, static_cast<const void*>(&depth));
        kept.keep = false;
        RenderPlan::runPass(kept, frame, scene);
        QCOMPARE(targets.gbufferRevision, start + 2);
        QCOMPARE(targets.gbufferWriter, static_cast<const void*>(&kept));
    }

    void textureUnitsAreDistinct() {
        QSet<GLuint> units;
        QSet<QByteArray> names;
        for (const SamplerBinding& b : kSamplerBindings) {
            const GLuint unit = GLuint(b.unit) + GLuint(b.offset);
            // The one shared unit (textureunits.h): the G-buffer's link target (deferred lighting programs
            // only) and the tone map's input are never sampled by one program.
            const bool shared = QByteArray(b.uniform) == "uGBufferLink" &&
                                TextureUnit::GBufferLink == TextureUnit::SceneColor;
            QVERIFY2(shared || !units.contains(unit), b.uniform);
            QVERIFY2(!names.contains(b.uniform), b.uniform);
            // GL 3.3 guarantees 16 units; only the environment's (checked at initialisation by
            // EnvironmentGl: fewer units, no environment lighting), the area lights' LTC table and the
            // lights' IES and gobo arrays (checked by ShapingInput::initialize: fewer units, unshaped) lie
            // beyond.
            QVERIFY2(
                unit < 16 ||
                    (unit >= GLuint(TextureUnit::EnvSpecular) && unit < GLuint(kEnvironmentUnitsNeeded)) ||
                    unit == GLuint(TextureUnit::Ltc) || unit == GLuint(TextureUnit::Ies) ||
                    unit == GLuint(TextureUnit::Gobos),
                b.uniform);
            units.insert(unit);
            names.insert(b.uniform);
        }
    }

    void gbufferCodecRoundTrips() {
        lighting::Surface<float> s;
        s.position = {1.5f, -2.25f, -7.0f};
        s.normal = {0.0f, 0.6f, 0.8f};
        s.albedo = {0.1f, 0.2f, 0.3f};
        s.specular = {0.4f, 0.5f, 0.6f};
        s.emissive = {0.7f, 0.8f, 0.9f};
        s.shininess = 42.0f;
        const GBufferTexels t = encodeGBuffer(s);
        const lighting::Surface<float> d = decodeGBuffer(t);
        QCOMPARE(d.position, s.position);
        QCOMPARE(d.normal, s.normal);
        QCOMPARE(d.albedo, s.albedo);
        QCOMPARE(d.specular, s.specular);
        QCOMPARE(d.emissive, s.emissive);
        QCOMPARE(d.shininess, s.shininess);
        // Classic: every channel of every target holds exactly one field. Physically based: at most one
        // (ks and shininess have no meaning there; metallic, roughness and occlusion take ks's channels).
        for (ShadingModel model : {ShadingModel::Classic, ShadingModel::Pbr}) {
            int used[kGBufferTargets][4] = {};
            for (const GBufferSlot& slot : kGBufferLayout)
                if (usedUnder(slot, model))
                    for (int c = 0; c < slot.width; ++c)
                        ++used[slot.target][slot.channel + c];
            for (const auto& target : used)
                for (int n : target)
                    QVERIFY(model == ShadingModel::Classic ? n == 1 : n <= 1);
        }
        lighting::Surface<float> p = s;
        p.metallic = 0.25f, p.roughness = 0.625f, p.occlusion = 0.5f;
        const lighting::Surface<float> pd =
            decodeGBuffer(encodeGBuffer(p, ShadingModel::Pbr), ShadingModel::Pbr);
        QCOMPARE(pd.position, p.position);
        QCOMPARE(pd.normal, p.normal);
        QCOMPARE(pd.albedo, p.albedo);
        QCOMPARE(pd.emissive, p.emissive);
        QCOMPARE(pd.metallic, p.metallic);
        QCOMPARE(pd.roughness, p.roughness);
        QCOMPARE(pd.occlusion, p.occlusion);
        // The classic encoding is the one it always was: the PBR fields do not reach it.
        QCOMPARE(encodeGBuffer(p), encodeGBuffer(s));
        // The GLSL twin is generated from the same table; the rows of one model are inside its #if.
        const QByteArray glsl = gbufferGlsl();
        for (const GBufferSlot& slot : kGBufferLayout) {
            const QByteArray line = QByteArray("s.") + slot.member;
            QVERIFY2(glsl.contains(line), slot.member);
            if (slot.use == GBufferUse::Pbr)
                QVERIFY(glsl.contains("#ifdef LR_PBR\n    g" + QByteArray::number(slot.target)));
        }
    }

    // Physically based shading is a key bit (LR_PBR) that classic keys never carry: a classic prelude
    // has no PBR define, no PBR texture or approximation define even when the material has those textures
    // or the set names B5/B6; the PBR key differs by the LR_PBR line and what hangs on it.
    void pbrIsAKeyBitClassicNeverSees() {
        Rig rig = rigOf({point({0, 0, 1}, FalloffModel::InverseSquare)});
        rig.shading.specular = SpecularModel::BlinnPhong;
        rig.shading.viewer = ViewerModel::Infinite;
        FeatureKey classic;
        classic.rig = rigFeatures(rig);
        classic.quality = Quality::Balanced;
        classic.approximations = approx::forTier(approx::kBalancedMask, Quality::Balanced);
        FeatureKey classicTextured = classic;
        classicTextured.material.metalRoughTexture = classicTextured.material.occlusionTexture = true;
        const QByteArray prelude = shaderPrelude(classic);
        for (const char* define :
             {"LR_PBR", "LR_B5", "LR_B6", "LR_METAL_ROUGH_TEXTURE", "LR_OCCLUSION_TEXTURE"}) {
            QVERIFY2(!prelude.contains(define), define);
            QVERIFY2(!shaderPrelude(classicTextured).contains(define), define);
        }
        QVERIFY(!classic.describe().contains(QLatin1String("pbr")));

        rig.shading.model = ShadingModel::Pbr;
        FeatureKey pbr = classic;
        pbr.rig = rigFeatures(rig);
        QVERIFY(pbr.rig.shading == ShadingModel::Pbr);
        // Neither the specular nor the viewer model splits PBR variants; PBR always uses the local viewer.
        QVERIFY(pbr.rig.specular == SpecularModel::Phong);
        QVERIFY(pbr.rig.viewer == ViewerModel::Local);
        QVERIFY(pbr.bits() != classic.bits());
        QVERIFY(pbr.describe().contains(QLatin1String("shading:pbr")));
        pbr.material.metalRoughTexture = pbr.material.occlusionTexture = true;
        const QByteArray p = shaderPrelude(pbr);
        for (const char* define : {"#define LR_PBR 1", "#define LR_B5 1", "#define LR_B6 1",
                                   "#define LR_METAL_ROUGH_TEXTURE 1", "#define LR_OCCLUSION_TEXTURE 1"})
            QVERIFY2(p.contains(define), define);
        // Far lights (LightSet::farLights) are a PBR key bit; a classic key never carries it.
        QVERIFY(!p.contains("LR_FAR_LIGHTS"));
        FeatureKey far = pbr;
        far.rig = frameRigFeatures(rig, true, false);
        QVERIFY(far.bits() != pbr.bits());
        QVERIFY(shaderPrelude(far).contains("#define LR_FAR_LIGHTS 1"));
        QVERIFY(!frameRigFeatures(rigOf({point({0, 0, 1}, FalloffModel::None)}), true, false).farLights);
        // The texture bits are key bits of their own.
        FeatureKey untextured = pbr;
        untextured.material = {};
        QVERIFY(untextured.bits() != pbr.bits());

        // The names of the BRDF's approximations parse.
        std::uint8_t set = 0;
        QString error;
        QVERIFY(approx::parseApproximations(QStringLiteral("b5,B6"), &set, &error));
        QCOMPARE(int(set), int(approx::kB5 | approx::kB6));
        QCOMPARE(approx::approximationNames(set), QStringLiteral("b5,b6"));
    }

    // The tone map is compiled into display-output programs (one operator's code, not all five behind a
    // run-time switch) and splits only them: radiance and G-buffer keys ignore it.
    void toneMapIsADisplayKeyBit() {
        FeatureKey display;
        display.rig = rigFeatures(rigOf({point({0, 0, 1}, FalloffModel::InverseSquare)}));
        FeatureKey agx = display;
        agx.toneMap = ToneMap::Agx;
        QVERIFY(agx.bits() != display.bits());
        QVERIFY(shaderPrelude(display).contains("#define LR_TONE_MAP LR_TONEMAP_CLAMP\n"));
        QVERIFY(shaderPrelude(agx).contains("#define LR_TONE_MAP LR_TONEMAP_AGX\n"));
        QVERIFY(agx.describe().contains(QLatin1String("tone-map:agx")));
        FeatureKey radiance = display;
        radiance.output = ShaderOutput::Radiance;
        QVERIFY(!shaderPrelude(radiance).contains("LR_TONE_MAP"));
    }

    void colourModuleIsTheOneDisplayTransform() {
        QCOMPARE(colour::exposureScale(1.0), 2.0);
        QCOMPARE(colour::exposureScale(-2.0), 0.25);
        QCOMPARE(colour::exposureScale(1000.0), std::exp2(60.0)); // clamped to ±60 EV
        const glm::dvec3 radiance(0.02, 0.3, 4.0);
        for (int i = 0; i < enumCount<ToneMap>(); ++i) {
            const ToneMap op = ToneMap(i);
            const glm::dvec3 d = colour::displayColour(radiance, 2.0, op);
            const glm::dvec3 m = colour::toneMapRgb(op, radiance * 2.0);
            for (int c = 0; c < 3; ++c) {
                QCOMPARE(d[c], colour::linearToSrgb(m[c]));
                if (op != ToneMap::Neutral && op != ToneMap::Agx) // the per-channel operators
                    QCOMPARE(m[c], colour::toneMap(op, radiance[c] * 2.0));
            }
        }
        QCOMPARE(colour::srgbToLinear(colour::linearToSrgb(0.5)), 0.5);
    }

    void planIsRebuiltOnlyWhenTheFrameKindChanges() {
        if (!startGl()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        QString error;
        QVERIFY(m_gl->setModel(sphereScene(), &error));
        m_gl->setRig(rigOf({point({0.5, 1.0, 2.0}, FalloffModel::InverseSquare)}));
        RenderSettings s;
        s.msaaSamples = 0;
        s.shadingPath = ShadingPath::Forward; // Auto would shade this one-material model deferred
        QVERIFY2(m_gl->renderFrame(sphereCamera(), QSize(64, 48), s, &error), qPrintable(error));
        const int builds = m_gl->renderer().stats().renderPlanBuilds;
        QCOMPARE(m_gl->renderer().renderPlan(), QStringLiteral("geometry (shaded) > present"));
        s.exposureEV = 1.5; // a value, not a kind of frame
        s.toneMap = ToneMap::Aces;
        QVERIFY(m_gl->renderFrame(sphereCamera(), QSize(64, 48), s, &error));
        QCOMPARE(m_gl->renderer().stats().renderPlanBuilds, builds);
        s.hdrTarget = true;
        QVERIFY(m_gl->renderFrame(sphereCamera(), QSize(64, 48), s, &error));
        QCOMPARE(m_gl->renderer().stats().renderPlanBuilds, builds + 1);
        QCOMPARE(m_gl->renderer().renderPlan(), QStringLiteral("geometry (shaded) > tone map"));
        s.shadingPath = ShadingPath::Deferred;
        s.showGrid = true;
        QVERIFY(m_gl->renderFrame(sphereCamera(), QSize(64, 48), s, &error));
        QCOMPARE(m_gl->renderer().renderPlan(),
                 QStringLiteral("geometry (G-buffer) > deferred lighting > tone map > overlay"));
    }

    // Issue 12: from above, the ground grid lies under the whole model: every pixel inside the model's
    // silhouette must be exactly what the frame without the grid has there (it showed through at 30%).
    void gridIsHiddenByTheModel_data() {
        QTest::addColumn<int>("msaa");
        QTest::addColumn<bool>("hdr");
        QTest::addColumn<int>("path");
        QTest::newRow("display") << 0 << false << int(ShadingPath::Forward);
        QTest::newRow("display-msaa") << 4 << false << int(ShadingPath::Forward);
        QTest::newRow("hdr-msaa") << 4 << true << int(ShadingPath::Forward);
        QTest::newRow("deferred") << 0 << false << int(ShadingPath::Deferred);
    }

    void gridIsHiddenByTheModel() {
        if (!startGl()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        QFETCH(int, msaa);
        QFETCH(bool, hdr);
        QFETCH(int, path);
        QString error;
        QVERIFY(m_gl->setModel(sphereScene(), &error));
        m_gl->setRig(rigOf({point({0.5, 2.0, 1.0}, FalloffModel::None)}));
        ViewCamera top;
        top.eye = {0.0, 4.0, 0.0};
        top.target = {0.0, 0.0, 0.0};
        top.up = {0.0, 0.0, -1.0};
        top.yfovDeg = 45.0;
        const QSize size(160, 120);
        RenderSettings s;
        s.msaaSamples = msaa;
        s.hdrTarget = hdr;
        s.shadingPath = ShadingPath(path);
        const QImage without = m_gl->renderImage(top, size, s, 1, &error);
        s.showGrid = true;
        const QImage with = m_gl->renderImage(top, size, s, 1, &error);
        GBuffer g;
        QVERIFY2(!without.isNull() && !with.isNull() && m_gl->renderGBuffer(top, size, s, &g, &error),
                 qPrintable(error));
        const auto covered = [&](int x, int y) {
            return x >= 0 && y >= 0 && x < size.width() && y < size.height() && g.position.at(x, y).w > 0.5f;
        };
        int inside = 0, changedInside = 0, gridOutside = 0;
        for (int y = 0; y < size.height(); ++y) {
            for (int x = 0; x < size.width(); ++x) {
                const bool changed = with.pixel(x, y) != without.pixel(x, y);
                bool interior = true; // the silhouette's edge pixels mix model and ground under MSAA
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        interior = interior && covered(x + dx, y + dy);
                if (interior) {
                    ++inside;
                    changedInside += changed;
                } else if (!covered(x, y)) {
                    gridOutside += changed;
                }
            }
        }
        QVERIFY2(inside > 2000, qPrintable(QString::number(inside)));
        QVERIFY2(gridOutside > 200, qPrintable(QString::number(gridOutside))); // the grid is drawn around it
        QCOMPARE(changedInside, 0);
    }

    // The grid fades with distance (as Blender's): seen obliquely, its far edge is much fainter than its
    // near edge (without the fade both are drawn alike).
    void gridFadesWithDistance() {
        if (!startGl()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        QString error;
        QVERIFY(m_gl->setModel(nullptr, &error)); // the grid alone: under the unit sphere's bounds
        m_gl->setRig(Rig());
        ViewCamera cam;
        cam.eye = {0.0, 1.0, 4.0};
        cam.target = {0.0, -0.577, 0.0};
        cam.yfovDeg = 45.0;
        const QSize size(200, 240);
        RenderSettings s;
        s.msaaSamples = 0;
        const QImage without = m_gl->renderImage(cam, size, s, 1, &error);
        s.showGrid = true;
        const QImage with = m_gl->renderImage(cam, size, s, 1, &error);
        QVERIFY2(!without.isNull() && !with.isNull(), qPrintable(error));
        // The rows of the grid's near (z = +1.5) and far (z = -1.5) edges.
        const ViewCamera e = m_gl->renderer().effectiveCamera(cam);
        const Bounds b = m_gl->renderer().bounds();
        const auto row = [&](double z) {
            const glm::dvec4 p = e.projection(double(size.width()) / size.height()) * e.view() *
                                 glm::dvec4(0.0, b.min.y, z, 1.0);
            return int((0.5 - 0.5 * p.y / p.w) * size.height());
        };
        const int nearRow = row(1.45), farRow = row(-1.45);
        QVERIFY2(farRow + 10 < nearRow && farRow >= 0 && nearRow < size.height(),
                 qPrintable(QStringLiteral("%1 %2").arg(farRow).arg(nearRow)));
        const auto strongest = [&](int y0, int y1) {
            int m = 0;
            for (int y = y0; y <= y1; ++y)
                for (int x = 0; x < size.width(); ++x)
                    m = std::max(m, std::abs(qGreen(with.pixel(x, y)) - qGreen(without.pixel(x, y))));
            return m;
        };
        const int nearLevels = strongest(nearRow - 4, nearRow + 2),
                  farLevels = strongest(farRow - 2, farRow + 2);
        QVERIFY2(nearLevels > 40, qPrintable(QString::number(nearLevels)));
        QVERIFY2(farLevels * 4 < nearLevels,
                 qPrintable(QStringLiteral("far %1, near %2").arg(farLevels).arg(nearLevels)));
    }
};

LR_GL_TEST_MAIN(TestRenderPasses)
#include "tst_renderpasses.moc"
