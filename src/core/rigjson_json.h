// A small strict JSON reader and writer helpers for rig files (private to rigjson*.cpp).
//
// Why not QJsonDocument: it silently keeps only one of two duplicate keys, turns 1e999 into an error
// without saying where, gives byte offsets but no JSON path, and its writer sorts keys and picks its own
// number format. This parser keeps what the rig reader needs to report every problem precisely: the
// source text of each number, duplicate keys with their paths, a nesting-depth and value-count limit,
// and line/column positions for syntax errors. Input must be UTF-8 (an optional BOM is skipped).
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace lr::json {

constexpr int kMaxDepth = 32;          // arrays and objects nested deeper are refused
constexpr qint64 kMaxValues = 1 << 20; // values in one document (a bound on memory, ~4 MiB lights max)

struct Member;

struct Value {
    enum class Kind : quint8 { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    bool finite = true; // Number: false when the text is out of the range of a double (1e999, 1e-400)
    double number = 0.0;
    qint32 offset = 0; // first byte of the value in the source
    qint32 length = 0; // bytes of a number's text
    QString string;
    std::vector<Value> items;    // Array
    std::vector<Member> members; // Object, in source order, duplicates included

    bool isNumber() const { return kind == Kind::Number; }
    // The first member named `key`, or nullptr.
    const Value* find(QStringView key) const;
};

struct Member {
    QString key;
    Value value;
    bool duplicate = false; // an earlier member has the same key (already reported by parse())
};

struct Document {
    Value root;
    bool complete = false; // false: a syntax error stopped the parse (root is partial, don't use it)
    QStringList errors;    // "LOCATION: reason" without the file name; duplicates first, then syntax
    // Set when the kMaxValues limit stopped the parse: the path of the value past the limit ("lights[74897]
    // .color[0]"), so that a reader can say which part of its format made the document too large.
    std::optional<QString> valueLimitPath;
};

Document parse(const QByteArray& data);

// Offset of the first byte of `data` (from `from` on) that is not well-formed UTF-8 (overlong forms,
// surrogates and code points above U+10FFFF included), or -1.
qsizetype invalidUtf8At(const QByteArray& data, qsizetype from);
// Appends code point `cp` (a scalar value) encoded as UTF-8.
void appendUtf8(QByteArray& out, char32_t cp);

// Path helpers: appendKey("lights[0]", "color") -> "lights[0].color"; keys that are not identifiers are
// quoted: lights[0]["my key"], and keys over 64 characters shortened: extra["aaaa..."...].
// appendIndex("lights", 2) -> "lights[2]".
QString appendKey(const QString& path, const QString& key);
QString appendIndex(const QString& path, qsizetype index);

// For messages: a number as written in the file ("-5", "1e999 (out of the range of a double)"), a string
// quoted and shortened, or the kind ("an array", "an object", "true", "null").
QString describe(const Value& v, const QByteArray& source);

// Shortest text that reads back as exactly v (std::to_chars digits, JavaScript-style layout: fixed for
// 1e-6 <= |v| < 1e21, else exponent form). Integers have no ".0"; -0 is written as 0; NaN and
// infinities as null, which no numeric field accepts (so saveRigFile refuses such a rig).
QByteArray formatNumber(double v);
// A JSON string literal: quotes, \" \\ \b \f \n \r \t, other control characters as \u00XX, the rest as
// UTF-8 (an unpaired surrogate, which UTF-8 cannot hold, becomes U+FFFD as in QString::toUtf8).
QByteArray quote(const QString& s);

} // namespace lr::json
