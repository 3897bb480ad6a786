#include "gizmointeraction.h"

#include "core/fallofftraits.h"
#include "editor/changelightvalues.h"
#include "render/gizmos.h"
#include "scene.h"
#include "undodiscard.h"

#include <cmath>
#include <limits>

#include <QLineF>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace lr {

glm::dvec3 lightAnchor(const Rig& rig, const SceneFrame& frame, const Light& light) {
    if (light.usesPosition()) return rigToWorld(rig, frame, light.position);
    return render::directionalAnchor(frame, light.direction);
}

double spotGizmoLength(const Rig& rig, const SceneFrame& frame, const Light& light) {
    // As render/gizmos.cpp draws it: the range (at most 3 radii) when the light has a finite one, else a
    // radius.
    const double radius = frame.radius > 0.0 && std::isfinite(frame.radius) ? frame.radius : 1.0;
    const Falloff& f = light.falloff;
    const double range = falloffBounded(f) ? f.range / distanceScale(rig, frame) : -1.0;
    return range > 0.0 && std::isfinite(range) && range < radius * 1e4 ? std::min(range, radius * 3.0)
                                                                       : radius;
}

double roundConeAngle(double degrees) {
    return std::round(degrees / kConeStepDegrees) * kConeStepDegrees;
}

GizmoInteraction::GizmoInteraction(Document* document, Scene* scene) : m_doc(document), m_scene(scene) {}
GizmoInteraction::~GizmoInteraction() = default;

int GizmoInteraction::pickLight(const ScreenProjector& projector, const QPointF& screen) const {
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    std::vector<glm::dvec3> anchors;
    anchors.reserve(rig.lights.size());
    for (const Light& l : rig.lights)
        anchors.push_back(lightAnchor(rig, frame, l));
    const int icon = pickNearest(projector, anchors, screen, kPickPixels);
    return icon >= 0 ? icon : pickAreaLight(projector, screen);
}

int GizmoInteraction::pickAreaLight(const ScreenProjector& projector, const QPointF& screen) const {
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    int best = -1;
    double bestDepth = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& l = rig.lights[i];
        if (!l.isArea()) continue;
        if (!hitsPolygon(projector, render::areaOutline(rig, frame, l, 32), screen, kPickPixels)) continue;
        const double depth = projector.depth(lightAnchor(rig, frame, l));
        if (depth < bestDepth) {
            best = int(i);
            bestDepth = depth;
        }
    }
    return best;
}

GizmoInteraction::SizeHandle GizmoInteraction::pickSizeHandle(const ScreenProjector& projector,
                                                              const QPointF& screen) const {
    const QList<int> rows = m_doc->selectedRows();
    if (rows.size() != 1 || !m_doc->light(rows[0]).isArea()) return {};
    SizeHandle best;
    double bestDist = kPickPixels;
    for (const render::AreaHandle& h :
         render::areaHandles(m_doc->rig(), m_scene->frame(), m_doc->light(rows[0]))) {
        const auto p = projector.project(h.position);
        if (!p) continue;
        const double d = QLineF(*p, screen).length();
        if (d <= bestDist) {
            best = {rows[0], h};
            bestDist = d;
        }
    }
    return best;
}

int GizmoInteraction::pickConeEdge(const ScreenProjector& projector, const QPointF& screen) const {
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    int best = -1;
    double bestDist = kPickPixels;
    for (int row : m_doc->selectedRows()) {
        const Light& l = rig.lights[size_t(row)];
        if (l.type != LightType::Spot) continue;
        const auto rim =
            coneRim(lightAnchor(rig, frame, l), l.direction, l.cone.outer, spotGizmoLength(rig, frame, l));
        const double d = distanceToConeRim(projector, rim, screen);
        if (d <= bestDist) {
            best = row;
            bestDist = d;
        }
    }
    return best;
}

