// Imports each file named on the command line with lr::loadModel and prints one line per file:
//   OK <file> triangles=N meshes=N materials=N textures=N lights=N cameras=N ms=T warnings=N
// With --materials first, also each material's physically based values and textures (WxH or -), and each
// warning (for checking what the importer makes of a file by hand):
//   MATERIAL "<name>" pbr=0|1 metallic=F roughness=F alpha=MODE/CUTOFF base=WxH mr=WxH occlusion=WxH*S
//            normal=WxH*S emissive=WxH*(R,G,B) transforms=N
//   WARNING <text>
//   ERROR <message>
//   BAD <file>: <invariant broken>      (exit code 3)
// Used by tst_model_shared to import every third-party file in a child process, so that an importer
// crash is reported for that file instead of ending the test.
#include "model/modelloader.h"
#include "modelchecks.h"

#include <QCoreApplication>
#include <cstdio>
#include <sys/resource.h>

#if defined(__SANITIZE_ADDRESS__)
#define LIGHTRIG_PROBE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIGHTRIG_PROBE_ASAN 1
#endif
#endif

static QByteArray textureSize(const lr::Model& m, int t) {
    if (t < 0) return "-";
    const QImage& image = m.textures[size_t(t)].image;
    return QByteArray::number(image.width()) + 'x' + QByteArray::number(image.height());
}

static void printMaterials(const lr::Model& m) {
    for (const lr::Material& mat : m.materials) {
        int transforms = 0;
        for (const lr::TextureTransform& t :
             {mat.baseColorTransform, mat.normalTransform, mat.emissiveTransform,
              mat.metallicRoughnessTransform, mat.occlusionTransform})
            transforms += !t.isIdentity();
        std::printf(
            "MATERIAL \"%s\" pbr=%d metallic=%g roughness=%g alpha=%s/%g base=%s mr=%s occlusion=%s*%g "
            "normal=%s*%g emissive=%s*(%g,%g,%g) transforms=%d\n",
            qPrintable(mat.name), int(mat.pbr), double(mat.metallic), double(mat.roughness),
            qPrintable(lr::toString(mat.alphaMode)), double(mat.alphaCutoff),
            textureSize(m, mat.baseColorTexture).constData(),
            textureSize(m, mat.metallicRoughnessTexture).constData(),
            textureSize(m, mat.occlusionTexture).constData(), double(mat.occlusionStrength),
            textureSize(m, mat.normalTexture).constData(), double(mat.normalScale),
            textureSize(m, mat.emissiveTexture).constData(), double(mat.emissive.r), double(mat.emissive.g),
            double(mat.emissive.b), transforms);
    }
    for (const QString& w : m.warnings)
        std::printf("WARNING %s\n", qPrintable(w));
}

int main(int argc, char** argv) {
    // An allocation bomb must end in std::bad_alloc (a message), not in swapping or the OOM killer.
    // AddressSanitizer reserves terabytes of address space, so it keeps the default.
#ifndef LIGHTRIG_PROBE_ASAN
    const rlimit limit{rlim_t(4) << 30, rlim_t(4) << 30};
    setrlimit(RLIMIT_AS, &limit);
#endif
    QCoreApplication app(argc, argv);
    int status = 0;
    QStringList paths = app.arguments().mid(1);
    const bool materials = !paths.isEmpty() && paths.front() == QLatin1String("--materials");
    if (materials) paths.removeFirst();
    for (const QString& path : paths) {
        const lr::ModelLoadResult r = lr::loadModel(path);
        if (!r.ok()) {
            std::printf("ERROR %s\n", qPrintable(r.error));
        } else if (const QString problem = lr::test::modelProblems(*r.model); !problem.isEmpty()) {
            std::printf("BAD %s: %s\n", qPrintable(path), qPrintable(problem));
            status = 3;
        } else {
            const lr::Model& m = *r.model;
            std::printf(
                "OK %s triangles=%zu meshes=%zu materials=%zu textures=%zu lights=%zu cameras=%zu ms=%.1f "
                "warnings=%lld\n",
                qPrintable(path), m.triangleCount(), m.meshes.size(), m.materials.size(), m.textures.size(),
                m.lights.lights.size(), m.cameras.size(), m.loadMs, qlonglong(m.warnings.size()));
            if (materials) printMaterials(m);
        }
        std::fflush(stdout);
    }
    return status;
}
