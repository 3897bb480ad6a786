// The light-property row of a light's linking (issue 38, core/lightlink.h): its value is the whole LightLink,
// so one ChangeLightValue sets the links of several lights (one value each) as one undo step. Checked as the
// rig reader checks a "link" object (docs/rig-format.md), so a saved rig always loads again with the same
// lists. Also joins the table's halves (lightproperty_parts.h).
#include "core/rigjson.h"
#include "editor/lightproperty.h"
#include "editor/lightproperty_parts.h"

#include <QCoreApplication>
#include <QSet>
#include <vector>

namespace lr {

namespace {

QString checkNames(const QStringList& names, const char* list) {
    if (names.size() > kMaxLinkNames)
        return QStringLiteral("%1 has %2 names; at most %3")
            .arg(QLatin1String(list))
            .arg(names.size())
            .arg(kMaxLinkNames);
    QSet<QString> seen;
    for (const QString& name : names) {
        if (const QString problem = partNameProblem(name); !problem.isEmpty())
            return QStringLiteral("%1: %2").arg(QLatin1String(list), problem);
        qsizetype codePoints = 0;
        for (const QChar c : name) {
            codePoints += !c.isLowSurrogate();
            if (c.category() == QChar::Other_Control)
                return QStringLiteral("%1: a part name must not contain control characters")
                    .arg(QLatin1String(list));
        }
        if (codePoints > kMaxRigNameLength)
            return QStringLiteral("%1: \"%2\" is longer than %3 characters")
                .arg(QLatin1String(list), name.left(40))
                .arg(kMaxRigNameLength);
        if (seen.contains(name))
            return QStringLiteral("%1 names \"%2\" twice").arg(QLatin1String(list), name);
        seen.insert(name);
    }
    return {};
}

QString checkLink(const LightPropertyInfo&, const QVariant& v) {
    if (v.metaType() != QMetaType::fromType<LightLink>())
        return QStringLiteral("linking must be a light link");
    const LightLink k = v.value<LightLink>();
    for (const auto& [names, list] : {std::pair{&k.lit.include, "link.include"},
                                      {&k.lit.exclude, "link.exclude"},
                                      {&k.shadow.include, "link.shadow.include"},
                                      {&k.shadow.exclude, "link.shadow.exclude"}})
        if (QString e = checkNames(*names, list); !e.isEmpty()) return e;
    return {};
}

QString undoLink(const QString& lights, const QVariant& link) {
    return link.value<LightLink>().isDefault()
               ? QCoreApplication::translate("lr::ChangeLightValue", "Reset the linking of %1").arg(lights)
               : QCoreApplication::translate("lr::ChangeLightValue", "Change the linking of %1").arg(lights);
}

const LightPropertyInfo kLinkRow = {.id = LightProperty::Link,
                                    .name = QT_TRANSLATE_NOOP("lr::LightProperty", "linking"),
                                    .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Linking"),
                                    .key = "link",
                                    .jsonField = "link",
                                    .kind = LightValueKind::Link,
                                    .check = checkLink,
                                    .get = [](const Light& l) { return QVariant::fromValue(l.link); },
                                    .set = [](Light& l, const QVariant& v) { l.link = v.value<LightLink>(); },
                                    .undoText = undoLink};

} // namespace

const LightPropertyInfo& linkLightProperty() {
    return kLinkRow;
}

std::span<const LightPropertyInfo> lightProperties() {
    static const std::vector<LightPropertyInfo> rows = [] {
        std::vector<LightPropertyInfo> out(valueLightProperties().begin(), valueLightProperties().end());
        out.insert(out.end(), goboLightProperties().begin(), goboLightProperties().end());
        out.insert(out.end(), barnDoorLightProperties().begin(), barnDoorLightProperties().end());
        out.insert(out.end(), iesLightProperties().begin(), iesLightProperties().end()); // issue 39
        out.push_back(kLinkRow); // last: the dock shows it as a section of its own below the values
        return out;
    }();
    return rows;
}

} // namespace lr
