// A measuring harness for shadows (not a test): the model's own lights, every one casting (soft: emitter
// 5% of the model's radius), over a visible ground, per quality tier in a fresh context each:
//   first frame (shader compile, map renders), ms/frame while orbiting (maps cached), while one light is
//   dragged every frame (its map re-rendered), with all lights moved every frame (every map re-rendered),
//   the same view without shadows, the time per map (RenderStats::shadowMapMs over the layers) and the
//   maps' memory. Medians of process CPU ms per frame (glFinish each; LR_PERF_WALL=1: wall clock).
//   shadow_perf MODEL [frames=20] [WxH=1280x720]
// LR_PERF_AREA=W[:near][:two]: the lights replaced by one casting rect light W model radii square, 3 radii
// above the model's centre shining down (a perspective map), or 1.3 radii (`near`: a cube of 5 faces;
// `two`: two-sided, 6).
#include "core/prepare.h"
#include "model/modelloader.h"
#include "render/offscreen.h"

#include <QElapsedTimer>
#include <QFile>
#include <QGuiApplication>
#include <QTextStream>
#include <algorithm>
#include <ctime>
#include <vector>

using namespace lr;

static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    QTextStream out(stdout);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        out << "usage: shadow_perf MODEL [frames] [WxH]\n";
        return 2;
    }
    const int frames = std::max(1, args.value(2, QStringLiteral("20")).toInt());
    const QStringList wh = args.value(3, QStringLiteral("1280x720")).split(QLatin1Char('x'));
    const QSize size(wh.value(0).toInt(), wh.value(1).toInt());
    ModelLoadResult loaded = loadModel(args[1]);
    if (!loaded.ok()) {
        out << loaded.error << '\n';
        return 1;
    }
    const Model& model = *loaded.model;
    Rig rig = model.lights;
    rig.shading.model = ShadingModel::Pbr;
    rig.ground.mode = GroundMode::Visible;
    int casters = 0;
    for (Light& l : rig.lights) {
        l.shadow.enabled = l.castsShadows();
        l.shadow.size = 0.05 * model.bounds.radius();
        l.shadow.angle = 1.0;
        casters += l.hasShadow() ? 1 : 0;
    }
    if (const QString area = qEnvironmentVariable("LR_PERF_AREA"); !area.isEmpty()) {
        const double r = model.bounds.radius();
        Light l = makeLight(LightType::Rect, QStringLiteral("softbox"));
        l.position = model.bounds.center() +
                     glm::dvec3(0.0, (area.contains(QLatin1String("near")) ? 1.3 : 3.0) * r, 0.0);
        l.direction = {0.0, -1.0, 0.0};
        l.area.width = l.area.height = area.section(QLatin1Char(':'), 0, 0).toDouble() * r;
        l.area.twoSided = area.contains(QLatin1String("two"));
        l.intensity = 5.0;
        l.shadow.enabled = true;
        rig.space = RigSpace::World;
        rig.lights = {l};
        casters = 1;
    }
    Rig plain = rig;
    for (Light& l : plain.lights)
        l.shadow.enabled = false;
    const ViewCamera start = model.cameras.empty()
                                 ? *standardView(QStringLiteral("three-quarter"), model.bounds, 16.0 / 9.0)
                                 : fromModelCamera(model.cameras[0], model.bounds.radius());
    out << args[1].section(QLatin1Char('/'), -1) << ": " << model.triangleCount() << " tris, " << casters
        << " casting lights of " << rig.lights.size() << ", ground, " << size.width() << 'x' << size.height()
        << ", PBR, no MSAA\n";
    { // The same first frame without shadows (exact tier, ground on), for comparison.
        OffscreenRenderer gl;
        QString error;
        if (!gl.initialize(&error)) {
            out << error << '\n';
            return 1;
        }
        QElapsedTimer t;
        t.start();
        gl.setModel(loaded.model);
        gl.setRig(plain);
        RenderSettings r;
        r.msaaSamples = 0;
        gl.renderFrame(start, size, r, &error);
        out << QStringLiteral("  first frame without shadows (exact): %1 ms\n")
                   .arg(t.nsecsElapsed() * 1e-6, 0, 'f', 0);
    }
    // LR_PERF_TIERS=exact,fast (default: all three); LR_PERF_SHADOWS=FILE, LR_PERF_LIGHTING=FILE: try a
    // variant of shadows.glsl or lighting.glsl.
    const QString tiers = qEnvironmentVariable("LR_PERF_TIERS", QStringLiteral("fast,balanced,exact"));
    for (Quality q : {Quality::Fast, Quality::Balanced, Quality::Exact}) {
        if (!tiers.contains(toString(q))) continue;
        OffscreenRenderer gl;
        QString error;
        if (!gl.initialize(&error)) {
            out << error << '\n';
            return 1;
        }
        if (const QString file = qEnvironmentVariable("LR_PERF_SHADOWS"); !file.isEmpty()) {
            QFile f(file);
            if (f.open(QIODevice::ReadOnly))
                gl.renderer().setShaderSourceOverride(QStringLiteral("shadows.glsl"), f.readAll());
        }
        if (const QString file = qEnvironmentVariable("LR_PERF_LIGHTING"); !file.isEmpty()) {
            QFile f(file);
            if (f.open(QIODevice::ReadOnly))
                gl.renderer().setShaderSourceOverride(QStringLiteral("lighting.glsl"), f.readAll());
        }
        RenderSettings s;
        s.quality = q;
        s.msaaSamples = 0;
        s.waitForShadowMaps = true; // shadowMapMs: the maps' own time
        QElapsedTimer t;
        t.start();
        gl.setModel(loaded.model);
        gl.setRig(rig);
        ViewCamera cam = start;
        if (!gl.renderFrame(cam, size, s, &error)) {
            out << error << '\n';
            return 1;
        }
        const double first = t.nsecsElapsed() * 1e-6;
        // LR_PERF_SAVE=PREFIX: PREFIX-TIER.png of the first view, to look at
        if (const QString save = qEnvironmentVariable("LR_PERF_SAVE"); !save.isEmpty())
            gl.renderImage(cam, size, s, 1, &error)
                .save(save + QLatin1Char('-') + toString(q) + QStringLiteral(".png"));
        const qint64 bytes = gl.renderer().stats().shadowMapBytes;
        // Process CPU time of a frame (all threads: llvmpipe's included), robust on a shared machine;
        // LR_PERF_WALL=1 for wall-clock time.
        const bool wall = qEnvironmentVariableIsSet("LR_PERF_WALL");
        auto measure = [&](auto&& step) {
            std::vector<double> ms;
            for (int i = 0; i < frames; ++i) {
                step(i);
                t.restart();
                const std::clock_t c0 = std::clock();
                gl.renderFrame(cam, size, s, &error);
                ms.push_back(wall ? t.nsecsElapsed() * 1e-6
                                  : double(std::clock() - c0) * 1000.0 / CLOCKS_PER_SEC);
            }
            return median(ms);
        };
        int mapsWhileOrbiting = 0, mapsWhileDragging = 0;
        std::vector<double> perLayer; // the shadow pass's own time over the layers it rendered
        const double orbit = measure([&](int i) {
            cam.orbit(2.0, 0.0);
            if (i > 0) mapsWhileOrbiting += gl.renderer().stats().shadowMapsRendered; // the last frame's
        });
        Rig moving = rig;
        const double drag = measure([&](int i) {
            moving.lights[0].position.x += (i % 2 ? -0.01 : 0.01) * model.bounds.radius();
            if (i > 0) mapsWhileDragging += gl.renderer().stats().shadowMapsRendered;
            gl.setRig(moving);
        });
        const double all = measure([&](int i) {
            const RenderStats& st = gl.renderer().stats();
            if (i > 0 && st.shadowLayersRendered > 0)
                perLayer.push_back(st.shadowMapMs / st.shadowLayersRendered);
            for (Light& l : moving.lights)
                l.position.y += (i % 2 ? -0.01 : 0.01) * model.bounds.radius();
            gl.setRig(moving);
        });
        gl.setRig(plain);
        gl.renderFrame(cam, size, s, &error); // compile the unshadowed variant outside the timing
        const double none = measure([&](int) { cam.orbit(2.0, 0.0); });
        out << QStringLiteral(
                   "  %1: first frame %2 ms | orbiting %3 ms/frame (%4 maps re-rendered), dragging one "
                   "light %5 ms/frame (%10 maps), moving all %6 ms/frame, without shadows %7 ms/frame | per "
                   "map "
                   "%8 ms (its pass, waited for) | maps %9 MiB\n")
                   .arg(toString(q), -8)
                   .arg(first, 0, 'f', 0)
                   .arg(orbit, 0, 'f', 1)
                   .arg(mapsWhileOrbiting)
                   .arg(drag, 0, 'f', 1)
                   .arg(all, 0, 'f', 1)
                   .arg(none, 0, 'f', 1)
                   .arg(median(perLayer), 0, 'f', 2)
                   .arg(double(bytes) / (1 << 20), 0, 'f', 0)
                   .arg(mapsWhileDragging);
    }
    return 0;
}
