// A light's "link", "gobo" and "barnDoors" outside a rig file (rigjson_extras.h): the glTF export
// writes them in a light node's extras.lightrig (core/gltflights.h), and the import reads them back with
// the rig's own readers, so that a bad value is refused with the rig format's reason and a JSON path into
// the glTF file.
#include "rigjson_extras.h"

#include "rigjson_check.h"

namespace lr {

using json::Value;

LightExtras readLightExtras(const QByteArray& objectJson, const QString& file, const QString& path) {
    LightExtras out;
    const json::Document doc = json::parse(objectJson);
    if (!doc.complete || !doc.errors.isEmpty()) {
        for (const QString& e : doc.errors)
            out.errors << QStringLiteral("%1: %2: %3").arg(file, path, e);
        if (out.errors.isEmpty()) out.errors << QStringLiteral("%1: %2: not valid JSON").arg(file, path);
        return out;
    }
    if (doc.root.kind != Value::Kind::Object) {
        out.errors << QStringLiteral("%1: %2: must be an object").arg(file, path);
        return out;
    }
    // One checker per key, so that each key's errors leave the others alone; a value with an error is
    // not kept.
    const auto readKey = [&](const char* key, auto& target, auto&& reader) {
        const Value* v = doc.root.find(QString::fromLatin1(key));
        if (!v) return;
        rigjson::Checker c(objectJson, file);
        auto value = reader(c, *v, json::appendKey(path, QString::fromLatin1(key)));
        const RigReadResult r = c.result(Rig{});
        out.errors << r.errors;
        out.warnings << r.warnings;
        if (r.errors.isEmpty()) target = std::move(value);
    };
    readKey("link", out.link, [](rigjson::Checker& c, const Value& v, const QString& p) {
        return rigjson::readLink(c, v, p, kRigFormatVersion);
    });
    readKey("gobo", out.gobo, [](rigjson::Checker& c, const Value& v, const QString& p) {
        return rigjson::readGobo(c, v, p, kRigFormatVersion);
    });
    readKey("barnDoors", out.barnDoors, [](rigjson::Checker& c, const Value& v, const QString& p) {
        return rigjson::readBarnDoors(c, v, p, kRigFormatVersion);
    });
    return out;
}

} // namespace lr
