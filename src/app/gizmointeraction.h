// Direct manipulation of lights in the viewport, independent of GL: picking a light's gizmo (an area light
// also by its outline or anywhere inside it), dragging it in the view plane (Ctrl or Alt: along the view
// axis), dragging a spot's cone edge to change its outer angle, dragging an area light's size handles,
// aiming the selected lights at a point of the model and placing their highlight on it. Every change goes
// through the Document's commands; one drag is one undo step (a continuous-edit session from press to
// release).
#pragma once

#include "core/prepare.h"
#include "editor/document.h"
#include "picking.h"
#include "render/gizmos.h"

#include <QPointF>
#include <memory>
#include <optional>

namespace lr {

class Scene;

// Where a light's gizmo is drawn (world): its position for point and spot lights; for directional and rim
// lights (which have no position) outside the scene's bounding sphere, against the light's direction.
glm::dvec3 lightAnchor(const Rig& rig, const SceneFrame& frame, const Light& light);
// Length (world) of a spot light's cone gizmo: its range when it has one (capped), else the scene's radius.
double spotGizmoLength(const Rig& rig, const SceneFrame& frame, const Light& light);

// Cone angles set by dragging the cone edge are rounded to this step (degrees); typed values stay exact.
constexpr double kConeStepDegrees = 0.5;
double roundConeAngle(double degrees);

class GizmoInteraction {
  public:
    static constexpr double kPickPixels = 12.0; // how near a click must be to a gizmo
    static constexpr double kDragThreshold = 3.0;

    enum class Drag { None, Move, MoveAlongView, ConeOuter, AreaSize };

    GizmoInteraction(Document* document, Scene* scene);
    ~GizmoInteraction();

    // Light row whose gizmo is nearest to `screen` (within kPickPixels), or -1.
    int pickLight(const ScreenProjector& projector, const QPointF& screen) const;
    // Area light row whose outline passes within kPickPixels of `screen` or encloses it (nearest the camera),
    // or -1. pickLight tries the icons first, then this.
    int pickAreaLight(const ScreenProjector& projector, const QPointF& screen) const;
    // The size handle under `screen` (within kPickPixels) of the one selected area light; row -1 when none.
    struct SizeHandle {
        int row = -1;
        render::AreaHandle handle;
    };
    SizeHandle pickSizeHandle(const ScreenProjector& projector, const QPointF& screen) const;
    // Selected spot light row whose outer cone rim passes within kPickPixels of `screen`, or -1.
    int pickConeEdge(const ScreenProjector& projector, const QPointF& screen) const;

    // Left button pressed (without Shift). Returns true when it hit a gizmo (the caller then does not orbit);
    // the light is selected (Ctrl: added; Ctrl+click on a selected one: removed at the release unless it was
    // dragged) and a drag may follow.
    bool press(const ScreenProjector& projector, const QPointF& screen, Qt::KeyboardModifiers modifiers);
    // Mouse moved with the button held; `worldPerPixel` converts pixels to world units at the light's depth.
    void move(const ScreenProjector& projector, const QPointF& screen, Qt::KeyboardModifiers modifiers);
    void release(); // the button was released: ends the drag (one undo step)
    // Ends the drag and takes back what it changed (Escape), leaving nothing on the redo side. Returns true
    // when there was something to undo.
    bool cancel();
    bool isDragging() const { return m_drag != Drag::None; }
    Drag drag() const { return m_drag; }

    // Aims the selected spot, directional and rim lights at the model point under `screen` (one undo step).
    // Returns false (and *message) when nothing is hit or no selected light has a direction.
    bool aimSelectedAt(const ScreenProjector& projector, const QPointF& screen, QString* message);

    // "Place the highlight" (a plain click on the model): moves each selected light so that its mirror
    // reflection, seen along the view ray through `screen`, lands on the model point P there: with R the
    // view ray mirrored about the surface normal at P (intersectModelWithNormal: the shading normal), a light
    // with a position goes to P + R·d, keeping its distance d from P; a light with a direction (spot, rect,
    // disk, directional, rim) turns to -R, so a spot or area light faces P. Position and direction are one
    // undo step. Missed: the ray misses the model; NothingSelected: it hits the model but no light is
    // selected; Refused: the document refused the values (*message says why). Only Placed changes the rig.
    enum class Highlight { Missed, NothingSelected, Placed, Refused };
    Highlight placeHighlight(const ScreenProjector& projector, const QPointF& screen, QString* message);

  private:
    void reset();
    void applyMove(const ScreenProjector& projector, const QPointF& screen, bool alongView);
    void applyAreaSize(const ScreenProjector& projector, const QPointF& screen);

    Document* m_doc;
    Scene* m_scene;
    Drag m_drag = Drag::None;
    bool m_started = false; // the mouse moved past kDragThreshold
    QPointF m_pressPos;
    QList<int> m_rows;                    // lights being dragged
    std::vector<glm::dvec3> m_startWorld; // their anchors at the press (world)
    glm::dvec3 m_pickedAnchor{0.0};
    double m_rimDistance = 0.0;  // cone drags
    render::AreaHandle m_handle; // area size drags: the handle at the press
    glm::dvec3 m_areaCentre{0.0};
    int m_startIndex = 0;    // undo index when the drag started moving
    LightId m_toggleOff = 0; // Ctrl+click on a selected light: deselect at the release if not dragged
    std::unique_ptr<ContinuousEdit> m_edit;
};

} // namespace lr
