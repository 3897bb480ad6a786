// Duplicate: copies of the given lights inserted as one block after the last of them, selected. A copy is
// named the way Add names a new light (the original's name without its number, then the first free number:
// "Key" -> "Key 2", "Key 2" -> "Key 3"), and a copy with a position is moved aside (duplicateOffset) so that
// it does not sit exactly on its original or on an earlier copy.
#pragma once

#include "editor/addlights.h"

namespace lr {

class DuplicateLights : public AddLights {
  public:
    static std::unique_ptr<DuplicateLights> create(Document* document, const QList<int>& rows,
                                                   QString* error = nullptr);

  private:
    using AddLights::AddLights;
};

// "Key 2" -> "Key"; a name that is only a number, or has none, stays as it is.
QString duplicateBaseName(const QString& name);
// How far a copy moves from its original, along +x in rig units: a tenth of the light's distance from the
// rig's origin, at least 0.1 (so a copy of a light at the origin still moves).
glm::dvec3 duplicateOffset(const Light& light);

} // namespace lr
