// Area lights in the viewport (issue 16): the outline and handle geometry of rect and disk lights
// (render/gizmos.h), picking them by outline or inside, dragging their size handles (one undo step), and
// "place the highlight" / Shift+click aim (app/gizmointeraction.h), against hand-built cameras.
#include "app/controlshelp.h"
#include "app/gizmointeraction.h"
#include "app/picking.h"
#include "app/scene.h"
#include "editor/document.h"
#include "model/model.h"
#include "render/gizmos.h"

#include "pickingcamera.h"

#include <QTest>
#include <glm/gtc/matrix_transform.hpp>

using namespace lr;
using namespace lr::test;

namespace {
QString str(const glm::dvec3& v) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}
Light rectLight(const glm::dvec3& position, const glm::dvec3& direction, double width, double height) {
    Light l = makeLight(LightType::Rect, QStringLiteral("Softbox"));
    l.position = position;
    l.direction = direction;
    l.area.width = width;
    l.area.height = height;
    return l;
}
// A document with these lights (world-space rig unless told), the first selected.
void setUp(Document& doc, std::vector<Light> lights, RigSpace space = RigSpace::World) {
    Rig rig;
    rig.space = space;
    rig.lights = std::move(lights);
    doc.newRig(rig);
    doc.setSelectedRows({0});
}
} // namespace

