#include "iesshade.h"

#include "prepare.h"

namespace lr {

double iesScale(const IesSpec& spec, const IesProfile& profile) {
    if (spec.level == IesLevel::Profile) return spec.multiplier;
    return profile.peak > 0.0 ? spec.multiplier / profile.peak : 0.0;
}

void applyIesProfile(lighting::ShadeLight<double>& o, const Light& light, const IesProfile* profile,
                     const glm::dmat4& view) {
    if (!profile || !light.ies || !light.usesPosition() || light.isArea()) return;
    const auto toView = [&](const glm::dvec3& d) {
        return glm::normalize(glm::dvec3(view * glm::dvec4(d, 0.0)));
    };
    const glm::dvec3 nadir = lighting::safeNormalize(light.direction, glm::dvec3(0.0, -1.0, 0.0));
    const AreaAxes axes = areaAxes(nadir, light.ies->rotation);
    o.ies = profile;
    o.iesNadir = toView(nadir);
    o.iesX = toView(axes.x);
    o.iesY = toView(axes.y);
    o.iesScale = iesScale(*light.ies, *profile);
    if (light.ies->level == IesLevel::Profile) { // the file's candela replace the light's intensity
        const glm::dvec3 color = light.effectiveColor();
        o.color = color;
        o.specular = light.specularIsColor ? light.specular : color * light.specular.x;
        o.ambient = light.ambient.value_or(glm::dvec3(0.0));
    }
}

} // namespace lr
