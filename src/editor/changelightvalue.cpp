#include "editor/changelightvalue.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::ChangeLightValue", text);
}
} // namespace

std::unique_ptr<ChangeLightValue> ChangeLightValue::create(Document* doc, const QList<int>& rows,
                                                           LightProperty property, const QVariant& value,
                                                           QString* error) {
    QVariantList values;
    values.fill(value, rows.size());
    return create(doc, rows, property, values, error);
}

std::unique_ptr<ChangeLightValue> ChangeLightValue::create(Document* doc, const QList<int>& rows,
                                                           LightProperty property, const QVariantList& values,
                                                           QString* error) {
    auto fail = [&](const QString& reason) {
        if (error) *error = reason;
        return nullptr;
    };
    if (property == LightProperty::Any || int(property) < 0 || int(property) >= kLightPropertyCount)
        return fail(tr("not an editable light value"));
    if (values.size() != rows.size())
        return fail(tr("%1 values for %2 lights").arg(values.size()).arg(rows.size()));
    if (rows.isEmpty()) return fail(tr("no light selected"));

    // Sort by row, drop duplicate rows (the first value wins) and rows where the property does not apply.
    std::vector<std::pair<int, int>> order; // (row, index into values)
    order.reserve(size_t(rows.size()));
    for (int i = 0; i < rows.size(); ++i) {
        if (rows[i] < 0 || rows[i] >= doc->lightCount()) return fail(tr("no light at row %1").arg(rows[i]));
        order.emplace_back(rows[i], i);
    }
    std::stable_sort(order.begin(), order.end(), [](auto a, auto b) { return a.first < b.first; });
    order.erase(std::unique(order.begin(), order.end(), [](auto a, auto b) { return a.first == b.first; }),
                order.end());

    QList<int> kept;
    std::vector<Light> before, after;
    kept.reserve(qsizetype(order.size()));
    before.reserve(order.size());
    after.reserve(order.size());
    for (const auto& [row, vi] : order) {
        const Light& l = doc->light(row);
        if (!lightPropertyApplies(l, property)) continue;
        if (const QString e = validateLightValue(l, property, values[vi]); !e.isEmpty())
            return fail(order.size() > 1 ? QStringLiteral("%1: %2").arg(l.name, e) : e);
        kept.append(row);
        before.push_back(l);
        after.push_back(withLightValue(l, property, values[vi]));
    }
    if (kept.isEmpty())
        return fail(tr("the %1 does not apply to %2")
                        .arg(lightPropertyName(property),
                             rows.size() == 1 ? doc->light(rows[0]).name : tr("the selected lights")));
    return std::unique_ptr<ChangeLightValue>(
        new ChangeLightValue(doc, std::move(kept), property, std::move(before), std::move(after)));
}

ChangeLightValue::ChangeLightValue(Document* doc, QList<int> rows, LightProperty property,
                                   std::vector<Light> before, std::vector<Light> after)
    : m_doc(doc), m_rows(std::move(rows)), m_property(property), m_before(std::move(before)),
      m_after(std::move(after)), m_session(doc->continuousEditSession()) {
    const QString what = lightPropertyName(property);
    setText(m_rows.size() == 1 ? tr("Change %1 of %2").arg(what, m_before.front().name)
                               : tr("Change %1 of %2 lights").arg(what).arg(m_rows.size()));
}

void ChangeLightValue::undo() {
    m_doc->setLightsAt(m_rows, m_before, m_property);
}

void ChangeLightValue::redo() {
    m_doc->setLightsAt(m_rows, m_after, m_property);
    updateObsolete();
}

void ChangeLightValue::updateObsolete() {
    setObsolete(m_before == m_after);
}

bool ChangeLightValue::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const ChangeLightValue*>(other);
    if (m_session == 0 || o->m_session != m_session || o->m_property != m_property || o->m_rows != m_rows)
        return false;
    m_after = o->m_after;
    updateObsolete();
    return true;
}

} // namespace lr
