#include "editor/replacerig.h"

namespace lr {

std::unique_ptr<ReplaceRig> ReplaceRig::create(Document* doc, const Rig& rig, const QString& text,
                                               QString* error) {
    if (const QString e = validateRig(rig); !e.isEmpty()) {
        if (error) *error = e;
        return nullptr;
    }
    return std::unique_ptr<ReplaceRig>(new ReplaceRig(doc, rig, text));
}

ReplaceRig::ReplaceRig(Document* doc, Rig rig, const QString& text)
    : RigCommand(doc), m_before(doc->rig()), m_after(std::move(rig)), m_beforeIds(doc->lightIds()) {
    setText(text);
}

void ReplaceRig::undo() {
    resetRig(m_before, m_beforeIds);
}

void ReplaceRig::redo() {
    if (m_afterIds.size() != qsizetype(m_after.lights.size())) {
        m_afterIds.clear();
        for (size_t i = 0; i < m_after.lights.size(); ++i)
            m_afterIds.append(newLightId());
    }
    resetRig(m_after, m_afterIds);
}

} // namespace lr
