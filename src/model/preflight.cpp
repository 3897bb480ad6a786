// Checks run on a model file before Assimp sees it, for inputs known to make Assimp 5.2.5 allocate
// without bound, hang, abort or crash: glTF data URIs over the size limit, GLB header and chunk
// lengths beyond the file, OFF and PLY headers declaring more elements than the file can hold (Assimp
// allocates by the declared count), PLY headers without end_header (Assimp waits for it forever),
// Collada index lists with non-numeric characters (an endless loop in Assimp), and ASCII PLY data with
// non-numeric lines (a comment inside the data makes the Debian build abort in an ai_assert). Each check is
// linear in the file's size.
#include "importdetail.h"

#include <QByteArrayView>
#include <QFile>
#include <QFileInfo>
#include <charconv>
#include <limits>

namespace lr::detail {

namespace {

struct Bytes {
    QFile file;
    QByteArray owned;
    QByteArrayView view;
    explicit Bytes(const QString& path) : file(path) {
        if (!file.open(QIODevice::ReadOnly)) return;
        const qint64 size = file.size();
        if (const uchar* mapped = size > 0 ? file.map(0, size) : nullptr) {
            view = QByteArrayView(reinterpret_cast<const char*>(mapped), size);
        } else {
            owned = file.readAll();
            view = owned;
        }
    }
};

// Next line of `text` starting at *pos (without the line break); false at the end.
bool nextLine(QByteArrayView text, qsizetype* pos, QByteArrayView* line) {
    if (*pos >= text.size()) return false;
    qsizetype end = text.indexOf('\n', *pos);
    if (end < 0) end = text.size();
    *line = text.sliced(*pos, end - *pos);
    if (line->endsWith('\r')) line->chop(1);
    *pos = end + 1;
    return true;
}

std::vector<QByteArrayView> words(QByteArrayView line) {
    std::vector<QByteArrayView> out;
    qsizetype i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const qsizetype start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i > start) out.push_back(line.sliced(start, i - start));
    }
    return out;
}

// A non-negative decimal count; -1 when it is not one. Saturates instead of wrapping.
qint64 count(QByteArrayView word) {
    quint64 v = 0;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ptr != word.data() + word.size()) return -1;
    if (ec == std::errc::result_out_of_range || v > quint64(std::numeric_limits<qint64>::max() / 16))
        return std::numeric_limits<qint64>::max() / 16;
    return ec == std::errc() ? qint64(v) : -1;
}

QString tooManyElements(qint64 declared, const char* what, qint64 needed, qint64 available) {
    return QStringLiteral("the header declares %1 %2, which need at least %3 bytes, but the file has %4")
        .arg(declared)
        .arg(QLatin1String(what))
        .arg(needed)
        .arg(available);
}

QString checkOff(QByteArrayView text) {
    qsizetype pos = 0;
    QByteArrayView line;
    std::vector<QByteArrayView> counts;
    bool sawKeyword = false;
    while (nextLine(text, &pos, &line)) {
        std::vector<QByteArrayView> w = words(line);
        if (w.empty() || w[0].startsWith('#')) continue;
        if (!sawKeyword) {
            sawKeyword = true;
            if (!w[0].endsWith("OFF")) return {};
            w.erase(w.begin());
            if (w.empty()) continue;
        }
        counts = w;
        break;
    }
    if (counts.size() < 2) return {};
    const qint64 vertices = count(counts[0]), faces = count(counts[1]);
    if (vertices < 0 || faces < 0) return {};
    const qint64 needed = vertices * 6 + faces * 4; // "0 0 0\n" and "1 0\n" at the least
    if (needed > text.size() - pos)
        return tooManyElements(vertices + faces, "vertices and faces", needed, text.size());
    return {};
}

