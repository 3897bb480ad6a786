// Light linking and shadow linking (issue 38; docs/light-linking.md): which parts of the model a light
// lights, and which parts cast its shadow. A part is one mesh of the model as the Model dock lists it (a
// glTF primitive placed by a node), or the rig's ground.
//
// Names. A name in a list matches a part when it equals the part's node name, its mesh name or its
// material name; "node:NAME", "mesh:NAME" and "material:NAME" match that kind only (for a model whose node
// and material share a name). The ground answers to "ground". Matching is exact and case-sensitive.
//
// Lists. A PartSet is every part, unless `include` names some (then only the parts it matches), less the
// parts `exclude` matches: exclusion wins. A name matching no part of the loaded model is kept (the rig may
// be meant for another model) and reported as a warning, never dropped.
//
// Renderers do not match names: resolveLinks turns a rig and a model's parts into classes (parts that the
// same lights reach share a lighting class; parts that cast for the same lights share a shadow class) and
// per light a 32-bit mask of the classes it reaches, so that a shader, a G-buffer or an Embree ray mask holds
// linking in a few bits. A rig without links resolves to inactive: renderers then compile and test nothing.
#pragma once

#include <QString>
#include <QStringList>
#include <cstdint>
#include <utility>
#include <vector>

namespace lr {

struct Light;

struct PartSet {
    QStringList include; // empty: every part
    QStringList exclude;
    bool isEverything() const { return include.isEmpty() && exclude.isEmpty(); }
    bool operator==(const PartSet&) const = default;
};

// Light::link. Rig format version 3 ("link": {"include": [...], "exclude": [...], "shadow": {...}}).
struct LightLink {
    PartSet lit;    // the parts the light lights
    PartSet shadow; // the parts that cast its shadow (only where it casts one)
    bool isDefault() const { return lit.isEverything() && shadow.isEverything(); }
    bool operator==(const LightLink&) const = default;
};

// The names one part answers to (scene/linkparts.h makes them from a model).
struct PartNames {
    QString node, mesh, material;
    bool ground = false; // the rig's ground: answers to "ground" only
    static PartNames of(QString node, QString mesh = {}, QString material = {}) {
        PartNames p;
        p.node = std::move(node), p.mesh = std::move(mesh), p.material = std::move(material);
        return p;
    }
    static PartNames theGround() {
        PartNames p;
        p.ground = true;
        return p;
    }
    bool operator==(const PartNames&) const = default;
};

constexpr int kMaxLinkClasses = 32; // a class is one bit of a light's mask
constexpr std::uint32_t kAllLinkClasses = 0xffffffffu;

// Whether `name` (as a list holds it, prefix included) names `part`.
bool partNameMatches(const QString& name, const PartNames& part);
bool partSetContains(const PartSet& set, const PartNames& part);
// A name as a list may hold it: non-empty, and a prefix ("node:", "mesh:", "material:") followed by a name;
// the reason when not (rig reader and editor).
QString partNameProblem(const QString& name);

struct LinkResolution {
    bool active = false; // some light's link is not the default; false: every mask all ones, classes 0
    // Per part (the order of the PartNames given):
    std::vector<std::uint8_t> litClass, shadowClass;
    // Per light (the order of the lights given): bit c set when the light lights the parts of lighting
    // class c (litMask) / when the parts of shadow class c cast its shadow (shadowMask).
    std::vector<std::uint32_t> litMask, shadowMask;
    int litClasses = 1, shadowClasses = 1;
    // Names that match no part: "Rim: link.include: \"Visor\" matches no part of the model".
    QStringList warnings;

    bool lights(std::size_t light, std::size_t part) const {
        return !active || (litMask[light] >> litClass[part] & 1u);
    }
    bool casts(std::size_t light, std::size_t part) const {
        return !active || (shadowMask[light] >> shadowClass[part] & 1u);
    }
};

// Classes for `parts` under `lights` (disabled lights included: masks are per index). More distinct sets of
// lights than kMaxLinkClasses: the parts past the limit get class 0's lights, with a warning.
LinkResolution resolveLinks(const std::vector<Light>& lights, const std::vector<PartNames>& parts);

// What each linked light's names match, for `render` and `validate --model`: one line per name, e.g.
// "Rim: link.include \"Visor\": 2 parts (Visor, Visor_glass)", or "... : no part of the model".
QStringList describeLinkMatches(const std::vector<Light>& lights, const std::vector<PartNames>& parts);

} // namespace lr
