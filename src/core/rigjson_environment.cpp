// The rig's "environment" object (docs/rig-format.md "environment", issue 15): which keys it has, their
// defaults and ranges, and its canonical form.
#include "rigjson_check.h"

#include <cmath>

namespace lr {

double normalizedEnvironmentRotation(double degrees) {
    if (!std::isfinite(degrees)) return degrees;
    double r = std::fmod(degrees, 360.0); // exact
    if (r < 0.0) r += 360.0;
    if (r >= 360.0) r = 0.0; // -1e-20 + 360 rounds to 360
    return r + 0.0;          // -0 -> 0
}

namespace rigjson {

using json::Value;

namespace {

// "file": a path (relative to the rig's folder, or absolute) or "builtin:NAME"; never empty.
std::optional<QString> readFile(Checker& c, const Value& v, const QString& path) {
    if (v.kind != Value::Kind::String) {
        c.expected(v, path, QStringLiteral("a file name (a string)"));
        return std::nullopt;
    }
    const QString& s = v.string;
    const QString builtin = QString::fromLatin1(kBuiltinEnvironmentPrefix);
    if (s.isEmpty())
        c.error(path,
                QStringLiteral("must not be empty; an image environment names its file, relative to the "
                               "rig's folder, absolute, or \"builtin:NAME\""));
    else if (s.size() > kMaxEnvironmentPathLength)
        c.error(path, QStringLiteral("must be at most %1 characters, got %2")
                          .arg(kMaxEnvironmentPathLength)
                          .arg(s.size()));
    else if (s.contains(QChar(0)))
        c.error(path, QStringLiteral("must not contain a NUL character (\\u0000)"));
    else if (s == builtin)
        c.error(path, QStringLiteral("\"%1\" needs the name of a bundled environment after it, e.g. "
                                     "\"%1studio\"")
                          .arg(builtin));
    else
        return s;
    return std::nullopt;
}

std::optional<Softbox> readSoftbox(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Softbox b;
    const auto number = [&](const char* key, double& out, const Interval& in) {
        if (const Value* x = o.take(key)) o.keep(c.number(*x, o.path(key), in), out);
    };
    number("azimuth", b.azimuth, {});
    number("elevation", b.elevation, {-90.0, true, 90.0, true});
    number("width", b.width, positive(kMaxSoftboxAngle));
    number("height", b.height, positive(kMaxSoftboxAngle));
    if (const Value* x = o.take("color")) o.keep(c.color(*x, o.path("color")), b.color);
    number("intensity", b.intensity, nonNegative(kMaxRigIntensity));
    return o.result(b);
}

std::optional<EnvironmentSpot> readSpot(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    EnvironmentSpot s;
    if (const Value* d = o.require("direction", QStringLiteral("missing; a dimmed spot needs a direction "
                                                               "[x, y, z] (the spot's centre)")))
        o.keep(c.direction(*d, o.path("direction")), s.direction);
    const auto number = [&](const char* key, double& out, const Interval& in) {
        if (const Value* x = o.take(key)) o.keep(c.number(*x, o.path(key), in), out);
    };
    number("angle", s.angle, positive(kMaxEnvironmentSpotAngle));
    number("factor", s.factor, nonNegative(1.0));
    number("threshold", s.threshold, nonNegative(kMaxEnvironmentSpotThreshold));
    return o.result(s);
}

// An array of at most `max` objects read by `item`; false when anything in it was invalid.
template <typename T, typename Item>
bool readList(Checker& c, const Value& v, const QString& path, int max, const QString& what,
              std::vector<T>& out, Item&& item) {
    if (v.kind != Value::Kind::Array) {
        c.expected(v, path, QStringLiteral("an array of %1 [...]").arg(what));
        return false;
    }
    if (v.items.size() > size_t(max)) {
        c.error(path, QStringLiteral("%1 %2; at most %3 are allowed").arg(v.items.size()).arg(what).arg(max));
        return false;
    }
    bool ok = true;
    out.clear();
    for (size_t i = 0; i < v.items.size(); ++i) {
        if (auto x = item(c, v.items[i], json::appendIndex(path, qsizetype(i))))
            out.push_back(std::move(*x));
        else
            ok = false;
    }
    return ok;
}

std::optional<Studio> readStudio(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Studio s;
    for (const auto& [key, out] :
         {std::pair{"zenith", &s.zenith}, std::pair{"horizon", &s.horizon}, std::pair{"floor", &s.floor}})
        if (const Value* x = o.take(key)) o.keep(c.color(*x, o.path(key)), *out);
    if (const Value* x = o.take("softboxes"))
        if (!readList(c, *x, o.path("softboxes"), kMaxEnvironmentSoftboxes, QStringLiteral("softboxes"),
                      s.softboxes, readSoftbox))
            o.invalidate();
    return o.result(s);
}

// Canonical text: the writer's conventions (rigjson_write.cpp), for the one object that nests blocks.
QByteArray num(double v) {
    return json::formatNumber(v);
}
QByteArray vec(const glm::dvec3& v) {
    return '[' + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ']';
}
using Fields = std::vector<std::pair<const char*, QByteArray>>;
QByteArray inlineObject(const Fields& fields) {
    QByteArray out = "{";
    for (size_t i = 0; i < fields.size(); ++i)
        out += (i ? ", \"" : "\"") + QByteArray(fields[i].first) + "\": " + fields[i].second;
    return out + '}';
}
QByteArray block(const Fields& fields, const QByteArray& indent) {
    QByteArray out = "{\n";
    for (size_t i = 0; i < fields.size(); ++i)
        out += indent + "  \"" + fields[i].first + "\": " + fields[i].second +
               (i + 1 < fields.size() ? ",\n" : "\n");
    return out + indent + '}';
}
QByteArray list(const std::vector<QByteArray>& items, const QByteArray& indent) {
    if (items.empty()) return "[]";
    QByteArray out = "[\n";
    for (size_t i = 0; i < items.size(); ++i)
        out += indent + "  " + items[i] + (i + 1 < items.size() ? ",\n" : "\n");
    return out + indent + ']';
}

} // namespace

std::optional<Environment> readEnvironment(Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Environment e;
    if (const Value* s =
            o.require("source", QStringLiteral("missing; one of %1").arg(allowedNames<EnvironmentSource>())))
        o.keep(c.enumValue<EnvironmentSource>(*s, o.path("source")), e.source);
    if (e.source == EnvironmentSource::Image) {
        if (const Value* f =
                o.require("file", QStringLiteral("missing; an image environment needs \"file\": an "
                                                 ".hdr or .exr file relative to the rig's folder, "
                                                 "absolute, or \"builtin:NAME\"")))
            o.keep(readFile(c, *f, o.path("file")), e.file);
    } else if (const Value* f = o.take("file")) {
        o.keep(readFile(c, *f, o.path("file")), e.file);
    }
    const auto number = [&](const char* key, double& out, const Interval& in) {
        if (const Value* x = o.take(key)) o.keep(c.number(*x, o.path(key), in), out);
    };
    number("intensity", e.intensity, {-kMaxEnvironmentEV, true, kMaxEnvironmentEV, true});
    number("rotation", e.rotation, {});
    e.rotation = normalizedEnvironmentRotation(e.rotation);
    if (const Value* b = o.take("background"))
        o.keep(c.enumValue<EnvironmentBackground>(*b, o.path("background")), e.background);
    number("blur", e.blur, nonNegative(1.0));
    if (const Value* d = o.take("diffuse"))
        o.keep(c.enumValue<DiffuseModel>(*d, o.path("diffuse")), e.diffuse);
    if (const Value* s = o.take("studio")) o.keep(readStudio(c, *s, o.path("studio")), e.studio);
    if (const Value* s = o.take("spots"))
        if (!readList(c, *s, o.path("spots"), kMaxEnvironmentSpots, QStringLiteral("spots"), e.spots,
                      readSpot))
            o.invalidate();
    return o.result(e);
}

std::optional<QByteArray> writeEnvironment(const Environment& e) {
    if (e == Environment{}) return std::nullopt;
    Fields f{{"source", json::quote(toString(e.source))}};
    if (!e.file.isEmpty()) f.push_back({"file", json::quote(e.file)});
    f.push_back({"intensity", num(e.intensity)});
    f.push_back({"rotation", num(normalizedEnvironmentRotation(e.rotation))});
    f.push_back({"background", json::quote(toString(e.background))});
    f.push_back({"blur", num(e.blur)});
    f.push_back({"diffuse", json::quote(toString(e.diffuse))});
    if (e.source == EnvironmentSource::Studio || e.studio != Studio{}) {
        std::vector<QByteArray> boxes;
        for (const Softbox& b : e.studio.softboxes)
            boxes.push_back(inlineObject({{"azimuth", num(b.azimuth)},
                                          {"elevation", num(b.elevation)},
                                          {"width", num(b.width)},
                                          {"height", num(b.height)},
                                          {"color", vec(b.color)},
                                          {"intensity", num(b.intensity)}}));
        f.push_back({"studio", block({{"zenith", vec(e.studio.zenith)},
                                      {"horizon", vec(e.studio.horizon)},
                                      {"floor", vec(e.studio.floor)},
                                      {"softboxes", list(boxes, "      ")}},
                                     "    ")});
    }
    if (!e.spots.empty()) {
        std::vector<QByteArray> spots;
        for (const EnvironmentSpot& s : e.spots) {
            std::vector<std::pair<const char*, QByteArray>> keys = {
                {"direction", vec(s.direction)}, {"angle", num(s.angle)}, {"factor", num(s.factor)}};
            if (s.threshold > 0.0) keys.push_back({"threshold", num(s.threshold)});
            spots.push_back(inlineObject(keys));
        }
        f.push_back({"spots", list(spots, "    ")});
    }
    return block(f, "  ");
}

} // namespace rigjson
} // namespace lr
