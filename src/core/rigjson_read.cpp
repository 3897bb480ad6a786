// readRigJson: the rig file reader. Every rule of docs/rig-format.md is checked here; each problem is
// reported with its JSON path and reading goes on, so one pass lists every error in the file.
#include "rigjson.h"
#include "rigjson_check.h"

#include <cmath>

namespace lr {

using json::Value;
using rigjson::Checker;
using rigjson::ObjectView;
using rigjson::readCone;
using rigjson::readFalloff;
using rigjson::readGround;
using rigjson::readShadow;
using rigjson::rejectMisplaced;

namespace {

void readSpecular(Checker& c, const Value& v, const QString& path, Light& l) {
    if (v.isNumber()) {
        if (const auto f = c.number(v, path, rigjson::nonNegative(kMaxRigIntensity))) {
            l.specular = glm::dvec3(*f);
            l.specularIsColor = false;
        }
    } else if (v.kind == Value::Kind::Array) {
        if (const auto col = c.color(v, path)) {
            l.specular = *col;
            l.specularIsColor = true;
        }
    } else {
        c.expected(v, path, QStringLiteral("a factor >= 0 or an RGB colour [r, g, b]"));
    }
}

// `area` and its keys written on the light itself.
void readAreaOf(Checker& c, ObjectView& o, std::optional<LightType> type, const QString& a, Light& l) {
    const bool area = !type || traitsOf(*type).isArea;
    if (area) {
        if (const Value* x = o.take("area"))
            if (const auto shape = rigjson::readArea(c, *x, o.path("area"), type)) l.area = *shape;
    } else {
        o.reject("area", QStringLiteral("%1 has no area (only %2 lights have one: they emit from a surface)")
                             .arg(a, lightTypesWith(&LightTypeTraits::isArea)));
    }
    for (const char* key : {"width", "height", "radius", "roll", "twoSided"})
        o.reject(key, area ? QStringLiteral("belongs in \"area\"")
                           : QStringLiteral(
                                 "%1 has no %2 (it would belong in \"area\", which only %3 lights have)")
                                 .arg(a, QLatin1String(key), lightTypesWith(&LightTypeTraits::isArea)));
}

std::optional<Light> readLight(Checker& c, const Value& v, const QString& path, int version) {
    if (!c.isObject(v, path)) return std::nullopt;
    ObjectView o(c, v, path);
    Light l;
    std::optional<LightType> type;
    if (const Value* t = o.take("type"))
        type = c.enumValue<LightType>(*t, o.path("type"));
    else
        c.error(o.path("type"), QStringLiteral("missing; one of %1").arg(allowedNames<LightType>()));
    if (type && rigjson::firstFormatVersion(*type) > version) {
        // An older file cannot hold the type (no writer made it, an older reader refuses it): say so.
        c.error(o.path("type"),
                QStringLiteral("%1 lights came with version %2 of the format, but the file says \"version\": "
                               "%3; write \"version\": %2")
                    .arg(toString(*type))
                    .arg(rigjson::firstFormatVersion(*type))
                    .arg(version));
        type.reset();
    }
    if (type) l.type = *type;
    const QString a = type ? QStringLiteral("a %1 light").arg(toString(*type)) : QString();
    const auto is = [&](bool (Light::*uses)() const) { return !type || (l.*uses)(); }; // unknown type: allow

    const auto name = [&](const Value& x, const QString& p) { return c.name(x, p); };
    const auto color = [&](const Value& x, const QString& p) { return c.color(x, p); };
    o.read("name", l.name, name);
    o.read("group", l.group, name);
    o.read("enabled", l.enabled, [&](const Value& x, const QString& p) { return c.boolean(x, p); });
    o.read("color", l.color, color);
    if (const Value* t = o.take("temperature"))
        l.temperature = c.number(*t, o.path("temperature"), {1000.0, true, 40000.0, true});
    o.read("intensity", l.intensity, [&](const Value& x, const QString& p) {
        return c.number(x, p, rigjson::nonNegative(kMaxRigIntensity));
    });

    if (is(&Light::usesPosition)) {
        if (const Value* p = o.take("position")) {
            if (const auto pos = c.point(*p, o.path("position"))) l.position = *pos;
        } else if (type) {
            c.error(o.path("position"), QStringLiteral("missing; %1 needs a position [x, y, z]").arg(a));
        }
    } else {
        o.reject("position", QStringLiteral("%1 has no position (only %2 lights have one)")
                                 .arg(a, lightTypesWith(&LightTypeTraits::usesPosition)));
    }
    if (is(&Light::usesDirection)) {
        if (const Value* d = o.take("direction")) {
            if (const auto dir = c.direction(*d, o.path("direction"))) l.direction = *dir;
        } else if (type) {
            c.error(
                o.path("direction"),
                QStringLiteral("missing; %1 needs a direction [x, y, z], where its light travels").arg(a));
        }
    } else if (type == LightType::Point && v.find(u"ies")) { // issue 39: the profile's nadir (default down)
        if (const Value* d = o.take("direction"))
            if (const auto dir = c.direction(*d, o.path("direction"))) l.direction = *dir;
    } else {
        o.reject("direction", QStringLiteral("%1 has no direction (it shines in all directions)").arg(a));
    }
    if (is(&Light::usesFalloff)) {
        if (const Value* f = o.take("falloff")) {
            if (const auto falloff = readFalloff(c, *f, o.path("falloff"))) l.falloff = *falloff;
        } else if (type) {
            c.error(o.path("falloff"),
                    QStringLiteral("missing; %1 needs a falloff, e.g. {\"model\": \"none\"}").arg(a));
        }
    } else {
        o.reject("falloff", QStringLiteral("%1 has no falloff (only %2 lights have one)")
                                .arg(a, lightTypesWith(&LightTypeTraits::usesFalloff)));
    }
    if (is(&Light::usesCone)) {
        if (const Value* cv = o.take("cone"))
            if (const auto cone = readCone(c, *cv, o.path("cone"))) l.cone = *cone;
    } else {
        o.reject("cone", QStringLiteral("%1 has no cone (only %2 lights have one)")
                             .arg(a, lightTypesWith(&LightTypeTraits::usesCone)));
    }
    if (is(&Light::usesSurfaceModels)) {
        o.read("diffuse", l.diffuse,
               [&](const Value& x, const QString& p) { return c.enumValue<DiffuseModel>(x, p); });
        if (const Value* s = o.take("specular")) readSpecular(c, *s, o.path("specular"), l);
        if (const Value* am = o.take("ambient")) l.ambient = c.color(*am, o.path("ambient"));
    } else {
        for (const char* key : {"diffuse", "specular", "ambient"})
            o.reject(key, QStringLiteral("%1 has no %2 term").arg(a, QLatin1String(key)));
    }
    if (is(&Light::usesRimExponent))
        o.read("exponent", l.rimExponent, [&](const Value& x, const QString& p) {
            return c.number(x, p, rigjson::positive(kMaxRigExponent));
        });
    else
        o.reject("exponent", QStringLiteral("only %1 lights have an exponent; a falloff or cone exponent "
                                            "belongs in \"falloff\" or \"cone\"")
                                 .arg(lightTypesWith(&LightTypeTraits::usesRimExponent)));
    readAreaOf(c, o, type, a, l);
    if (is(&Light::castsShadows)) {
        if (const Value* s = o.take("shadow"))
            if (const auto shadow = readShadow(c, *s, o.path("shadow"), type)) l.shadow = *shadow;
    } else {
        o.reject("shadow",
                 QStringLiteral("%1 casts no shadow: it brightens the edges that face away from the "
                                "viewer and comes from no place that anything could block (only "
                                "%2 lights cast shadows)")
                     .arg(a, lightTypesWith(&LightTypeTraits::castsShadows)));
    }
    if (const Value* k = o.take("link"))
        if (const auto link = rigjson::readLink(c, *k, o.path("link"), version)) l.link = *link;
    if (!type || *type == LightType::Spot) {
        if (const Value* g = o.take("gobo"))
            if (const auto gobo = rigjson::readGobo(c, *g, o.path("gobo"), version)) l.gobo = *gobo;
    } else {
        o.reject("gobo",
                 QStringLiteral("only spot lights have a gobo (an image projected through the cone)"));
    }
    if (!type || *type == LightType::Rect) {
        if (const Value* b = o.take("barnDoors"))
            if (const auto doors = rigjson::readBarnDoors(c, *b, o.path("barnDoors"), version))
                l.barnDoors = doors;
    } else {
        o.reject("barnDoors", QStringLiteral("%1 has no barn doors (only rect lights have them: flaps on the "
                                             "edges of its emitter)")
                                  .arg(a));
    }
    if (const Value* x = o.take("ies")) l.ies = rigjson::readIes(c, *x, o.path("ies"), version, type);
    rejectMisplaced(o, false, false, a, is(&Light::usesFalloff), is(&Light::usesCone));
    o.finish();
    return type ? std::optional(l) : std::nullopt;
}

void readShading(Checker& c, const Value& v, const QString& path, Shading& s) {
    if (!c.isObject(v, path)) return;
    ObjectView o(c, v, path);
    o.read("model", s.model,
           [&](const Value& x, const QString& p) { return c.enumValue<ShadingModel>(x, p); });
    if (s.model == ShadingModel::Pbr) {
        for (const char* key : {"specular", "viewer", "shininess"})
            o.reject(key, QStringLiteral("physically based shading (\"model\": \"pbr\") has no %1; the "
                                         "materials' roughness and metallic values replace it")
                              .arg(QLatin1String(key)));
        o.finish();
        return;
    }
    o.read("specular", s.specular,
           [&](const Value& x, const QString& p) { return c.enumValue<SpecularModel>(x, p); });
    o.read("viewer", s.viewer,
           [&](const Value& x, const QString& p) { return c.enumValue<ViewerModel>(x, p); });
    o.read("shininess", s.shininess, [&](const Value& x, const QString& p) {
        return c.number(x, p, rigjson::positive(kMaxRigExponent));
    });
    o.finish();
}

// Checks "format" and "version"; false when the rest of the file must not be read. *version: the file's
// (every version from 1 to kRigFormatVersion is read; the newest when it is missing or invalid).
bool readHeader(Checker& c, ObjectView& top, int* version) {
    *version = kRigFormatVersion;
    if (const Value* f = top.take("format")) {
        if (f->kind != Value::Kind::String || f->string != QLatin1String("lightrig")) {
            c.expected(*f, QStringLiteral("format"),
                       QStringLiteral("\"lightrig\" (this is not a LightRig rig file)"));
            return false;
        }
    } else {
        c.error(QStringLiteral("format"),
                QStringLiteral("missing; a rig file starts with \"format\": \"lightrig\""));
    }
    if (const Value* v = top.take("version")) {
        const bool integer = v->isNumber() && v->finite && v->number == std::floor(v->number);
        if (integer && v->number > kRigFormatVersion) {
            c.error(QStringLiteral("version"),
                    QStringLiteral("the file is version %1, newer than this LightRig reads (version %2); "
                                   "open it with a newer LightRig")
                        .arg(QString::fromLatin1(json::formatNumber(v->number)))
                        .arg(kRigFormatVersion));
            return false;
        }
        if (!integer || v->number < 1)
            c.expected(*v, QStringLiteral("version"),
                       QStringLiteral("an integer from 1 to %1").arg(kRigFormatVersion));
        else
            *version = int(v->number);
    } else {
        c.error(QStringLiteral("version"),
                QStringLiteral("missing; this reader expects \"version\": %1").arg(kRigFormatVersion));
    }
    return true;
}

// When the parser's value limit stopped at lights[N] with N past kMaxRigLights: N (the lights read).
std::optional<qsizetype> lightsAtValueLimit(const json::Document& doc) {
    static const QString prefix = QStringLiteral("lights[");
    if (!doc.valueLimitPath || !doc.valueLimitPath->startsWith(prefix)) return std::nullopt;
    const qsizetype close = doc.valueLimitPath->indexOf(QLatin1Char(']'), prefix.size());
    bool ok = false;
    const qsizetype index = doc.valueLimitPath->mid(prefix.size(), close - prefix.size()).toLongLong(&ok);
    if (!ok || close < 0 || index < kMaxRigLights) return std::nullopt;
    return index;
}

} // namespace

RigReadResult readRigJson(const QByteArray& data, const QString& displayName) {
    Checker c(data, displayName);
    if (data.size() > kMaxRigFileBytes) {
        c.fileError(QStringLiteral("the file is %1 bytes; rig files are limited to %2 MiB")
                        .arg(data.size())
                        .arg(kMaxRigFileBytes / (1024 * 1024)));
        return c.result(std::nullopt);
    }
    const json::Document doc = json::parse(data);
    if (const std::optional<qsizetype> lights = lightsAtValueLimit(doc)) {
        // A rig of 100,000 lights runs into the parser's value limit first: give the light-count error
        // a rig of 4,097 lights gets, not "more than 1048576 values" somewhere inside light 74,897.
        c.error(
            QStringLiteral("lights"),
            QStringLiteral("more than %1 lights; at most %2 are allowed").arg(*lights).arg(kMaxRigLights));
        return c.result(std::nullopt);
    }
    for (const QString& e : doc.errors)
        c.fileError(e);
    if (!doc.complete) return c.result(std::nullopt);
    if (doc.root.kind != Value::Kind::Object) {
        c.expected(doc.root, QStringLiteral("(top level)"),
                   QStringLiteral("a JSON object {\"format\": \"lightrig\", ...}"));
        return c.result(std::nullopt);
    }
    ObjectView top(c, doc.root, QString());
    int version = kRigFormatVersion;
    if (!readHeader(c, top, &version)) return c.result(std::nullopt);

    Rig rig;
    top.read("name", rig.name, [&](const Value& x, const QString& p) { return c.name(x, p); });
    top.read("space", rig.space,
             [&](const Value& x, const QString& p) { return c.enumValue<RigSpace>(x, p); });
    top.read("ambient", rig.ambient, [&](const Value& x, const QString& p) { return c.color(x, p); });
    if (const Value* s = top.take("shading")) readShading(c, *s, QStringLiteral("shading"), rig.shading);
    if (const Value* g = top.take("ground"))
        if (const auto ground = readGround(c, *g, QStringLiteral("ground"))) rig.ground = *ground;
    if (const Value* e = top.take("environment"))
        if (auto env = rigjson::readEnvironment(c, *e, QStringLiteral("environment"))) rig.environment = *env;
    if (const Value* v = top.take("view"))
        if (auto view = rigjson::readView(c, *v, QStringLiteral("view"), false)) rig.view = *view;
    if (const Value* v = top.take("views"))
        if (auto views = rigjson::readViews(c, *v, QStringLiteral("views"))) rig.views = std::move(*views);
    if (const Value* lights = top.take("lights")) {
        if (lights->kind != Value::Kind::Array) {
            c.expected(*lights, QStringLiteral("lights"), QStringLiteral("an array of lights [...]"));
        } else if (lights->items.size() > size_t(kMaxRigLights)) {
            c.error(QStringLiteral("lights"), QStringLiteral("%1 lights; at most %2 are allowed")
                                                  .arg(lights->items.size())
                                                  .arg(kMaxRigLights));
        } else {
            for (size_t i = 0; i < lights->items.size(); ++i)
                if (auto l = readLight(c, lights->items[i],
                                       json::appendIndex(QStringLiteral("lights"), qsizetype(i)), version))
                    rig.lights.push_back(std::move(*l));
            if (const int casters = shadowCasterCount(rig.lights); casters > kMaxShadowCasters)
                c.error(QStringLiteral("lights"),
                        QStringLiteral(
                            "%1 lights have \"shadow\": {\"enabled\": true}; at most %2 lights can cast "
                            "shadows (one shadow map each): switch off the shadow of %3 of them")
                            .arg(casters)
                            .arg(kMaxShadowCasters)
                            .arg(casters - kMaxShadowCasters));
        }
    } else {
        c.error(QStringLiteral("lights"),
                QStringLiteral("missing; a rig has \"lights\": [...] (it may be empty)"));
    }
    top.finish();
    return c.result(std::move(rig));
}

} // namespace lr