class TestAreaGizmos : public QObject {
    Q_OBJECT
  private slots:
    void rectOutlineFollowsAreaAxes() {
        Rig rig;
        rig.space = RigSpace::Model;
        const SceneFrame frame{glm::dvec3(10, 0, 0), 2.0}; // model space: rig units are 2 world units
        Light l = rectLight({0.5, 1, 0}, glm::normalize(glm::dvec3(-1, -2, 0.5)), 3.0, 1.0);
        l.area.roll = 30.0;
        rig.lights = {l};
        const AreaAxes a = areaAxes(l.direction, l.area.roll);
        const glm::dvec3 c = frame.center + l.position * 2.0;
        const auto corners = render::areaOutline(rig, frame, l);
        QCOMPARE(corners.size(), size_t(4));
        const glm::dvec3 hx = a.x * 3.0, hy = a.y * 1.0; // half sizes 1.5 and 0.5 rig units, × 2
        QVERIFY2(near(corners[0], c + hx + hy), qPrintable(str(corners[0])));
        QVERIFY(near(corners[1], c - hx + hy));
        QVERIFY(near(corners[2], c - hx - hy));
        QVERIFY(near(corners[3], c + hx - hy));
        const auto handles = render::areaHandles(rig, frame, l);
        QCOMPARE(handles.size(), size_t(4));
        QVERIFY(near(handles[0].position, c + hx) && handles[0].size == render::AreaSize::Width);
        QVERIFY(near(handles[2].position, c + hy) && handles[2].size == render::AreaSize::Height);

        // The gizmo draws the four edges (in view space: the view only moves the world 100 units away).
        const glm::dmat4 view = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -100));
        auto toView = [&](const glm::dvec3& q) { return glm::dvec3(view * glm::dvec4(q, 1.0)); };
        render::GizmoOptions options;
        auto hasLine = [&](const render::GizmoGeometry& g, const glm::dvec3& p, const glm::dvec3& q) {
            for (size_t i = 0; i + 1 < g.lines.size(); i += 2)
                if (near(glm::dvec3(g.lines[i].position), toView(p), 1e-4) &&
                    near(glm::dvec3(g.lines[i + 1].position), toView(q), 1e-4))
                    return true;
            return false;
        };
        const render::GizmoGeometry g = render::buildGizmos(rig, frame, {}, view, options);
        for (size_t k = 0; k < 4; ++k)
            QVERIFY2(hasLine(g, corners[k], corners[(k + 1) % 4]), qPrintable(QString::number(k)));
        // The normal: a line from the centre along the direction; a two-sided light has one the other way
        // too.
        auto normalLines = [&](const render::GizmoGeometry& geo, const glm::dvec3& dir) {
            int n = 0;
            for (size_t i = 0; i + 1 < geo.lines.size(); i += 2)
                if (near(glm::dvec3(geo.lines[i].position), toView(c), 1e-4) &&
                    glm::dot(glm::normalize(glm::dvec3(geo.lines[i + 1].position) - toView(c)), dir) > 0.9999)
                    ++n;
            return n;
        };
        QCOMPARE(normalLines(g, l.direction), 1);
        QCOMPARE(normalLines(g, -l.direction), 0);
        rig.lights[0].area.twoSided = true;
        const render::GizmoGeometry g2 = render::buildGizmos(rig, frame, {}, view, options);
        QCOMPARE(normalLines(g2, -l.direction), 1);
        // Handles are drawn only while it alone is selected.
        const size_t pointsBefore = g2.points.size();
        options.selected = {0};
        QCOMPARE(render::buildGizmos(rig, frame, {}, view, options).points.size(), pointsBefore + 4);
    }

    void diskOutlineIsItsRim() {
        Rig rig;
        rig.space = RigSpace::World;
        Light l = makeLight(LightType::Disk, QStringLiteral("Disk"));
        l.position = {1, 2, 3};
        l.direction = glm::normalize(glm::dvec3(0.3, -1, 0.2));
        l.area.radius = 0.75;
        const auto rim = render::areaOutline(rig, SceneFrame{}, l, 24);
        QCOMPARE(rim.size(), size_t(24));
        for (const glm::dvec3& p : rim) {
            QVERIFY(std::abs(glm::length(p - l.position) - 0.75) < 1e-12);
            QVERIFY(std::abs(glm::dot(p - l.position, l.direction)) < 1e-12); // in the light's plane
        }
        QVERIFY(near(rim[0], l.position + areaAxes(l.direction, 0.0).x * 0.75));
        QVERIFY(render::areaOutline(rig, SceneFrame{}, makeLight(LightType::Spot, "s")).empty());
    }

    void picksByOutlineOrInside() {
        Document doc;
        Scene scene; // empty: the unit frame at the origin
        // 8 × 4 world units facing the camera: 40 × 20 pixels around (100, 50); a point light elsewhere.
        Light point = makeLight(LightType::Point, QStringLiteral("Point"));
        point.position = {-16, 0, 0}; // screen (20, 50)
        setUp(doc, {rectLight({0, 0, 0}, {0, 0, 1}, 8.0, 4.0), point});
        GizmoInteraction gi(&doc, &scene);
        const ScreenProjector p = frontCamera();
        QCOMPARE(gi.pickLight(p, QPointF(115, 52)), 0); // inside, 15 px from the icon
        QCOMPARE(gi.pickAreaLight(p, QPointF(115, 52)), 0);
        QCOMPARE(gi.pickLight(p, QPointF(125, 50)), 0);  // 5 px outside the right edge: on the outline
        QCOMPARE(gi.pickLight(p, QPointF(135, 50)), -1); // 15 px outside
        QCOMPARE(gi.pickLight(p, QPointF(100, 75)), -1); // 15 px below the bottom edge
        QCOMPARE(gi.pickLight(p, QPointF(20, 50)), 1);
        // Seen edge-on (the light's plane through the eye), a rect is a line: picked along it only.
        doc.setLightValue({0}, LightProperty::Direction, QVariant::fromValue(glm::dvec3(0, 1, 0)));
        QCOMPARE(gi.pickAreaLight(p, QPointF(115, 52)), 0);  // 2 px from the line
        QCOMPARE(gi.pickAreaLight(p, QPointF(115, 70)), -1); // 20 px off it
    }

    void sizeDragIsOneUndoStep() {
        Document doc;
        Scene scene;
        setUp(doc, {rectLight({0, 0, 0}, {0, 0, 1}, 8.0, 4.0)});
        GizmoInteraction gi(&doc, &scene);
        const ScreenProjector p = frontCamera();
        // areaAxes((0,0,1)): x = (0,0,1) × +Y = (-1,0,0), so the +x handle is on the left, at (80, 50).
        const auto h = gi.pickSizeHandle(p, QPointF(80, 50));
        QCOMPARE(h.row, 0);
        QVERIFY(h.handle.size == render::AreaSize::Width);
        const int before = doc.undoStack()->count();
        QVERIFY(gi.press(p, QPointF(80, 50), Qt::NoModifier));
        QVERIFY(gi.drag() == GizmoInteraction::Drag::AreaSize);
        gi.move(p, QPointF(75, 50), Qt::NoModifier);
        gi.move(p, QPointF(70, 50), Qt::NoModifier); // 30 px = 6 units left of the centre: width 12
        gi.release();
        QCOMPARE(doc.undoStack()->count(), before + 1);
        QVERIFY2(std::abs(doc.light(0).area.width - 12.0) < 1e-9,
                 qPrintable(QString::number(doc.light(0).area.width)));
        QCOMPARE(doc.light(0).area.height, 4.0);
        QVERIFY(near(doc.light(0).position, glm::dvec3(0))); // symmetric: the centre stays
        doc.undoStack()->undo();
        QCOMPARE(doc.light(0).area.width, 8.0);

        // The height handle (+y, up: screen (100, 40)); the disk's radius handle, in a model-space rig.
        QVERIFY(gi.press(p, QPointF(100, 40), Qt::NoModifier));
        gi.move(p, QPointF(100, 35), Qt::NoModifier); // 15 px = 3 units above the centre: height 6
        gi.release();
        QVERIFY(std::abs(doc.light(0).area.height - 6.0) < 1e-9);

        Light disk = makeLight(LightType::Disk, QStringLiteral("Disk"));
        disk.position = {0, 0, 0};
        disk.direction = {0, 0, 1};
        disk.area.radius = 1.0; // × the frame radius 2 below: 2 world units, 10 px
        setUp(doc, {disk}, RigSpace::Model);
        auto sphere = std::make_shared<Model>(makeSphere(1.0, 8, 4, glm::dvec3(0, 0, -50)));
        sphere->bounds = {{-2, -2, -52}, {2, 2, -48}}; // centre (0,0,-50), radius 2√3
        scene.setModel(sphere, QString());
        const double radius = scene.frame().radius;
        const ScreenProjector far(
            glm::lookAt(glm::dvec3(0, 0, -40), glm::dvec3(0, 0, -50), glm::dvec3(0, 1, 0)),
            glm::perspective(glm::radians(90.0), 2.0, 0.1, 100.0), QSizeF(200, 100));
        const glm::dvec3 rimWorld = scene.frame().center + glm::dvec3(-radius, 0, 0); // +x = (-1,0,0)
        const auto onRim = far.project(rimWorld);
        QVERIFY(onRim);
        QVERIFY(gi.press(far, *onRim, Qt::NoModifier));
        QVERIFY(gi.drag() == GizmoInteraction::Drag::AreaSize);
        const auto out = far.project(scene.frame().center + glm::dvec3(-1.5 * radius, 0, 0));
        gi.move(far, *out, Qt::NoModifier);
        gi.release();
        QVERIFY2(std::abs(doc.light(0).area.radius - 1.5) < 1e-9,
                 qPrintable(QString::number(doc.light(0).area.radius)));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void cancelledSizeDragLeavesNothing() {
        Document doc;
        Scene scene;
        setUp(doc, {rectLight({0, 0, 0}, {0, 0, 1}, 8.0, 4.0)});
        GizmoInteraction gi(&doc, &scene);
        const ScreenProjector p = frontCamera();
        QVERIFY(gi.press(p, QPointF(80, 50), Qt::NoModifier));
        gi.move(p, QPointF(60, 50), Qt::NoModifier);
        QVERIFY(gi.cancel());
        QCOMPARE(doc.light(0).area.width, 8.0);
        QCOMPARE(doc.undoStack()->count(), 0);
    }

    void placesTheHighlight() {
        Document doc;
        Scene scene;
        scene.setModel(std::make_shared<Model>(makeSphere(1.0, 64, 32)), QString());
        Light spot = makeLight(LightType::Spot, QStringLiteral("Spot"));
        spot.position = {3, 1, 2};
        spot.direction = {0, -1, 0};
        Light sun = makeLight(LightType::Directional, QStringLiteral("Sun"));
        sun.direction = {0, -1, 0};
        Light point = makeLight(LightType::Point, QStringLiteral("Point"));
        point.position = {-2, 2, 2};
        setUp(doc, {rectLight({2, 3, 4}, {0, -1, 0}, 1.0, 0.5), spot, sun, point}, RigSpace::Model);
        doc.setSelectedRows({0, 1, 2, 3});
        const Rig before = doc.rig();
        const SceneFrame frame = scene.frame();
        GizmoInteraction gi(&doc, &scene);
        const ScreenProjector p = frontCamera();
        const QPointF click(103, 47); // on the sphere, off its centre
        const Ray ray = p.ray(click);
        const auto hit = intersectModelWithNormal(*scene.model(), ray);
        QVERIFY(hit);
        // The shading normal of a finely tessellated unit sphere is (almost) the radial direction.
        QVERIFY2(glm::dot(hit->normal, glm::normalize(hit->point)) > 0.9999, qPrintable(str(hit->normal)));
        const glm::dvec3 mirror = mirrorDirection(ray.direction, hit->normal);
        QVERIFY(glm::dot(mirror, hit->normal) > 0.0); // leaves the surface on the viewer's side

        QString message;
        QVERIFY(gi.placeHighlight(p, click, &message) == GizmoInteraction::Highlight::Placed);
        QCOMPARE(doc.undoStack()->count(), 1);
        for (int row : {0, 1, 3}) {
            const glm::dvec3 was = rigToWorld(before, frame, before.lights[size_t(row)].position);
            const glm::dvec3 now = rigToWorld(doc.rig(), frame, doc.light(row).position);
            // reflect(view ray, N) at P points at the light, which kept its distance from P.
            QVERIFY2(glm::dot(glm::normalize(now - hit->point), mirror) > 1.0 - 1e-9, qPrintable(str(now)));
            QVERIFY(std::abs(glm::length(now - hit->point) - glm::length(was - hit->point)) < 1e-9);
            if (doc.light(row).usesDirection()) // rect and spot face P
                QVERIFY2(near(doc.light(row).direction, glm::normalize(hit->point - now), 1e-9),
                         qPrintable(str(doc.light(row).direction)));
        }
        QVERIFY(near(doc.light(2).direction, -mirror, 1e-12)); // the directional light only turns
        // One undo step restores position and direction together.
        doc.undoStack()->undo();
        QVERIFY(doc.rig().lights == before.lights);
        doc.undoStack()->redo();

        // A click off the model (the viewport then deselects), or with nothing selected: nothing changes.
        QVERIFY(gi.placeHighlight(p, QPointF(5, 5), &message) == GizmoInteraction::Highlight::Missed);
        doc.setSelection({});
        QVERIFY(gi.placeHighlight(p, click, &message) == GizmoInteraction::Highlight::NothingSelected);
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void shiftClickStillAims() {
        Document doc;
        Scene scene;
        scene.setModel(std::make_shared<Model>(makeSphere(1.0, 64, 32)), QString());
        setUp(doc, {rectLight({3, 3, 3}, {0, -1, 0}, 1.0, 1.0)});
        GizmoInteraction gi(&doc, &scene);
        const ScreenProjector p = frontCamera();
        const QPointF click(103, 47);
        const auto hit = intersectModel(*scene.model(), p.ray(click));
        QVERIFY(hit);
        QString message;
        QVERIFY(gi.aimSelectedAt(p, click, &message));
        QVERIFY(near(doc.light(0).position, glm::dvec3(3, 3, 3))); // aiming does not move it
        QVERIFY(near(doc.light(0).direction, glm::normalize(*hit - glm::dvec3(3, 3, 3)), 1e-12));
        QCOMPARE(doc.undoStack()->count(), 1);
        // Help › Controls tells both gestures apart.
        QStringList help;
        for (const ControlBinding& b : mouseBindings())
            help << b.input + QLatin1Char('=') + b.effect;
        QVERIFY(help.filter(QStringLiteral("Ctrl+click the model=Place the highlight")).size() == 1);
        QVERIFY(help.filter(QStringLiteral("Shift+click the model=Aim")).size() == 1);
    }
};

QTEST_GUILESS_MAIN(TestAreaGizmos)
#include "tst_areagizmos.moc"
