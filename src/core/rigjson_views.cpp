// The rig's camera "view" and its named "views" (docs/rig-format.md, issue 41): which keys a view has, their
// defaults and ranges, and their canonical form. Both are optional: a rig without them reads as before.
#include "rigjson_check.h"

#include <QSet>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr::rigjson {

using json::Value;

namespace {
constexpr double kMaxViewFov = 170.0; // degrees, vertical

QByteArray num(double v) {
    return json::formatNumber(v);
}
QByteArray vec(const glm::dvec3& v) {
    return '[' + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ']';
}
} // namespace

std::optional<RigView> readView(Checker& c, const Value& v, const QString& path, bool named) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    RigView view;
    if (named) {
        if (const Value* n = o.require("name", QStringLiteral("missing; a saved view has a \"name\""))) {
            const auto name = c.name(*n, o.path("name"));
            if (name && name->trimmed().isEmpty())
                c.error(o.path("name"), QStringLiteral("must not be empty"));
            if (name && !name->trimmed().isEmpty())
                view.name = *name;
            else
                o.invalidate();
        }
    }
    const auto point = [&](const char* key, glm::dvec3& out) {
        if (const Value* x = o.require(key, QStringLiteral("missing; a view has \"eye\" and \"target\" "
                                                           "points [x, y, z]")))
            o.keep(c.point(*x, o.path(key)), out);
    };
    point("eye", view.eye);
    point("target", view.target);
    o.read("up", view.up, [&](const Value& x, const QString& p) { return c.direction(x, p); });
    if (const Value* f = o.take("yfov"))
        o.keep(c.number(*f, o.path("yfov"), {0.0, false, kMaxViewFov, true}), view.yfovDeg);
    const glm::dvec3 forward = view.target - view.eye;
    const double distance = glm::length(forward);
    if (!(distance > 0.0) || !std::isfinite(distance)) {
        c.error(o.path("target"), QStringLiteral("must differ from \"eye\" (the camera looks from the eye "
                                                 "at the target)"));
        o.invalidate();
    } else if (glm::length(glm::cross(forward / distance, view.up)) < 1e-9) {
        c.error(o.path("up"), QStringLiteral("must not be parallel to the view direction (target - eye)"));
        o.invalidate();
    }
    return o.result(view);
}

std::optional<std::vector<RigView>> readViews(Checker& c, const Value& v, const QString& path) {
    if (v.kind != Value::Kind::Array) {
        c.expected(v, path, QStringLiteral("an array of named views [{\"name\": ..., \"eye\": ...}, ...]"));
        return std::nullopt;
    }
    if (v.items.size() > size_t(kMaxRigViews)) {
        c.error(path,
                QStringLiteral("%1 views; at most %2 are allowed").arg(v.items.size()).arg(kMaxRigViews));
        return std::nullopt;
    }
    std::vector<RigView> views;
    QSet<QString> names;
    bool valid = true;
    for (size_t i = 0; i < v.items.size(); ++i) {
        const QString at = json::appendIndex(path, qsizetype(i));
        auto view = readView(c, v.items[i], at, true);
        if (!view) {
            valid = false;
            continue;
        }
        if (names.contains(view->name)) {
            c.error(json::appendKey(at, QStringLiteral("name")),
                    QStringLiteral("\"%1\" is the name of an earlier view; names must be unique")
                        .arg(view->name));
            valid = false;
            continue;
        }
        names.insert(view->name);
        views.push_back(std::move(*view));
    }
    return valid ? std::optional(std::move(views)) : std::nullopt;
}

QByteArray writeView(const RigView& view, bool named) {
    QByteArray out = "{";
    if (named) out += "\"name\": " + json::quote(view.name) + ", ";
    out += "\"eye\": " + vec(view.eye) + ", \"target\": " + vec(view.target) +
           ", \"up\": " + vec(normalizeDirection(view.up)) + ", \"yfov\": " + num(view.yfovDeg);
    return out + '}';
}

} // namespace lr::rigjson
