#include "rigjson_check.h"

#include "lighting.h"

#include <cmath>

namespace lr::rigjson {

using json::Value;

namespace {
// A bound as people write it: 90, 1000000, and 1e12 rather than 1000000000000.
QString bound(double v) {
    const double e = std::round(std::log10(std::abs(v)));
    if (std::abs(v) >= 1e7 && v == std::copysign(std::pow(10.0, e), v))
        return (v < 0 ? QStringLiteral("-1e") : QStringLiteral("1e")) + QString::number(int(e));
    return QString::fromLatin1(json::formatNumber(v));
}
} // namespace

QString Interval::describe() const {
    QString s = QStringLiteral("a finite number");
    const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
    if (hasMin && hasMax && minInclusive && maxInclusive)
        return s + QStringLiteral(" from %1 to %2").arg(bound(min), bound(max));
    if (hasMin)
        s += QStringLiteral(" %1 %2").arg(minInclusive ? QStringLiteral(">=") : QStringLiteral(">"),
                                          bound(min));
    if (hasMax)
        s += QStringLiteral("%1 %2 %3")
                 .arg(hasMin ? QStringLiteral(" and") : QString(),
                      maxInclusive ? QStringLiteral("<=") : QStringLiteral("<"), bound(max));
    return s;
}

bool Interval::contains(double v) const {
    if (!std::isfinite(v)) return false;
    if (minInclusive ? !(v >= min) : !(v > min)) return false;
    if (maxInclusive ? !(v <= max) : !(v < max)) return false;
    return true;
}

void Checker::error(const QString& path, const QString& reason) {
    if (m_errors.size() >= kMaxMessages) {
        ++m_droppedErrors;
        return;
    }
    m_errors << (path.isEmpty() ? QStringLiteral("%1: %2").arg(m_file, reason)
                                : QStringLiteral("%1: %2: %3").arg(m_file, path, reason));
}

void Checker::warning(const QString& path, const QString& reason) {
    if (m_warnings.size() >= kMaxMessages) {
        ++m_droppedWarnings;
        return;
    }
    m_warnings << QStringLiteral("%1: %2: %3").arg(m_file, path, reason);
}

void Checker::fileError(const QString& reason) {
    error(QString(), reason);
}

RigReadResult Checker::result(std::optional<Rig> rig) const {
    RigReadResult r;
    r.errors = m_errors;
    r.warnings = m_warnings;
    r.unlistedErrors = m_droppedErrors;
    if (m_droppedErrors)
        r.errors << QStringLiteral("%1: %2 more errors not listed").arg(m_file).arg(m_droppedErrors);
    if (m_droppedWarnings)
        r.warnings << QStringLiteral("%1: %2 more warnings not listed").arg(m_file).arg(m_droppedWarnings);
    if (r.errors.isEmpty()) r.rig = std::move(rig);
    return r;
}

std::optional<double> Checker::number(const Value& v, const QString& path, const Interval& in) {
    if (v.isNumber() && v.finite && in.contains(v.number)) return v.number;
    expected(v, path, in.describe());
    return std::nullopt;
}

std::optional<bool> Checker::boolean(const Value& v, const QString& path) {
    if (v.kind == Value::Kind::Bool) return v.boolean;
    expected(v, path, QStringLiteral("true or false"));
    return std::nullopt;
}

std::optional<QString> Checker::name(const Value& v, const QString& path) {
    if (v.kind != Value::Kind::String) {
        expected(v, path, QStringLiteral("a string"));
        return std::nullopt;
    }
    qsizetype codePoints = 0;
    for (qsizetype i = 0; i < v.string.size(); ++i)
        if (!v.string.at(i).isLowSurrogate()) ++codePoints;
    if (codePoints > kMaxRigNameLength) {
        error(path,
              QStringLiteral("must be at most %1 characters, got %2").arg(kMaxRigNameLength).arg(codePoints));
        return std::nullopt;
    }
    return v.string;
}

std::optional<glm::dvec3> Checker::vec3(const Value& v, const QString& path, const Interval& in,
                                        const QString& what) {
    if (v.kind != Value::Kind::Array || v.items.size() != 3) {
        expected(v, path, what);
        return std::nullopt;
    }
    glm::dvec3 out;
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
        const auto c = number(v.items[size_t(i)], json::appendIndex(path, i), in);
        if (c) out[i] = *c;
        ok = ok && c.has_value();
    }
    return ok ? std::optional(out) : std::nullopt;
}

std::optional<glm::dvec3> Checker::color(const Value& v, const QString& path) {
    return vec3(v, path, nonNegative(kMaxRigIntensity),
                QStringLiteral("an RGB colour [r, g, b] (linear, >= 0)"));
}

std::optional<glm::dvec3> Checker::albedo(const Value& v, const QString& path) {
    return vec3(v, path, nonNegative(1.0), QStringLiteral("an RGB albedo [r, g, b] (linear, 0 ... 1)"));
}

std::optional<glm::dvec3> Checker::point(const Value& v, const QString& path) {
    return vec3(v, path, {-kMaxRigLength, true, kMaxRigLength, true}, QStringLiteral("a point [x, y, z]"));
}

std::optional<glm::dvec3> Checker::direction(const Value& v, const QString& path) {
    const auto d = vec3(v, path, {}, QStringLiteral("a direction [x, y, z]"));
    if (!d) return std::nullopt;
    if (*d == glm::dvec3(0.0)) {
        error(path, QStringLiteral("must not be the zero vector [0, 0, 0]"));
        return std::nullopt;
    }
    return normalizeDirection(*d);
}

bool Checker::isObject(const Value& v, const QString& path) {
    if (v.kind == Value::Kind::Object) return true;
    expected(v, path, QStringLiteral("an object {...}"));
    return false;
}

ObjectView::ObjectView(Checker& checker, const Value& object, const QString& path)
    : m_checker(checker), m_object(object), m_path(path), m_used(object.members.size(), false) {}

const Value* ObjectView::take(const char* key) {
    const QLatin1String k(key);
    for (size_t i = 0; i < m_object.members.size(); ++i) {
        const json::Member& m = m_object.members[i];
        if (m.key != k) continue;
        m_used[i] = true;
        if (!m.duplicate) return &m.value;
    }
    return nullptr;
}

const Value* ObjectView::require(const char* key, const QString& missing) {
    if (const Value* v = take(key)) return v;
    m_checker.error(path(key), missing);
    m_valid = false;
    return nullptr;
}

void ObjectView::reject(const char* key, const QString& reason) {
    if (take(key)) m_checker.error(path(key), reason);
}

void ObjectView::finish() {
    for (size_t i = 0; i < m_object.members.size(); ++i)
        if (!m_used[i] && !m_object.members[i].duplicate)
            m_checker.warning(json::appendKey(m_path, m_object.members[i].key),
                              QStringLiteral("unknown key (ignored)"));
}

glm::dvec3 normalizeDirection(const glm::dvec3& v) {
    const double length2 = glm::dot(v, v);
    if (std::abs(length2 - 1.0) <= 1e-12) return v;
    return lighting::safeNormalize(v, glm::dvec3(0.0, -1.0, 0.0));
}

} // namespace lr::rigjson
