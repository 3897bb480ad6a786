// The light-property rows of a spot's gobo (issue 39, core/lightshaping.h GoboSpec; docs/rig-format.md
// "gobo"): its file (empty removes the gobo, a name adds one), and while it has one its scale and rotation,
// in the rig reader's ranges so that a saved rig always loads again.
#include "editor/lightproperty.h"
#include "editor/lightproperty_parts.h"
#include "editor/propertyvalue.h"

#include <QCoreApplication>
#include <iterator>

namespace lr {

namespace {

using namespace propertyvalue;
using P = LightProperty;
using K = LightValueKind;
using T = LightTypeTraits;

bool hasGobo(const Light& l) {
    return l.gobo.has_value();
}

QString checkGoboFile(const LightPropertyInfo&, const QVariant& v) {
    if (v.metaType().id() != QMetaType::QString) return QStringLiteral("gobo file must be text");
    const QString s = v.toString();
    if (s.size() > 4096)
        return QStringLiteral("gobo file must be at most 4096 characters, got %1").arg(s.size());
    if (s.contains(QChar(0))) return QStringLiteral("gobo file must not contain a NUL character");
    return {};
}

// The rig reader resolves a relative file against the rig's folder (resolveLightFiles); a name typed here
// is used as it is until the rig is read again.
void setGoboFile(Light& l, const QVariant& v) {
    const QString file = v.toString().trimmed();
    if (file.isEmpty()) {
        l.gobo.reset();
        return;
    }
    if (!l.gobo) l.gobo = GoboSpec{};
    if (l.gobo->file != file) l.gobo->resolved.clear();
    l.gobo->file = file;
}

const LightPropertyInfo kGoboRows[] = {
    {.id = P::GoboFile,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "gobo file"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Gobo file"),
     .key = "goboFile",
     .jsonField = "gobo.file",
     .kind = K::Text,
     .usedBy = &T::usesCone,
     .check = checkGoboFile,
     .get = [](const Light& l) { return QVariant(l.gobo ? l.gobo->file : QString()); },
     .set = setGoboFile},
    {.id = P::GoboScale,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "gobo scale"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Gobo scale"),
     .key = "goboScale",
     .jsonField = "gobo.scale",
     .kind = K::Number,
     .min = 0.01,
     .max = 100.0,
     .unit = "× the cone's width",
     .usedBy = &T::usesCone,
     .shown = hasGobo,
     .get = [](const Light& l) { return QVariant(l.gobo ? l.gobo->scale : 1.0); },
     .set =
         [](Light& l, const QVariant& v) {
             if (l.gobo) l.gobo->scale = number(v, l.gobo->scale);
         }},
    {.id = P::GoboRotation,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "gobo rotation"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Gobo rotation"),
     .key = "goboRotation",
     .jsonField = "gobo.rotation",
     .kind = K::Number,
     .min = -360.0,
     .max = 360.0,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::usesCone,
     .shown = hasGobo,
     .get = [](const Light& l) { return QVariant(l.gobo ? l.gobo->rotation : 0.0); },
     .set =
         [](Light& l, const QVariant& v) {
             if (l.gobo) l.gobo->rotation = number(v, l.gobo->rotation);
         }},
};
static_assert(std::size(kGoboRows) == kGoboLightPropertyCount);

} // namespace

std::span<const LightPropertyInfo> goboLightProperties() {
    return kGoboRows;
}

} // namespace lr
