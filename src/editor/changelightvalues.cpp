#include "editor/changelightvalues.h"

#include <QCoreApplication>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::ChangeLightValues", text);
}
} // namespace

std::unique_ptr<ChangeLightValues> ChangeLightValues::create(Document* doc,
                                                             const QList<LightValueEdit>& edits,
                                                             const QString& text, QString* error) {
    auto fail = [&](const QString& reason) {
        if (error) *error = reason;
        return nullptr;
    };
    QList<int> rows; // first-seen order
    std::vector<Light> after;
    for (const LightValueEdit& e : edits) {
        if (e.row < 0 || e.row >= doc->lightCount()) return fail(tr("no light at row %1").arg(e.row));
        if (e.property == LightProperty::Any || int(e.property) < 0 || int(e.property) >= kLightPropertyCount)
            return fail(tr("not an editable light value"));
        qsizetype i = rows.indexOf(e.row);
        if (i < 0) {
            rows.append(e.row);
            after.push_back(doc->light(e.row));
            i = rows.size() - 1;
        }
        Light& l = after[size_t(i)];
        if (!lightPropertyApplies(l, e.property))
            return fail(
                tr("the %1 does not apply to %2").arg(lightPropertyInfo(e.property)->displayName(), l.name));
        if (const QString v = validateLightValue(l, e.property, e.value); !v.isEmpty())
            return fail(QStringLiteral("%1: %2").arg(l.name, v));
        l = withLightValue(l, e.property, e.value);
    }
    QList<LightId> ids;
    std::vector<Light> before, changed;
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const Light& now = doc->light(rows[i]);
        if (after[size_t(i)] == now) continue;
        ids.append(doc->lightId(rows[i]));
        before.push_back(now);
        changed.push_back(after[size_t(i)]);
    }
    if (ids.isEmpty()) return fail(QString()); // nothing to do: no step, and not an error
    return std::unique_ptr<ChangeLightValues>(
        new ChangeLightValues(doc, std::move(ids), std::move(before), std::move(changed), text));
}

ChangeLightValues::ChangeLightValues(Document* doc, QList<LightId> ids, std::vector<Light> before,
                                     std::vector<Light> after, const QString& text)
    : RigCommand(doc), m_ids(std::move(ids)), m_before(std::move(before)), m_after(std::move(after)) {
    setText(text);
}

void ChangeLightValues::undo() {
    setLights(m_ids, m_before, LightProperty::Any);
}

void ChangeLightValues::redo() {
    setLights(m_ids, m_after, LightProperty::Any);
}

} // namespace lr
