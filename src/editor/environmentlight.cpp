#include "editor/environmentlight.h"

#include "editor/document.h"
#include "editor/environmentvalue.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::EnvironmentLight", text);
}
} // namespace

EnvironmentLightResult addLightFromEnvironment(Document* doc, const EnvironmentImage& image,
                                               const glm::dvec3& clicked, bool dimSpot) {
    const Rig& rig = doc->rig();
    EnvironmentLightResult out;
    if (rig.environment.isNone()) {
        out.message = tr("The rig has no environment to take a light from.");
        return out;
    }
    out.light = lightFromEnvironment(image, rig.environment.rotation, rig.environment.intensity,
                                     rig.shading.model, clicked);
    if (!out.light.found) {
        out.message = out.light.reason;
        return out;
    }
    if (doc->lightCount() >= kMaxRigLights) {
        out.message = tr("The rig is full (%1 lights).").arg(kMaxRigLights);
        return out;
    }
    QString name;
    for (int n = 1; name.isEmpty(); ++n) {
        const QString candidate = tr("Env light %1").arg(n);
        if (doc->uniqueLightName(candidate) == candidate) name = candidate;
    }
    Light light = makeLight(LightType::Directional, name);
    light.direction = out.light.direction;
    light.color = out.light.color;
    light.intensity = std::min(out.light.intensity, kMaxIntensity);
    Environment environment = rig.environment;
    if (dimSpot) environment.spots.push_back(out.light.spot);
    // Checked before anything is pushed, so the step is never half done.
    if (QString e = validateLight(light); !e.isEmpty()) {
        out.message = e;
        return out;
    }
    if (QString e = validateEnvironment(environment); !e.isEmpty()) {
        out.message = e;
        return out;
    }
    QUndoStack* stack = doc->undoStack();
    stack->beginMacro(tr("Light from environment"));
    QString error;
    bool ok = doc->addLights(-1, {light}, tr("Add %1").arg(name), &error);
    if (ok && dimSpot)
        ok = doc->setRigValue(RigProperty::Environment, QVariant::fromValue(environment), &error);
    stack->endMacro();
    if (!ok) { // cannot happen after the checks above; never leave half a step behind
        stack->undo();
        out.message = error;
        return out;
    }
    out.added = true;
    out.row = doc->lightCount() - 1;
    out.message = tr("Added %1 from the environment: %2 %3%4")
                      .arg(name)
                      .arg(light.intensity, 0, 'g', 4)
                      .arg(rig.shading.model == ShadingModel::Pbr ? tr("lux") : tr("(classic intensity)"))
                      .arg(dimSpot ? tr(", the spot dimmed") : QString());
    return out;
}

} // namespace lr
