// A measuring harness (not a test): renders a model with its own camera 0 and lights (else a standard view
// and the default-free rig of scenes.h) and prints the first-frame time and the median ms/frame over N
// frames (glFinish each), wall clock and process CPU time (all threads: robust on a shared machine).
//   render_perf MODEL [frames=60] [msaa=0] [WxH=1280x720]
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
        out << "usage: render_perf MODEL [frames] [msaa] [WxH]\n";
        return 2;
    }
    const int frames = args.value(2, QStringLiteral("60")).toInt();
    const int msaa = args.value(3, QStringLiteral("0")).toInt();
    const QStringList wh = args.value(4, QStringLiteral("1280x720")).split(QLatin1Char('x'));
    const QSize size(wh.value(0).toInt(), wh.value(1).toInt());
    QElapsedTimer t;
    t.start();
    ModelLoadResult loaded = loadModel(args[1]);
    if (!loaded.ok()) {
        out << loaded.error << '\n';
        return 1;
    }
    const double loadMs = t.nsecsElapsed() * 1e-6;
    t.restart();
    OffscreenRenderer gl;
    QString error;
    if (!gl.initialize(&error)) {
        out << error << '\n';
        return 1;
    }
    const double contextMs = t.nsecsElapsed() * 1e-6;
    const QByteArray mode = qgetenv("LR_PERF_MODE");
    if (const QString file = qEnvironmentVariable("LR_PERF_LIGHTING");
        !file.isEmpty()) { // try a shader variant
        QFile f(file);
        if (f.open(QIODevice::ReadOnly))
            gl.renderer().setShaderSourceOverride(QStringLiteral("lighting.glsl"), f.readAll());
    }
    ViewCamera cam = loaded.model->cameras.empty()
                         ? *standardView(QStringLiteral("three-quarter"), loaded.model->bounds, 16.0 / 9.0)
                         : fromModelCamera(loaded.model->cameras[0], loaded.model->bounds.radius());
    RenderSettings s;
    s.msaaSamples = msaa;
    const QByteArray path = qgetenv("LR_PERF_PATH"); // forward | deferred (default: auto)
    if (path == "forward") s.shadingPath = ShadingPath::Forward;
    if (path == "deferred") s.shadingPath = ShadingPath::Deferred;
    t.restart();
    // LR_PERF_MODE=nomodel|nolights|notex|plane (experiments)
    if (mode.contains("plane")) { // a screen-filling plane: full SIMD efficiency, 921600 shaded pixels
        Rig lights = loaded.model->lights;
        loaded.model = std::make_shared<Model>(makePlane(2.0));
        loaded.model->lights = lights;
        cam = ViewCamera();
        cam.eye = {0, 0, 1.2};
    }
    if (mode.contains("notex"))
        for (Material& m : loaded.model->materials)
            m.baseColorTexture = m.normalTexture = m.emissiveTexture = -1;
    if (mode != "nomodel") gl.setModel(loaded.model);
    gl.setRig(mode.contains("nolights") ? Rig() : loaded.model->lights);
    if (!gl.renderFrame(cam, size, s, &error)) {
        out << error << '\n';
        return 1;
    }
    const double firstMs = t.nsecsElapsed() * 1e-6;
    if (const QString save = qEnvironmentVariable("LR_PERF_SAVE"); !save.isEmpty()) { // a look at the gizmos
        RenderSettings g = s;
        g.showGizmos = g.showGrid = true;
        g.selectedLights = {0};
        gl.renderImage(cam, size, g, 1, &error).save(save);
    }
    std::vector<double> wall, cpu, gpu;
    for (int i = 0; i < frames; ++i) {
        t.restart();
        const std::clock_t c0 = std::clock();
        gl.renderFrame(cam, size, s, &error);
        wall.push_back(t.nsecsElapsed() * 1e-6);
        cpu.push_back(double(std::clock() - c0) * 1000.0 / CLOCKS_PER_SEC);
        if (gl.renderer().stats().lastGpuMs >= 0) gpu.push_back(gl.renderer().stats().lastGpuMs);
    }
    out << QStringLiteral(
               "%1: %2 tris, %3 lights, %4x%5 msaa %6 | load %7 ms, context %8 ms, first frame %9 ms | "
               "median wall %10 ms, min %11, cpu %12 ms (min %15), gpu %13 ms over %14 frames\n")
               .arg(args[1].section(QLatin1Char('/'), -1))
               .arg(loaded.model->triangleCount())
               .arg(gl.renderer().stats().lightsUploaded)
               .arg(size.width())
               .arg(size.height())
               .arg(msaa)
               .arg(loadMs, 0, 'f', 0)
               .arg(contextMs, 0, 'f', 0)
               .arg(firstMs, 0, 'f', 0)
               .arg(median(wall), 0, 'f', 2)
               .arg(*std::min_element(wall.begin(), wall.end()), 0, 'f', 2)
               .arg(median(cpu), 0, 'f', 2)
               .arg(median(gpu), 0, 'f', 2)
               .arg(frames)
               .arg(*std::min_element(cpu.begin(), cpu.end()), 0, 'f', 2);
    return 0;
}
