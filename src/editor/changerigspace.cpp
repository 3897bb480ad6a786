#include "editor/changerigspace.h"

#include "core/fallofftraits.h"
#include "editor/lightproperty.h"

#include <QCoreApplication>
#include <cmath>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::ChangeRigSpace", text);
}
} // namespace

std::optional<Rig> convertRigSpace(const Rig& rig, RigSpace space, const SceneFrame& frame, QString* error) {
    if (rig.space == space) return rig;
    Rig out = rig;
    out.space = space;
    const double radius = frame.radius > 0.0 && std::isfinite(frame.radius) ? frame.radius : 1.0;
    const SceneFrame f{frame.center, radius};
    // Distances in `out` units per distance in `rig` units: 1/radius from world to model, radius back.
    const double k = space == RigSpace::Model ? 1.0 / radius : radius;
    for (Light& l : out.lights) {
        if (!l.usesPosition()) continue;
        l.position = worldToRig(out, f, rigToWorld(rig, f, l.position));
        l.shadow.size *= k; // the emitter's diameter is a distance too (an angle needs nothing)
        // An area light's size too (its luminance is per unit area and solid angle: unchanged).
        for (double* size : {&l.area.width, &l.area.height, &l.area.radius})
            *size *= k;
        scaleFalloffLengths(l.falloff, l.intensity, k); // the range, the terms, 1/d²'s intensity
        if (const QString e = validateLight(l); !e.isEmpty()) {
            if (error) *error = tr("cannot switch to %1 space: %2: %3").arg(toString(space), l.name, e);
            return std::nullopt;
        }
    }
    return out;
}

std::unique_ptr<ChangeRigSpace> ChangeRigSpace::create(Document* doc, RigSpace space, const SceneFrame& frame,
                                                       QString* error) {
    if (doc->rig().space == space) {
        if (error) *error = tr("the rig already is in %1 space").arg(toString(space));
        return nullptr;
    }
    std::optional<Rig> after = convertRigSpace(doc->rig(), space, frame, error);
    if (!after) return nullptr;
    return std::unique_ptr<ChangeRigSpace>(new ChangeRigSpace(doc, doc->rig(), std::move(*after)));
}

ChangeRigSpace::ChangeRigSpace(Document* doc, Rig before, Rig after)
    : RigCommand(doc), m_ids(doc->lightIds()), m_before(std::move(before)), m_after(std::move(after)) {
    setText(tr("Switch the rig to %1 space").arg(toString(m_after.space)));
}

void ChangeRigSpace::apply(const Rig& rig) {
    Rig space;
    space.space = rig.space;
    setRigValue(RigProperty::Space, rigValue(space, RigProperty::Space));
    if (!rig.lights.empty()) setLights(m_ids, rig.lights, LightProperty::Any);
}

void ChangeRigSpace::undo() {
    apply(m_before);
}

void ChangeRigSpace::redo() {
    apply(m_after);
}

bool changeRigSpace(Document* doc, RigSpace space, const SceneFrame& frame, QString* error) {
    auto cmd = ChangeRigSpace::create(doc, space, frame, error);
    if (!cmd) return false;
    doc->undoStack()->push(cmd.release());
    return true;
}

} // namespace lr
