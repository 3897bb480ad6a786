#include "editor/applylightmix.h"

#include <QCoreApplication>
#include <QSet>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("lr::ApplyLightMix", text);
}
} // namespace

std::vector<LightGroup> groupsAtRows(const Document& doc, const std::vector<LightGroup>& groups,
                                     const QList<LightId>& idsThen, QStringList* missing) {
    std::vector<LightGroup> out = groups;
    for (LightGroup& g : out) {
        if (g.kind != LightGroupKind::Lights) continue;
        std::vector<int> rows;
        bool gone = false;
        for (int i : g.lights) {
            const int row = i >= 0 && i < idsThen.size() ? doc.rowOf(idsThen[i]) : -1;
            if (row >= 0)
                rows.push_back(row);
            else
                gone = true;
        }
        if (gone && missing)
            *missing << tr("%1: a light of the group was deleted since the render; the others get the mix")
                            .arg(g.name);
        g.lights = std::move(rows);
    }
    return out;
}

std::unique_ptr<ApplyLightMix> ApplyLightMix::create(Document* doc, const std::vector<LightGroup>& groups,
                                                     const LightMix& mix, QStringList* notApplied,
                                                     QString* error) {
    auto fail = [&](const QString& reason) {
        if (error) *error = reason;
        return nullptr;
    };
    // applyLightMix trusts its indices: a group naming a light the rig does not have loses that light.
    std::vector<LightGroup> checked = groups;
    for (LightGroup& g : checked)
        std::erase_if(g.lights, [&](int i) { return i < 0 || i >= doc->lightCount(); });
    const Rig& before = doc->rig();
    Rig after = applyLightMix(before, checked, mix, notApplied);
    if (after == before) return fail(tr("the mix changes nothing the rig holds"));
    if (const QString e = validateRig(after); !e.isEmpty()) return fail(e);
    return std::unique_ptr<ApplyLightMix>(new ApplyLightMix(doc, before, std::move(after)));
}

ApplyLightMix::ApplyLightMix(Document* doc, Rig before, Rig after)
    : RigCommand(doc), m_before(std::move(before)), m_after(std::move(after)) {
    for (size_t i = 0; i < m_after.lights.size(); ++i) {
        if (m_after.lights[i] == m_before.lights[i]) continue;
        m_ids.append(doc->lightId(int(i)));
        m_rowsThen.push_back(i);
    }
    // applyLightMix changes lights, the ambient and the environment, nothing else: what apply() sets.
    Rig expected = m_before;
    expected.lights = m_after.lights;
    expected.ambient = m_after.ambient;
    expected.environment = m_after.environment;
    Q_ASSERT(expected == m_after);
    setText(tr("Apply light mix"));
}

void ApplyLightMix::apply(const Rig& rig) {
    std::vector<Light> lights;
    lights.reserve(m_rowsThen.size());
    for (size_t i : m_rowsThen)
        lights.push_back(rig.lights[i]);
    if (!lights.empty()) setLights(m_ids, lights, LightProperty::Any);
    if (m_before.ambient != m_after.ambient)
        setRigValue(RigProperty::Ambient, rigValue(rig, RigProperty::Ambient));
    if (m_before.environment != m_after.environment)
        setRigValue(RigProperty::Environment, rigValue(rig, RigProperty::Environment));
}

void ApplyLightMix::undo() {
    apply(m_before);
}

void ApplyLightMix::redo() {
    apply(m_after);
}

bool applyLightMixToDocument(Document* doc, const std::vector<LightGroup>& groups, const LightMix& mix,
                             QStringList* notApplied, QString* error) {
    auto cmd = ApplyLightMix::create(doc, groups, mix, notApplied, error);
    if (!cmd) return false;
    doc->undoStack()->push(cmd.release());
    return true;
}

} // namespace lr
