#include "modeltreemodel.h"

#include "scene/linkparts.h"

#include <QCoreApplication>

namespace lr {

namespace {
QString num(double v) {
    return QString::number(v, 'g', 4);
}

QString rgb(const glm::vec3& c) {
    return QStringLiteral("%1, %2, %3").arg(num(c.r), num(c.g), num(c.b));
}

QString alphaModeText(AlphaMode mode) {
    switch (mode) {
    case AlphaMode::Opaque:
        return QStringLiteral("opaque");
    case AlphaMode::Mask:
        return QStringLiteral("mask");
    case AlphaMode::Blend:
        return QStringLiteral("blend");
    }
    return QStringLiteral("?");
}
} // namespace

ModelTreeModel::ModelTreeModel(QObject* parent) : QAbstractItemModel(parent) {
    build();
}

void ModelTreeModel::setModel(std::shared_ptr<const Model> model) {
    beginResetModel();
    m_model = std::move(model);
    build();
    endResetModel();
}

QString ModelTreeModel::textureText(const Model& model, int texture) {
    if (texture < 0) return tr("none");
    if (size_t(texture) >= model.textures.size()) return tr("missing (texture %1)").arg(texture);
    const Texture& t = model.textures[size_t(texture)];
    return QStringLiteral("%1 (%2×%3)").arg(t.name).arg(t.image.width()).arg(t.image.height());
}

QString ModelTreeModel::samplingText(const TextureSampling& s) {
    QString text = s.wrapS == s.wrapT ? tr("wrap %1").arg(toString(s.wrapS))
                                      : tr("wrap S %1, T %2").arg(toString(s.wrapS), toString(s.wrapT));
    if (s.nearestMagnification) text += tr("; magnified nearest");
    return text;
}

QString ModelTreeModel::transformText(const TextureTransform& t) {
    if (t.isIdentity()) return {};
    return tr("offset %1, %2; rotation %3°; scale %4, %5")
        .arg(num(t.offset.x), num(t.offset.y), num(double(t.rotation) * 180.0 / 3.14159265358979323846),
             num(t.scale.x), num(t.scale.y));
}

int ModelTreeModel::add(int parent, QString name, QString value, QString toolTip) {
    Node n;
    n.name = std::move(name);
    n.value = std::move(value);
    n.toolTip = std::move(toolTip);
    n.parent = parent;
    const int id = int(m_nodes.size());
    if (parent >= 0) {
        n.row = int(m_nodes[size_t(parent)].children.size());
        m_nodes[size_t(parent)].children.push_back(id);
    }
    m_nodes.push_back(std::move(n));
    return id;
}

void ModelTreeModel::addMaterial(int parent, const Material& m) {
    const Model& model = *m_model;
    add(parent, tr("physically based values"),
        m.pbr ? tr("from the file") : tr("converted from specular and shininess"),
        m.pbr ? tr("The file carried metal-rough values (glTF, or PBR keys of another format).")
              : tr("The file had none: metallic and roughness were converted from the classic specular and "
                   "shininess (docs/lighting-models.md)."));
    add(parent, tr("base colour"),
        QStringLiteral("%1; alpha %2").arg(rgb(glm::vec3(m.baseColor)), num(m.baseColor.a)),
        tr("Linear RGBA factor"));
    add(parent, tr("metallic"), num(m.metallic));
    add(parent, tr("roughness"), num(m.roughness));
    add(parent, tr("occlusion strength"), num(m.occlusionStrength));
    add(parent, tr("normal scale"), num(m.normalScale));
    add(parent, tr("emissive"), rgb(m.emissive),
        tr("Linear factor, KHR_materials_emissive_strength folded in"));
    add(parent, tr("alpha mode"),
        m.alphaMode == AlphaMode::Mask ? tr("mask, cutoff %1").arg(num(m.alphaCutoff))
                                       : alphaModeText(m.alphaMode));
    add(parent, tr("double-sided"), m.doubleSided ? tr("yes") : tr("no"));
    add(parent, tr("specular (classic)"), rgb(m.specular));
    add(parent, tr("shininess (classic)"), m.shininess < 0.0f ? tr("the rig's") : num(m.shininess));
    const struct {
        const char* role;
        int texture;
        const TextureTransform* transform;
        const TextureSampling* sampling;
        const char* note;
    } textures[] = {
        {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "base colour texture"), m.baseColorTexture,
         &m.baseColorTransform, &m.baseColorSampling, QT_TRANSLATE_NOOP("lr::ModelTreeModel", "sRGB")},
        {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "metallic-roughness texture"), m.metallicRoughnessTexture,
         &m.metallicRoughnessTransform, &m.metallicRoughnessSampling,
         QT_TRANSLATE_NOOP("lr::ModelTreeModel", "linear: G = roughness, B = metallic")},
        {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "normal texture"), m.normalTexture, &m.normalTransform,
         &m.normalSampling, QT_TRANSLATE_NOOP("lr::ModelTreeModel", "linear, tangent space")},
        {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "occlusion texture"), m.occlusionTexture,
         &m.occlusionTransform, &m.occlusionSampling,
         QT_TRANSLATE_NOOP("lr::ModelTreeModel", "linear: R = occlusion")},
        {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "emissive texture"), m.emissiveTexture, &m.emissiveTransform,
         &m.emissiveSampling, QT_TRANSLATE_NOOP("lr::ModelTreeModel", "sRGB")},
    };
    for (const auto& t : textures) {
        const int row = add(parent, tr(t.role), textureText(model, t.texture), tr(t.note));
        if (t.texture < 0) continue;
        if (const QString transform = transformText(*t.transform); !transform.isEmpty())
            add(row, tr("texture transform"), transform, tr("KHR_texture_transform"));
        if (!t.sampling->isDefault())
            add(row, tr("sampler"), samplingText(*t.sampling),
                tr("The glTF sampler's wrap modes and magnification filter"));
    }
    if (m.extensions.empty()) return;
    int notRendered = 0;
    for (const MaterialExtension& x : m.extensions)
        notRendered += materialExtensionRendered(x.name) ? 0 : 1;
    const int row = add(parent, tr("extensions"),
                        notRendered ? tr("%n not rendered", nullptr, notRendered) : tr("all rendered"),
                        tr("The glTF material extensions the file gives this material, with their values"));
    for (const MaterialExtension& x : m.extensions)
        add(row, x.name, x.values,
            materialExtensionRendered(x.name)
                ? tr("Rendered")
                : tr("Not rendered: the material is drawn with its core metal-rough values"));
}

