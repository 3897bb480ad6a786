// A spot light's "gobo" object (docs/rig-format.md "gobo", issue 39; core/lightshaping.h GoboSpec): an
// image projected through the cone, scaled and turned.
//   "gobo": {"file": "gobos/window.png", "scale": 1, "rotation": 0}
// Format version 4: an older reader would ignore the key and light the spot unshaped, so a rig with a gobo
// says version 4 and an older LightRig refuses it (as "link" did with version 3).
#include "rigjson_check.h"

namespace lr::rigjson {

using json::Value;

namespace {

std::optional<QString> readGoboFile(Checker& c, const Value& v, const QString& path) {
    if (v.kind != Value::Kind::String) {
        c.expected(v, path, QStringLiteral("a file name (a string): a PNG or OpenEXR image"));
        return std::nullopt;
    }
    const QString& s = v.string;
    if (s.isEmpty()) {
        c.error(path, QStringLiteral("must not be empty; a gobo names its PNG or OpenEXR image, relative to "
                                     "the rig's folder or absolute"));
        return std::nullopt;
    }
    if (s.size() > kMaxGoboPathLength) {
        c.error(
            path,
            QStringLiteral("must be at most %1 characters, got %2").arg(kMaxGoboPathLength).arg(s.size()));
        return std::nullopt;
    }
    if (s.contains(QChar(0))) {
        c.error(path, QStringLiteral("must not contain a NUL character (\\u0000)"));
        return std::nullopt;
    }
    return s;
}

} // namespace

std::optional<GoboSpec> readGobo(Checker& c, const Value& v, const QString& path, int version) {
    if (version < kGoboFormatVersion) {
        c.error(path,
                QStringLiteral("gobos came with version %1 of the format, but the file says \"version\": "
                               "%2; write \"version\": %1")
                    .arg(kGoboFormatVersion)
                    .arg(version));
        return std::nullopt;
    }
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    GoboSpec g;
    if (const Value* f = o.require("file", QStringLiteral("missing; a gobo needs \"file\": a PNG or OpenEXR "
                                                          "image relative to the rig's folder")))
        o.keep(readGoboFile(c, *f, o.path("file")), g.file);
    o.read("scale", g.scale, [&](const Value& x, const QString& p) {
        return c.number(x, p, {kMinGoboScale, true, kMaxGoboScale, true});
    });
    o.read("rotation", g.rotation, [&](const Value& x, const QString& p) {
        return c.number(x, p, {-360.0, true, 360.0, true});
    });
    return o.result(g);
}

QByteArray writeGobo(const GoboSpec& g) {
    QByteArrayList fields{"\"file\": " + json::quote(g.file)};
    if (g.scale != 1.0) fields << "\"scale\": " + json::formatNumber(g.scale);
    if (g.rotation != 0.0) fields << "\"rotation\": " + json::formatNumber(g.rotation);
    return '{' + fields.join(", ") + '}';
}

} // namespace lr::rigjson
