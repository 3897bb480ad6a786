// Interaction proxies (render/lod.h): only dense models get one, it indexes the mesh's own vertices with
// far fewer triangles, and the renderer draws it only while interactive, close to the full mesh's image.
#include "glfixture.h"
#include "scenes.h"

#include "render/imageerrors.h"
#include "render/lod.h"
#include "render/offscreen.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

std::shared_ptr<Model> denseSphere() { // 640 × 320 × 2 = 409,600 triangles
    auto m = std::make_shared<Model>(makeSphere(1.0, 640, 320));
    m->materials[0].baseColor = {0.7f, 0.7f, 0.9f, 1.0f};
    return m;
}

} // namespace

class TestLod : public QObject {
    Q_OBJECT
  private slots:
    void smallModelsGetNone() {
        QVERIFY(render::buildInteractionLods(*sphereScene()).empty());
        QVERIFY(render::buildInteractionLods(Model{}).empty());
    }

    void denseMeshesSimplifyOverTheirOwnVertices() {
        const auto model = denseSphere();
        QVERIFY(std::int64_t(model->triangleCount()) >= render::kLodMinTriangles);
        const auto lods = render::buildInteractionLods(*model);
        QCOMPARE(int(lods.size()), 1);
        const Mesh& mesh = model->meshes[size_t(lods[0].mesh)];
        const auto& indices = lods[0].indices;
        QCOMPARE(indices.size() % 3, size_t(0));
        QVERIFY2(indices.size() / 3 <= size_t(render::kLodTargetTriangles * 3 / 2),
                 qPrintable(QString::number(indices.size() / 3)));
        QVERIFY(indices.size() / 3 >= size_t(render::kLodTargetTriangles / 4)); // still a sphere, not a blob
        for (std::uint32_t i : indices)
            QVERIFY(i < mesh.vertices.size());
    }

    void drawnOnlyWhileInteractive() {
        LR_REQUIRE_DISPLAY();
        OffscreenRenderer gl;
        QString error;
        QVERIFY2(gl.initialize(&error), qPrintable(error));
        const auto model = denseSphere();
        QVERIFY(gl.setModel(model, &error));
        Rig rig;
        rig.lights.push_back(point({2.0, 2.0, 3.0}, FalloffModel::None));
        gl.setRig(rig);
        QVERIFY(gl.renderer().waitForInteractionProxies());
        RenderSettings still;
        still.msaaSamples = 0;
        RenderSettings moving = still;
        moving.interactive = true;
        const QSize size(160, 120);
        const QImage full = gl.renderImage(sphereCamera(), size, still, 1, &error);
        QVERIFY2(!full.isNull(), qPrintable(error));
        QCOMPARE(gl.renderer().stats().trianglesDrawn, qint64(model->triangleCount()));
        const QImage proxy = gl.renderImage(sphereCamera(), size, moving, 1, &error);
        QVERIFY2(!proxy.isNull(), qPrintable(error));
        const qint64 drawn = gl.renderer().stats().trianglesDrawn;
        QVERIFY2(drawn > 0 && drawn <= render::kLodTargetTriangles * 3 / 2,
                 qPrintable(QString::number(drawn)));
        const double mean = imageErrors(full, proxy).meanLevels;
        QVERIFY2(mean < 2.0, qPrintable(QStringLiteral("mean difference %1 levels").arg(mean)));
        QCOMPARE(gl.renderImage(sphereCamera(), size, still, 1, &error), full); // and back to the full mesh
    }
};

LR_GL_TEST_MAIN(TestLod)
#include "tst_lod.moc"
