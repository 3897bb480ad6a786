// Importing a model file with Assimp into a Model (model.h): triangles with the node transforms applied
// (in double, relative to the bounds centre), materials with decoded textures, and the file's lights
// and cameras. Every failure is a message naming the file; nothing here throws.
//
// Conventions of the result (see model.h):
// - Vertex::uv: (0, 0) is the top-left texel, i.e. the first row of the QImage, so QImage bits upload
//   to glTexImage2D as they are (Assimp's bottom-left UVs are flipped here).
// - Vertex::tangent: xyz along +u, w such that w * cross(normal, tangent.xyz) points "up" in the
//   image (the +Y / green axis of an OpenGL-style normal map, which is what glTF uses).
// - Triangles are counter-clockwise seen from the side the normal points to (negative-determinant
//   node transforms are un-mirrored by flipping the winding).
//
// Lights (Model::lights, world space, RigSpace::World):
// - intensity = the largest colour component of what the file gives, colour = that colour / intensity.
//   Assimp folds glTF's intensity into the colour; this recovers glTF's split exactly when a colour
//   component is 1 (as exporters write them).
// - point and spot lights: glTF and pure 1/d² attenuation -> FalloffModel::InverseSquare with the
//   glTF range (node metadata "PBR_LightRange") or -1; other constant/linear/quadratic attenuation ->
//   FalloffModel::InversePolynomial with the file's coefficients.
// - spot cones: ConeModel::Smooth. Assimp 5.2.5's glTF importer stores KHR_lights_punctual's
//   innerConeAngle/outerConeAngle unchanged, i.e. half-angles from the axis, and the cone exponent is
//   2 (glTF's reference squares the smooth ramp). For other formats (FBX, Collada, ASE, ...) Assimp's
//   mAngleInnerCone/mAngleOuterCone are the full cone angles of the source format, halved here.
// - ambient lights add to Rig::ambient; area lights are skipped with a warning.
// Cameras (Model::cameras): position/forward/up from the camera's node. aiCamera::mHorizontalFOV is a
// full angle (despite aiCamera's comment saying "half"): Collada and FBX store the true horizontal
// angle, so yfov = 2 atan(tan(hfov / 2) / aspect); Assimp 5.2.5's glTF importer stores yfov * aspect,
// so yfov = hfov / aspect there, and it also copies the node's translation into mPosition, which is
// ignored for glTF (the camera sits at its node's origin). No aspect in the file: yfov = hfov.
#pragma once

#include "model.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <memory>

namespace lr {

struct ModelLoadOptions {
    // Files the model refers to (buffers, material libraries, textures) by an absolute path or one
    // that leaves the model's folder with "..": refused unless this is set. A refused texture is
    // skipped with a warning (a file of the same name inside the model's folder is used instead).
    bool allowTexturesOutsideFolder = false;
    // Largest "data:" URI in a glTF file (buffers and images), in decoded-or-not bytes of the URI text.
    qint64 maxDataUriBytes = 64ll * 1024 * 1024;
    // Called now and then with the fraction done in [0, 1]; return false to cancel the load.
    // Called on the loading thread.
    std::function<bool(double)> progress;
};

struct ModelLoadResult {
    std::shared_ptr<Model> model; // null on failure
    QString error;                // "could not import PATH: <reason>" on failure, PATH as given
    bool cancelled = false;       // the progress callback returned false
    bool ok() const { return model != nullptr; }
};

// Thread-safe (each call has its own Assimp importer); may be called from a worker thread.
ModelLoadResult loadModel(const QString& path, const ModelLoadOptions& options = {});

// Lower-case file name suffixes Assimp can import ("obj", "gltf", ...), sorted.
QStringList importableSuffixes();
// "3D models (*.obj *.gltf ...)" for QFileDialog.
QString modelFileFilter();

} // namespace lr
