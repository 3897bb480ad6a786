// What the open model holds, as a tree for the Model dock (issue 13): four branches — Meshes (name,
// triangles, vertices, material), Materials (every value of model.h's Material: base colour, metallic,
// roughness, each texture with its role, name and size and its KHR_texture_transform, occlusion strength,
// normal scale, emissive, alpha mode and cutoff, double-sided, the classic specular and shininess, and
// whether its physically based values came from the file or were converted), Textures (name, size) and
// Warnings (each import warning in full). Two columns: what, and its value. Read-only; rebuilt (a model
// reset) when the model changes. Issue 38: under each mesh, "lit by" and "casts shadow of": how many of the
// rig's lights (switched on) light it and cast a shadow from it under light linking (core/lightlink.h),
// their names in the tooltip; setLights updates them in place (dataChanged, no reset).
#pragma once

#include "core/rig.h"
#include "model/model.h"

#include <QAbstractItemModel>
#include <memory>
#include <vector>

namespace lr {

class ModelTreeModel : public QAbstractItemModel {
    Q_OBJECT
  public:
    enum Branch { Meshes, Materials, Textures, Warnings, BranchCount };
    enum Column { NameColumn, ValueColumn, ColumnCount };

    explicit ModelTreeModel(QObject* parent = nullptr);

    void setModel(std::shared_ptr<const Model> model);
    const std::shared_ptr<const Model>& model() const { return m_model; }
    // The rig's lights, for each mesh's "lit by" and "casts shadow of" rows.
    void setLights(const std::vector<Light>& lights);
    // A mesh's "lit by" (shadow false) or "casts shadow of" row; invalid when there is no such mesh.
    QModelIndex linkIndex(int mesh, bool shadow, int column = ValueColumn) const;
    QModelIndex branchIndex(Branch branch) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // "name<TAB>value" per row, the lines of a copy.
    QString copyText(const QModelIndexList& rows) const;

    // A texture as the dock writes it: "name (W×H)", or "none" for -1, "missing" for a bad index.
    static QString textureText(const Model& model, int texture);
    static QString transformText(const TextureTransform& t); // "" for the identity
    static QString samplingText(const TextureSampling& s);   // "wrap clamp-to-edge; magnified nearest"

  private:
    struct Node {
        QString name, value, toolTip;
        int parent = -1; // node index; -1 for a branch
        int row = 0;     // within its parent
        std::vector<int> children;
    };
    int add(int parent, QString name, QString value = {}, QString toolTip = {});
    void build();
    void addMaterial(int parent, const Material& m);
    void updateLinks(bool notify);

    std::shared_ptr<const Model> m_model;
    std::vector<Node> m_nodes; // the branches are nodes 0..BranchCount-1
    std::vector<Light> m_lights;
    std::vector<int> m_litNodes, m_shadowNodes; // per mesh
};

} // namespace lr
