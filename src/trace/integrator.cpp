#include "integrator.h"

#include "bsdf.h"

#include "core/envintegrate.h"
#include "core/montecarlo.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lr::trace {

namespace {

using envintegrate::luminance;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double powerHeuristic(double a, double b) {
    const double a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0 && std::isfinite(a2 + b2) ? a2 / (a2 + b2) : (std::isinf(a) ? 1.0 : 0.0);
}

double maxOf(const glm::dvec3& c) {
    return std::max({c.x, c.y, c.z});
}

double cosineTerm(DiffuseModel model, double nDotL) {
    return model == DiffuseModel::Lambert ? lighting::diffuseLambert(nDotL)
                                          : lighting::diffuseHalfLambert(nDotL);
}

// Where the shadow ray of a point, spot or directional light goes: a uniform point of the disk of the
// emitter's radius facing `p` (or the centre), or a direction within its cone. *distance: infinite for
// directional lights.
glm::dvec3 shadowTarget(const TraceLight& light, const glm::dvec3& p, const glm::dvec3& toLight, Sampler& s,
                        double* distance) {
    const ShadowEmitter& e = light.emitter;
    if (e.directional) {
        *distance = kInfinity;
        if (!(e.halfAngle > 0.0)) return toLight;
        const glm::dvec2 u = s.next2();
        return montecarlo::around(toLight, 1.0 - u.x * (1.0 - std::cos(e.halfAngle)),
                                  2.0 * std::numbers::pi * u.y);
    }
    glm::dvec3 target = light.shade.position;
    if (e.radius > 0.0) {
        glm::dvec3 t, b;
        montecarlo::frameAround(toLight, &t, &b);
        const glm::dvec2 u = s.next2();
        const double r = e.radius * std::sqrt(u.x), phi = 2.0 * std::numbers::pi * u.y;
        target += r * (std::cos(phi) * t + std::sin(phi) * b);
    }
    const glm::dvec3 d = target - p;
    *distance = glm::length(d);
    return *distance > 0.0 ? d / *distance : toLight;
}

struct Vertex {
    const TraceScene& scene;
    const SurfacePoint& s;
    const Bsdf& bsdf;
    Sampler& sampler;
    const glm::dvec3& beta; // the path's throughput to this vertex
    glm::dvec3* groups;     // null, or the sample's per-group radiance (PathSplit::groups)
};

// Next-event estimation at one surface: every light, the environment and one emissive triangle. Each
// term is also added, × beta, to its group when the sample is split.
glm::dvec3 directLight(const Vertex& v) {
    const TraceScene& scene = v.scene;
    const SurfacePoint& s = v.s;
    const Bsdf& bsdf = v.bsdf;
    const glm::dvec3 N = bsdf.normal();
    const glm::dvec3 cDiff = bsdf.diffuseColor() * (lighting::saturate(s.occlusion) / std::numbers::pi);
    glm::dvec3 sum(0.0);
    const auto add = [&](const glm::dvec3& term, int group) {
        sum += term;
        if (v.groups) v.groups[group] += v.beta * term;
    };
    add(scene.ambient() * cDiff, scene.ambientGroup());
    lighting::Surface<double> surf;
    surf.position = s.position;
    surf.normal = N;
    for (const TraceLight& light : scene.lights()) {
        if (scene.linked() && !scene.lights(light, s.part)) continue; // none of its terms here
        const lighting::ShadeLight<double>& l = light.shade;
        if (traitsOf(l.type).isArea) {
            if (!areaLightFaces(light, s.position)) continue;
            add(l.ambient * cDiff, light.group);
            if (!(light.area > 0.0)) continue;
            const glm::dvec2 u = v.sampler.next2();
            const AreaLightSample q = sampleAreaLightFrom(light, s.position, u.x, u.y);
            const glm::dvec3 d = q.point - s.position;
            const double dist = glm::length(d), pdf = q.pdf;
            if (!(dist > 0.0) || !(pdf > 0.0) || !std::isfinite(pdf)) continue;
            const glm::dvec3 w = d / dist;
            const lighting::PbrLobes<double> f = bsdf.lobes(w, cosineTerm(l.diffuse, glm::dot(N, w)));
            const glm::dvec3 c = l.color * f.diffuse + l.specular * f.specular;
            if (!(maxOf(c) > 0.0)) continue;
            if (!scene.unoccluded(scene.offset(s, w), w, dist * (1.0 - 1e-6), v.sampler,
                                  light.emitter.shadowMask))
                continue;
            add(c * (powerHeuristic(pdf, bsdf.pdf(w)) / pdf), light.group);
            continue;
        }
        glm::dvec3 L;
        double attenuation;
        if (!lighting::lightArrival(l, surf, scene.settings(), &L, &attenuation)) continue;
        const glm::dvec3 tint = lighting::goboTint(l, L); // issue 39: 1 without a gobo
        add(attenuation * l.ambient * cDiff * tint, light.group);
        const lighting::PbrLobes<double> f = bsdf.lobes(L, cosineTerm(l.diffuse, glm::dot(N, L)));
        const glm::dvec3 c = attenuation * tint * (l.color * f.diffuse + l.specular * f.specular);
        if (!(maxOf(c) > 0.0)) continue;
        double distance = kInfinity;
        const glm::dvec3 w = shadowTarget(light, s.position, L, v.sampler, &distance);
        const glm::dvec3 origin = scene.offset(s, w);
        if (scene.unoccluded(origin, w, std::isfinite(distance) ? distance * (1.0 - 1e-9) : distance,
                             v.sampler, light.emitter.shadowMask))
            add(c, light.group);
    }
    if (scene.hasEnvironment()) {
        glm::dvec3 w;
        double pdf;
        const glm::dvec2 u = v.sampler.next2();
        if (scene.environment().sample(u.x, u.y, v.sampler.next(), &w, &pdf)) {
            const glm::dvec3 f = bsdf.eval(w);
            if (maxOf(f) > 0.0 && glm::dot(w, s.geometric) > 0.0 &&
                scene.unoccluded(scene.offset(s, w), w, kInfinity, v.sampler))
                add(f * scene.environment().radiance(w) * (powerHeuristic(pdf, bsdf.pdf(w)) / pdf),
                    scene.environmentGroup());
        }
    }
    if (!scene.emissive().empty()) {
        double probability;
        const EmissiveTriangles::Triangle& tri = scene.emissive().pick(v.sampler.next(), &probability);
        const glm::dvec2 u = v.sampler.next2();
        const glm::dvec2 bc = sampleTriangle(u.x, u.y);
        const glm::dvec3 q = tri.p0 * (1.0 - bc.x - bc.y) + tri.p1 * bc.x + tri.p2 * bc.y;
        const glm::dvec3 d = q - s.position;
        const double dist = glm::length(d);
        const glm::dvec3 ng = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
        const double ngl = glm::length(ng);
        if (dist > 0.0 && ngl > 0.0 && tri.area > 0.0) {
            const glm::dvec3 w = d / dist;
            const double cosL = std::abs(glm::dot(w, ng / ngl));
            const double pdf = probability / tri.area * dist * dist / cosL;
            const glm::dvec3 f = bsdf.eval(w);
            if (cosL > 0.0 && std::isfinite(pdf) && maxOf(f) > 0.0 && glm::dot(w, s.geometric) > 0.0 &&
                scene.unoccluded(scene.offset(s, w), w, dist - 2.0 * scene.epsilon(), v.sampler)) {
                EmbreeHit h;
                h.hit = true, h.part = tri.part, h.triangle = tri.triangle, h.u = bc.x, h.v = bc.y;
                h.normal = ng / ngl;
                const glm::dvec3 le = scene.surface(h, s.position, w).emissive;
                add(f * le * (powerHeuristic(pdf, bsdf.pdf(w)) / pdf), scene.emissiveGroup());
            }
        }
    }
    return sum;
}

// The shadow catcher seen by a camera ray: the share of the lights' and the environment's light (as
// luminance on a white Lambertian plane) that reaches it.
double catcherLight(const TraceScene& scene, const glm::dvec3& p, Sampler& sampler) {
    const glm::dvec3 up = scene.catcher()->normal;
    const glm::dvec3 origin = p + up * scene.epsilon();
    double lit = 0.0, all = 0.0;
    lighting::Surface<double> surf;
    surf.position = p;
    surf.normal = up;
    for (const TraceLight& light : scene.lights()) {
        if (scene.linked() && !scene.lights(light, scene.catcherPart())) continue;
        const lighting::ShadeLight<double>& l = light.shade;
        glm::dvec3 w;
        double e = 0.0, distance = kInfinity;
        if (traitsOf(l.type).isArea) {
            if (!(light.area > 0.0) || !areaLightFaces(light, p)) continue;
            const glm::dvec2 u = sampler.next2();
            const glm::dvec3 onEmitter = sampleAreaLight(light, u.x, u.y);
            if (!areaLightSees(light, p, onEmitter)) continue; // behind a barn door's flap
            const glm::dvec3 d = onEmitter - p;
            distance = glm::length(d);
            if (!(distance > 0.0)) continue;
            w = d / distance;
            e = luminance(l.color) * lighting::saturate(glm::dot(up, w)) * light.area *
                std::abs(glm::dot(w, l.direction)) / (distance * distance);
            distance *= 1.0 - 1e-6;
        } else {
            glm::dvec3 L;
            double attenuation;
            if (!lighting::lightArrival(l, surf, scene.settings(), &L, &attenuation)) continue;
            e = attenuation * luminance(l.color * lighting::goboTint(l, L)) *
                lighting::saturate(glm::dot(up, L));
            w = shadowTarget(light, p, L, sampler, &distance);
        }
        if (!(e > 0.0) || !std::isfinite(e)) continue;
        all += e;
        if (glm::dot(w, up) > 0.0 && scene.unoccluded(origin, w, distance, sampler, light.emitter.shadowMask))
            lit += e;
    }
    glm::dvec3 w;
    double pdf;
    const glm::dvec2 u = sampler.next2();
    if (scene.hasEnvironment() && scene.environment().sample(u.x, u.y, sampler.next(), &w, &pdf)) {
        const double e =
            luminance(scene.environment().radiance(w)) * lighting::saturate(glm::dot(up, w)) / pdf;
        if (e > 0.0 && std::isfinite(e)) {
            all += e;
            if (scene.unoccluded(origin, w, kInfinity, sampler)) lit += e;
        }
    }
    return all > 0.0 ? lit / all : 1.0;
}

} // namespace

