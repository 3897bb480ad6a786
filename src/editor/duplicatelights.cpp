#include "editor/duplicatelights.h"

#include <QCoreApplication>
#include <algorithm>

namespace lr {

std::unique_ptr<DuplicateLights> DuplicateLights::create(Document* doc, const QList<int>& rows,
                                                         QString* error) {
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.isEmpty() || sorted.front() < 0 || sorted.back() >= doc->lightCount()) {
        if (error) *error = QCoreApplication::translate("lr::DuplicateLights", "no light selected");
        return nullptr;
    }
    // Validates count and values the same way as AddLights.
    std::vector<Light> copies;
    copies.reserve(size_t(sorted.size()));
    for (int r : sorted) {
        Light l = doc->light(r);
        l.name =
            (l.name + QCoreApplication::translate("lr::DuplicateLights", " copy")).left(kMaxLightNameLength);
        copies.push_back(std::move(l));
    }
    const QString text =
        sorted.size() == 1
            ? QCoreApplication::translate("lr::DuplicateLights", "Duplicate %1")
                  .arg(doc->light(sorted.front()).name)
            : QCoreApplication::translate("lr::DuplicateLights", "Duplicate %1 lights").arg(sorted.size());
    if (!AddLights::create(doc, sorted.back() + 1, copies, text, error)) return nullptr;
    return std::unique_ptr<DuplicateLights>(
        new DuplicateLights(doc, sorted.back() + 1, std::move(copies), text));
}

} // namespace lr
