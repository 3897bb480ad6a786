#include "editor/duplicatelights.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>
#include <glm/geometric.hpp>

namespace lr {

QString duplicateBaseName(const QString& name) {
    static const QRegularExpression numbered(QStringLiteral("^(.*\\S) +\\d+$"));
    const QRegularExpressionMatch m = numbered.match(name);
    return m.hasMatch() ? m.captured(1) : name;
}

glm::dvec3 duplicateOffset(const Light& light) {
    return {0.1 * std::max(glm::length(light.position), 1.0), 0.0, 0.0};
}

namespace {
bool positionTaken(const std::vector<glm::dvec3>& taken, const glm::dvec3& p) {
    return std::any_of(taken.begin(), taken.end(),
                       [&](const glm::dvec3& q) { return glm::length(p - q) < 1e-9; });
}
} // namespace

std::unique_ptr<DuplicateLights> DuplicateLights::create(Document* doc, const QList<int>& rows,
                                                         QString* error) {
    QList<int> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.isEmpty() || sorted.front() < 0 || sorted.back() >= doc->lightCount()) {
        if (error) *error = QCoreApplication::translate("lr::DuplicateLights", "no light selected");
        return nullptr;
    }
    std::vector<glm::dvec3> positions; // where positioned lights are (and copies will be)
    for (const Light& l : doc->rig().lights)
        if (l.usesPosition()) positions.push_back(l.position);
    QSet<QString> newNames;
    // Validates count and values the same way as AddLights.
    std::vector<Light> copies;
    copies.reserve(size_t(sorted.size()));
    for (int r : sorted) {
        Light l = doc->light(r);
        l.name = doc->uniqueLightName(duplicateBaseName(l.name), newNames).left(kMaxLightNameLength);
        newNames.insert(l.name);
        if (l.usesPosition()) {
            const glm::dvec3 step = duplicateOffset(l);
            glm::dvec3 p = l.position + step;
            for (int k = 0; k < 1000 && positionTaken(positions, p); ++k)
                p += step;
            if (std::abs(p.x) <= kMaxCoordinate) l.position = p; // else stays on its original
            positions.push_back(l.position);
        }
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
