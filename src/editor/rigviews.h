// The rig's named view bookmarks (Rig::views, docs/rig-format.md "views") as undo steps: saving a view under
// a name (replacing one of that name) and removing one. The viewport's camera itself is no part of the undo
// history; recalling a view moves the camera and is not a step either.
#pragma once

#include "editor/rigcommand.h"

#include <memory>

namespace lr {

class ChangeRigViews : public RigCommand {
  public:
    // `views` become the rig's (names unique and non-empty, at most kMaxRigViews: else nullptr and *error).
    static std::unique_ptr<ChangeRigViews> create(Document* document, std::vector<RigView> views,
                                                  const QString& text, QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    ChangeRigViews(Document* document, std::vector<RigView> views, const QString& text);
    void apply(const std::vector<RigView>& views);
    std::vector<RigView> m_before, m_after;
};

// Convenience over ChangeRigViews: one undo step each ("Save view “Front”", "Remove view “Front”").
bool saveRigView(Document* document, const RigView& view, QString* error = nullptr);
bool removeRigView(Document* document, const QString& name, QString* error = nullptr);

} // namespace lr