bool GizmoInteraction::press(const ScreenProjector& projector, const QPointF& screen,
                             Qt::KeyboardModifiers modifiers) {
    reset();
    m_pressPos = screen;
    if (const SizeHandle h = pickSizeHandle(projector, screen); h.row >= 0) {
        m_drag = Drag::AreaSize;
        m_rows = {h.row};
        m_handle = h.handle;
        m_areaCentre = lightAnchor(m_doc->rig(), m_scene->frame(), m_doc->light(h.row));
        return true;
    }
    const int cone = pickConeEdge(projector, screen);
    const int row = cone >= 0 ? -1 : pickLight(projector, screen);
    if (cone < 0 && row < 0) return false;
    if (cone >= 0) {
        m_drag = Drag::ConeOuter;
        m_rows = {cone};
        // The rim's distance along the axis at the press stays fixed for the whole drag (see picking.h).
        const Light& l = m_doc->light(cone);
        const double len = spotGizmoLength(m_doc->rig(), m_scene->frame(), l);
        m_rimDistance = len * std::max(std::cos(glm::radians(l.cone.outer)), 0.05);
        return true;
    }
    // Select: a plain click makes it the selection (keeping a multi-selection it belongs to, so several
    // lights can be dragged together). Ctrl adds it; Ctrl+click on a selected light (without a drag, since
    // Ctrl+drag moves along the view axis) removes it at the release.
    const LightId id = m_doc->lightId(row);
    QSet<LightId> selection = m_doc->selection();
    if (modifiers & Qt::ControlModifier) {
        if (selection.contains(id))
            m_toggleOff = id;
        else
            selection.insert(id);
    } else if (!selection.contains(id)) {
        selection = {id};
    }
    m_doc->setSelection(selection, id);
    m_rows = m_doc->selectedRows();
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    m_startWorld.clear();
    for (int r : m_rows)
        m_startWorld.push_back(lightAnchor(rig, frame, rig.lights[size_t(r)]));
    m_pickedAnchor = lightAnchor(rig, frame, rig.lights[size_t(row)]);
    m_drag = Drag::Move;
    return true;
}

void GizmoInteraction::move(const ScreenProjector& projector, const QPointF& screen,
                            Qt::KeyboardModifiers modifiers) {
    if (m_drag == Drag::None) return;
    if (!m_started) {
        if (QLineF(m_pressPos, screen).length() < kDragThreshold) return;
        m_started = true;
        m_startIndex = m_doc->undoStack()->index();
        m_edit = std::make_unique<ContinuousEdit>(m_doc);
    }
    if (m_drag == Drag::ConeOuter) {
        const int row = m_rows.value(0, -1);
        if (row < 0 || row >= m_doc->lightCount()) return;
        const Light& l = m_doc->light(row);
        const auto angle = coneAngleUnderCursor(projector, lightAnchor(m_doc->rig(), m_scene->frame(), l),
                                                l.direction, screen, m_rimDistance);
        // A smooth cone's outer angle stays at or above its inner one (the document refuses less).
        const double lowest = l.cone.model == ConeModel::Smooth ? std::max(0.5, l.cone.inner) : 0.5;
        // Rounded to kConeStepDegrees: a drag leaves 32.5°, not 32.59493°.
        if (angle)
            m_doc->setLightValue({row}, LightProperty::ConeOuter,
                                 std::clamp(roundConeAngle(*angle), lowest, 90.0));
        return;
    }
    if (m_drag == Drag::AreaSize) {
        applyAreaSize(projector, screen);
        return;
    }
    const bool alongView = modifiers & (Qt::ControlModifier | Qt::AltModifier);
    m_drag = alongView ? Drag::MoveAlongView : Drag::Move;
    applyMove(projector, screen, alongView);
}

void GizmoInteraction::applyAreaSize(const ScreenProjector& projector, const QPointF& screen) {
    const int row = m_rows.value(0, -1);
    if (row < 0 || row >= m_doc->lightCount()) return;
    // The point of the handle's axis (through the centre) nearest to the cursor's ray: the new half size,
    // symmetric about the centre, which stays put.
    const auto t = closestOnAxis(projector.ray(screen), m_areaCentre, m_handle.axis);
    if (!t) return;
    const double half = std::abs(*t) * distanceScale(m_doc->rig(), m_scene->frame()); // rig units
    if (!std::isfinite(half)) return;
    switch (m_handle.size) {
    case render::AreaSize::Width:
        m_doc->setLightValue({row}, LightProperty::AreaWidth, 2.0 * half);
        break;
    case render::AreaSize::Height:
        m_doc->setLightValue({row}, LightProperty::AreaHeight, 2.0 * half);
        break;
    case render::AreaSize::Radius:
        m_doc->setLightValue({row}, LightProperty::AreaRadius, half);
        break;
    }
}

