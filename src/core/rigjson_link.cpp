// A light's "link" object (docs/rig-format.md "link", issue 38): which parts of the model the light lights
// and which cast its shadow, as lists of part names (core/lightlink.h).
//   "link": {"include": ["Body"], "exclude": ["Stand"], "shadow": {"exclude": ["Glass"]}}
#include "rigjson_check.h"

#include <QSet>

namespace lr::rigjson {

using json::Value;

namespace {

std::optional<QStringList> readNames(Checker& c, const Value& v, const QString& path) {
    if (v.kind != Value::Kind::Array) {
        c.expected(v, path, QStringLiteral("an array of part names, e.g. [\"Body\", \"material:Glass\"]"));
        return std::nullopt;
    }
    if (v.items.size() > std::size_t(kMaxLinkNames)) {
        c.error(path, QStringLiteral("has %1 names; at most %2").arg(v.items.size()).arg(kMaxLinkNames));
        return std::nullopt;
    }
    QStringList names;
    QSet<QString> seen;
    bool ok = true;
    for (std::size_t i = 0; i < v.items.size(); ++i) {
        const QString at = json::appendIndex(path, qsizetype(i));
        const auto name = c.name(v.items[i], at);
        if (!name) {
            ok = false;
            continue;
        }
        if (const QString problem = partNameProblem(*name); !problem.isEmpty()) {
            c.error(at, problem);
            ok = false;
            continue;
        }
        if (seen.contains(*name)) {
            c.warning(at, QStringLiteral("\"%1\" is listed twice (the second is ignored)").arg(*name));
            continue;
        }
        seen.insert(*name);
        names << *name;
    }
    return ok ? std::optional<QStringList>(names) : std::nullopt;
}

void readLists(Checker& c, ObjectView& o, PartSet& set) {
    o.read("include", set.include, [&](const Value& x, const QString& p) { return readNames(c, x, p); });
    o.read("exclude", set.exclude, [&](const Value& x, const QString& p) { return readNames(c, x, p); });
}

QByteArray names(const QStringList& list) {
    QByteArray out = "[";
    for (qsizetype i = 0; i < list.size(); ++i)
        out += (i ? ", " : "") + json::quote(list[i]);
    return out + ']';
}

QByteArray lists(const PartSet& set, const QByteArray& tail = {}) {
    QByteArrayList fields;
    if (!set.include.isEmpty()) fields << "\"include\": " + names(set.include);
    if (!set.exclude.isEmpty()) fields << "\"exclude\": " + names(set.exclude);
    if (!tail.isEmpty()) fields << tail;
    return '{' + fields.join(", ") + '}';
}

} // namespace

std::optional<LightLink> readLink(Checker& c, const Value& v, const QString& path, int version) {
    if (version < kLinkFormatVersion) {
        c.error(path,
                QStringLiteral("links came with version %1 of the format, but the file says \"version\": "
                               "%2; write \"version\": %1")
                    .arg(kLinkFormatVersion)
                    .arg(version));
        return std::nullopt;
    }
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    LightLink link;
    readLists(c, o, link.lit);
    if (const Value* s = o.take("shadow")) {
        if (c.isObject(*s, o.path("shadow"))) {
            ObjectView so(c, *s, o.path("shadow"));
            readLists(c, so, link.shadow);
            if (const auto set = so.result(link.shadow))
                link.shadow = *set;
            else
                o.invalidate();
        } else {
            o.invalidate();
        }
    }
    return o.result(link);
}

std::optional<QByteArray> writeLink(const LightLink& link) {
    if (link.isDefault()) return std::nullopt;
    const QByteArray shadow = link.shadow.isEverything() ? QByteArray() : "\"shadow\": " + lists(link.shadow);
    return lists(link.lit, shadow);
}

} // namespace lr::rigjson
