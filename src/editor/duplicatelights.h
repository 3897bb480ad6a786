// Duplicate: copies of the given lights ("NAME copy") inserted as one block after the last of them, selected.
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

} // namespace lr
