// Strict RFC 8259 JSON parser for rig files; see rigjson_json.h for why it is not QJsonDocument.
#include "rigjson_json.h"

#include <QHash>
#include <charconv>
#include <variant>

namespace lr::json {

namespace {

class Parser {
  public:
    explicit Parser(const QByteArray& data) : m_data(data), m_p(data.constData()), m_end(m_p + data.size()) {}

    Document run() {
        Document doc;
        if (m_data.startsWith("\xEF\xBB\xBF")) m_p += 3; // a UTF-8 BOM (Windows editors) is tolerated
        if (const char* utf16 = utf16Endianness(m_data))
            return fail(doc, 0,
                        QStringLiteral("the file is UTF-16 (%1); rig files must be UTF-8 (save it as UTF-8)")
                            .arg(QLatin1String(utf16)));
        if (const qsizetype bad = invalidUtf8At(m_data, m_p - m_data.constData()); bad >= 0)
            return fail(doc, bad,
                        QStringLiteral("not valid UTF-8 text (byte 0x%1; is this a binary file?)")
                            .arg(uchar(m_data[bad]), 2, 16, QLatin1Char('0')));
        if (const qsizetype nul = m_data.indexOf('\0'); nul >= 0)
            return fail(doc, nul, QStringLiteral("contains a NUL byte: not a text file"));
        skipSpace();
        if (m_p == m_end) {
            doc.errors << QStringLiteral(
                "the file is empty; a rig file is a JSON object {\"format\": \"lightrig\", ...}");
            return doc;
        }
        if (parseValue(doc.root)) {
            skipSpace();
            if (m_p != m_end) error(QStringLiteral("unexpected text after the end of the JSON document"));
        }
        doc.errors = m_errors;
        if (m_moreDuplicates)
            doc.errors << QStringLiteral("%1 more duplicate keys not listed").arg(m_moreDuplicates);
        if (m_valueLimit) doc.valueLimitPath = m_syntaxPath;
        if (!m_syntax.isEmpty()) return fail(doc, m_syntaxAt, m_syntax);
        doc.complete = true;
        return doc;
    }

  private:
    using Segment = std::variant<QString, qsizetype>;

    Document& fail(Document& doc, qsizetype at, const QString& reason) {
        int line = 1, column = 1;
        for (qsizetype i = 0; i < at && i < m_data.size(); ++i) {
            const char c = m_data[i];
            if (c == '\n')
                line++, column = 1;
            else if ((uchar(c) & 0xC0) != 0x80)
                column++; // count characters, not UTF-8 bytes
        }
        QString where = QStringLiteral("line %1, column %2").arg(line).arg(column);
        if (!m_syntaxPath.isEmpty()) where += QStringLiteral(" (in %1)").arg(m_syntaxPath);
        doc.errors << where + QStringLiteral(": ") + reason;
        doc.complete = false;
        return doc;
    }

    bool error(const QString& reason) {
        if (m_syntax.isEmpty()) {
            m_syntax = reason;
            m_syntaxAt = m_p - m_data.constData();
            m_syntaxPath = currentPath();
        }
        return false;
    }
    bool unexpected(const char* expected) {
        if (m_p == m_end)
            return error(QStringLiteral("unexpected end of file, expected %1 (is the file truncated?)")
                             .arg(QLatin1String(expected)));
        if (const qsizetype n = nonFiniteWord(); n > 0)
            return error(
                QStringLiteral("%1 is not a JSON number; numbers must be finite").arg(QLatin1String(m_p, n)));
        const QString ch = QString::fromUtf8(m_p, std::min<qsizetype>(4, m_end - m_p)).left(1);
        return error(QStringLiteral("unexpected '%1', expected %2").arg(ch, QLatin1String(expected)));
    }

    // The length of a non-finite number as other languages write it at m_p ("NaN", "-nan", "+Infinity",
    // "INF", any case, an optional sign), or 0.
    qsizetype nonFiniteWord() const {
        const char* p = m_p;
        if (p != m_end && (*p == '-' || *p == '+')) ++p;
        for (const char* word : {"infinity", "inf", "nan"}) {
            const qsizetype n = qsizetype(qstrlen(word));
            if (m_end - p >= n &&
                QByteArrayView(p, n).compare(QByteArrayView(word, n), Qt::CaseInsensitive) == 0)
                return p + n - m_p;
        }
        return 0;
    }

