// Adding lights, a camera and a note to a glTF 2.0 asset without touching anything else (issue 17,
// docs/export.md). The JSON is edited as text: every top-level member, array item and object member the
// export does not change is copied byte for byte from the source (materials, meshes, accessors,
// animations, skins, other extensions, extras), and a GLB's chunks after the JSON chunk (BIN, and any
// other) are copied unchanged. What changes:
//   - extensions.KHR_lights_punctual.lights is replaced by the rig's lights, and a node that pointed at one
//     of the file's own lights loses that reference (the rig replaces the model's lights, as in LightRig);
//   - one node per light and one for the camera are appended and listed in the default scene's nodes;
//   - the camera, when given, becomes cameras[0] (viewers show the first camera) and nodes' camera
//     indices move up by one;
//   - extensionsUsed lists KHR_lights_punctual (or no longer does, with no lights left), extras.lightrig
//     holds the note.
// A file is untrusted: a malformed GLB or JSON, or a glTF whose parts are not what the specification says
// (nodes not an array of objects, ...) is an error naming the part and the reason; nothing is produced.
#pragma once

#include "gltflights.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace lr {

inline constexpr qint64 kMaxGltfJsonBytes = 64ll << 20; // a JSON chunk or .gltf file larger is refused

struct GlbParts {
    QByteArray json; // the JSON chunk's content (padding included)
    QByteArray rest; // every chunk after it, as in the file (BIN first when there is one)
    QByteArray bin;  // the BIN chunk's content, or empty
    bool hasBin = false;
};

// Whether `data` starts like a GLB ("glTF" magic).
bool isGlb(const QByteArray& data);
// The chunks of a GLB; nullopt and *error ("the header claims 1000 bytes but the file has 900") when the
// header, the chunk lengths or types are inconsistent.
std::optional<GlbParts> parseGlb(const QByteArray& data, QString* error);
// A GLB of `json` (padded with spaces to 4 bytes) followed by `rest` (chunks, as parseGlb returned them).
QByteArray writeGlb(const QByteArray& json, const QByteArray& rest);

struct GltfAdditions {
    std::vector<GltfLight> lights;
    std::optional<GltfCamera> camera;
    QJsonObject note;         // extras.lightrig (skipped when empty)
    QByteArray embedBinAsUri; // non-empty: buffers[0] gets this as a data: URI (GLB in, .gltf out)
    // Both set: relative file URIs of buffers and images are rewritten to name the same files from the
    // output's folder (an export written elsewhere than its source), Windows paths fixed (rebaseUri), and a
    // file a viewer will not find is a note.
    QString sourceFolder, outputFolder;
};

struct GltfRewriteResult {
    QByteArray json;   // empty on error
    QString error;     // "nodes[3]: must be an object"
    QStringList notes; // what else changed: "the model's 8 lights replaced by the rig's 3"
    bool ok() const { return error.isEmpty(); }
};

// The source's JSON with the additions.
GltfRewriteResult rewriteGltfJson(const QByteArray& json, const GltfAdditions& additions);

// A glTF of the lights alone (nodes and KHR_lights_punctual, no meshes), to merge into another scene.
QByteArray lightsOnlyGltfJson(const GltfAdditions& additions);

// The URIs of buffers and images that name files (not data: URIs).
QStringList externalUris(const QByteArray& json);
// A relative file URI as seen from `outputFolder` instead of `sourceFolder` (percent-encoded as glTF wants);
// data: URIs, URIs with a scheme and absolute paths are returned as they are. Issue 41: Windows separators
// (`.\tex.png`) become '/', a Windows drive path (`D:\maps\tex.png`) the file of that name beside the
// model when there is one; *problem (when given) says why a viewer will not find the file (a drive path
// without that file, a missing file), else is cleared. Same folder: unchanged but for those two fixes.
QString rebaseUri(const QString& uri, const QString& sourceFolder, const QString& outputFolder,
                  QString* problem = nullptr);

} // namespace lr
