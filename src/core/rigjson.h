// Rig files: JSON, format "lightrig", versions 1 to 4 (docs/rig-format.md). Reading validates everything and
// reports every error as "FILE: json.path: reason"; writing is canonical (stable key order, only the
// fields a light's type and models use) and atomic.
#pragma once

#include "rig.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace lr {

// The newest version this LightRig reads; it reads every older one too. 2 (issue 16) added the rect and disk
// light types and their "area", 3 (issue 38) a light's "link", 4 (issue 39) a light's "ies", a spot's "gobo"
// and a rect light's "barnDoors"; a rig is written as the oldest version that holds it (rigjson_area.cpp), so
// a rig without links stays version 2 byte for byte.
constexpr int kRigFormatVersion = 4;
constexpr qint64 kMaxRigFileBytes = 16 * 1024 * 1024;
constexpr int kMaxRigLights = 4096;
// Value limits of the format (docs/rig-format.md), for editors that want to stay within them.
constexpr int kMaxRigNameLength = 256;   // rig and light names, in characters (code points)
constexpr int kMaxLinkNames = 1024;      // names in one of a light's link lists
constexpr double kMaxRigIntensity = 1e6; // intensity, colour components, specular, ambient
constexpr double kMaxRigLength = 1e12;   // |position components|, ranges, inverse-polynomial terms
constexpr double kMaxRigExponent = 1e4;  // falloff, cone and rim exponents, shininess
// A light's "shadow" and the rig's "ground" (docs/rig-format.md; lr::Shadow, lr::Ground in rig.h).
constexpr int kMinShadowResolution = 256; // texels per side, a power of two
constexpr int kMaxShadowResolution = 4096;
constexpr double kMaxShadowBias = 16.0;  // bias and normal offset, shadow-map texels, >= 0
constexpr double kMaxShadowAngle = 10.0; // a directional light's angular diameter, degrees, >= 0
// The rig's "environment" (docs/rig-format.md; lr::Environment in environment.h).
constexpr double kMaxEnvironmentEV = 20.0;            // intensity, EV: -20 ... 20
constexpr double kMaxSoftboxAngle = 170.0;            // a softbox's width and height, degrees: (0, 170]
constexpr double kMaxEnvironmentSpotAngle = 90.0;     // a dimmed spot's angle, degrees: (0, 90]
constexpr double kMaxEnvironmentSpotThreshold = 1e30; // a dimmed spot's luminance threshold: 0 ... 1e30
constexpr int kMaxEnvironmentSoftboxes = 32;
constexpr int kMaxEnvironmentSpots = 64;
constexpr int kMaxEnvironmentPathLength = 4096; // "file", in characters

// A rotation in degrees as the format writes it: in [0, 360) (-90 -> 270, 720 -> 0); non-finite values are
// returned as they are (the reader refuses them).
double normalizedEnvironmentRotation(double degrees);

// Whether v is a shadow-map resolution the format allows: a power of two from 256 to 4096.
constexpr bool isShadowResolution(double v) {
    for (int r = kMinShadowResolution; r <= kMaxShadowResolution; r *= 2)
        if (v == r) return true;
    return false;
}
// The lights that hold a shadow map: a type that casts shadows with its shadow switched on, whether the
// light itself is on or off (switching a light on never runs into kMaxShadowCasters). At most
// kMaxShadowCasters in a rig file and in the editor.
inline int shadowCasterCount(const std::vector<Light>& lights) {
    int n = 0;
    for (const Light& l : lights)
        n += l.castsShadows() && l.shadow.enabled;
    return n;
}

struct RigReadResult {
    std::optional<Rig> rig; // set only when errors is empty
    QStringList errors;     // "FILE: lights[2].falloff.range: must be a finite number > 0, got -5"
    QStringList warnings;   // unknown keys and the like, same format
    int unlistedErrors = 0; // errors past the listed ones (errors ends "FILE: N more errors not listed")
    bool ok() const { return rig.has_value(); }
    // Every error found, listed or not (the "N more errors not listed" line is not one).
    int errorCount() const { return int(errors.size()) - (unlistedErrors ? 1 : 0) + unlistedErrors; }
};

// displayName is the FILE part of messages (usually the file name as the user gave it).
RigReadResult readRigJson(const QByteArray& data, const QString& displayName);
RigReadResult readRigFile(const QString& filePath);

QByteArray writeRigJson(const Rig& rig);
// Atomic (writeFileAtomically, atomicwrite.h): on failure the previous file is intact and *error says why:
// "FILE: not saved: no space left on device".
bool saveRigFile(const Rig& rig, const QString& filePath, QString* error);

// Built-in presets (resources/presets/*.json embedded as :/resources/presets/NAME.json).
QStringList builtinPresetNames(); // sorted, without ".json"
QString builtinPresetPath(const QString& name);
RigReadResult readBuiltinPreset(const QString& name);
Rig defaultRig(); // the "default" preset; a built-in fallback if it were ever unreadable

} // namespace lr