    // "little-endian" or "big-endian" when `data` looks like UTF-16 text (a UTF-16 byte order mark, or a
    // NUL in every other byte of the first characters, as ASCII JSON encoded in UTF-16 has), else nullptr.
    static const char* utf16Endianness(const QByteArray& data) {
        if (data.startsWith("\xFF\xFE")) return "little-endian";
        if (data.startsWith("\xFE\xFF")) return "big-endian";
        if (data.size() < 2) return nullptr;
        const qsizetype n = std::min<qsizetype>(data.size() & ~qsizetype(1), 64);
        bool evenNul = true, oddNul = true;
        for (qsizetype i = 0; i < n; i += 2) {
            evenNul = evenNul && data[i] == '\0' && data[i + 1] != '\0';
            oddNul = oddNul && data[i + 1] == '\0' && data[i] != '\0';
        }
        return oddNul ? "little-endian" : evenNul ? "big-endian" : nullptr;
    }

    QString currentPath() const {
        QString path;
        for (const Segment& s : m_path)
            path = std::holds_alternative<QString>(s) ? appendKey(path, std::get<QString>(s))
                                                      : appendIndex(path, std::get<qsizetype>(s));
        return path;
    }

    void skipSpace() {
        while (m_p != m_end && (*m_p == ' ' || *m_p == '\n' || *m_p == '\r' || *m_p == '\t'))
            ++m_p;
    }

    bool parseValue(Value& out) {
        if (++m_values > kMaxValues) {
            m_valueLimit = m_syntax.isEmpty();
            return error(QStringLiteral("more than %1 values; not a rig file").arg(kMaxValues));
        }
        out.offset = qint32(m_p - m_data.constData());
        if (m_p == m_end) return unexpected("a value");
        switch (*m_p) {
        case '{':
            return parseContainer(out, true);
        case '[':
            return parseContainer(out, false);
        case '"':
            out.kind = Value::Kind::String;
            return parseString(out.string);
        case 't':
            return literal(out, "true", Value::Kind::Bool, true);
        case 'f':
            return literal(out, "false", Value::Kind::Bool, false);
        case 'n':
            return literal(out, "null", Value::Kind::Null, false);
        default:
            if (*m_p == '-' || (*m_p >= '0' && *m_p <= '9')) return parseNumber(out);
            return unexpected("a value");
        }
    }

    bool literal(Value& out, const char* word, Value::Kind kind, bool b) {
        const qsizetype n = qsizetype(qstrlen(word));
        if (m_end - m_p < n || QByteArrayView(m_p, n) != QByteArrayView(word, n))
            return unexpected("a value");
        m_p += n;
        out.kind = kind;
        out.boolean = b;
        return true;
    }

    bool parseNumber(Value& out) {
        const char* start = m_p;
        auto digits = [&] {
            const char* d = m_p;
            while (m_p != m_end && *m_p >= '0' && *m_p <= '9')
                ++m_p;
            return m_p != d;
        };
        if (*m_p == '-') ++m_p;
        if (m_p != m_end && *m_p == '0') {
            ++m_p;
            if (m_p != m_end && *m_p >= '0' && *m_p <= '9')
                return error(QStringLiteral("numbers must not have leading zeros"));
        } else if (!digits()) {
            m_p = start; // report "-Infinity" or "-x" as a whole
            return unexpected("a value");
        }
        if (m_p != m_end && *m_p == '.') {
            ++m_p;
            if (!digits()) return unexpected("a digit after '.'");
        }
        if (m_p != m_end && (*m_p == 'e' || *m_p == 'E')) {
            ++m_p;
            if (m_p != m_end && (*m_p == '+' || *m_p == '-')) ++m_p;
            if (!digits()) return unexpected("a digit in the exponent");
        }
        out.kind = Value::Kind::Number;
        out.length = qint32(m_p - start);
        const auto result = std::from_chars(start, m_p, out.number);
        out.finite = result.ec == std::errc();
        if (!out.finite) out.number = 0.0;
        return true;
    }

    bool parseString(QString& out) {
        ++m_p; // opening quote
        const char* start = m_p;
        while (m_p != m_end && *m_p != '"' && *m_p != '\\' && uchar(*m_p) >= 0x20)
            ++m_p;
        if (m_p != m_end && *m_p == '"') { // fast path: no escapes
            out = QString::fromUtf8(start, m_p - start);
            ++m_p;
            return true;
        }
        QByteArray bytes(start, m_p - start);
        while (true) {
            if (m_p == m_end) return unexpected("'\"' to end the string");
            const uchar c = uchar(*m_p);
            if (c == '"') break;
            if (c < 0x20)
                return error(QStringLiteral("control character U+%1 inside a string (write it as an escape)")
                                 .arg(c, 4, 16, QLatin1Char('0')));
            if (c != '\\') {
                bytes += char(c);
                ++m_p;
                continue;
            }
            if (++m_p == m_end) return unexpected("an escape");
            const char e = *m_p++;
            switch (e) {
            case '"':
                bytes += '"';
                break;
            case '\\':
                bytes += '\\';
                break;
            case '/':
                bytes += '/';
                break;
            case 'b':
                bytes += '\b';
                break;
            case 'f':
                bytes += '\f';
                break;
            case 'n':
                bytes += '\n';
                break;
            case 'r':
                bytes += '\r';
                break;
            case 't':
                bytes += '\t';
                break;
            case 'u': {
                char32_t cp = 0;
                if (!hex4(cp)) return false;
                if (cp >= 0xD800 && cp <= 0xDBFF) {
                    char32_t low = 0;
                    if (m_end - m_p < 2 || m_p[0] != '\\' || m_p[1] != 'u' || ((m_p += 2), !hex4(low)) ||
                        low < 0xDC00 || low > 0xDFFF)
                        return error(
                            QStringLiteral("\\u escape: a high surrogate must be followed by a low one"));
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
                    return error(QStringLiteral("\\u escape: unpaired low surrogate"));
                }
                appendUtf8(bytes, cp);
                break;
            }
            default:
                --m_p;
                return error(QStringLiteral("invalid escape '\\%1' in a string").arg(QLatin1Char(e)));
            }
        }
        ++m_p;
        out = QString::fromUtf8(bytes);
        return true;
    }

