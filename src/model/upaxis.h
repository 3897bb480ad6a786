// A model's up axis: files from Z-up tools (many STL, some FBX and OBJ) lie on their side in LightRig's
// y-up world. The editor remembers, per file, which of the file's axes points up and rotates the imported
// Model data by a quarter or half turn before anything uses it (renderer, picking, bounds, the model-space
// rig frame). The rig is never touched: it stays in LightRig's y-up world.
#pragma once

#include "model/model.h"

#include <QString>
#include <QStringList>
#include <glm/mat3x3.hpp>

namespace lr {

// Which axis of the file points up. YUp leaves the model as imported.
enum class ModelUpAxis { YUp, ZUp, XUp, NegYUp, NegZUp, NegXUp };
constexpr int kModelUpAxisCount = 6;

QString toString(ModelUpAxis axis); // "+Y", "+Z", "+X", "-Y", "-Z", "-X"
ModelUpAxis modelUpAxisFromString(const QString& text, bool* ok = nullptr); // YUp when not ok
QStringList modelUpAxisNames();                                             // in enum order

// The proper rotation (det 1) that takes the file's up axis onto +Y (a quarter or half turn).
glm::dmat3 upAxisRotation(ModelUpAxis axis);

// The model with a signed axis permutation of det 1 (as upAxisRotation returns, or products and
// transposes of them) applied to its world positions (origin and vertices), normals, tangents, bounds, and
// its own lights and cameras. Exact: every entry is 0 or ±1.
Model rotateModel(const Model& model, const glm::dmat3& rotation);
// rotateModel(model, upAxisRotation(axis)); YUp returns it unchanged.
Model rotateModelUp(const Model& model, ModelUpAxis axis);

} // namespace lr
