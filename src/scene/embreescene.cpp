#include "embreescene.h"

#include <algorithm>
#include <cmath>
#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <limits>

namespace lr {

namespace {

RTCScene scene(void* p) {
    return static_cast<RTCScene>(p);
}

float farOf(double distance) {
    return distance < double(std::numeric_limits<float>::max()) ? float(distance)
                                                                : std::numeric_limits<float>::infinity();
}

// Rejects the hits on a geometry whose mask (its user data) shares no bit with the ray's: what the ray
// masks do, where the device has none.
void maskFilter(const RTCFilterFunctionNArguments* args) {
    const std::uint32_t geometryMask = *static_cast<const std::uint32_t*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] != 0 && !(RTCRayN_mask(args->ray, args->N, i) & geometryMask)) args->valid[i] = 0;
}

} // namespace

std::vector<std::uint32_t> EmbreeScene::shadowClassMasks(const LinkResolution& links) {
    std::vector<std::uint32_t> masks;
    if (!links.active) return masks;
    masks.reserve(links.shadowClass.size());
    for (const std::uint8_t c : links.shadowClass)
        masks.push_back(1u << (c % kMaxLinkClasses));
    return masks;
}

EmbreeScene::EmbreeScene(const std::vector<const Model*>& models, const glm::dvec3& origin,
                         std::vector<std::uint32_t> partMasks, bool forceFilter)
    : m_origin(origin) {
    RTCDevice dev = rtcNewDevice(nullptr);
    if (!dev) {
        m_error = QStringLiteral("Embree could not start (rtcNewDevice failed)");
        return;
    }
    m_device = dev;
    if (!partMasks.empty()) {
        const bool rayMasks = rtcGetDeviceProperty(dev, RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED) != 0;
        if (rayMasks && !forceFilter) {
            m_maskMethod = MaskMethod::RayMask;
        } else if (rtcGetDeviceProperty(dev, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) != 0) {
            m_maskMethod = MaskMethod::Filter;
        } else {
            m_error = QStringLiteral("this Embree has neither ray masks nor filter functions, which shadow "
                                     "linking needs");
            return;
        }
        size_t geometries = 0;
        for (const Model* model : models)
            geometries += model ? model->meshes.size() : 0;
        partMasks.resize(geometries, kAllLinkClasses); // set before any geometry points into it
        m_masks = std::move(partMasks);
    }
    RTCScene sc = rtcNewScene(dev);
    rtcSetSceneFlags(sc, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(sc, RTC_BUILD_QUALITY_HIGH);
    for (const Model* model : models) {
        if (!model) continue;
        const glm::dvec3 shift = model->origin - m_origin;
        for (size_t m = 0; m < model->meshes.size(); ++m) {
            const Mesh& mesh = model->meshes[m];
            const auto id = unsigned(m_parts.size());
            m_parts.push_back({model, int(m)});
            const size_t count = mesh.indices.size() / 3;
            if (count == 0 || mesh.vertices.empty()) continue;
            RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
            auto* ix = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
                geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), count));
            if (v && ix) {
                for (size_t i = 0; i < mesh.vertices.size(); ++i) {
                    const glm::vec3 p(shift + glm::dvec3(mesh.vertices[i].position));
                    v[3 * i] = p.x, v[3 * i + 1] = p.y, v[3 * i + 2] = p.z;
                }
                std::copy_n(mesh.indices.begin(), 3 * count, ix);
                if (m_maskMethod == MaskMethod::RayMask) {
                    rtcSetGeometryMask(geom, m_masks[id]);
                } else if (m_maskMethod == MaskMethod::Filter) {
                    rtcSetGeometryUserData(geom, &m_masks[id]);
                    rtcSetGeometryIntersectFilterFunction(geom, maskFilter);
                    rtcSetGeometryOccludedFilterFunction(geom, maskFilter);
                }
                rtcCommitGeometry(geom);
                rtcAttachGeometryByID(sc, geom, id);
                m_triangles += std::int64_t(count);
            }
            rtcReleaseGeometry(geom);
        }
    }
    rtcCommitScene(sc);
    if (const RTCError e = rtcGetDeviceError(dev); e != RTC_ERROR_NONE) {
        m_error = QStringLiteral("Embree could not build the ray-tracing scene (error %1, %2 triangles)")
                      .arg(int(e))
                      .arg(m_triangles);
        rtcReleaseScene(sc);
        return;
    }
    m_scene = sc;
}

EmbreeScene::~EmbreeScene() {
    if (m_scene) rtcReleaseScene(scene(m_scene));
    if (m_device) rtcReleaseDevice(static_cast<RTCDevice>(m_device));
}

bool EmbreeScene::occluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance, double tnear,
                           std::uint32_t mask) const {
    if (!m_scene) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    const glm::vec3 o(origin - m_origin);
    ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
    ray.dir_x = float(dir.x), ray.dir_y = float(dir.y), ray.dir_z = float(dir.z);
    ray.tnear = float(std::max(0.0, tnear));
    ray.tfar = farOf(distance);
    ray.mask = mask;
    rtcOccluded1(scene(m_scene), &context, &ray);
    return ray.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

EmbreeHit EmbreeScene::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tnear, double tfar,
                                 std::uint32_t mask) const {
    EmbreeHit out;
    if (!m_scene) return out;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    const glm::vec3 o(origin - m_origin);
    rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
    rh.ray.dir_x = float(dir.x), rh.ray.dir_y = float(dir.y), rh.ray.dir_z = float(dir.z);
    rh.ray.tnear = float(std::max(0.0, tnear));
    rh.ray.tfar = farOf(tfar);
    rh.ray.mask = mask;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene(m_scene), &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
    out.hit = true;
    out.part = rh.hit.geomID;
    out.triangle = rh.hit.primID;
    out.u = rh.hit.u, out.v = rh.hit.v, out.t = rh.ray.tfar;
    const glm::dvec3 n(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    const double len = glm::length(n);
    out.normal = len > 0.0 && std::isfinite(len) ? n / len : -dir;
    return out;
}

} // namespace lr
