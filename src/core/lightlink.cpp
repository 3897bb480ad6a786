#include "lightlink.h"

#include "rig.h"

#include <map>

namespace lr {

namespace {

struct Prefix {
    QLatin1StringView text;
    QString PartNames::*field;
};
const Prefix kPrefixes[] = {{QLatin1StringView("node:"), &PartNames::node},
                            {QLatin1StringView("mesh:"), &PartNames::mesh},
                            {QLatin1StringView("material:"), &PartNames::material}};

QString lightLabel(const Light& l, std::size_t index) {
    return l.name.isEmpty() ? QStringLiteral("light %1").arg(index + 1) : l.name;
}

// The name of a part for a report: its node, else its mesh, else its material.
QString partLabel(const PartNames& p) {
    if (p.ground) return QStringLiteral("ground");
    for (const QString* s : {&p.node, &p.mesh, &p.material})
        if (!s->isEmpty()) return *s;
    return QStringLiteral("(unnamed)");
}

struct ListRef {
    const char* key; // "link.include" ...
    const QStringList& names;
};
std::vector<ListRef> listsOf(const LightLink& k) {
    return {{"link.include", k.lit.include},
            {"link.exclude", k.lit.exclude},
            {"link.shadow.include", k.shadow.include},
            {"link.shadow.exclude", k.shadow.exclude}};
}

// Classes from one signature per part: equal signatures share a class, in the order of first appearance.
// Returns the class of each part and the signatures of the classes; parts past kMaxLinkClasses get class 0.
std::vector<std::uint8_t> classify(const std::vector<std::vector<bool>>& signatures,
                                   std::vector<std::vector<bool>>* classes, bool* overflow) {
    std::map<std::vector<bool>, int> index;
    std::vector<std::uint8_t> out(signatures.size(), 0);
    for (std::size_t p = 0; p < signatures.size(); ++p) {
        auto it = index.find(signatures[p]);
        if (it == index.end()) {
            if (int(classes->size()) == kMaxLinkClasses) {
                *overflow = true;
                continue; // class 0
            }
            it = index.emplace(signatures[p], int(classes->size())).first;
            classes->push_back(signatures[p]);
        }
        out[p] = std::uint8_t(it->second);
    }
    return out;
}

} // namespace

bool partNameMatches(const QString& name, const PartNames& part) {
    if (part.ground) return name == QLatin1String("ground");
    for (const Prefix& prefix : kPrefixes)
        if (name.startsWith(prefix.text))
            return QStringView(name).mid(prefix.text.size()) == part.*prefix.field;
    return name == part.node || name == part.mesh || name == part.material;
}

bool partSetContains(const PartSet& set, const PartNames& part) {
    const auto any = [&](const QStringList& names) {
        for (const QString& n : names)
            if (partNameMatches(n, part)) return true;
        return false;
    };
    if (!set.include.isEmpty() && !any(set.include)) return false;
    return !any(set.exclude);
}

QString partNameProblem(const QString& name) {
    if (name.isEmpty()) return QStringLiteral("is empty; name a node, a mesh, a material or \"ground\"");
    for (const Prefix& prefix : kPrefixes)
        if (name == prefix.text)
            return QStringLiteral("\"%1\" names nothing: write the %2's name after the colon")
                .arg(name, QString(prefix.text).chopped(1));
    return {};
}

LinkResolution resolveLinks(const std::vector<Light>& lights, const std::vector<PartNames>& parts) {
    LinkResolution r;
    const std::size_t n = lights.size();
    r.litMask.assign(n, kAllLinkClasses);
    r.shadowMask.assign(n, kAllLinkClasses);
    r.litClass.assign(parts.size(), 0);
    r.shadowClass.assign(parts.size(), 0);
    std::vector<std::size_t> litLinked, shadowLinked;
    for (std::size_t i = 0; i < n; ++i) {
        const LightLink& k = lights[i].link;
        if (!k.lit.isEverything()) litLinked.push_back(i);
        if (!k.shadow.isEverything()) shadowLinked.push_back(i);
        for (const ListRef& list : listsOf(k))
            for (const QString& name : list.names) {
                bool found = false;
                for (const PartNames& p : parts)
                    if ((found = partNameMatches(name, p))) break;
                if (!found)
                    r.warnings << QStringLiteral("%1: %2: \"%3\" matches no part of the model")
                                      .arg(lightLabel(lights[i], i), QLatin1String(list.key), name);
            }
    }
    r.active = !litLinked.empty() || !shadowLinked.empty();
    if (!r.active) return r;

    const auto resolve = [&](const std::vector<std::size_t>& linked, PartSet LightLink::*set,
                             std::vector<std::uint8_t>& partClass, std::vector<std::uint32_t>& mask,
                             const char* what) {
        std::vector<std::vector<bool>> signatures(parts.size(), std::vector<bool>(linked.size()));
        for (std::size_t p = 0; p < parts.size(); ++p)
            for (std::size_t j = 0; j < linked.size(); ++j)
                signatures[p][j] = partSetContains(lights[linked[j]].link.*set, parts[p]);
        std::vector<std::vector<bool>> classes;
        bool overflow = false;
        partClass = classify(signatures, &classes, &overflow);
        if (overflow)
            r.warnings << QStringLiteral("the links divide the model into more than %1 sets of %2; the parts "
                                         "past the first %1 are treated as the first part")
                              .arg(kMaxLinkClasses)
                              .arg(QLatin1String(what));
        for (std::size_t j = 0; j < linked.size(); ++j) {
            std::uint32_t m = 0;
            for (std::size_t c = 0; c < classes.size(); ++c)
                if (classes[c][j]) m |= 1u << c;
            mask[linked[j]] = m;
        }
        return int(std::max<std::size_t>(classes.size(), 1));
    };
    r.litClasses = resolve(litLinked, &LightLink::lit, r.litClass, r.litMask, "lights");
    r.shadowClasses =
        resolve(shadowLinked, &LightLink::shadow, r.shadowClass, r.shadowMask, "shadow casters");
    return r;
}

QStringList describeLinkMatches(const std::vector<Light>& lights, const std::vector<PartNames>& parts) {
    QStringList out;
    for (std::size_t i = 0; i < lights.size(); ++i)
        for (const ListRef& list : listsOf(lights[i].link))
            for (const QString& name : list.names) {
                QStringList matched;
                for (const PartNames& p : parts)
                    if (partNameMatches(name, p)) matched << partLabel(p);
                const QString what =
                    matched.isEmpty()
                        ? QStringLiteral("no part of the model")
                        : QStringLiteral("%1 part%2 (%3)")
                              .arg(matched.size())
                              .arg(matched.size() == 1 ? "" : "s")
                              .arg(matched.size() > 8 ? (matched.mid(0, 8).join(QStringLiteral(", ")) +
                                                         QStringLiteral(", …"))
                                                      : matched.join(QStringLiteral(", ")));
                out << QStringLiteral("%1: %2 \"%3\": %4")
                           .arg(lightLabel(lights[i], i), QLatin1String(list.key), name, what);
            }
    return out;
}

} // namespace lr