int plyTypeSize(QByteArrayView type) {
    for (const auto& [name, size] : {std::pair{"char", 1},
                                     {"uchar", 1},
                                     {"int8", 1},
                                     {"uint8", 1},
                                     {"short", 2},
                                     {"ushort", 2},
                                     {"int16", 2},
                                     {"uint16", 2},
                                     {"int", 4},
                                     {"uint", 4},
                                     {"int32", 4},
                                     {"uint32", 4},
                                     {"float", 4},
                                     {"float32", 4},
                                     {"double", 8},
                                     {"float64", 8}})
        if (type == QByteArrayView(name)) return size;
    return 1;
}

QString checkPly(QByteArrayView text) {
    qsizetype pos = 0;
    QByteArrayView line;
    bool ascii = false, ended = false;
    qint64 needed = 0, declared = 0, elementCount = 0, elementBytes = 0;
    while (nextLine(text, &pos, &line)) {
        const std::vector<QByteArrayView> w = words(line);
        if (w.empty()) continue;
        if (w[0] == "format" && w.size() > 1) ascii = w[1] == "ascii";
        if (w[0] == "element" || w[0] == "end_header") {
            needed += elementCount * elementBytes;
            declared += elementCount;
            elementCount = w.size() > 2 ? std::max<qint64>(count(w[2]), 0) : 0;
            elementBytes = 0;
        }
        if (w[0] == "property" && w.size() > 1) {
            const bool list = w[1] == "list";
            elementBytes += ascii ? 2 : plyTypeSize(list && w.size() > 2 ? w[2] : w[1]);
        }
        if (w[0] == "end_header") {
            ended = true;
            break;
        }
        if (needed > std::numeric_limits<qint64>::max() / 4) break;
    }
    if (!ended) return QStringLiteral("the PLY header has no end_header line (is the file truncated?)");
    if (needed > text.size() - pos) return tooManyElements(declared, "elements", needed, text.size());
    if (!ascii) return {};
    for (int lineNo = 1; nextLine(text, &pos, &line); ++lineNo) {
        qsizetype i = 0;
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        if (i == line.size()) continue;
        const char c = line[i];
        if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') continue;
        return QStringLiteral(
                   "line %1 of the data is not a row of numbers (\"%2\"); PLY allows comments only "
                   "in the header")
            .arg(lineNo)
            .arg(QString::fromLatin1(line.first(std::min<qsizetype>(line.size(), 40)).toByteArray()));
    }
    return {};
}

// Collada index lists (<p>, <h>) hold integers only: Assimp 5.2.5 reads them with a loop that stops only
// at the end of the text, and a character that is not part of a number is never consumed (a '4' turned
// into '$' in duck.dae hung the importer until the time limit).
QString checkColladaIndices(QByteArrayView text) {
    int line = 1;
    qsizetype counted = 0;
    for (qsizetype at = text.indexOf("<"); at >= 0 && at + 2 < text.size(); at = text.indexOf("<", at + 1)) {
        const char tag = text[at + 1], after = text[at + 2];
        if ((tag != 'p' && tag != 'h') || (after != '>' && after != ' ' && after != '\t' && after != '\n'))
            continue;
        const qsizetype open = text.indexOf('>', at);
        if (open < 0) return {};
        for (qsizetype i = open + 1; i < text.size() && text[i] != '<'; ++i) {
            const char c = text[i];
            if ((c >= '0' && c <= '9') || c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '-' ||
                c == '+')
                continue;
            for (; counted < i; ++counted)
                line += text[counted] == '\n' ? 1 : 0;
            const QString what = uchar(c) >= 0x20 && uchar(c) < 0x7f
                                     ? QStringLiteral("'%1'").arg(QLatin1Char(c))
                                     : QStringLiteral("byte 0x%1").arg(uchar(c), 2, 16, QLatin1Char('0'));
            return QStringLiteral("line %1: the <%2> index list holds %3, which is not part of an integer")
                .arg(line)
                .arg(QLatin1Char(tag))
                .arg(what);
        }
        at = open;
    }
    return {};
}

