// Shared by the environment tests on the GPU (tst_environment_render, tst_environment_background):
// environments whose answer is known in closed form (a uniform one, the studio with one softbox), a rig
// lit by the environment alone, a white sphere, a camera in front of it, and a fixture that renders.
#pragma once

#include "render/offscreen.h"
#include "scene/environmentloader.h"
#include "scene/envprefilter.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <memory>

namespace lr::test {

inline const QSize kSize(160, 120);
inline std::shared_ptr<const LoadedEnvironment> loaded(EnvironmentImage image) {
    auto e = std::make_shared<LoadedEnvironment>();
    e->spec.source = EnvironmentSource::Image;
    e->source = QStringLiteral("test");
    e->prefiltered = prefilterEnvironment(image);
    e->image = std::move(image);
    return e;
}

inline std::shared_ptr<const LoadedEnvironment> uniformEnvironment(glm::vec3 radiance) {
    EnvironmentImage image;
    image.width = 64;
    image.height = 32;
    image.texels.assign(size_t(64 * 32), radiance);
    return loaded(std::move(image));
}

// The procedural studio with one square softbox (size degrees of arc a side).
inline Studio oneSoftbox(double azimuth, double elevation, double size, double intensity) {
    Softbox box;
    box.azimuth = azimuth;
    box.elevation = elevation;
    box.width = box.height = size;
    box.intensity = intensity;
    Studio studio;
    studio.softboxes = {box};
    return studio;
}

inline Rig environmentRig(ShadingModel shading,
                          EnvironmentBackground background = EnvironmentBackground::Color) {
    Rig r;
    r.shading.model = shading;
    r.ambient = glm::dvec3(0.0);
    r.environment.source = EnvironmentSource::Image;
    r.environment.background = background;
    return r;
}

// A white sphere: Lambertian (classic, ks 0) or metallic 0, roughness 1 (physically based).
inline std::shared_ptr<Model> whiteSphere(glm::vec3 specular = glm::vec3(0.0f), float shininess = 32.0f) {
    auto m = std::make_shared<Model>(makeSphere(1.0, 96, 48));
    m->materials[0].baseColor = {1.0f, 1.0f, 1.0f, 1.0f};
    m->materials[0].specular = specular;
    m->materials[0].shininess = shininess;
    m->materials[0].metallic = 0.0f;
    m->materials[0].roughness = 1.0f;
    return m;
}

inline ViewCamera frontCamera() {
    ViewCamera c;
    c.eye = {0.0, 0.0, 3.5};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 45.0;
    return c;
}

inline RenderSettings settingsFor(Quality q, ShadingPath path = ShadingPath::Forward) {
    RenderSettings s;
    s.quality = q;
    s.msaaSamples = 0;
    s.shadingPath = path;
    return s;
}

class EnvironmentFixture {
  protected:
    std::unique_ptr<OffscreenRenderer> m_gl;

    FloatImage radiance(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(cam, kSize, s, &out, &error)) qWarning("%s", qPrintable(error));
        return out;
    }
    QImage image(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        QString error;
        QImage out = m_gl->renderImage(cam, kSize, s, 1, &error);
        if (out.isNull()) qWarning("%s", qPrintable(error));
        return out;
    }
};

} // namespace lr::test
