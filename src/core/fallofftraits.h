// What each distance-falloff model is: one row per FalloffModel, in enum order, and one row per field of a
// falloff object. Everything that used to list the models by hand reads these tables instead: which keys a
// model's "falloff" object has and in which order the canonical form writes them (rigjson_models.cpp,
// rigjson_write.cpp), each field's limits (the reader and the editor's property rows), whether its range is
// required, optional or absent and so whether it bounds the light's reach (culling, clustered shading, the
// gizmo's range sphere, the shaders' LR_FALLOFF_BOUNDED from shadergen.cpp), and how its values change with
// the unit of length (rig space switches, imported lights). The formula itself is not here: lighting.h and
// its GLSL twin. Adding a falloff model: docs/architecture.md, "Where to add things".
#pragma once

#include "rig.h"
#include "rigjson.h"

#include <array>

namespace lr {

// A field of a "falloff" object, in the reader's order (the order its errors are reported in).
enum class FalloffKey { Range, Exponent, Constant, Linear, Quadratic };
constexpr int kFalloffKeyCount = 5;

struct FalloffField {
    FalloffKey key;
    const char* json; // its key in the "falloff" object
    double Falloff::*member;
    double min, max; // limits of the format (docs/rig-format.md): [min, max], (min, max] when minExclusive
    bool minExclusive;
    // Also a key outside "falloff" (the cone's and a rim light's exponent): the reader does not call it
    // misplaced on the light or in "cone".
    bool sharedKey;
    // How the value changes when lengths are measured in a unit k times smaller (d' = k d): multiplied by
    // k^lengthPower (the range: 1; the linear term: -1; the quadratic term: -2).
    int lengthPower;
    // The reader's error for the key in the object of a model without it: %1 the model, %2 the models with
    // it.
    const char* absent;
};

inline constexpr std::array<FalloffField, kFalloffKeyCount> kFalloffFields{{
    {FalloffKey::Range, "range", &Falloff::range, 0.0, kMaxRigLength, true, false, 1,
     "the %1 falloff has no range"},
    {FalloffKey::Exponent, "exponent", &Falloff::exponent, 0.0, kMaxRigExponent, true, true, 0,
     "the %1 falloff has no exponent (only %2 has one)"},
    {FalloffKey::Constant, "constant", &Falloff::constant, 0.0, kMaxRigLength, false, false, 0,
     "the %1 falloff has no constant term (only %2 has)"},
    {FalloffKey::Linear, "linear", &Falloff::linear, 0.0, kMaxRigLength, false, false, -1,
     "the %1 falloff has no linear term (only %2 has)"},
    {FalloffKey::Quadratic, "quadratic", &Falloff::quadratic, 0.0, kMaxRigLength, false, false, -2,
     "the %1 falloff has no quadratic term (only %2 has)"},
}};

// Whether a model has a range, and so whether it bounds the light's reach.
enum class RangeRule {
    None,     // no range: the light reaches everywhere
    Required, // always a range: zero at d >= range
    Optional, // a range window when it has one (range >= 0); unbounded without
};

struct FalloffTraits {
    FalloffModel model;
    // Its keys besides "model", the first keyCount, in the order the canonical form writes them.
    std::array<FalloffKey, kFalloffKeyCount> keys;
    int keyCount;
    RangeRule range;
    bool needsPositiveTerm; // some of constant, linear, quadratic must be > 0 (else infinitely bright)
    // How its intensity changes with the unit of length (see FalloffField::lengthPower): 1/d² with no
    // coefficient keeps its brightness at a point by scaling the intensity by k².
    int intensityLengthPower;
};

inline constexpr std::array<FalloffTraits, size_t(enumCount<FalloffModel>())> kFalloffTraits{{
    {.model = FalloffModel::None, .keys = {}, .keyCount = 0, .range = RangeRule::None},
    {.model = FalloffModel::RangePower,
     .keys = {FalloffKey::Range, FalloffKey::Exponent},
     .keyCount = 2,
     .range = RangeRule::Required},
    {.model = FalloffModel::InversePolynomial,
     .keys = {FalloffKey::Constant, FalloffKey::Linear, FalloffKey::Quadratic, FalloffKey::Range},
     .keyCount = 4,
     .range = RangeRule::Optional,
     .needsPositiveTerm = true},
    {.model = FalloffModel::RangeQuadratic,
     .keys = {FalloffKey::Range},
     .keyCount = 1,
     .range = RangeRule::Required},
    {.model = FalloffModel::InverseSquare,
     .keys = {FalloffKey::Range},
     .keyCount = 1,
     .range = RangeRule::Optional,
     .intensityLengthPower = 2},
}};

// A row's keys agree with its range rule: a range key exactly where the rule has a range.
static_assert(
    [] {
        for (size_t i = 0; i < kFalloffTraits.size(); ++i) {
            const FalloffTraits& t = kFalloffTraits[i];
            if (int(t.model) != int(i) || t.keyCount < 0 || t.keyCount > kFalloffKeyCount) return false;
            bool range = false;
            for (int k = 0; k < t.keyCount; ++k)
                range |= t.keys[size_t(k)] == FalloffKey::Range;
            if (range != (t.range != RangeRule::None)) return false;
        }
        for (size_t i = 0; i < kFalloffFields.size(); ++i)
            if (int(kFalloffFields[i].key) != int(i)) return false;
        return true;
    }(),
    "kFalloffTraits: one row per FalloffModel in enum order, a range key exactly where it has a range; "
    "kFalloffFields: one row per FalloffKey in order");

constexpr const FalloffTraits& falloffTraitsOf(FalloffModel model) {
    return kFalloffTraits[size_t(model)];
}

constexpr const FalloffField& falloffField(FalloffKey key) {
    return kFalloffFields[size_t(key)];
}

// Whether the model's falloff object has this key.
constexpr bool falloffUses(FalloffModel model, FalloffKey key) {
    const FalloffTraits& t = falloffTraitsOf(model);
    for (int k = 0; k < t.keyCount; ++k)
        if (t.keys[size_t(k)] == key) return true;
    return false;
}

// Whether the falloff is exactly zero at d >= range: a required range always, an optional one when set.
inline bool falloffBounded(const Falloff& f) {
    const RangeRule r = falloffTraitsOf(f.model).range;
    return r == RangeRule::Required || (r == RangeRule::Optional && f.hasRange());
}

// Lengths measured in a unit k times smaller (d' = k d): the falloff's values and the light's intensity so
// that a(d) and the light's brightness stay the same at every point.
inline void scaleFalloffLengths(Falloff& f, double& intensity, double k) {
    for (const FalloffField& field : kFalloffFields) {
        double& v = f.*field.member;
        if (field.key == FalloffKey::Range && !f.hasRange()) continue; // "no range" stays negative
        switch (field.lengthPower) {
        case 1:
            v *= k;
            break;
        case -1:
            if (falloffUses(f.model, field.key)) v /= k;
            break;
        case -2:
            if (falloffUses(f.model, field.key)) v /= k * k;
            break;
        default:
            break;
        }
    }
    if (falloffTraitsOf(f.model).intensityLengthPower == 2) intensity *= k * k;
}

// The names of the models whose object has the key, quoted, for messages: "\"range-power\"".
QString falloffModelsWith(FalloffKey key);

} // namespace lr
