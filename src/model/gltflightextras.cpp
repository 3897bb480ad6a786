// What Assimp 5.2.5 does not read of a glTF's lights (issue 39, docs/export.md "Import"): EXT_lights_ies
// instances and LightRig's extras.lightrig {link, gobo, barnDoors} on light nodes, in the import worker;
// whatever cannot be used is a warning naming the file and the JSON field, never a failed import. An
// EXT_lights_ies node is a point light at the node's origin, its nadir the node's -Z and horizontal angle 0
// its +X (the inverse of core/gltflights_ies.cpp), level "profile".
#include "importdetail.h"

#include "core/rigjson.h"
#include "core/rigjson_extras.h"

#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <optional>

namespace lr::detail {

namespace {

struct SceneNode {
    int index;
    glm::dmat4 world;
};

// `N` numbers of a JSON array, or nullopt when it is not exactly that.
template <int N> std::optional<std::array<double, N>> numbers(const QJsonValue& v) {
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != N) return std::nullopt;
    std::array<double, N> out{};
    for (int i = 0; i < N; ++i) {
        if (!a[i].isDouble()) return std::nullopt;
        out[i] = a[i].toDouble();
    }
    return out;
}

// A node's local transform: its matrix (column-major), else translation × rotation × scale.
glm::dmat4 localTransform(const QJsonObject& node) {
    if (const auto m = numbers<16>(node.value(QLatin1String("matrix")))) {
        glm::dmat4 out(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                out[c][r] = (*m)[c * 4 + r];
        return out;
    }
    glm::dmat4 t(1.0), s(1.0);
    if (const auto v = numbers<3>(node.value(QLatin1String("translation"))))
        t[3] = glm::dvec4((*v)[0], (*v)[1], (*v)[2], 1.0);
    glm::dquat q(1.0, 0.0, 0.0, 0.0);
    if (const auto v = numbers<4>(node.value(QLatin1String("rotation"))))
        q = glm::dquat((*v)[3], (*v)[0], (*v)[1], (*v)[2]); // glTF: x, y, z, w
    if (const double n = glm::length(q); std::isfinite(n) && n > 0.0) q /= n;
    if (const auto v = numbers<3>(node.value(QLatin1String("scale"))))
        s = glm::dmat4(glm::dvec4((*v)[0], 0, 0, 0), glm::dvec4(0, (*v)[1], 0, 0),
                       glm::dvec4(0, 0, (*v)[2], 0), glm::dvec4(0, 0, 0, 1));
    return t * glm::dmat4(glm::mat3_cast(q)) * s;
}

// The nodes of the default scene (else scenes[0], else every node no other node has as a child), each
// once, with its world transform.
std::vector<SceneNode> sceneNodes(const QJsonObject& root) {
    const QJsonArray nodes = root.value(QLatin1String("nodes")).toArray();
    const QJsonArray scenes = root.value(QLatin1String("scenes")).toArray();
    QJsonArray roots;
    if (!scenes.isEmpty()) {
        const int scene = root.value(QLatin1String("scene")).toInt(0);
        roots = scenes.at(scene >= 0 && scene < scenes.size() ? scene : 0)
                    .toObject()
                    .value(QLatin1String("nodes"))
                    .toArray();
    } else {
        std::vector<bool> child(std::size_t(nodes.size()), false);
        for (const QJsonValue& n : nodes)
            for (const QJsonValue& c : n.toObject().value(QLatin1String("children")).toArray())
                if (const int i = c.toInt(-1); i >= 0 && i < nodes.size()) child[std::size_t(i)] = true;
        for (qsizetype i = 0; i < nodes.size(); ++i)
            if (!child[std::size_t(i)]) roots.append(int(i));
    }
    std::vector<SceneNode> out;
    std::vector<bool> seen(std::size_t(nodes.size()), false);
    std::vector<SceneNode> stack;
    for (qsizetype i = roots.size() - 1; i >= 0; --i)
        stack.push_back({roots[i].toInt(-1), glm::dmat4(1.0)});
    while (!stack.empty()) {
        const SceneNode parent = stack.back();
        stack.pop_back();
        if (parent.index < 0 || parent.index >= nodes.size() || seen[std::size_t(parent.index)]) continue;
        seen[std::size_t(parent.index)] = true;
        const QJsonObject node = nodes[parent.index].toObject();
        const SceneNode here{parent.index, parent.world * localTransform(node)};
        out.push_back(here);
        const QJsonArray children = node.value(QLatin1String("children")).toArray();
        for (qsizetype i = children.size() - 1; i >= 0; --i)
            stack.push_back({children[i].toInt(-1), here.world});
    }
    return out;
}

// Whether the rig format takes `light` (the check lights.cpp makes of Assimp's lights); else the reason.
QString rigProblem(const Light& light) {
    Rig one;
    one.lights = {light};
    const RigReadResult check = readRigJson(writeRigJson(one), QStringLiteral("-"));
    return check.ok() ? QString() : check.errors.first().mid(3);
}

struct Context {
    const QJsonObject& root;
    const ModelFolder& folder;
    qint64 maxDataUriBytes;
    Model& model;
    void warn(const QString& field, const QString& what) const {
        model.warnings << QStringLiteral("%1: %2: %3").arg(folder.displayName(), field, what);
    }
};

// The point light of an EXT_lights_ies instance; nullopt (with a warning) when it cannot be placed.
std::optional<Light> iesLight(const Context& cx, const SceneNode& n, const QJsonObject& node,
                              const QJsonObject& instance) {
    const QString at = QStringLiteral("nodes[%1].extensions.EXT_lights_ies").arg(n.index);
    Light l;
    l.type = LightType::Point;
    l.name = node.value(QLatin1String("name")).toString();
    if (l.name.isEmpty()) l.name = QStringLiteral("nodes[%1]").arg(n.index);
    l.name.truncate(kMaxRigNameLength);
    l.falloff.model = FalloffModel::InverseSquare;
    l.falloff.range = -1.0;
    double multiplier = 1.0;
    if (const QJsonValue m = instance.value(QLatin1String("multiplier")); !m.isUndefined()) {
        if (m.isDouble() && std::isfinite(m.toDouble()) && m.toDouble() >= 0.0)
            multiplier = m.toDouble();
        else
            cx.warn(at + QStringLiteral(".multiplier"), QStringLiteral("must be a number >= 0; 1 instead"));
    }
    glm::dvec3 color(1.0);
    if (const QJsonValue c = instance.value(QLatin1String("color")); !c.isUndefined()) {
        const auto rgb = numbers<3>(c);
        if (rgb && std::isfinite((*rgb)[0] + (*rgb)[1] + (*rgb)[2]) &&
            std::min({(*rgb)[0], (*rgb)[1], (*rgb)[2]}) >= 0.0)
            color = {(*rgb)[0], (*rgb)[1], (*rgb)[2]};
        else
            cx.warn(at + QStringLiteral(".color"),
                    QStringLiteral("must be three numbers >= 0; white instead"));
    }
    const double peak = std::max({color.r, color.g, color.b});
    l.color = peak > 0.0 ? color / peak : glm::dvec3(1.0);
    multiplier *= peak;
    if (multiplier > kMaxRigIntensity) {
        cx.warn(at, QStringLiteral("multiplier × colour %1 clamped to %2")
                        .arg(multiplier, 0, 'g', 6)
                        .arg(kMaxRigIntensity, 0, 'g', 6));
        multiplier = kMaxRigIntensity;
    }
    l.position = glm::dvec3(n.world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dmat3 axes(n.world);
    const glm::dvec3 nadir = axes * glm::dvec3(0.0, 0.0, -1.0);
    const double length = glm::length(nadir);
    if (!std::isfinite(l.position.x + l.position.y + l.position.z) || !std::isfinite(length) ||
        !(length > 0.0)) {
        cx.warn(QStringLiteral("nodes[%1]").arg(n.index),
                QStringLiteral("an EXT_lights_ies light without a finite position and direction; skipped"));
        return std::nullopt;
    }
    l.direction = nadir / length;
    const double rotation =
        normalizedEnvironmentRotation(rollForUp(l.direction, axes * glm::dvec3(0.0, 1.0, 0.0)));
    const QJsonValue index = instance.value(QLatin1String("light"));
    const GltfIesProfile profile =
        readGltfIesProfile(cx.root, index.isDouble() ? index.toInt(-1) : -1, cx.folder, cx.maxDataUriBytes);
    if (profile.file.isEmpty()) {
        cx.warn(profile.field,
                QStringLiteral("%1; light \"%2\" imported without its profile, as a point light "
                               "of its multiplier in candela")
                    .arg(profile.error, l.name));
        l.intensity = multiplier;
    } else {
        l.intensity = 1.0; // level "profile": the file's candela × multiplier; the intensity is not used
        l.ies = IesSpec{profile.file, {}, multiplier, IesLevel::Profile, rotation};
    }
    if (const QString problem = rigProblem(l); !problem.isEmpty()) {
        cx.warn(QStringLiteral("nodes[%1]").arg(n.index),
                QStringLiteral("not a valid rig light (%1); skipped").arg(problem));
        return std::nullopt;
    }
    return l;
}

// A node's extras.lightrig onto the light at `target` in the model's rig (-1: none, `why` says why).
void applyExtras(const Context& cx, int nodeIndex, const QJsonObject& lightrig, int target,
                 const QString& why) {
    const QString at = QStringLiteral("nodes[%1].extras.lightrig").arg(nodeIndex);
    LightExtras x =
        readLightExtras(QJsonDocument(lightrig).toJson(QJsonDocument::Compact), cx.folder.displayName(), at);
    for (const QString& e : x.errors)
        cx.model.warnings << e + QStringLiteral(" (ignored)");
    cx.model.warnings << x.warnings;
    if (!x.link && !x.gobo && !x.barnDoors) return;
    if (target < 0) {
        cx.warn(at, QStringLiteral("ignored: %1").arg(why));
        return;
    }
    Light& l = cx.model.lights.lights[std::size_t(target)];
    if (x.link) l.link = *x.link;
    if (x.gobo && l.type != LightType::Spot) {
        cx.warn(
            at + QStringLiteral(".gobo"),
            QStringLiteral("ignored: only spot lights have a gobo, and \"%1\" is a %2 light (a spot with an "
                           "IES profile is exported as an EXT_lights_ies point light)")
                .arg(l.name, toString(l.type)));
    } else if (x.gobo) {
        QString refusal;
        const QString path = cx.folder.resolve(x.gobo->file, &refusal);
        if (path.isEmpty())
            cx.warn(at + QStringLiteral(".gobo.file"), QStringLiteral("ignored: %1").arg(refusal));
        else if (!QFileInfo(path).isFile())
            cx.warn(at + QStringLiteral(".gobo.file"), QStringLiteral("ignored: %1: no such file").arg(path));
        else
            l.gobo = GoboSpec{path, {}, x.gobo->scale, x.gobo->rotation};
    }
    if (x.barnDoors && l.type == LightType::Rect)
        l.barnDoors = *x.barnDoors;
    else if (x.barnDoors)
        cx.warn(
            at + QStringLiteral(".barnDoors"),
            QStringLiteral("ignored: glTF has no rect lights, and \"%1\" is the %2 light that stands in for "
                           "one; barn doors need the rect")
                .arg(l.name, toString(l.type)));
}

} // namespace

void readGltfLightExtras(const QByteArray& json, const ModelFolder& folder, qint64 maxDataUriBytes,
                         Model& model) {
    if (!json.contains("EXT_lights_ies") && !json.contains("lightrig")) return; // the common case
    const QJsonObject root = QJsonDocument::fromJson(json).object();
    const QJsonArray nodes = root.value(QLatin1String("nodes")).toArray();
    const Context cx{root, folder, maxDataUriBytes, model};
    const std::vector<SceneNode> scene = sceneNodes(root);
    std::vector<Light>& lights = model.lights.lights;
    // Assimp names a glTF light after its node ("nodes[N]" or "nodes_N" when the node has no name).
    const std::size_t fromAssimp = lights.size();
    QHash<QString, int> lightNodesNamed;
    const auto assimpName = [&](int i) {
        const QString name = nodes[i].toObject().value(QLatin1String("name")).toString();
        return name.isEmpty()
                   ? QStringList{QStringLiteral("nodes[%1]").arg(i), QStringLiteral("nodes_%1").arg(i)}
                   : QStringList{name};
    };
    const auto extensionsOf = [&](const QJsonObject& node) {
        return node.value(QLatin1String("extensions")).toObject();
    };
    for (const SceneNode& n : scene)
        if (extensionsOf(nodes[n.index].toObject()).contains(QLatin1String("KHR_lights_punctual")))
            for (const QString& name : assimpName(n.index))
                ++lightNodesNamed[name];
    for (const SceneNode& n : scene) {
        const QJsonObject node = nodes[n.index].toObject();
        const QJsonObject extensions = extensionsOf(node);
        int target = -1;
        QString why = QStringLiteral("the node has no light");
        if (const QJsonValue ies = extensions.value(QLatin1String("EXT_lights_ies")); ies.isObject()) {
            if (lights.size() >= std::size_t(kMaxRigLights)) {
                cx.warn(QStringLiteral("nodes[%1]").arg(n.index),
                        QStringLiteral("more than %1 lights; this EXT_lights_ies light is skipped")
                            .arg(kMaxRigLights));
                continue;
            }
            if (std::optional<Light> l = iesLight(cx, n, node, ies.toObject())) {
                lights.push_back(std::move(*l));
                target = int(lights.size()) - 1;
            } else {
                why = QStringLiteral("its EXT_lights_ies light was skipped");
            }
        } else if (extensions.contains(QLatin1String("KHR_lights_punctual"))) {
            why = QStringLiteral("its light cannot be told from another light of the same name");
            for (const QString& name : assimpName(n.index)) {
                int found = -1, count = 0;
                for (std::size_t i = 0; i < fromAssimp; ++i)
                    if (lights[i].name == name) {
                        found = int(i);
                        ++count;
                    }
                if (count == 1 && lightNodesNamed.value(name) == 1) target = found;
                if (count == 0 && target < 0) why = QStringLiteral("its light was not imported");
            }
        }
        const QJsonValue lightrig =
            node.value(QLatin1String("extras")).toObject().value(QLatin1String("lightrig"));
        if (lightrig.isObject()) applyExtras(cx, n.index, lightrig.toObject(), target, why);
    }
}

} // namespace lr::detail
