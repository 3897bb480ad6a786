#include "gltfrewrite.h"

#include "rigjson_json.h"

#include <QDir>
#include <QJsonDocument>
#include <QMap>
#include <algorithm>
#include <cmath>

namespace lr {

namespace {

const QString kExt = QStringLiteral("KHR_lights_punctual");
const QString kIes = QStringLiteral("EXT_lights_ies"); // issue 39: lights with an IES profile

// The end of the (well-formed) JSON value that starts at `at`.
qsizetype valueEnd(const QByteArray& s, qsizetype at) {
    int depth = 0;
    bool inString = false;
    for (qsizetype i = at; i < s.size(); ++i) {
        const char c = s[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"') {
                inString = false;
                if (depth == 0) return i + 1;
            }
            continue;
        }
        if (c == '"')
            inString = true;
        else if (c == '{' || c == '[')
            ++depth;
        else if (c == '}' || c == ']') {
            if (--depth <= 0) return depth < 0 ? i : i + 1;
        } else if (depth == 0 && (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r'))
            return i;
    }
    return s.size();
}

QByteArray raw(const QByteArray& s, const json::Value& v) {
    return s.mid(v.offset, valueEnd(s, v.offset) - v.offset);
}

QByteArray text(const QJsonValue& v) {
    const QByteArray a = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return a.mid(1, a.size() - 2);
}

// `object` with members replaced (a value), removed (nullopt) or appended (absent from it), the others
// copied as they are in the source.
using Edits = QMap<QString, std::optional<QByteArray>>;
QByteArray editObject(const QByteArray& s, const json::Value& object, const Edits& edits) {
    QByteArray out("{");
    QSet<QString> seen;
    auto add = [&](const QString& key, const QByteArray& value) {
        if (out.size() > 1) out += ',';
        out += json::quote(key) + ':' + value;
    };
    for (const json::Member& m : object.members) {
        if (!edits.contains(m.key)) {
            add(m.key, raw(s, m.value));
            continue;
        }
        seen.insert(m.key);
        if (const auto& v = edits.value(m.key)) add(m.key, *v);
    }
    for (auto it = edits.begin(); it != edits.end(); ++it)
        if (!seen.contains(it.key()) && it.value()) add(it.key(), *it.value());
    return out + '}';
}

QByteArray joinArray(const QList<QByteArray>& items) {
    QByteArray out("[");
    for (qsizetype i = 0; i < items.size(); ++i)
        out += (i ? "," : "") + items[i];
    return out + ']';
}

// The member `key` of the root if it is of `kind`; *error when it is there but is not.
const json::Value* part(const json::Value& parent, const QString& key, json::Value::Kind kind,
                        const QString& path, QString* error) {
    const json::Value* v = parent.find(key);
    if (v && v->kind != kind && error->isEmpty())
        *error = QStringLiteral("%1: must be %2")
                     .arg(json::appendKey(path, key), kind == json::Value::Kind::Array
                                                          ? QStringLiteral("an array")
                                                          : QStringLiteral("an object"));
    return v && v->kind == kind ? v : nullptr;
}

// Every item of an array part must be an object.
void checkObjects(const json::Value* array, const QString& key, QString* error) {
    if (!array) return;
    for (size_t i = 0; i < array->items.size() && error->isEmpty(); ++i)
        if (array->items[i].kind != json::Value::Kind::Object)
            *error = QStringLiteral("%1: must be an object").arg(json::appendIndex(key, qsizetype(i)));
}

} // namespace

GltfRewriteResult rewriteGltfJson(const QByteArray& s, const GltfAdditions& add) {
    GltfRewriteResult r;
    const json::Document doc = json::parse(s);
    if (!doc.complete || !doc.errors.isEmpty()) {
        r.error = QStringLiteral("not valid JSON: %1").arg(doc.errors.value(0, QStringLiteral("incomplete")));
        return r;
    }
    using K = json::Value::Kind;
    const json::Value& root = doc.root;
    if (root.kind != K::Object) {
        r.error = QStringLiteral("the JSON is not an object");
        return r;
    }
    QString& error = r.error;
    const QString top;
    const json::Value* asset = part(root, QStringLiteral("asset"), K::Object, top, &error);
    const json::Value* version = asset ? asset->find(QStringLiteral("version")) : nullptr;
    if (error.isEmpty() &&
        (!version || version->kind != K::String || !version->string.startsWith(QLatin1String("2."))))
        error = QStringLiteral("asset.version: must be \"2.0\" (only glTF 2.0 is exported)");
    const json::Value* nodes = part(root, QStringLiteral("nodes"), K::Array, top, &error);
    const json::Value* scenes = part(root, QStringLiteral("scenes"), K::Array, top, &error);
    const json::Value* cameras = part(root, QStringLiteral("cameras"), K::Array, top, &error);
    const json::Value* buffers = part(root, QStringLiteral("buffers"), K::Array, top, &error);
    const json::Value* extensions = part(root, QStringLiteral("extensions"), K::Object, top, &error);
    const json::Value* used = part(root, QStringLiteral("extensionsUsed"), K::Array, top, &error);
    const json::Value* required = part(root, QStringLiteral("extensionsRequired"), K::Array, top, &error);
    checkObjects(nodes, QStringLiteral("nodes"), &error);
    checkObjects(scenes, QStringLiteral("scenes"), &error);
    const json::Value* sceneNumber = root.find(QStringLiteral("scene"));
    size_t sceneIndex = 0;
    if (sceneNumber) {
        const double v = sceneNumber->number;
        if (!sceneNumber->isNumber() || v < 0 || v != std::floor(v) || !scenes ||
            v >= double(scenes->items.size()))
            error = error.isEmpty() ? QStringLiteral("scene: must be the index of one of the scenes") : error;
        else
            sceneIndex = size_t(v);
    }
    const json::Value* sceneNodes =
        scenes && sceneIndex < scenes->items.size()
            ? part(scenes->items[sceneIndex], QStringLiteral("nodes"), K::Array,
                   json::appendIndex(QStringLiteral("scenes"), qsizetype(sceneIndex)), &error)
            : nullptr;
    if (!add.embedBinAsUri.isEmpty() && error.isEmpty() &&
        (!buffers || buffers->items.empty() || buffers->items[0].kind != K::Object ||
         buffers->items[0].find(QStringLiteral("uri"))))
        error = QStringLiteral("buffers[0]: the GLB's BIN chunk has no buffer without a uri");
    if (!error.isEmpty()) return r;

    const bool addCamera = add.camera.has_value();
    const int lightCount = int(add.lights.size());
    const std::vector<int> indices = gltfLightIndices(add.lights);
    const int iesCount = int(std::count_if(add.lights.begin(), add.lights.end(),
                                           [](const GltfLight& l) { return l.ies.has_value(); }));
    const int punctualCount = lightCount - iesCount;
    Edits rootEdits;
    // Nodes: drop references to the file's own lights, move camera indices, append ours.
    QList<QByteArray> nodeTexts;
    int dropped = 0;
    if (nodes)
        for (const json::Value& node : nodes->items) {
            Edits e;
            const json::Value* ext = node.find(QStringLiteral("extensions"));
            if (ext && ext->kind == K::Object && (ext->find(kExt) || ext->find(kIes))) {
                ++dropped; // the file's own lights, punctual or IES profiles, are replaced by the rig's
                Edits x;
                for (const QString& key : {kExt, kIes})
                    if (ext->find(key)) x.insert(key, std::nullopt);
                const bool alone = ext->members.size() == size_t(x.size());
                e.insert(QStringLiteral("extensions"),
                         alone ? std::nullopt : std::optional(editObject(s, *ext, x)));
            }
            const json::Value* camera = node.find(QStringLiteral("camera"));
            if (addCamera && camera && camera->isNumber())
                e.insert(QStringLiteral("camera"), json::formatNumber(camera->number + 1));
            nodeTexts << (e.isEmpty() ? raw(s, node) : editObject(s, node, e));
        }
    const int first = int(nodeTexts.size());
    QList<QByteArray> added;
    for (int i = 0; i < lightCount; ++i) {
        nodeTexts << text(add.lights[size_t(i)].nodeJson(indices[size_t(i)]));
        added << QByteArray::number(first + i);
    }
    if (addCamera) {
        nodeTexts << text(add.camera->nodeJson(0));
        added << QByteArray::number(first + lightCount);
    }
    if (!added.isEmpty() || dropped) rootEdits.insert(QStringLiteral("nodes"), joinArray(nodeTexts));
    if (dropped) r.notes << QStringLiteral("%1 node(s) no longer carry the model's own lights").arg(dropped);
    // The default scene lists the new nodes.
    if (!added.isEmpty()) {
        if (scenes && !scenes->items.empty()) {
            QList<QByteArray> list;
            if (sceneNodes)
                for (const json::Value& v : sceneNodes->items)
                    list << raw(s, v);
            list += added;
            QList<QByteArray> sceneTexts;
            for (size_t i = 0; i < scenes->items.size(); ++i)
                sceneTexts << (i == sceneIndex ? editObject(s, scenes->items[i],
                                                            {{QStringLiteral("nodes"), joinArray(list)}})
                                               : raw(s, scenes->items[i]));
            rootEdits.insert(QStringLiteral("scenes"), joinArray(sceneTexts));
        } else {
            rootEdits.insert(QStringLiteral("scenes"), "[{\"nodes\":" + joinArray(added) + "}]");
            rootEdits.insert(QStringLiteral("scene"), "0");
        }
    }
    if (addCamera) {
        QList<QByteArray> list{text(add.camera->cameraJson())};
        if (cameras)
            for (const json::Value& v : cameras->items)
                list << raw(s, v);
        rootEdits.insert(QStringLiteral("cameras"), joinArray(list));
    }
    // The extension: our lights replace the file's.
    const json::Value* oldExt = extensions ? extensions->find(kExt) : nullptr;
    const json::Value* oldLights =
        oldExt && oldExt->kind == K::Object ? oldExt->find(QStringLiteral("lights")) : nullptr;
    if (oldLights && oldLights->kind == K::Array)
        r.notes << QStringLiteral("the model's %1 light(s) replaced by the rig's %2")
                       .arg(oldLights->items.size())
                       .arg(lightCount);
    QJsonArray lights, profiles;
    for (const GltfLight& l : add.lights)
        l.ies ? profiles.append(l.ies->profileJson()) : lights.append(l.lightJson());
    const std::optional<QByteArray> ours =
        punctualCount ? std::optional(text(QJsonObject{{QStringLiteral("lights"), lights}})) : std::nullopt;
    const std::optional<QByteArray> oursIes =
        iesCount ? std::optional(text(QJsonObject{{QStringLiteral("lights"), profiles}})) : std::nullopt;
    const json::Value* oldIes = extensions ? extensions->find(kIes) : nullptr;
    if (extensions) {
        size_t left = (ours ? 1 : 0) + (oursIes ? 1 : 0);
        for (const json::Member& m : extensions->members)
            left += m.key != kExt && m.key != kIes;
        if (ours || oldExt || oursIes || oldIes)
            rootEdits.insert(
                QStringLiteral("extensions"),
                left == 0 ? std::nullopt
                          : std::optional(editObject(s, *extensions, {{kExt, ours}, {kIes, oursIes}})));
    } else if (ours || oursIes) {
        QList<QByteArray> members;
        if (ours) members << json::quote(kExt) + ":" + *ours;
        if (oursIes) members << json::quote(kIes) + ":" + *oursIes;
        rootEdits.insert(QStringLiteral("extensions"), "{" + members.join(',') + "}");
    }
    // extensionsUsed (and Required) name each extension exactly when lights of it are left.
    for (const auto& [array, key, keepPunctual, keepIes] :
         {std::tuple{used, QStringLiteral("extensionsUsed"), punctualCount > 0, iesCount > 0},
          std::tuple{required, QStringLiteral("extensionsRequired"), false, false}}) {
        QList<QByteArray> names;
        bool hadPunctual = false, hadIes = false;
        if (array)
            for (const json::Value& v : array->items) {
                const bool isExt = v.kind == K::String && v.string == kExt;
                const bool isIes = v.kind == K::String && v.string == kIes;
                hadPunctual = hadPunctual || isExt;
                hadIes = hadIes || isIes;
                if (!isExt && !isIes) names << raw(s, v);
            }
        if (keepPunctual) names << json::quote(kExt);
        if (keepIes) names << json::quote(kIes);
        if (hadPunctual != keepPunctual || hadIes != keepIes)
            rootEdits.insert(key, names.isEmpty() ? std::nullopt : std::optional(joinArray(names)));
    }
    // The note.
    if (!add.note.isEmpty()) {
        const json::Value* extras = root.find(QStringLiteral("extras"));
        const QByteArray note = text(add.note);
        if (!extras)
            rootEdits.insert(QStringLiteral("extras"), "{\"lightrig\":" + note + "}");
        else if (extras->kind == K::Object)
            rootEdits.insert(QStringLiteral("extras"),
                             editObject(s, *extras, {{QStringLiteral("lightrig"), note}}));
        else
            r.notes << QStringLiteral(
                "extras is not an object: the note (environment, ambient) is not written");
    }
    // Buffers and images: the BIN chunk as a data: URI, file URIs rebased to the output's folder.
    const bool rebase = !add.sourceFolder.isEmpty() && !add.outputFolder.isEmpty();
    int rebased = 0;
    for (const QString& key : {QStringLiteral("buffers"), QStringLiteral("images")}) {
        const json::Value* array = root.find(key);
        if (!array || array->kind != K::Array) continue;
        QList<QByteArray> list;
        bool changed = false;
        for (size_t i = 0; i < array->items.size(); ++i) {
            const json::Value& item = array->items[i];
            const json::Value* uri = item.kind == K::Object ? item.find(QStringLiteral("uri")) : nullptr;
            std::optional<QByteArray> value;
            if (key == QLatin1String("buffers") && i == 0 && !add.embedBinAsUri.isEmpty()) {
                const json::Value* length = item.find(QStringLiteral("byteLength"));
                const double n = length && length->isNumber() && length->number >= 0 ? length->number : 0.0;
                const QByteArray data =
                    add.embedBinAsUri.left(qsizetype(std::min(n, double(add.embedBinAsUri.size()))));
                value = "\"data:application/octet-stream;base64," + data.toBase64() + '"';
            } else if (rebase && uri && uri->kind == K::String) {
                QString problem;
                const QString moved = rebaseUri(uri->string, add.sourceFolder, add.outputFolder, &problem);
                if (!problem.isEmpty())
                    r.notes
                        << QStringLiteral("%1[%2].uri \"%3\": %4").arg(key).arg(i).arg(uri->string, problem);
                if (moved != uri->string) {
                    value = json::quote(moved);
                    ++rebased;
                }
            }
            changed = changed || value.has_value();
            list << (value ? editObject(s, item, {{QStringLiteral("uri"), *value}}) : raw(s, item));
        }
        if (changed) rootEdits.insert(key, joinArray(list));
    }
    if (rebased)
        r.notes
            << QStringLiteral("%1 file reference(s) rewritten relative to the output's folder").arg(rebased);
    r.json = editObject(s, root, rootEdits);
    return r;
}

} // namespace lr
