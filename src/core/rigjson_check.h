// Validation helpers for the rig reader (private to rigjson*.cpp): a message collector that formats
// "FILE: json.path: reason", typed value readers that report what they expected and what they got,
// and ObjectView, which tracks the keys an object's reader used so the rest become warnings.
#pragma once

#include "rigjson.h"
#include "rigjson_json.h"
#include "types.h"

#include <glm/vec3.hpp>
#include <optional>

namespace lr::rigjson {

constexpr int kMaxMessages = 200; // errors (and warnings) listed per file; the rest are counted

// A closed or open bound on a number; infinite values mean "no bound".
struct Interval {
    double min = -std::numeric_limits<double>::infinity();
    bool minInclusive = true;
    double max = std::numeric_limits<double>::infinity();
    bool maxInclusive = true;
    QString describe() const; // "a finite number > 0 and <= 90"
    bool contains(double v) const;
};
inline Interval positive(double max) {
    return {0.0, false, max, true};
}
inline Interval nonNegative(double max) {
    return {0.0, true, max, true};
}

class Checker {
  public:
    Checker(const QByteArray& source, const QString& file) : m_source(source), m_file(file) {}

    void error(const QString& path, const QString& reason);
    void warning(const QString& path, const QString& reason);
    void fileError(const QString& reason); // about the whole file: "FILE: reason"
    bool hasErrors() const { return !m_errors.isEmpty(); }
    RigReadResult result(std::optional<Rig> rig) const;

    QString describe(const json::Value& v) const { return json::describe(v, m_source); }
    void expected(const json::Value& v, const QString& path, const QString& what) {
        error(path, QStringLiteral("must be %1, got %2").arg(what, describe(v)));
    }

    std::optional<double> number(const json::Value& v, const QString& path, const Interval& in);
    std::optional<bool> boolean(const json::Value& v, const QString& path);
    std::optional<QString> name(const json::Value& v, const QString& path);
    std::optional<glm::dvec3> color(const json::Value& v, const QString& path);
    std::optional<glm::dvec3> albedo(const json::Value& v, const QString& path);    // components 0 ... 1
    std::optional<glm::dvec3> point(const json::Value& v, const QString& path);     // |x| <= kMaxRigLength
    std::optional<glm::dvec3> direction(const json::Value& v, const QString& path); // non-zero, normalised
    bool isObject(const json::Value& v, const QString& path);

    template <typename E> std::optional<E> enumValue(const json::Value& v, const QString& path) {
        if (v.kind == json::Value::Kind::String)
            if (const auto e = fromString<E>(v.string)) return e;
        expected(v, path, allowedNames<E>());
        return std::nullopt;
    }

  private:
    std::optional<glm::dvec3> vec3(const json::Value& v, const QString& path, const Interval& in,
                                   const QString& what);
    const QByteArray& m_source;
    QString m_file;
    QStringList m_errors, m_warnings;
    int m_droppedErrors = 0, m_droppedWarnings = 0;
};

// One JSON object being read: take() the keys the format defines for it, reject() the ones it defines
// elsewhere, and finish() to warn about the rest. A value that fails its reader (keep(), read(), require())
// makes the object invalid: result() then gives nullopt, the errors already reported.
class ObjectView {
  public:
    ObjectView(Checker& checker, const json::Value& object, const QString& path);

    const json::Value* take(const char* key); // first occurrence (duplicates are parse errors)
    QString path(const char* key) const { return json::appendKey(m_path, QString::fromLatin1(key)); }
    const QString& path() const { return m_path; }
    void reject(const char* key, const QString& reason); // present -> error at path.key
    void finish(); // every key not taken or rejected -> "unknown key (ignored)" warning

    // take() + the typed reader; leaves `out` alone when the key is absent or invalid.
    template <typename T, typename Read> void read(const char* key, T& out, Read&& reader) {
        if (const json::Value* v = take(key)) keep(reader(*v, path(key)), out);
    }
    // A reader's result into `out`, or the object marked invalid.
    template <typename R, typename T> void keep(const R& result, T& out) {
        if (result)
            out = *result;
        else
            m_valid = false;
    }
    // take() a key the object must have; when it is missing, the error `missing` at path.key.
    const json::Value* require(const char* key, const QString& missing);
    void invalidate() { m_valid = false; }
    // finish(), then `value` unless something in the object was invalid.
    template <typename T> std::optional<T> result(T value) {
        finish();
        return m_valid ? std::optional<T>(std::move(value)) : std::nullopt;
    }