    bool hex4(char32_t& cp) {
        for (int i = 0; i < 4; ++i, ++m_p) {
            if (m_p == m_end) return unexpected("4 hex digits after \\u");
            const char c = *m_p;
            const int v = c >= '0' && c <= '9'   ? c - '0'
                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                 : -1;
            if (v < 0) return unexpected("4 hex digits after \\u");
            cp = cp * 16 + char32_t(v);
        }
        return true;
    }

    bool parseContainer(Value& out, bool object) {
        out.kind = object ? Value::Kind::Object : Value::Kind::Array;
        if (++m_depth > kMaxDepth)
            return error(QStringLiteral("nested deeper than %1 levels").arg(kMaxDepth));
        const char close = object ? '}' : ']';
        ++m_p;
        skipSpace();
        QHash<QString, qsizetype> seen; // key -> first index, once the object is large
        if (m_p != m_end && *m_p == close) {
            ++m_p;
            --m_depth;
            return true;
        }
        while (true) {
            skipSpace();
            if (object) {
                if (m_p == m_end || *m_p != '"') return unexpected("a key in double quotes");
                Member m;
                if (!parseString(m.key)) return false;
                skipSpace();
                if (m_p == m_end || *m_p != ':') return unexpected("':' after the key");
                ++m_p;
                skipSpace();
                m.duplicate = isDuplicate(out.members, seen, m.key);
                m_path.emplace_back(m.key);
                // Bounded: each message holds the path, so thousands of duplicates under a long key would
                // cost time and memory quadratic in the file size (tests/safety/tst_readerlimits.cpp).
                if (m.duplicate && m_errors.size() < kMaxDuplicateMessages)
                    m_errors << QStringLiteral("%1: duplicate key; each key may appear only once")
                                    .arg(currentPath());
                else if (m.duplicate)
                    ++m_moreDuplicates;
                if (!parseValue(m.value)) return false;
                m_path.pop_back();
                out.members.push_back(std::move(m));
            } else {
                m_path.emplace_back(qsizetype(out.items.size()));
                out.items.emplace_back();
                if (!parseValue(out.items.back())) return false;
                m_path.pop_back();
            }
            skipSpace();
            if (m_p != m_end && *m_p == ',') {
                ++m_p;
                continue;
            }
            if (m_p != m_end && *m_p == close) break;
            return unexpected(object ? "',' or '}'" : "',' or ']'");
        }
        ++m_p;
        --m_depth;
        return true;
    }

    static bool isDuplicate(const std::vector<Member>& members, QHash<QString, qsizetype>& seen,
                            const QString& key) {
        constexpr size_t kLinear = 16; // small objects: a scan; large ones (unknown data): a hash
        if (members.size() < kLinear) {
            for (const Member& m : members)
                if (m.key == key) return true;
            return false;
        }
        if (seen.isEmpty())
            for (size_t i = 0; i < members.size(); ++i)
                seen.insert(members[i].key, qsizetype(i));
        if (seen.contains(key)) return true;
        seen.insert(key, qsizetype(members.size()));
        return false;
    }

    const QByteArray& m_data;
    const char* m_p;
    const char* m_end;
    int m_depth = 0;
    qint64 m_values = 0;
    bool m_valueLimit = false;
    static constexpr qsizetype kMaxDuplicateMessages = 200;
    qint64 m_moreDuplicates = 0;
    std::vector<Segment> m_path;
    QStringList m_errors;
    QString m_syntax, m_syntaxPath;
    qsizetype m_syntaxAt = 0;
};

} // namespace

Document parse(const QByteArray& data) {
    return Parser(data).run();
}

const Value* Value::find(QStringView key) const {
    for (const Member& m : members)
        if (m.key == key) return &m.value;
    return nullptr;
}

} // namespace lr::json
