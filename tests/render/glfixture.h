// Shared by the GL tests of the renderer: a main() that runs without a display (every GL test then
// skips with the reason) and a comparison of GPU float read-backs with the src/core double reference.
#pragma once

#include "core/prepare.h"
#include "core/shade.h"
#include "render/floatimage.h"
#include "render/gbuffer.h"
#include "support/cli.h"

#include <QGuiApplication>
#include <QString>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <glm/mat4x4.hpp>

namespace lr::test {

using lrtest::haveDisplay; // tests/support/cli.h

#define LR_REQUIRE_DISPLAY()                                                                                 \
    do {                                                                                                     \
        if (!lr::test::haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");        \
    } while (0)

// Without a display, start on the offscreen platform (no OpenGL there) so the tests can skip cleanly.
#define LR_GL_TEST_MAIN(TestClass)                                                                           \
    int main(int argc, char** argv) {                                                                        \
        if (!lr::test::haveDisplay()) qputenv("QT_QPA_PLATFORM", "offscreen");                               \
        QGuiApplication app(argc, argv);                                                                     \
        TestClass tc;                                                                                        \
        QTEST_SET_MAIN_SOURCE_PATH                                                                           \
        return QTest::qExec(&tc, argc, argv);                                                                \
    }

// The largest per-channel |a − b| / max(1, |a|) of two images of one size (RGBA, alpha included).
inline double maxRelativeDifference(const FloatImage& a, const FloatImage& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int k = 0; k < 4; ++k)
            worst = std::max(worst, double(std::abs(a.pixels[i][k] - b.pixels[i][k])) /
                                        std::max(1.0, double(std::abs(a.pixels[i][k]))));
    return worst;
}

struct Comparison {
    int covered = 0;  // pixels with a surface
    int compared = 0; // ... whose reference is well-conditioned
    int skipped = 0;  // ... where a nudge of ~8 float ulps of the point moves the reference by > tol (edges)
    int failures = 0;
    int nonFinite = 0;     // GPU pixels that are NaN or Inf (anywhere in the image)
    double maxError = 0.0; // max over compared channels of |gpu - ref| / max(1, |ref|)
    double maxReference = 0.0;
    QString firstFailure;
    QString summary() const {
        return QStringLiteral("covered %1, compared %2, skipped %3, failed %4, non-finite %5, max error %6, "
                              "max radiance %7%8")
            .arg(covered)
            .arg(compared)
            .arg(skipped)
            .arg(failures)
            .arg(nonFinite)
            .arg(maxError, 0, 'g', 3)
            .arg(maxReference, 0, 'g', 3)
            .arg(firstFailure.isEmpty() ? QString() : QStringLiteral("; first: ") + firstFailure);
    }
};

// Per channel: |gpu − ref| <= tol · max(1, |ref|), ref = lighting::shadeSurface<double> of the pixel's
// G-buffer surface with the rig prepared in double for `view`.
inline Comparison compareWithReference(const FloatImage& radiance, const GBuffer& g, const Rig& rig,
                                       const SceneFrame& frame, const glm::dmat4& view, double tol) {
    using V = glm::dvec3;
    Comparison c;
    const auto lights = prepareLights(rig, frame, view);
    const auto settings = prepareSettings(rig, frame);
    for (int y = 0; y < radiance.height; ++y) {
        for (int x = 0; x < radiance.width; ++x) {
            const glm::vec4 gpu = radiance.at(x, y);
            if (!std::isfinite(gpu.x) || !std::isfinite(gpu.y) || !std::isfinite(gpu.z) ||
                !std::isfinite(gpu.w)) {
                ++c.nonFinite;
                continue;
            }
            if (g.position.at(x, y).w < 0.5f) continue;
            ++c.covered;
            const lighting::Surface<double> s = render::surfaceAt(g, x, y); // the G-buffer codec's decode
            const V ref = lighting::shadeSurface<double>(s, lights, settings);
            // Conditioning: nudge the point by ~8 float ulps of its coordinates; a jump means an edge.
            double spread = 0.0;
            const double h = 1e-6 * std::max(1e-3, glm::length(s.position));
            for (int axis = 0; axis < 3; ++axis) {
                for (double sign : {-1.0, 1.0}) {
                    lighting::Surface<double> t = s;
                    t.position[axis] += sign * h;
                    const V r = lighting::shadeSurface<double>(t, lights, settings);
                    for (int k = 0; k < 3; ++k)
                        spread = std::max(spread, std::abs(r[k] - ref[k]) / std::max(1.0, std::abs(ref[k])));
                }
            }
            if (!(spread <= tol)) {
                ++c.skipped;
                continue;
            }
            ++c.compared;
            for (int k = 0; k < 3; ++k) {
                c.maxReference = std::max(c.maxReference, std::abs(ref[k]));
                const double e = std::abs(double(gpu[k]) - ref[k]) / std::max(1.0, std::abs(ref[k]));
                c.maxError = std::max(c.maxError, std::isfinite(e) ? e : 1e300);
                if (!(e <= tol)) {
                    if (c.failures == 0)
                        c.firstFailure = QStringLiteral("pixel (%1,%2) channel %3: gpu %4, reference %5")
                                             .arg(x)
                                             .arg(y)
                                             .arg(k)
                                             .arg(double(gpu[k]), 0, 'g', 9)
                                             .arg(ref[k], 0, 'g', 9);
                    ++c.failures;
                    break;
                }
            }
        }
    }
    return c;
}

} // namespace lr::test