  private:
    Checker& m_checker;
    const json::Value& m_object;
    QString m_path;
    std::vector<bool> m_used;
    bool m_valid = true;
};

// rigjson_models.cpp: a light's "falloff" and "cone" objects; nullopt when invalid (errors reported).
std::optional<Falloff> readFalloff(Checker& c, const json::Value& v, const QString& path);
std::optional<Cone> readCone(Checker& c, const json::Value& v, const QString& path);
// rigjson_shadow.cpp: a light's "shadow" (type: the light's, nullopt when unknown: every key allowed) and the
// rig's "ground"; nullopt when invalid (errors reported).
std::optional<Shadow> readShadow(Checker& c, const json::Value& v, const QString& path,
                                 std::optional<LightType> type);
std::optional<Ground> readGround(Checker& c, const json::Value& v, const QString& path);
// rigjson_area.cpp: an area light's "area" (type: the light's, nullopt when unknown: every key allowed);
// nullopt when invalid (errors reported). The first format version that has a light type (rect and disk: 2),
// and the version a rig is written as: the oldest that holds every light it has.
std::optional<AreaShape> readArea(Checker& c, const json::Value& v, const QString& path,
                                  std::optional<LightType> type);
int firstFormatVersion(LightType type);
int formatVersionFor(const Rig& rig);
// rigjson_link.cpp: a light's "link" (issue 38, format version 3); nullopt when invalid (errors reported),
// and its canonical text (nullopt for the default link, which is not written).
constexpr int kLinkFormatVersion = 3;
std::optional<LightLink> readLink(Checker& c, const json::Value& v, const QString& path, int version);
std::optional<QByteArray> writeLink(const LightLink& link);
// rigjson_gobo.cpp: a spot light's "gobo" (issue 39, format version 4); nullopt when invalid (errors
// reported), and its canonical text.
constexpr int kGoboFormatVersion = 4;
constexpr int kMaxGoboPathLength = 4096;
constexpr double kMinGoboScale = 0.01, kMaxGoboScale = 100.0;
std::optional<GoboSpec> readGobo(Checker& c, const json::Value& v, const QString& path, int version);
QByteArray writeGobo(const GoboSpec& g);
// rigjson_barndoors.cpp: a rect light's "barnDoors" (issue 39, format version 4); nullopt when invalid
// (errors reported), and its canonical text.
constexpr int kBarnDoorsFormatVersion = 4;
std::optional<BarnDoors> readBarnDoors(Checker& c, const json::Value& v, const QString& path, int version);
QByteArray writeBarnDoors(const BarnDoors& barnDoors);
// rigjson_ies.cpp: a point or spot light's "ies" (issue 39, format version 4; type nullopt when unknown);
// nullopt when invalid (errors reported), and its canonical text.
constexpr int kIesFormatVersion = 4;
std::optional<IesSpec> readIes(Checker& c, const json::Value& v, const QString& path, int version,
                               std::optional<LightType> type);
QByteArray writeIes(const IesSpec& spec);
// rigjson_environment.cpp: the rig's "environment" (nullopt when invalid, errors reported), and its canonical
// text (nullopt for the default environment, which is not written).
std::optional<Environment> readEnvironment(Checker& c, const json::Value& v, const QString& path);
std::optional<QByteArray> writeEnvironment(const Environment& environment);
// rigjson_views.cpp: the rig's "view" (named: false) or one of its "views" (named: true), and the "views"
// array (names unique, at most kMaxRigViews); nullopt when invalid (errors reported). writeView: canonical,
// on one line.
std::optional<RigView> readView(Checker& c, const json::Value& v, const QString& path, bool named);
std::optional<std::vector<RigView>> readViews(Checker& c, const json::Value& v, const QString& path);
QByteArray writeView(const RigView& view, bool named);
// Errors for keys of "falloff" or "cone" written on the light itself or in the other object. `light`
// describes the light ("a point light") when `o` is the light object, with whether its type has a
// falloff and a cone, so that the message can say "a directional light has no range".
void rejectMisplaced(ObjectView& o, bool inFalloff, bool inCone, const QString& light = {},
                     bool hasFalloff = true, bool hasCone = true);

// Unit length to double precision: vectors already within 1e-12 of unit length are kept bit for bit, so
// that load -> save -> load is exact; others are scaled (safely for tiny and huge components).
glm::dvec3 normalizeDirection(const glm::dvec3& v);

} // namespace lr::rigjson
