// A light's "ies" object (docs/rig-format.md "ies", issue 39): an IES profile on a point or spot light.
//   "ies": {"file": "profiles/downlight.ies", "multiplier": 1, "level": "light", "rotation": 0}
// "file" is required (relative to the rig's folder, or absolute); the rest have these defaults. The file
// itself is read when the scene is loaded (scene/lightassets.h), not here.
#include "rigjson_check.h"

#include <cmath>

namespace lr::rigjson {

using json::Value;

namespace {

std::optional<QString> readIesPath(Checker& c, const Value& v, const QString& path) {
    if (v.kind != Value::Kind::String) {
        c.expected(v, path, QStringLiteral("an IES file name (a string)"));
        return std::nullopt;
    }
    const QString& s = v.string;
    if (s.isEmpty())
        c.error(path, QStringLiteral("must not be empty; name an IES (LM-63) file relative to the rig's "
                                     "folder, or absolute"));
    else if (s.size() > kMaxEnvironmentPathLength)
        c.error(path, QStringLiteral("must be at most %1 characters, got %2")
                          .arg(kMaxEnvironmentPathLength)
                          .arg(s.size()));
    else if (s.contains(QChar(0)))
        c.error(path, QStringLiteral("must not contain a NUL character (\\u0000)"));
    else
        return s;
    return std::nullopt;
}

std::optional<IesLevel> readLevel(Checker& c, const Value& v, const QString& path) {
    if (v.kind == Value::Kind::String && v.string == QLatin1String("profile")) return IesLevel::Profile;
    if (v.kind == Value::Kind::String && v.string == QLatin1String("light")) return IesLevel::Light;
    c.expected(v, path,
               QStringLiteral("\"light\" (the light's intensity sets the peak) or \"profile\" (the file's "
                              "candela)"));
    return std::nullopt;
}

QByteArray num(double v) {
    return json::formatNumber(v);
}

} // namespace

std::optional<IesSpec> readIes(Checker& c, const Value& v, const QString& path, int version,
                               std::optional<LightType> type) {
    if (type && (!traitsOf(*type).usesPosition || traitsOf(*type).isArea)) {
        c.error(path, QStringLiteral("a %1 light has no IES profile (only point and spot lights have one)")
                          .arg(toString(*type)));
        return std::nullopt;
    }
    if (version < kIesFormatVersion) {
        c.error(path, QStringLiteral("IES profiles came with version %1 of the format, but the file says "
                                     "\"version\": %2; write \"version\": %1")
                          .arg(kIesFormatVersion)
                          .arg(version));
        return std::nullopt;
    }
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    IesSpec s;
    if (const Value* f = o.require("file", QStringLiteral("missing; \"ies\" names its IES (LM-63) file, "
                                                          "relative to the rig's folder or absolute")))
        o.keep(readIesPath(c, *f, o.path("file")), s.file);
    o.read("multiplier", s.multiplier,
           [&](const Value& x, const QString& p) { return c.number(x, p, nonNegative(kMaxRigIntensity)); });
    o.read("level", s.level, [&](const Value& x, const QString& p) { return readLevel(c, x, p); });
    o.read("rotation", s.rotation, [&](const Value& x, const QString& p) { return c.number(x, p, {}); });
    s.rotation = normalizedEnvironmentRotation(s.rotation);
    return o.result(s);
}

QByteArray writeIes(const IesSpec& s) {
    return "{\"file\": " + json::quote(s.file) + ", \"multiplier\": " + num(s.multiplier) +
           ", \"level\": " + (s.level == IesLevel::Profile ? "\"profile\"" : "\"light\"") +
           ", \"rotation\": " + num(normalizedEnvironmentRotation(s.rotation)) + '}';
}

} // namespace lr::rigjson
