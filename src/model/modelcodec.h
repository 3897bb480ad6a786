// A compact binary form of a Model (model.h), for handing an imported model from the import worker
// (a child process, see isolatedimport.h) to the editor. The reader trusts nothing: every count is
// checked against the bytes that remain, every index and reference against what it points into,
// every enum against its range and every number for finiteness, so a corrupted, truncated or
// malicious reply gives an error message, never a crash or a model the renderer cannot draw.
//
// Layout (host byte order; the header records it and the reader refuses the other one):
//   header  "LRMODEL\0", u32 version, u32 byte-order mark 0x01020304, u32 sizeof(Vertex),
//           u32 reserved (0), u64 body size
//   body    model fields in a fixed order: strings as u32 byte count + UTF-8, vectors as u64 count +
//           elements, Vertex and index arrays as raw bytes, QImage as u32 width, u32 height, zeros up to
//           kModelCodecPixelAlignment, RGBA8888 rows without padding, u32 byte count + the colour space's
//           ICC profile (0: none).
// Adding a field to Model, Mesh, Material, Texture, Camera, Rig or Light means adding it here and
// raising kModelCodecVersion (the worker is always the same executable as its parent, so there is no
// compatibility to keep).
#pragma once

#include "model.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QImage>
#include <QString>
#include <array>
#include <functional>
#include <memory>

namespace lr {

inline constexpr char kModelCodecMagic[8] = {'L', 'R', 'M', 'O', 'D', 'E', 'L', '\0'};
inline constexpr quint32 kModelCodecVersion = 8; // 4: PBR material fields, rig shading model; 5: Light::area;
                                                 // 6: Mesh::node; 7: Light::link, ies, gobo, barnDoors;
                                                 // 8: Material samplings and extensions
inline constexpr quint32 kModelCodecByteOrderMark = 0x01020304u;
inline constexpr int kModelCodecHeaderSize = 32; // the body size is its last 8 bytes
// Texture pixels start this far apart from the start of the encoding (zero padding before them), so that a
// page-aligned copy of the encoding (a mapping) can lend each texture its own pages (ImageLender).
inline constexpr std::size_t kModelCodecPixelAlignment = 4096;

// Limits the reader enforces besides the size of the input.
struct ModelCodecLimits {
    int maxImageSide = 32768;        // pixels, either side of a texture
    qint64 maxStringBytes = 1 << 20; // names, paths, warnings
    qint64 maxIccBytes = 4 << 20;    // a texture's colour space (ICC profile)
};

// Receives the encoding in pieces; returns false to stop.
using ModelSink = std::function<bool(const char* data, std::size_t size)>;

// The encoded model (header + body) in one array. Textures are converted to RGBA8888 when they are not.
QByteArray encodeModel(const Model& model);
// The same bytes, streamed: large arrays reach the sink straight from the model, without a copy.
// False when the sink stopped it.
bool writeModel(const Model& model, const ModelSink& sink);
// encodeModel(model).size(), without encoding.
std::size_t encodedModelSize(const Model& model);

// The body size from a header (the first kModelCodecHeaderSize bytes), or -1 with *error set when the
// header is not one this build writes.
qint64 modelBodySize(QByteArrayView header, QString* error);

// The model from encodeModel's bytes, or null with *error set ("truncated in mesh 3 indices",
// "mesh 0: index 12 out of range (8 vertices)", ...). Never throws; never reads outside `bytes`.
// Lets decodeModel create a texture image on the input bytes instead of copying them: given the pixels
// (RGBA8888 rows without padding, aligned to kModelCodecPixelAlignment from the start of the input), it
// returns true and a cleanup function + argument for QImage's read-only external-buffer constructor, which
// Qt calls when the last copy of the image is gone; false: copy.
using ImageLender = std::function<bool(const char* pixels, std::size_t size, QImageCleanupFunction* cleanup,
                                       void** cleanupInfo)>;

std::shared_ptr<Model> decodeModel(QByteArrayView bytes, QString* error, const ModelCodecLimits& limits = {},
                                   const ImageLender& lend = {});

} // namespace lr
