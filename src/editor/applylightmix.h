// A light mix written into the document's rig (issue 37, docs/light-mixing.md; the Mixer dock's "Apply to
// rig"): core/lightmix.h applyLightMix on the rig as it is now, as ONE undo step that keeps every light's id
// (so the selection and the solo set stay): only the lights whose values change are set, and the rig's
// ambient and environment when they change. Undo restores the rig exactly.
//
// A mix is made on a render's groups, whose light indices are those of the rig that was rendered. The rig
// may have changed since (lights added, removed, reordered): groupsAtRows maps the groups through the ids
// the lights had then to the rows they have now.
#pragma once

#include "core/lightgroups.h"
#include "core/lightmix.h"
#include "editor/rigcommand.h"

#include <memory>

namespace lr {

// `groups` (light indices of a rig whose lights had `idsThen`) with each light at its row in `document` now.
// A light that is gone is left out and named in *missing ("key: a light of the group was deleted since the
// render"), once per group. Groups of other kinds are kept as they are.
std::vector<LightGroup> groupsAtRows(const Document& document, const std::vector<LightGroup>& groups,
                                     const QList<LightId>& idsThen, QStringList* missing = nullptr);

class ApplyLightMix : public RigCommand {
  public:
    // The rig with the mix applied (applyLightMix, its notApplied lines in *notApplied), as a command;
    // nullptr and *error when it would change nothing ("the mix changes nothing the rig holds") or leave a
    // value outside the rig format's limits (validateRig's reason).
    static std::unique_ptr<ApplyLightMix> create(Document* document, const std::vector<LightGroup>& groups,
                                                 const LightMix& mix, QStringList* notApplied = nullptr,
                                                 QString* error = nullptr);
    void undo() override;
    void redo() override;
    const Rig& after() const { return m_after; }

  private:
    ApplyLightMix(Document* document, Rig before, Rig after);
    void apply(const Rig& rig);
    Rig m_before, m_after;
    QList<LightId> m_ids;           // the lights that change
    std::vector<size_t> m_rowsThen; // their indices in m_before / m_after (same lights, same order)
};

// Creates and pushes the command; false and *error when refused (nothing changes then).
bool applyLightMixToDocument(Document* document, const std::vector<LightGroup>& groups, const LightMix& mix,
                             QStringList* notApplied = nullptr, QString* error = nullptr);

} // namespace lr
