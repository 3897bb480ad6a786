// Shaping a light's emission (issue 39; docs/light-shaping.md): an IES photometric profile on a point or
// spot light, a gobo (a projected image) on a spot, barn doors on a rect softbox. Plain rig data, as the
// file writes it; what each does to the light is core/ies.h, core/gobo.h and core/barndoors.h, and the
// files they name are loaded once per scene (scene/lightassets.h).
#pragma once

#include <QString>

namespace lr {

// Who sets an IES light's level: the profile's own candela (× multiplier; the light's intensity is not
// used) or the light's intensity (the profile normalised to a peak of 1, × multiplier).
enum class IesLevel { Profile, Light };

// An IES (ANSI/IES LM-63) profile on a point or spot light. Its photometric axis (vertical angle 0, the
// nadir) is the light's direction, and horizontal angle 0 lies along areaAxes(direction, rotation).x
// (core/prepare.h).
struct IesSpec {
    QString file;     // as the rig writes it: relative to the rig's folder, or absolute
    QString resolved; // in memory only: the absolute path (resolveLightFiles); empty: `file` as it is
    double multiplier = 1.0;
    IesLevel level = IesLevel::Light;
    double rotation = 0.0; // degrees about the photometric axis
    bool operator==(const IesSpec&) const = default;
};

// A gobo on a spot light: an image projected through the cone, `scale` times the cone's width, turned
// `rotation` degrees about the spot's axis.
struct GoboSpec {
    QString file;     // PNG or EXR, as IesSpec::file
    QString resolved; // as IesSpec::resolved
    double scale = 1.0;
    double rotation = 0.0;
    bool operator==(const GoboSpec&) const = default;
};

// Barn doors on a rect light, as Unreal Engine 5's rect light defines them: four flaps hinged on the
// emitter's edges, each `length` long (rig units), at `angle` degrees.
struct BarnDoors {
    double angle = 88.0;
    double length = 0.2;
    bool operator==(const BarnDoors&) const = default;
};

// Where a file a rig names is on disk: absolute as it is (cleaned), relative against the rig's folder
// (empty folder: the current one).
QString resolveRigRelative(const QString& file, const QString& rigFolder);

} // namespace lr
