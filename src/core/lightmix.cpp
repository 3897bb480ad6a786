#include "lightmix.h"

#include "rigjson_check.h"
#include "rigjson_json.h"

#include <algorithm>
#include <cmath>

namespace lr {

using json::Value;

glm::dvec3 GroupMix::factor() const {
    return enabled ? tint * std::exp2(ev) : glm::dvec3(0.0);
}

GroupMix LightMix::of(const QString& group) const {
    const auto it = groups.find(group);
    return it == groups.end() ? GroupMix{} : it->second;
}

bool LightMix::isIdentity() const {
    return std::all_of(groups.begin(), groups.end(), [](const auto& g) { return g.second.isIdentity(); });
}

namespace {

std::optional<GroupMix> readGroup(rigjson::Checker& c, const Value& v, const QString& path) {
    if (!c.isObject(v, path)) return std::nullopt;
    rigjson::ObjectView o(c, v, path);
    GroupMix g;
    o.read("enabled", g.enabled, [&](const Value& x, const QString& p) { return c.boolean(x, p); });
    o.read("ev", g.ev, [&](const Value& x, const QString& p) {
        return c.number(x, p, {-kMaxMixEV, true, kMaxMixEV, true});
    });
    if (const Value* t = o.take("tint")) {
        const QString p = o.path("tint");
        std::optional<glm::dvec3> tint;
        if (t->kind == Value::Kind::Array && t->items.size() == 3) {
            glm::dvec3 out;
            bool ok = true;
            for (int i = 0; i < 3; ++i) {
                const auto x =
                    c.number(t->items[size_t(i)], json::appendIndex(p, i), rigjson::nonNegative(kMaxMixTint));
                ok = ok && x;
                if (x) out[i] = *x;
            }
            if (ok) tint = out;
        } else {
            c.expected(*t, p, QStringLiteral("a colour [r, g, b]"));
        }
        o.keep(tint, g.tint);
    }
    return o.result(g);
}

} // namespace

LightMixReadResult readLightMix(const QByteArray& data, const QString& displayName,
                                const QStringList& known) {
    rigjson::Checker c(data, displayName);
    LightMixReadResult out;
    const auto finish = [&](std::optional<LightMix> mix) {
        const RigReadResult r = c.result(std::nullopt);
        out.errors = r.errors;
        out.warnings = r.warnings;
        if (out.errors.isEmpty()) out.mix = std::move(mix);
        return out;
    };
    const json::Document doc = json::parse(data);
    for (const QString& e : doc.errors)
        c.fileError(e);
    if (!doc.complete) return finish(std::nullopt);
    if (doc.root.kind != Value::Kind::Object) {
        c.expected(doc.root, QStringLiteral("(top level)"),
                   QStringLiteral("a JSON object {\"format\": \"lightrig-mix\", ...}"));
        return finish(std::nullopt);
    }
    rigjson::ObjectView top(c, doc.root, QString());
    if (const Value* f =
            top.require("format", QStringLiteral("missing; a mix file has \"format\": \"lightrig-mix\"")))
        if (f->kind != Value::Kind::String || f->string != QLatin1String("lightrig-mix"))
            c.expected(*f, QStringLiteral("format"), QStringLiteral("\"lightrig-mix\""));
    if (const Value* v = top.require(
            "version",
            QStringLiteral("missing; this reader expects \"version\": %1").arg(kLightMixFormatVersion))) {
        if (!v->isNumber() || v->number != std::floor(v->number) || v->number < 1)
            c.expected(*v, QStringLiteral("version"), QStringLiteral("a whole number >= 1"));
        else if (v->number > kLightMixFormatVersion)
            c.error(QStringLiteral("version"),
                    QStringLiteral("the file is version %1, newer than this LightRig reads (version %2)")
                        .arg(v->number)
                        .arg(kLightMixFormatVersion));
    }
    LightMix mix;
    if (const Value* g =
            top.require("groups", QStringLiteral("missing; a mix has \"groups\": {\"NAME\": {...}}"))) {
        if (c.isObject(*g, QStringLiteral("groups"))) {
            for (const json::Member& m : g->members) {
                if (m.duplicate) continue;
                const QString path = json::appendKey(QStringLiteral("groups"), m.key);
                if (!known.isEmpty() && !known.contains(m.key)) {
                    c.error(path, QStringLiteral("no such light group in the image; it has %1")
                                      .arg(known.join(QStringLiteral(", "))));
                    continue;
                }
                if (auto group = readGroup(c, m.value, path)) mix.groups[m.key] = *group;
            }
        }
    }
    top.finish();
    return finish(std::move(mix));
}

QByteArray writeLightMix(const LightMix& mix) {
    const auto num = [](double v) { return json::formatNumber(v); };
    QByteArray groups;
    for (const auto& [name, g] : mix.groups) {
        if (g.isIdentity()) continue;
        if (!groups.isEmpty()) groups += ",\n";
        groups += "    " + json::quote(name) + ": {\"enabled\": " + (g.enabled ? "true" : "false") +
                  ", \"ev\": " + num(g.ev) + ", \"tint\": [" + num(g.tint.x) + ", " + num(g.tint.y) + ", " +
                  num(g.tint.z) + "]}";
    }
    return "{\n  \"format\": \"lightrig-mix\",\n  \"version\": " +
           QByteArray::number(kLightMixFormatVersion) +
           ",\n  \"groups\": " + (groups.isEmpty() ? QByteArray("{}") : "{\n" + groups + "\n  }") + "\n}\n";
}

Rig applyLightMix(const Rig& rig, const std::vector<LightGroup>& groups, const LightMix& mix,
                  QStringList* notApplied) {
    Rig out = rig;
    const auto note = [&](const QString& line) {
        if (notApplied) *notApplied << line;
    };
    for (const LightGroup& group : groups) {
        const GroupMix g = mix.of(group.name);
        if (g.isIdentity()) continue;
        const glm::dvec3 tint = g.tint;
        const double scale = std::exp2(g.ev);
        switch (group.kind) {
        case LightGroupKind::Lights:
            for (int i : group.lights) {
                Light& l = out.lights[size_t(i)];
                if (!g.enabled) {
                    l.enabled = false;
                    continue;
                }
                // The colour's largest component goes into the intensity (colours stay within 0 ... 1 where
                // they were): intensity × colour is what the renderers use, so the product is what counts.
                glm::dvec3 color = l.color * tint;
                const double peak = std::max({color.x, color.y, color.z});
                double intensity = l.intensity * scale;
                if (peak > 1.0) color /= peak, intensity *= peak;
                if (!(intensity <= kMaxRigIntensity)) {
                    note(QStringLiteral("%1: the intensity would be %2, over the limit of %3; left as it was")
                             .arg(group.name)
                             .arg(intensity)
                             .arg(kMaxRigIntensity));
                    continue;
                }
                // A specular colour and an ambient term are × intensity too: each gets tint × 2^ev over the
                // intensity's own change.
                const glm::dvec3 applied = intensity > 0.0 ? tint * (scale * l.intensity / intensity) : tint;
                l.color = color;
                l.intensity = intensity;
                if (l.specularIsColor) l.specular *= applied;
                if (l.ambient) *l.ambient *= applied;
            }
            break;
        case LightGroupKind::Ambient:
            out.ambient *= g.factor();
            break;
        case LightGroupKind::Environment: {
            if (!g.enabled) {
                note(QStringLiteral("environment: switching it off is not applied (the rig would lose its "
                                    "environment); lower its EV instead"));
                break;
            }
            const double ev = out.environment.intensity + g.ev;
            if (std::abs(ev) > kMaxEnvironmentEV)
                note(QStringLiteral("environment: its intensity would be %1 EV, beyond ±%2; left as it was")
                         .arg(ev)
                         .arg(kMaxEnvironmentEV));
            else
                out.environment.intensity = ev;
            if (tint != glm::dvec3(1.0))
                note(QStringLiteral("environment: a rig's environment has no tint; the tint is not applied"));
            break;
        }
        case LightGroupKind::Emissive:
            note(QStringLiteral("emissive: the model's emission is a material property, not the rig's; not "
                                "applied"));
            break;
        case LightGroupKind::Background:
            note(QStringLiteral("background: not a light; not applied"));
            break;
        }
    }
    return out;
}

} // namespace lr
