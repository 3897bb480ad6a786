// Scene-linear images out as OpenEXR (issue 37, HDR output and light mixing): one single-part scanline
// file of one or more layers, ZIP compressed, top row first, premultiplied alpha (the EXR convention),
// with string attributes in the header (what the image is: its exposure and tone map, which are not
// applied to the pixels). Encoded in memory, so that the caller writes the bytes atomically
// (core/atomicwrite.h) like every other output. exrdecode.h reads such files back.
//
// Layers are named the way oiiotool, Nuke, Natron and Blender's compositor read them: the unnamed layer's
// channels are "R", "G", "B", "A" (what every viewer shows), a named layer's are "name.R", "name.G", ...
// A layer name is 1 to kMaxExrLayerName characters of [A-Za-z0-9_-]: no dot (it separates the layer from
// the channel), no space (legal in EXR, but compositors rewrite it and shell scripts trip on it), nothing
// outside ASCII. exrLayerName and uniqueExrLayerNames make such names from anything (a light group's name).
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <utility>
#include <vector>

namespace lr {

inline constexpr int kMaxExrLayerName = 64;
inline constexpr int kMaxExrChannelName = 32; // [A-Za-z0-9_], no dot
// At most this many channels in all, so that exrdecode.h reads every file written here.
inline constexpr int kMaxExrChannels = 256;

struct ExrLayer {
    QString name;         // "" = the unnamed default layer (channels "R","G","B","A"); else "name.R", ...
    QStringList channels; // e.g. {"R","G","B","A"}, {"R","G","B"}, {"X","Y","Z"}, {"Z"}
    std::vector<float> pixels; // width*height*channels.size(), interleaved, row-major, top row first
};

// Half: 16-bit floats (half the size; 3 significant digits). Finite values beyond half's range are
// clamped to ±65504 (not made infinite, which would poison every sum a mix makes); NaN and ±inf stay.
// Depth is always written as float whatever is asked: a channel "Z" in a layer with no "X" or "Y"
// (a vector's Z, "normal.Z", follows the layer), as depth beyond 65504 would be lost.
enum class ExrPixel { Half, Float };

// The file's bytes, or empty bytes and *error (a sentence naming the layer, channel or attribute) when:
// the size is empty or larger than exrdecode.h's limits; there is no layer; a layer name is not valid (see
// above) or appears twice (the unnamed one included); a channel name is empty, not [A-Za-z0-9_], longer
// than kMaxExrChannelName or twice in its layer; a layer has no channel or not width*height*channels
// values; there are more than kMaxExrChannels channels; an attribute name is empty, longer than 255 bytes
// (UTF-8), has a control character, appears twice or is one OpenEXR itself writes ("compression",
// "channels", "dataWindow", ...). Layers and channels may come in any order: the file sorts them by name
// (exrdecode.h returns them in a fixed order, not this one).
QByteArray encodeExrLayers(int width, int height, const std::vector<ExrLayer>& layers,
                           const std::vector<std::pair<QString, QString>>& attributes, ExrPixel pixel,
                           QString* error);

// One unnamed float RGBA layer: `rgba` is width × height × 4 floats, row-major (encodeExrLayers without
// copying the pixels).
QByteArray encodeExrRgba(int width, int height, const float* rgba,
                         const std::vector<std::pair<QString, QString>>& attributes, QString* error);

// Empty when `name` may name a layer (see above; "" is the unnamed layer), else why not.
QString exrLayerNameProblem(const QString& name);
// A valid, non-empty layer name for any string; a valid name is returned as it is. Letters lose their
// accents ("Schlüssel" -> "Schlussel"), each run of other characters becomes one "_" ("Key light (L)" ->
// "Key_light_L"), runs at either end are dropped, the result is cut to kMaxExrLayerName, and a name with
// nothing left is "layer".
QString exrLayerName(const QString& anyName);
// exrLayerName of each name, then made unique (exactly, as EXR compares) against each other and against
// `taken` (the caller's fixed layers: "albedo", "normal", "depth") by a suffix "_2", "_3", ...: the same
// number of names, in the same order.
QStringList uniqueExrLayerNames(const QStringList& anyNames, const QStringList& taken = {});

} // namespace lr
