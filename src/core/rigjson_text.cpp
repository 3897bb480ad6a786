// Text helpers shared by the rig reader and writer: JSON paths, value descriptions for messages, the
// canonical number and string forms.
#include "rigjson_json.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace lr::json {

namespace {
bool isIdentifier(const QString& key) {
    if (key.isEmpty()) return false;
    for (QChar c : key)
        if (!(c.isLetterOrNumber() && c.unicode() < 0x80) && c != QLatin1Char('_') && c != QLatin1Char('-'))
            return false;
    return true;
}
} // namespace

// Offset of the first byte that is not well-formed UTF-8 (overlong forms, surrogates and code points
// above U+10FFFF included), or -1.
qsizetype invalidUtf8At(const QByteArray& data, qsizetype from) {
    const auto* s = reinterpret_cast<const unsigned char*>(data.constData());
    const qsizetype n = data.size();
    for (qsizetype i = from; i < n;) {
        const unsigned c = s[i];
        if (c < 0x80) {
            ++i;
            continue;
        }
        int len;
        unsigned cp, min;
        if ((c & 0xE0) == 0xC0)
            len = 2, cp = c & 0x1F, min = 0x80;
        else if ((c & 0xF0) == 0xE0)
            len = 3, cp = c & 0x0F, min = 0x800;
        else if ((c & 0xF8) == 0xF0)
            len = 4, cp = c & 0x07, min = 0x10000;
        else
            return i;
        if (i + len > n) return i;
        for (int k = 1; k < len; ++k) {
            if ((s[i + k] & 0xC0) != 0x80) return i;
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
        i += len;
    }
    return -1;
}

void appendUtf8(QByteArray& out, char32_t cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xF0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3F));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

QString appendKey(const QString& path, const QString& key) {
    constexpr qsizetype kMaxShown =
        64; // longer keys are shortened: messages stay small (no key is that long)
    if (key.size() > kMaxShown)
        return path + QStringLiteral("[%1...]").arg(QString::fromUtf8(quote(key.left(kMaxShown - 16))));
    if (!isIdentifier(key)) return path + QLatin1Char('[') + QString::fromUtf8(quote(key)) + QLatin1Char(']');
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString appendIndex(const QString& path, qsizetype index) {
    return path + QLatin1Char('[') + QString::number(index) + QLatin1Char(']');
}

QString describe(const Value& v, const QByteArray& source) {
    switch (v.kind) {
    case Value::Kind::Null:
        return QStringLiteral("null");
    case Value::Kind::Bool:
        return v.boolean ? QStringLiteral("true") : QStringLiteral("false");
    case Value::Kind::Number: {
        const QString text = QString::fromUtf8(source.mid(v.offset, v.length));
        const QString shown = text.size() > 40 ? text.left(37) + QStringLiteral("...") : text;
        return v.finite ? shown : shown + QStringLiteral(" (out of the range of a double)");
    }
    case Value::Kind::String: {
        const QString s = v.string.size() > 40 ? v.string.left(37) + QStringLiteral("...") : v.string;
        return QStringLiteral("the string ") + QString::fromUtf8(quote(s));
    }
    case Value::Kind::Array:
        return QStringLiteral("an array of %1").arg(v.items.size());
    case Value::Kind::Object:
        return QStringLiteral("an object");
    }
    return {};
}

QByteArray formatNumber(double v) {
    if (!std::isfinite(v)) return QByteArrayLiteral("null"); // not JSON numbers: the reader rejects null
    if (v == 0.0) return QByteArrayLiteral("0");             // and -0
    // Shortest round-trip digits, in scientific form: [-]d[.ddd]e[+-]x
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, std::abs(v), std::chars_format::scientific);
    const std::string_view sci(buf, r.ptr);
    const size_t e = sci.find('e');
    std::string digits(sci.substr(0, e));
    if (digits.size() > 1) digits.erase(1, 1); // drop the '.'
    const int exponent = std::atoi(std::string(sci.substr(e + 1)).c_str());
    const int k = int(digits.size());
    const int n = exponent + 1; // position of the decimal point relative to the digits
    std::string out = v < 0 ? "-" : "";
    if (exponent >= -6 && exponent < 21) { // fixed notation, as JavaScript's Number.prototype.toString
        if (n >= k) {
            out += digits + std::string(size_t(n - k), '0');
        } else if (n > 0) {
            out += digits.substr(0, size_t(n)) + '.' + digits.substr(size_t(n));
        } else {
            out += "0." + std::string(size_t(-n), '0') + digits;
        }
    } else {
        out += digits.substr(0, 1);
        if (k > 1) out += '.' + digits.substr(1);
        out += exponent < 0 ? "e-" : "e+";
        out += std::to_string(std::abs(exponent));
    }
    return QByteArray::fromStdString(out);
}

QByteArray quote(const QString& s) {
    const QByteArray utf8 = s.toUtf8();
    QByteArray out;
    out.reserve(utf8.size() + 2);
    out += '"';
    for (const char c : utf8) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (uchar(c) < 0x20) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "\\u%04x", unsigned(uchar(c)));
                out += hex;
            } else {
                out += c;
            }
        }
    }
    out += '"';
    return out;
}

} // namespace lr::json