void GizmoInteraction::applyMove(const ScreenProjector& projector, const QPointF& screen, bool alongView) {
    // Every dragged light moves by the same world offset as the picked one.
    glm::dvec3 offset;
    if (alongView) {
        const double depth = std::max(projector.depth(m_pickedAnchor), 1e-6);
        offset =
            dragAlongViewAxis(projector, m_pickedAnchor, m_pressPos, screen, projector.worldPerPixel(depth)) -
            m_pickedAnchor;
    } else {
        offset = dragInViewPlane(projector, m_pickedAnchor, m_pressPos, screen) - m_pickedAnchor;
    }
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    QList<int> positionRows, directionRows;
    QVariantList positions, directions;
    for (int i = 0; i < m_rows.size(); ++i) {
        const int row = m_rows[i];
        if (row < 0 || row >= m_doc->lightCount()) continue;
        const Light& l = rig.lights[size_t(row)];
        const glm::dvec3 world = m_startWorld[size_t(i)] + offset;
        if (l.usesPosition()) {
            positionRows.append(row);
            positions.append(QVariant::fromValue(worldToRig(rig, frame, world)));
        } else {
            // Directional and rim lights: moving the gizmo around the scene turns the light towards the
            // centre.
            const glm::dvec3 d = frame.center - world;
            if (glm::length(d) > 1e-9 * std::max(1.0, frame.radius)) {
                directionRows.append(row);
                directions.append(QVariant::fromValue(glm::normalize(d)));
            }
        }
    }
    if (!positionRows.isEmpty()) m_doc->setLightValues(positionRows, LightProperty::Position, positions);
    if (!directionRows.isEmpty()) m_doc->setLightValues(directionRows, LightProperty::Direction, directions);
}

void GizmoInteraction::release() {
    if (!m_started && m_toggleOff) {
        QSet<LightId> selection = m_doc->selection();
        selection.remove(m_toggleOff);
        m_doc->setSelection(selection);
    }
    reset();
}

void GizmoInteraction::reset() {
    m_toggleOff = 0;
    m_edit.reset();
    m_drag = Drag::None;
    m_started = false;
    m_rows.clear();
    m_startWorld.clear();
}

bool GizmoInteraction::cancel() {
    const bool changed = m_started && m_edit;
    const int before = m_startIndex;
    reset();
    if (!changed) return false;
    // Take back every step the drag pushed (one merged step, or one per property for a mixed selection),
    // leaving nothing to redo: a cancelled drag never happened.
    discardStepsAbove(m_doc, before);
    return true;
}

bool GizmoInteraction::aimSelectedAt(const ScreenProjector& projector, const QPointF& screen,
                                     QString* message) {
    QList<int> rows;
    for (int row : m_doc->selectedRows())
        if (m_doc->light(row).usesDirection()) rows.append(row);
    if (rows.isEmpty()) {
        if (message) *message = QObject::tr("Select a spot, directional or rim light to aim it.");
        return false;
    }
    const auto hit = intersectModel(*m_scene->model(), projector.ray(screen));
    if (!hit) {
        if (message)
            *message = QObject::tr("Shift+click a point on the model to aim the selected light at it.");
        return false;
    }
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    QList<int> aimed;
    QVariantList directions;
    for (int row : rows) {
        const glm::dvec3 d = *hit - lightAnchor(rig, frame, rig.lights[size_t(row)]);
        if (!(glm::length(d) > 0.0)) continue;
        aimed.append(row);
        directions.append(QVariant::fromValue(glm::normalize(d)));
    }
    if (aimed.isEmpty()) return false;
    QString error;
    if (!m_doc->setLightValues(aimed, LightProperty::Direction, directions, &error)) {
        if (message) *message = error;
        return false;
    }
    return true;
}

GizmoInteraction::Highlight GizmoInteraction::placeHighlight(const ScreenProjector& projector,
                                                             const QPointF& screen, QString* message) {
    const QList<int> rows = m_doc->selectedRows();
    const Ray ray = projector.ray(screen);
    const auto hit = intersectModelWithNormal(*m_scene->model(), ray);
    if (!hit) return Highlight::Missed;
    if (rows.isEmpty()) return Highlight::NothingSelected;
    const glm::dvec3 mirror = glm::normalize(mirrorDirection(ray.direction, hit->normal));
    const Rig& rig = m_doc->rig();
    const SceneFrame frame = m_scene->frame();
    QList<LightValueEdit> edits;
    for (int row : rows) {
        const Light& l = rig.lights[size_t(row)];
        if (l.usesPosition()) {
            double d = glm::length(rigToWorld(rig, frame, l.position) - hit->point);
            if (!(d > 0.0) || !std::isfinite(d)) d = frame.radius; // a light on the point: one radius away
            edits.append({row, LightProperty::Position,
                          QVariant::fromValue(worldToRig(rig, frame, hit->point + mirror * d))});
        }
        if (l.usesDirection()) edits.append({row, LightProperty::Direction, QVariant::fromValue(-mirror)});
    }
    const QString text = rows.size() == 1
                             ? QObject::tr("Place the highlight of %1").arg(m_doc->light(rows[0]).name)
                             : QObject::tr("Place the highlight of %1 lights").arg(rows.size());
    QString error;
    auto command = ChangeLightValues::create(m_doc, edits, text, &error);
    if (!command) {
        if (error.isEmpty()) return Highlight::Placed; // already there
        if (message) *message = error;
        return Highlight::Refused;
    }
    m_doc->undoStack()->push(command.release());
    return Highlight::Placed;
}

} // namespace lr