PathSample tracePath(const TraceScene& scene, const glm::dvec3& cameraOrigin, const glm::dvec3& cameraDir,
                     Sampler& sampler, const TraceSettings& settings, PathSplit* split) {
    PathSample out;
    glm::dvec3* const groups = split ? split->groups : nullptr;
    const size_t groupCount = groups ? scene.groups().size() : 0;
    if (split) {
        std::fill(groups, groups + groupCount, glm::dvec3(0.0));
        split->hit = false;
        split->albedo = split->normal = glm::dvec3(0.0);
        split->distance = 0.0;
    }
    // The radiance's own sums, as they are without the split; the split's beside them.
    const auto tag = [groups](const glm::dvec3& term, int group) {
        if (groups) groups[group] += term;
    };
    glm::dvec3 origin = cameraOrigin, dir = cameraDir, beta(1.0);
    double prevPdf = 0.0;       // the BSDF density of `dir`; 0 for the camera ray (no MIS: seen directly)
    std::uint32_t prevPart = 0; // the part `dir` leaves (linking: the lights that may light it)
    for (int depth = 0;; ++depth) {
        sampler.startBounce(depth);
        const EmbreeHit hit = scene.intersect(origin, dir, kInfinity, sampler);
        double tMax = hit.hit ? hit.t : kInfinity;
        // Area lights: emitters only (no surface to reflect), invisible to camera rays as in the raster.
        // A light that does not light the part the ray leaves is not there for it (linking): next-event
        // estimation skips it there too, so the MIS weights of the two still sum to 1 for the lights that do.
        if (depth > 0) {
            const TraceLight* nearest = nullptr;
            for (const TraceLight& light : scene.lights())
                if (double t; traitsOf(light.shade.type).isArea &&
                              (!scene.linked() || scene.lights(light, prevPart)) &&
                              hitAreaLight(light, origin, dir, &t) && t < tMax)
                    tMax = t, nearest = &light;
            if (nearest) {
                const double pdfLight = areaLightPdf(*nearest, origin, dir, tMax);
                const glm::dvec3 term = beta * nearest->shade.color * powerHeuristic(prevPdf, pdfLight);
                out.radiance += term;
                tag(term, nearest->group);
                break;
            }
        }
        if (depth == 0 && scene.catcher()) {
            const double t = scene.hitCatcher(origin, dir);
            if (t > 0.0 && t < tMax) {
                const double share = catcherLight(scene, origin + t * dir, sampler);
                if (settings.transparent) {
                    out.alpha = 1.0 - share;
                } else {
                    const glm::dvec3 behind =
                        scene.environmentVisible() ? scene.environment().radiance(dir) : settings.background;
                    out.radiance = behind * share;
                    tag(out.radiance, scene.backgroundGroup());
                }
                break;
            }
        }
        if (!hit.hit) {
            if (depth == 0) {
                if (settings.transparent) {
                    out.alpha = 0.0;
                } else if (scene.environmentVisible()) {
                    out.radiance = scene.environment().radiance(dir);
                    tag(out.radiance, scene.environmentGroup());
                } else {
                    out.radiance = settings.background;
                    tag(out.radiance, scene.backgroundGroup());
                }
            } else if (scene.hasEnvironment()) {
                const glm::dvec3 term = beta * scene.environment().radiance(dir) *
                                        powerHeuristic(prevPdf, scene.environment().pdf(dir));
                out.radiance += term;
                tag(term, scene.environmentGroup());
            }
            break;
        }
        const SurfacePoint s = scene.surface(hit, origin, dir);
        if (depth == 0 && split) {
            split->hit = true;
            split->albedo = s.baseColor;
            split->normal = s.normal;
            split->distance = hit.t;
        }
        if (maxOf(s.emissive) > 0.0) {
            double w = 1.0;
            if (depth > 0) {
                const double cosL = std::abs(glm::dot(dir, hit.normal));
                const double pdfLight =
                    scene.emissive().areaDensity(hit.part, hit.triangle) * hit.t * hit.t / cosL;
                w = powerHeuristic(prevPdf, pdfLight);
            }
            const glm::dvec3 term = beta * s.emissive * w;
            out.radiance += term;
            tag(term, scene.emissiveGroup());
        }
        if (depth >= settings.bounces) break;
        const Bsdf bsdf(s.normal, -dir, s.baseColor, s.metallic, s.roughness);
        out.radiance += beta * directLight({scene, s, bsdf, sampler, beta, groups});
        const double lobe = sampler.next();
        const glm::dvec2 u = sampler.next2();
        const BsdfSample bs = bsdf.sample(lobe, u.x, u.y);
        if (!(bs.pdf > 0.0) || !(glm::dot(bs.direction, s.geometric) > 0.0)) break;
        beta *= bs.value / bs.pdf;
        if (!(maxOf(beta) > 0.0)) break;
        if (depth + 1 >= settings.rouletteDepth) {
            const double survive = std::min(0.95, maxOf(beta));
            if (!(sampler.next() < survive)) break;
            beta /= survive;
        }
        origin = scene.offset(s, bs.direction);
        dir = bs.direction;
        prevPdf = bs.pdf;
        prevPart = s.part;
    }
    const double r = out.radiance.x + out.radiance.y + out.radiance.z;
    out.finite = std::isfinite(r) && std::isfinite(out.alpha);
    if (!out.finite) {
        out.radiance = glm::dvec3(0.0);
        out.alpha = 1.0;
        if (groups) std::fill(groups, groups + groupCount, glm::dvec3(0.0));
    } else if (settings.fireflyClamp > 0.0 && maxOf(out.radiance) > settings.fireflyClamp) {
        const double k = settings.fireflyClamp / maxOf(out.radiance);
        out.radiance *= k;
        for (size_t g = 0; g < groupCount; ++g)
            groups[g] *= k;
    }
    return out;
}

} // namespace lr::trace
