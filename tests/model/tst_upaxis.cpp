// Issue 12 item 7: a model's up axis. Each choice is a proper rotation taking the file's up axis onto +Y,
// applied exactly to everything positional in the Model (origin, vertices, normals, tangents, bounds, the
// file's lights and cameras); composing back gives the model as imported.
#include "model/upaxis.h"

#include <QTest>
#include <glm/matrix.hpp>

using namespace lr;

namespace {
Model tiltedModel() {
    Model m = makeSphere(1.0, 8, 6, glm::dvec3(0.0, 0.0, 5.0));
    m.origin = glm::dvec3(1.0, 2.0, 3.0);
    for (Mesh& mesh : m.meshes)
        for (Vertex& v : mesh.vertices)
            v.tangent = glm::vec4(1.0f, 0.0f, 0.0f, -1.0f);
    Camera c;
    c.position = glm::dvec3(0.0, -10.0, 5.0);
    c.forward = glm::dvec3(0.0, 1.0, 0.0);
    c.up = glm::dvec3(0.0, 0.0, 1.0); // a Z-up file's camera
    m.cameras.push_back(c);
    Light l = makeLight(LightType::Spot, QStringLiteral("s"));
    l.position = glm::dvec3(0.0, 0.0, 9.0);
    l.direction = glm::dvec3(0.0, 0.0, -1.0); // shining down in Z-up
    m.lights.lights.push_back(l);
    return m;
}
} // namespace

class TestUpAxis : public QObject {
    Q_OBJECT
  private slots:
    void everyChoiceTakesItsAxisUp() {
        const glm::dvec3 axes[kModelUpAxisCount] = {{0, 1, 0},  {0, 0, 1},  {1, 0, 0},
                                                    {0, -1, 0}, {0, 0, -1}, {-1, 0, 0}};
        QCOMPARE(modelUpAxisNames().size(), kModelUpAxisCount);
        for (int i = 0; i < kModelUpAxisCount; ++i) {
            const glm::dmat3 r = upAxisRotation(ModelUpAxis(i));
            QCOMPARE(glm::determinant(r), 1.0); // a rotation, not a mirror
            QVERIFY2(r * axes[i] == glm::dvec3(0, 1, 0), qPrintable(toString(ModelUpAxis(i))));
            bool ok = false;
            QCOMPARE(int(modelUpAxisFromString(toString(ModelUpAxis(i)), &ok)), i);
            QVERIFY(ok);
        }
        bool ok = true;
        modelUpAxisFromString(QStringLiteral("sideways"), &ok);
        QVERIFY(!ok);
    }

    void zUp_standsTheModelUp() {
        const Model m = tiltedModel();
        const Model r = rotateModelUp(m, ModelUpAxis::ZUp);
        // The sphere was centred 5 units along +Z (up in the file): now 5 units up +Y.
        QCOMPARE(r.bounds.center(), glm::dvec3(0.0, 5.0, 0.0));
        QCOMPARE(r.bounds.radius(), m.bounds.radius());
        QCOMPARE(r.origin, glm::dvec3(1.0, 3.0, -2.0));
        // World positions rotate (origin + relative position), normals and tangents with them.
        const Vertex& a = m.meshes[0].vertices[7];
        const Vertex& b = r.meshes[0].vertices[7];
        const glm::dvec3 worldA = m.origin + glm::dvec3(a.position),
                         worldB = r.origin + glm::dvec3(b.position);
        QVERIFY(glm::length(worldB - upAxisRotation(ModelUpAxis::ZUp) * worldA) < 1e-5);
        QCOMPARE(b.normal, glm::vec3(a.normal.x, a.normal.z, -a.normal.y));
        QCOMPARE(b.tangent.w, a.tangent.w);
        QCOMPARE(r.cameras[0].up, glm::dvec3(0.0, 1.0, 0.0));
        QCOMPARE(r.lights.lights[0].direction, glm::dvec3(0.0, -1.0, 0.0)); // still shining down
        QCOMPARE(r.lights.lights[0].position, glm::dvec3(0.0, 9.0, 0.0));
    }

    void composingBack_givesTheImportedModel() {
        const Model m = tiltedModel();
        for (int i = 0; i < kModelUpAxisCount; ++i) {
            const Model r = rotateModelUp(m, ModelUpAxis(i));
            const Model back = rotateModel(r, glm::transpose(upAxisRotation(ModelUpAxis(i))));
            QCOMPARE(back.bounds.min, m.bounds.min);
            QCOMPARE(back.bounds.max, m.bounds.max);
            QCOMPARE(back.origin, m.origin);
            QCOMPARE(back.meshes[0].vertices[3].position, m.meshes[0].vertices[3].position);
            QCOMPARE(back.cameras[0].forward, m.cameras[0].forward);
        }
    }
};

QTEST_GUILESS_MAIN(TestUpAxis)
#include "tst_upaxis.moc"
