#include "renderlayersexr.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace lr {

namespace {

const char* kindName(LightGroupKind k) {
    switch (k) {
    case LightGroupKind::Lights:
        return "lights";
    case LightGroupKind::Environment:
        return "environment";
    case LightGroupKind::Emissive:
        return "emissive";
    case LightGroupKind::Ambient:
        return "ambient";
    case LightGroupKind::Background:
        return "background";
    }
    return "lights";
}

std::optional<LightGroupKind> kindOf(const QString& s) {
    for (LightGroupKind k : {LightGroupKind::Lights, LightGroupKind::Environment, LightGroupKind::Emissive,
                             LightGroupKind::Ambient, LightGroupKind::Background})
        if (s == QLatin1String(kindName(k))) return k;
    return std::nullopt;
}

ExrLayer layerOf(const QString& name, const FloatImage& image, const QStringList& channels) {
    ExrLayer layer;
    layer.name = name;
    layer.channels = channels;
    const size_t n = size_t(channels.size());
    layer.pixels.resize(image.pixels.size() * n);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (size_t c = 0; c < n; ++c)
            layer.pixels[i * n + c] = image.pixels[i][int(c)];
    return layer;
}

// The layer's channels `names` into x, y, z, w of an image (missing ones: `fill`).
FloatImage imageOf(const ExrFile& file, const ExrLayer& layer, const QStringList& names, float fill) {
    FloatImage out;
    out.width = file.width;
    out.height = file.height;
    out.pixels.assign(size_t(file.width) * size_t(file.height), glm::vec4(fill));
    const size_t n = size_t(layer.channels.size());
    for (int k = 0; k < names.size() && k < 4; ++k) {
        const qsizetype c = layer.channels.indexOf(names[k]);
        if (c < 0) continue;
        for (size_t i = 0; i < out.pixels.size(); ++i)
            out.pixels[i][k] = layer.pixels[i * n + size_t(c)];
    }
    return out;
}

const QStringList kRgb{QStringLiteral("R"), QStringLiteral("G"), QStringLiteral("B")};
const QStringList kAux{QStringLiteral("albedo"), QStringLiteral("normal"), QStringLiteral("depth")};

} // namespace

QByteArray encodeRenderLayersExr(const RenderLayers& layers,
                                 std::vector<std::pair<QString, QString>> attributes, ExrPixel pixel,
                                 QString* error) {
    std::vector<ExrLayer> out;
    out.push_back(layerOf(QString(), layers.beauty, kRgb + QStringList{QStringLiteral("A")}));
    const QStringList names = uniqueExrLayerNames(groupNames(layers.groups), kAux);
    QJsonArray groups;
    for (size_t g = 0; g < layers.groupImages.size() && g < layers.groups.size(); ++g) {
        out.push_back(layerOf(names[qsizetype(g)], layers.groupImages[g], kRgb));
        groups.append(QJsonObject{{QStringLiteral("layer"), names[qsizetype(g)]},
                                  {QStringLiteral("group"), layers.groups[g].name},
                                  {QStringLiteral("kind"), QLatin1String(kindName(layers.groups[g].kind))}});
    }
    if (!layers.albedo.isNull()) out.push_back(layerOf(QStringLiteral("albedo"), layers.albedo, kRgb));
    if (!layers.normal.isNull())
        out.push_back(layerOf(QStringLiteral("normal"), layers.normal,
                              {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}));
    if (!layers.depth.isNull())
        out.push_back(layerOf(QStringLiteral("depth"), layers.depth, {QStringLiteral("Z")}));
    attributes.push_back({QString::fromLatin1(kExrGroupsAttribute),
                          QString::fromUtf8(QJsonDocument(groups).toJson(QJsonDocument::Compact))});
    return encodeExrLayers(layers.beauty.width, layers.beauty.height, out, attributes, pixel, error);
}

std::optional<RenderLayers> renderLayersFromExr(const ExrFile& file, QString* error) {
    const ExrLayer* beauty = file.layer(QString());
    if (!beauty || !beauty->channels.contains(QStringLiteral("R")) ||
        !beauty->channels.contains(QStringLiteral("G")) || !beauty->channels.contains(QStringLiteral("B"))) {
        *error = QStringLiteral("it has no beauty image (channels R, G, B)");
        return std::nullopt;
    }
    RenderLayers out;
    out.beauty = imageOf(file, *beauty, kRgb + QStringList{QStringLiteral("A")}, 1.0f);
    if (beauty->channels.contains(QStringLiteral("A")) == false)
        for (glm::vec4& p : out.beauty.pixels)
            p.w = 1.0f;
    const auto attribute = [&](const char* name) -> std::optional<QString> {
        for (const auto& [key, value] : file.attributes)
            if (key == QLatin1String(name)) return value;
        return std::nullopt;
    };
    const auto addGroup = [&](const ExrLayer& layer, const QString& name, LightGroupKind kind) -> bool {
        for (const QString& c : kRgb)
            if (!layer.channels.contains(c)) {
                *error = QStringLiteral("layer %1 (group %2) has no channel %3").arg(layer.name, name, c);
                return false;
            }
        for (const LightGroup& g : out.groups)
            if (g.name == name) {
                *error = QStringLiteral("group %1 is listed twice").arg(name);
                return false;
            }
        out.groups.push_back({name, kind, {}});
        out.groupImages.push_back(imageOf(file, layer, kRgb, 0.0f));
        for (size_t i = 0; i < out.groupImages.back().pixels.size(); ++i)
            out.groupImages.back().pixels[i].w = out.beauty.pixels[i].w;
        return true;
    };
    if (const std::optional<QString> list = attribute(kExrGroupsAttribute)) {
        QJsonParseError parse;
        const QJsonDocument doc = QJsonDocument::fromJson(list->toUtf8(), &parse);
        if (!doc.isArray()) {
            *error = QStringLiteral("its %1 attribute is not a JSON array")
                         .arg(QLatin1String(kExrGroupsAttribute));
            return std::nullopt;
        }
        for (const QJsonValue& v : doc.array()) {
            const QJsonObject o = v.toObject();
            const QString layerName = o.value(QStringLiteral("layer")).toString();
            const QString group = o.value(QStringLiteral("group")).toString();
            const std::optional<LightGroupKind> kind = kindOf(o.value(QStringLiteral("kind")).toString());
            const ExrLayer* layer = layerName.isEmpty() ? nullptr : file.layer(layerName);
            if (!layer || group.isEmpty() || !kind) {
                *error =
                    QStringLiteral("its %1 attribute names a layer %2 that the file does not have, or no "
                                   "group or kind")
                        .arg(QLatin1String(kExrGroupsAttribute), layerName);
                return std::nullopt;
            }
            if (!addGroup(*layer, group, *kind)) return std::nullopt;
        }
    } else {
        for (const ExrLayer& layer : file.layers)
            if (!layer.name.isEmpty() && !kAux.contains(layer.name) &&
                !addGroup(layer, layer.name, LightGroupKind::Lights))
                return std::nullopt;
    }
    if (const ExrLayer* a = file.layer(QStringLiteral("albedo"))) out.albedo = imageOf(file, *a, kRgb, 0.0f);
    if (const ExrLayer* n = file.layer(QStringLiteral("normal")))
        out.normal = imageOf(file, *n, {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}, 0.0f);
    if (const ExrLayer* d = file.layer(QStringLiteral("depth")))
        out.depth = imageOf(file, *d, {QStringLiteral("Z")}, kBackgroundDepth);
    return out;
}

} // namespace lr
