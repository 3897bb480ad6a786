// Multi-layer OpenEXR files in (issue 37, light mixing: `lightrig mix AOVS.exr` reads what
// `lightrig render --aovs` wrote with exrencode.h). A file from the user is untrusted:
// importExrLayersIsolated decodes it in `lightrig import-worker` (isolatedimport.h: a crash, hang or
// allocation bomb ends the worker only) and checks everything the worker sends back; decodeExrLayers is the
// decoder itself, in this process.
//
// Read: single-part flat images (scanline or tiled; tiled ones at their full resolution), any
// compression OpenEXR 3 reads, half, float and uint channels (all returned as float). Channels are grouped
// into layers by their last dot, as oiiotool and the compositors do: "key.R" is channel "R" of layer
// "key", "ViewLayer.Combined.R" channel "R" of layer "ViewLayer.Combined", and channels without a dot
// ("R", "G", "B", "A", "Z") make the unnamed layer "". The file sorts its channels by name, so the order
// they were written in is gone: layers come back sorted by name (the unnamed one first), and each layer's
// channels in the order R, G, B, A, X, Y, Z, then any others by name. String attributes come back sorted by
// name; attributes of other types are skipped. Values are as stored: NaN and ±inf included.
// The image is the display window: a data window inside it (a crop) is read into place with 0 around it.
//
// Refused with a reason (no file name; decodeExrLayersFile and importExrLayersIsolated add it): not
// OpenEXR, several parts, deep data, a data window reaching outside the display window, subsampled
// channels, no channel, two channels that read as the same name, sides above kMaxExrSide, more than
// kMaxExrPixels pixels or kMaxExrChannels channels, more than kMaxExrDecodedBytes decoded, a header claiming
// more data than the file holds or more pixels than a file of its size can plausibly hold
// (maxExrDecodedBytes, checked before any pixel memory is allocated), truncated or corrupt data.
#pragma once

#include "exrencode.h"
#include "isolatedimport.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

namespace lr {

inline constexpr int kMaxExrSide = 32768;                // render --size's limit
inline constexpr qint64 kMaxExrPixels = 256ll << 20;     // 256 Mpx
inline constexpr qint64 kMaxExrDecodedBytes = 4ll << 30; // float values of all channels: 4 GiB
inline constexpr qint64 kMaxExrFileBytes = 3ll << 30;    // with the decoded values, within the worker's 8 GiB
// Decoded bytes (4 a value) allowed per byte of file, beyond kFreeExrBytes: twice what ZIP can reach on
// half data (deflate stops near 1032:1, and a half is half a float), so that every file exrencode.h writes
// is read whatever its content (an empty light group, a transparent background). Near-constant DWAA/DWAB
// files from other tools can reach 20000:1 and are refused. A 1 KB header claiming 64 Mpx is refused before
// anything is allocated.
inline constexpr qint64 kMaxExrExpansion = 4096;
inline constexpr qint64 kFreeExrBytes = 16ll << 20;
inline qint64 maxExrDecodedBytes(qint64 fileBytes) {
    return std::min(kMaxExrDecodedBytes, kFreeExrBytes + kMaxExrExpansion * std::max<qint64>(fileBytes, 0));
}
// Empty when width × height pixels of `channels` channels are within the limits above, else why not.
QString exrSizeProblem(qint64 width, qint64 height, int channels);

struct ExrFile {
    int width = 0, height = 0;
    std::vector<ExrLayer> layers;                        // in the order above; pixels as ExrLayer's
    std::vector<std::pair<QString, QString>> attributes; // the string attributes, by name
    const ExrLayer* layer(const QString& name) const;    // nullptr when there is none of that name
};

// Decodes a file's bytes in this process; std::nullopt and *error (the reason alone) on failure.
std::optional<ExrFile> decodeExrLayers(const QByteArray& bytes, QString* error);
// Reads `path` (a regular file, at most kMaxExrFileBytes; opened without blocking) and decodes it in this
// process: the worker does this. *error: "could not read PATH: REASON".
std::optional<ExrFile> decodeExrLayersFile(const QString& path, QString* error);
// Decodes `path` in the import worker and checks the reply. Blocking; thread-safe. *error as above, with
// the worker's failures ("the importer crashed (signal 11)", "... did not finish within 10 s ...") too.
std::optional<ExrFile> importExrLayersIsolated(const QString& path, QString* error,
                                               const ImportLimits& limits = {});

// The worker's reply (frame 'L', importprotocol.h): exrLayersReplyHead is everything but the pixels, which
// follow it layer by layer (the worker writes them from its ExrFile, without a copy); encodeExrLayersReply
// is the whole reply. decodeExrLayersReply is the parent's reading: false with `why` on anything out of the
// limits above or inconsistent (sizes, counts, names empty or twice).
QByteArray exrLayersReplyHead(const ExrFile& file);
QByteArray encodeExrLayersReply(const ExrFile& file);
bool decodeExrLayersReply(QByteArrayView payload, ExrFile* file, QString* why);
// The largest reply the parent takes for a file of `fileBytes`.
qint64 maxExrLayersReplyBytes(qint64 fileBytes);

} // namespace lr