void ModelTreeModel::build() {
    m_nodes.clear();
    m_litNodes.clear();
    m_shadowNodes.clear();
    static const char* const kBranches[] = {QT_TRANSLATE_NOOP("lr::ModelTreeModel", "Meshes"),
                                            QT_TRANSLATE_NOOP("lr::ModelTreeModel", "Materials"),
                                            QT_TRANSLATE_NOOP("lr::ModelTreeModel", "Textures"),
                                            QT_TRANSLATE_NOOP("lr::ModelTreeModel", "Warnings")};
    for (int b = 0; b < BranchCount; ++b) {
        const int id = add(-1, tr(kBranches[b]));
        m_nodes[size_t(id)].row = b;
    }
    if (!m_model) return;
    const Model& model = *m_model;
    for (const Mesh& mesh : model.meshes) {
        const QString material = mesh.material >= 0 && size_t(mesh.material) < model.materials.size()
                                     ? model.materials[size_t(mesh.material)].name
                                     : QString();
        const int id = add(Meshes, mesh.name.isEmpty() ? tr("(unnamed)") : mesh.name,
                           tr("%1 triangles, %2 vertices, material %3%4")
                               .arg(mesh.indices.size() / 3)
                               .arg(mesh.vertices.size())
                               .arg(mesh.material)
                               .arg(material.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(material)));
        m_litNodes.push_back(add(id, tr("lit by")));
        m_shadowNodes.push_back(add(id, tr("casts shadow of")));
    }
    updateLinks(false);
    // A material no mesh uses and the file does not name is an importer's placeholder (Assimp adds an
    // unnamed default material to every glTF scene): not listed (issue 41: DamagedHelmet's "material 1").
    std::vector<char> used(model.materials.size(), 0);
    for (const Mesh& mesh : model.meshes)
        if (mesh.material >= 0 && size_t(mesh.material) < used.size()) used[size_t(mesh.material)] = 1;
    int listed = 0;
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const Material& m = model.materials[i];
        if (!used[i] && m.name.isEmpty()) continue;
        const QString kind = m.pbr ? tr("physically based (from the file)") : tr("converted (classic file)");
        const int id = add(Materials, m.name.isEmpty() ? tr("material %1").arg(i) : m.name,
                           used[i] ? kind : tr("%1, no mesh uses it").arg(kind));
        addMaterial(id, m);
        ++listed;
    }
    for (const Texture& t : model.textures)
        add(Textures, t.name, QStringLiteral("%1×%2").arg(t.image.width()).arg(t.image.height()));
    for (int i = 0; i < model.warnings.size(); ++i)
        add(Warnings, model.warnings[i], QString(), model.warnings[i]);
    const int counts[] = {int(model.meshes.size()), listed, int(model.textures.size()),
                          int(model.warnings.size())};
    for (int b = 0; b < BranchCount; ++b)
        m_nodes[size_t(b)].value = QString::number(counts[b]);
}

