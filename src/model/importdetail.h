// Internal to lightrig_model: the steps of loadModel (modelloader.cpp), one file each.
#pragma once

#include "model.h"
#include "modelfolder.h"

#include <QByteArrayView>
#include <QHash>
#include <QJsonObject>
#include <QStringList>
#include <assimp/matrix4x4.h>
#include <functional>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

struct aiMaterial;
struct aiNode;
struct aiScene;
struct aiUVTransform;

namespace lr::detail {

glm::dmat4 toGlm(const aiMatrix4x4& m);
// The node's transform to world space (the product of its and its ancestors' transforms), in double.
glm::dmat4 worldTransform(const aiNode* node);

// meshes.cpp: instances every mesh of every node into model.meshes (world positions relative to the
// bounds centre, which becomes model.origin), drops invalid geometry with a warning, sets bounds.
// Returns false when `keepGoing` asked to stop.
bool convertMeshes(const aiScene* scene, const QString& displayName, Model& model,
                   const std::function<bool(double)>& keepGoing);

// Which importer's conventions a scene's materials follow (modelloader.cpp decides from the suffix).
enum class MaterialSource { Gltf, Fbx, Other };
MaterialSource materialSource(const QString& path);

// materials.cpp: model.materials (one per aiMaterial, never empty) and the textures they use. `gltfJson`:
// the glTF's JSON (gltfJsonOf), for what Assimp does not read (readGltfMaterialExtras); empty for others.
void convertMaterials(const aiScene* scene, const ModelFolder& folder, qint64 maxDataUriBytes,
                      MaterialSource source, const QByteArray& gltfJson, Model& model);

// gltfmaterials.cpp: what Assimp 5.2.5 does not read of a glTF material, per entry of its "materials"
// array, by material name: KHR_materials_emissive_strength, and the list of the material's extensions
// (Material::extensions). Read from the file's JSON (`json`: gltfJsonOf) only when it names a material
// extension; empty otherwise or when the JSON does not parse.
struct GltfMaterialExtras {
    glm::vec3 emissiveFactor{0.0f}; // to tell materials of one name apart
    double emissiveStrength = 1.0;
    std::vector<MaterialExtension> extensions;
    int extensionCount = 0; // how many the file lists (extensions holds at most kMaxMaterialExtensions)
};
using GltfMaterialExtrasByName = QMultiHash<QString, GltfMaterialExtras>;
GltfMaterialExtrasByName readGltfMaterialExtras(const QByteArray& json);
// The names of the file's KHR_materials_variants (`json`: gltfJsonOf), in the file's order; unnamed ones as
// "variant N". Empty when it has none.
QStringList readGltfVariantNames(const QByteArray& json);

// materials_pbr.cpp: what one material's conversion needs to know and where its warnings go.
struct MaterialContext {
    QString file;  // display name, for warnings
    QString label; // "material \"paint\"" or "material 3"
    MaterialSource source = MaterialSource::Other;
    QStringList* warnings = nullptr;
    GltfMaterialExtrasByName gltfExtras;
    void warn(const QString& what) const { *warnings << QStringLiteral("%1: %2: %3").arg(file, label, what); }
};
// Metallic, roughness, occlusion strength, normal scale, alpha mode and cutoff, the emissive strength, and
// whether they came from the file (Material::pbr) or from specular/shininess; sanitised with warnings.
void readPhysicalValues(const aiMaterial* am, const MaterialContext& ctx, Material& m);
// KHR_texture_transform's offset/rotation/scale from the aiUVTransform Assimp 5.2.5's glTF importer made of
// them (the inverse of its conversion); a non-finite transform is the identity, with a warning.
TextureTransform textureTransformFromAssimp(const aiUVTransform& t, const QString& role,
                                            const MaterialContext& ctx);

// lights.cpp: model.lights and model.cameras. `gltf`: the scene came from Assimp's glTF importers.
void convertLightsAndCameras(const aiScene* scene, bool gltf, const QString& displayName, Model& model);
// lights.cpp: the roll (degrees, -180 ... 180) that turns areaAxes(direction, 0)'s y towards `up` (its part
// perpendicular to the direction); 0 when up is parallel to the direction, zero or not finite.
double rollForUp(const glm::dvec3& direction, const glm::dvec3& up);

// gltflightextras.cpp (issue 39, docs/export.md "Import"): what Assimp 5.2.5 does not read of a glTF's
// lights, from its JSON (`json`: gltfJsonOf): each EXT_lights_ies instance becomes a point light with its IES
// profile, and a light node's extras.lightrig {link, gobo, barnDoors} go onto its light (read by the rig's
// readers). Everything that cannot be used is a warning naming the file and the JSON field; nothing fails the
// import.
void readGltfLightExtras(const QByteArray& json, const ModelFolder& folder, qint64 maxDataUriBytes,
                         Model& model);

// gltfiesprofile.cpp: the profile extensions.EXT_lights_ies.lights[index] of the glTF whose JSON is `root`,
// from its uri (data: or a file relative to the glTF, under `folder`'s rule) or its bufferView, checked by
// readIesData. `file` is what IesSpec::file names: the profile's own file, or, for an embedded one, its copy
// in the IES cache (cacheIesProfile); empty with `error` (and `field`, the JSON path it concerns) when none.
struct GltfIesProfile {
    QString file;
    QString field; // "extensions.EXT_lights_ies.lights[0].uri"
    QString error; // "embedded profile:12: ..." (core/ies.h's reason), "data: URI whose base64 ..."
};
GltfIesProfile readGltfIesProfile(const QJsonObject& root, int index, const ModelFolder& folder,
                                  qint64 maxDataUriBytes);
// Where embedded profiles are kept: $LIGHTRIG_IES_CACHE when set, else $XDG_DATA_HOME/lightrig/ies
// (~/.local/share/lightrig/ies), the same folder for the worker and the editor.
QString iesCacheFolder();
// `bytes` as <iesCacheFolder()>/<sha256 hex>.ies, written atomically once (an equal file is reused); its
// path, or empty with *error.
QString cacheIesProfile(const QByteArray& bytes, QString* error);

// meshes.cpp: the number of pairs of vertices within Assimp's smoothing distance of each other (1e-4 of
// a mesh's bounding-box diagonal), estimated per mesh from a grid of cells of that size: the work of
// the post-processing steps built on SpatialSort (smooth normals, tangents, joining), which grows with
// the square of the vertices at one position.
qint64 coincidentVertexPairs(const aiScene* scene);

// preflight.cpp: why the file must not reach Assimp (empty when it may): a data URI over the limit, GLB
// lengths beyond the file, an OFF/PLY header declaring more elements than the file holds or (PLY) not
// ending, non-numeric lines in ASCII PLY data.
QString preflight(const QString& path, qint64 maxDataUriBytes);
// The length of the longest "data:" URI in glTF JSON or a GLB's JSON chunk.
qint64 largestDataUri(QByteArrayView bytes);
// The little-endian u32 at `at` of a GLB header or chunk (the caller checked that 4 bytes are there).
quint32 glbU32(QByteArrayView bytes, qsizetype at);
// A GLB's JSON chunk starts at byte 20; its length as `header` (the file's first bytes, "glTF"...)
// declares it, clamped to a file of `fileSize` bytes; -1 when the header is short or the first chunk
// is not JSON.
qint64 glbJsonLength(QByteArrayView header, qint64 fileSize);

} // namespace lr::detail