// A binary glTF's header and chunk lengths against the bytes present: Assimp allocates what they claim
// (an 80-byte file whose JSON chunk claimed 4 GB cost 4.2 GB and a minute).
QString checkGlb(QByteArrayView bytes) {
    const qint64 size = bytes.size();
    if (size < 12)
        return QStringLiteral("the file is %1 bytes, shorter than a GLB header (12 bytes)").arg(size);
    const quint32 version = glbU32(bytes, 4), length = glbU32(bytes, 8);
    if (version != 1 && version != 2)
        return QStringLiteral("the GLB header has version %1; glTF binary files are version 1 or 2")
            .arg(version);
    if (length > size)
        return QStringLiteral("the GLB header declares %1 bytes, but the file has %2 (is it truncated or "
                              "corrupted?)")
            .arg(length)
            .arg(size);
    if (version == 1) { // glTF 1.0 binary: content length and format, then the content
        if (size < 20 || glbU32(bytes, 12) > quint32(length) - std::min<quint32>(length, 20))
            return QStringLiteral("the GLB content length exceeds the file's %1 bytes").arg(length);
        return {};
    }
    int index = 0;
    for (qint64 at = 12; at < length; ++index) {
        if (length - at < 8)
            return QStringLiteral("GLB chunk %1 is cut off after %2 bytes of its header")
                .arg(index)
                .arg(length - at);
        const quint32 chunk = glbU32(bytes, at);
        if (qint64(chunk) > length - at - 8)
            return QStringLiteral("GLB chunk %1 declares %2 bytes, but only %3 follow in the file")
                .arg(index)
                .arg(chunk)
                .arg(length - at - 8);
        at += 8 + qint64(chunk);
    }
    if (index == 0) return QStringLiteral("the GLB file has no JSON chunk");
    return {};
}

} // namespace

quint32 glbU32(QByteArrayView bytes, qsizetype at) {
    return quint32(uchar(bytes[at])) | quint32(uchar(bytes[at + 1])) << 8 |
           quint32(uchar(bytes[at + 2])) << 16 | quint32(uchar(bytes[at + 3])) << 24;
}

qint64 glbJsonLength(QByteArrayView header, qint64 fileSize) {
    // 12-byte header, then the first chunk: length, type ("JSON" = 0x4E4F534A), data.
    if (header.size() < 20 || glbU32(header, 16) != 0x4E4F534Au) return -1;
    return std::max<qint64>(0, std::min<qint64>(glbU32(header, 12), fileSize - 20));
}

qint64 largestDataUri(QByteArrayView bytes) {
    if (bytes.startsWith("glTF")) {
        if (bytes.size() < 20) return -1;
        bytes = bytes.sliced(20, std::max<qint64>(0, glbJsonLength(bytes, bytes.size())));
    }
    qint64 largest = 0;
    for (qsizetype at = bytes.indexOf("\"data:"); at >= 0; at = bytes.indexOf("\"data:", at + 1)) {
        qsizetype end = bytes.indexOf('"', at + 1);
        if (end < 0) end = bytes.size();
        largest = std::max<qint64>(largest, end - at - 1);
        at = end;
        if (at >= bytes.size()) break;
    }
    return largest;
}

QString preflight(const QString& path, qint64 maxDataUriBytes) {
    const Bytes bytes(path);
    const QByteArrayView text = bytes.view;
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (text.startsWith("glTF"))
        if (const QString refusal = checkGlb(text); !refusal.isEmpty()) return refusal;
    if (suffix == QLatin1String("gltf") || suffix == QLatin1String("glb") || text.startsWith("glTF")) {
        const qint64 largest = largestDataUri(text);
        if (largest > maxDataUriBytes)
            return QStringLiteral("a data URI of %1 bytes exceeds the limit of %2 bytes")
                .arg(largest)
                .arg(maxDataUriBytes);
    }
    if (suffix == QLatin1String("dae") ||
        text.first(std::min<qsizetype>(text.size(), 4096)).contains("<COLLADA"))
        if (const QString refusal = checkColladaIndices(text); !refusal.isEmpty()) return refusal;
    if (text.startsWith("ply\n") || text.startsWith("ply\r\n")) return checkPly(text);
    if (suffix == QLatin1String("off")) return checkOff(text);
    return {};
}

} // namespace lr::detail