void ModelTreeModel::setLights(const std::vector<Light>& lights) {
    m_lights = lights;
    updateLinks(true);
}

void ModelTreeModel::updateLinks(bool notify) {
    if (!m_model || m_litNodes.empty()) return;
    const std::vector<PartNames> parts = linkParts(m_model.get(), nullptr);
    const LinkResolution links = resolveLinks(m_lights, parts);
    int on = 0, shadows = 0;
    for (const Light& l : m_lights) {
        on += l.enabled;
        shadows += l.hasShadow();
    }
    for (std::size_t mesh = 0; mesh < m_litNodes.size(); ++mesh) {
        QStringList lit, cast;
        for (std::size_t j = 0; j < m_lights.size(); ++j) {
            if (m_lights[j].enabled && links.lights(j, mesh)) lit << m_lights[j].name;
            if (m_lights[j].hasShadow() && links.casts(j, mesh)) cast << m_lights[j].name;
        }
        const auto set = [&](int node, const QString& value, const QString& tip) {
            Node& n = m_nodes[size_t(node)];
            if (n.value == value && n.toolTip == tip) return;
            n.value = value;
            n.toolTip = tip;
            if (notify) {
                const QModelIndex i = createIndex(n.row, ValueColumn, quintptr(node));
                emit dataChanged(i.siblingAtColumn(NameColumn), i);
            }
        };
        set(m_litNodes[mesh],
            on == 1 ? tr("%1 of 1 light").arg(lit.size()) : tr("%1 of %2 lights").arg(lit.size()).arg(on),
            lit.isEmpty() ? tr("No light that is on lights this mesh")
                          : tr("Lit by: %1").arg(lit.join(QStringLiteral(", "))));
        set(m_shadowNodes[mesh],
            shadows == 1 ? tr("%1 of 1 shadow").arg(cast.size())
                         : tr("%1 of %2 shadows").arg(cast.size()).arg(shadows),
            cast.isEmpty() ? tr("This mesh casts no light's shadow")
                           : tr("Casts the shadow of: %1").arg(cast.join(QStringLiteral(", "))));
    }
}

QModelIndex ModelTreeModel::linkIndex(int mesh, bool shadow, int column) const {
    const std::vector<int>& nodes = shadow ? m_shadowNodes : m_litNodes;
    if (mesh < 0 || size_t(mesh) >= nodes.size()) return {};
    const int node = nodes[size_t(mesh)];
    return createIndex(m_nodes[size_t(node)].row, column, quintptr(node));
}

QModelIndex ModelTreeModel::branchIndex(Branch branch) const {
    return index(int(branch), 0);
}

QModelIndex ModelTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (row < 0 || column < 0 || column >= ColumnCount) return {};
    if (!parent.isValid()) return row < BranchCount ? createIndex(row, column, quintptr(row)) : QModelIndex();
    if (parent.model() != this || parent.column() != 0) return {};
    const Node& p = m_nodes[size_t(parent.internalId())];
    if (size_t(row) >= p.children.size()) return {};
    return createIndex(row, column, quintptr(p.children[size_t(row)]));
}

QModelIndex ModelTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.model() != this) return {};
    const int p = m_nodes[size_t(child.internalId())].parent;
    if (p < 0) return {};
    return createIndex(m_nodes[size_t(p)].row, 0, quintptr(p));
}

int ModelTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return BranchCount;
    if (parent.model() != this || parent.column() != 0) return 0;
    return int(m_nodes[size_t(parent.internalId())].children.size());
}

int ModelTreeModel::columnCount(const QModelIndex&) const {
    return ColumnCount;
}

QVariant ModelTreeModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.model() != this) return {};
    const Node& n = m_nodes[size_t(index.internalId())];
    switch (role) {
    case Qt::DisplayRole:
        return index.column() == NameColumn ? n.name : n.value;
    case Qt::ToolTipRole:
        return n.toolTip.isEmpty() ? QVariant() : QVariant(n.toolTip);
    default:
        return {};
    }
}

QVariant ModelTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    return section == NameColumn ? tr("Item") : section == ValueColumn ? tr("Value") : QVariant();
}

QString ModelTreeModel::copyText(const QModelIndexList& rows) const {
    QStringList lines;
    for (const QModelIndex& i : rows) {
        if (!i.isValid() || i.model() != this) continue;
        const Node& n = m_nodes[size_t(i.internalId())];
        lines << (n.value.isEmpty() ? n.name : n.name + QLatin1Char('\t') + n.value);
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace lr
