#include "turntable.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

namespace lr {

namespace {

glm::dquat aboutUp(double degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::dvec3(0.0, 1.0, 0.0));
}

// The index of the last run of '#' in the file-name part of `pattern` and its length; {-1, 0} if none.
std::pair<int, int> frameField(const QString& pattern) {
    const int nameStart = int(pattern.lastIndexOf(QLatin1Char('/'))) + 1;
    const int end = int(pattern.lastIndexOf(QLatin1Char('#')));
    if (end < nameStart) return {-1, 0};
    int start = end;
    while (start > nameStart && pattern[start - 1] == QLatin1Char('#'))
        --start;
    return {start, end - start + 1};
}

} // namespace

double turntableDegrees(int frame, int frames) {
    if (frame <= 0 || frames <= 0) return 0.0;
    return 360.0 * double(frame) / double(frames);
}

ViewCamera orbitCamera(const ViewCamera& camera, const glm::dvec3& center, double degrees) {
    if (degrees == 0.0) return camera;
    const glm::dquat q = aboutUp(degrees);
    ViewCamera c = camera;
    c.eye = center + q * (camera.eye - center);
    c.target = center + q * (camera.target - center);
    c.up = q * camera.up;
    return c;
}

Rig rotateRigLights(const Rig& rig, const glm::dvec3& center, double degrees) {
    if (degrees == 0.0) return rig;
    const glm::dquat q = aboutUp(degrees);
    const glm::dvec3 pivot = rig.space == RigSpace::Model ? glm::dvec3(0.0) : center;
    Rig r = rig;
    for (Light& l : r.lights) {
        l.position = pivot + q * (l.position - pivot);
        l.direction = q * l.direction;
    }
    r.environment.rotation += degrees;
    return r;
}

bool hasFrameField(const QString& pattern) {
    return frameField(pattern).first >= 0;
}

QString framePath(const QString& pattern, int frame) {
    const auto [start, length] = frameField(pattern);
    if (start < 0) return pattern;
    QString p = pattern;
    return p.replace(start, length, QStringLiteral("%1").arg(frame, length, 10, QLatin1Char('0')));
}

} // namespace lr
