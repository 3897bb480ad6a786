#include "editor/changelightvalue.h"

#include "core/rigjson.h"

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

    const LightPropertyInfo& row = *lightPropertyInfo(property);
    QList<LightId> kept;
    std::vector<Light> before, after;
    kept.reserve(qsizetype(order.size()));
    before.reserve(order.size());
    after.reserve(order.size());
    bool changes = false;
    for (const auto& [r, vi] : order) {
        const Light& l = doc->light(r);
        if (!row.applies(l)) continue;
        if (const QString e = validateLightValue(l, property, values[vi]); !e.isEmpty())
            return fail(order.size() > 1 ? QStringLiteral("%1: %2").arg(l.name, e) : e);
        kept.append(doc->lightId(r));
        before.push_back(l);
        after.push_back(withLightValue(l, property, values[vi]));
        changes = changes || after.back() != l;
    }
    if (kept.isEmpty())
        return fail(tr("the %1 does not apply to %2")
                        .arg(row.displayName(),
                             rows.size() == 1 ? doc->light(rows[0]).name : tr("the selected lights")));
    if (row.uniquePerLight) {
        // No two lights share it (names): a value another light has, or one given to several lights, gets
        // the first free number, as Add names new lights ("Key" -> "Key 2").
        QSet<QString> taken;
        for (int i = 0; i < doc->lightCount(); ++i)
            if (!kept.contains(doc->lightId(i))) taken.insert(row.get(doc->light(i)).toString());
        changes = false;
        for (size_t i = 0; i < after.size(); ++i) {
            const QString wanted = row.get(after[i]).toString();
            QString name = wanted;
            for (int n = 2; taken.contains(name); ++n)
                name = QStringLiteral("%1 %2").arg(wanted).arg(n);
            taken.insert(name);
            after[i] = withLightValue(after[i], property, name);
            if (const QString e = validateLightValue(after[i], property, name); !e.isEmpty()) return fail(e);
            changes = changes || after[i] != before[i];
        }
    }
    if (!changes) return fail(QString()); // nothing to do: no step, and not an error
    // At most kMaxShadowCasters shadows switched on (enabling one, or a type change that makes a kept shadow
    // count again): refused with the limit, never silently. Edits that add no caster always pass.
    int casters = 0, castersAfter = 0;
    for (size_t i = 0; i < before.size(); ++i) {
        casters += before[i].castsShadows() && before[i].shadow.enabled;
        castersAfter += after[i].castsShadows() && after[i].shadow.enabled;
    }
    if (castersAfter > casters) {
        const int total = shadowCasterCount(doc->rig().lights) - casters + castersAfter;
        if (const QString e = checkShadowCasterCount(total); !e.isEmpty()) return fail(e);
    }
    return std::unique_ptr<ChangeLightValue>(new ChangeLightValue(doc, std::move(kept), property,
                                                                  std::move(before), std::move(after),
                                                                  values.value(order.front().second)));
}

ChangeLightValue::ChangeLightValue(Document* doc, QList<LightId> ids, LightProperty property,
                                   std::vector<Light> before, std::vector<Light> after, const QVariant& value)
    : RigCommand(doc), m_ids(std::move(ids)), m_property(property), m_before(std::move(before)),
      m_after(std::move(after)), m_session(doc->continuousEditSession()) {
    const LightPropertyInfo& row = *lightPropertyInfo(property);
    const QString lights = m_ids.size() == 1 ? m_before.front().name : tr("%1 lights").arg(m_ids.size());
    setText(row.undoText ? row.undoText(lights, value)
                         : tr("Change %1 of %2").arg(row.displayName(), lights));
}

void ChangeLightValue::undo() {
    setLights(m_ids, m_before, m_property);
}

void ChangeLightValue::redo() {
    setLights(m_ids, m_after, m_property);
    updateObsolete();
}

void ChangeLightValue::updateObsolete() {
    setObsolete(m_before == m_after);
}

bool ChangeLightValue::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const ChangeLightValue*>(other);
    if (m_session == 0 || o->m_session != m_session || o->m_property != m_property || o->m_ids != m_ids)
        return false;
    if (m_property == LightProperty::Link) return false; // each linking edit is a step of its own (issue 38)
    m_after = o->m_after;
    updateObsolete();
    return true;
}

} // namespace lr
