// Assimp materials -> Material, and the textures they use decoded into RGBA8888 QImages: embedded
// ("*N" or by file name, compressed or raw aiTexel), data URIs, and files beside the model. The
// physically based values (metal-rough factors, occlusion, alpha mode, texture transforms, or their
// conversion from specular/shininess) are read in materials_pbr.cpp.
#include "importbudget.h"
#include "importdetail.h"

#include <QByteArray>
#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QImageReader>
#include <QThread>
#include <QThreadPool>

#include <QUrl>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/texture.h>
#include <cmath>
#include <memory>

namespace lr::detail {

namespace {

constexpr qint64 kMaxRawTexels = qint64(16384) * 16384;

float finiteOr(float v, float fallback) {
    return std::isfinite(v) ? v : fallback;
}

// Resolves the textures materials refer to while they are converted (load), then decodes them all at
// once on a thread pool (finish): large PNG/JPEG textures dominate the load time of glTF models.
class TextureLoader {
  public:
    TextureLoader(const aiScene* scene, const ModelFolder& folder, qint64 maxDataUriBytes, Model& model)
        : m_scene(scene), m_folder(folder), m_maxDataUri(maxDataUriBytes), m_model(model) {}

    // A provisional texture index for the material's first texture of `type`, or -1 (see finish).
    int load(const aiMaterial* mat, aiTextureType type, const char* role) {
        aiString path;
        if (mat->GetTextureCount(type) == 0 || mat->GetTexture(type, 0, &path) != AI_SUCCESS ||
            path.length == 0)
            return -1;
        const QString ref = QString::fromUtf8(path.C_Str());
        if (const auto cached = m_byRef.constFind(ref); cached != m_byRef.constEnd()) return *cached;
        Job job;
        job.ref = job.name = ref;
        job.role = QLatin1String(role);
        if ((job.embedded = m_scene->GetEmbeddedTexture(path.C_Str()))) {
            job.kind = Job::Embedded;
        } else if (ref.startsWith(QLatin1Char('*'))) {
            job.problem = QStringLiteral("no such embedded texture");
        } else if (ref.startsWith(QLatin1String("data:"), Qt::CaseInsensitive)) {
            job.kind = Job::DataUri;
        } else {
            job.name = locate(ref, &job.problem);
            if (const auto same = m_byFile.constFind(job.name);
                !job.name.isEmpty() && same != m_byFile.constEnd()) {
                m_byRef.insert(ref, *same);
                return *same;
            }
            if (!job.name.isEmpty()) {
                job.kind = Job::File;
                m_byFile.insert(job.name, int(m_jobs.size()));
            }
        }
        m_byRef.insert(ref, int(m_jobs.size()));
        m_jobs.push_back(std::move(job));
        return int(m_jobs.size()) - 1;
    }

    // Decodes every texture, fills model.textures and rewrites the materials' provisional indices;
    // textures that cannot be decoded become -1 with a warning.
    void finish() {
        if (m_jobs.size() == 1) {
            decode(m_jobs.front());
        } else if (m_jobs.size() > 1) {
            QThreadPool pool;
            pool.setMaxThreadCount(std::clamp(QThread::idealThreadCount(), 1, int(m_jobs.size())));
            std::vector<std::unique_ptr<QRunnable>> tasks;
            for (Job& job : m_jobs) {
                tasks.emplace_back(QRunnable::create([this, &job] { decode(job); }));
                tasks.back()->setAutoDelete(false);
                pool.start(tasks.back().get());
            }
            // This thread decodes what no pool thread has begun: all of it when no thread could start
            // (a thread's stack is refused under a low address-space limit), where waiting would hang.
            for (const std::unique_ptr<QRunnable>& task : tasks)
                if (pool.tryTake(task.get())) task->run();
            pool.waitForDone();
        }
        std::vector<int> remap(m_jobs.size(), -1);
        for (std::size_t i = 0; i < m_jobs.size(); ++i) {
            Job& job = m_jobs[i];
            if (job.image.isNull()) {
                m_model.warnings << QStringLiteral("%1: %2 texture %3: %4 (not used)")
                                        .arg(m_folder.displayName(), job.role, job.ref, job.problem);
                continue;
            }
            remap[i] = int(m_model.textures.size());
            m_model.textures.push_back({job.name, std::move(job.image)});
        }
        for (Material& m : m_model.materials)
            for (int* t : {&m.baseColorTexture, &m.normalTexture, &m.emissiveTexture,
                           &m.metallicRoughnessTexture, &m.occlusionTexture})
                *t = *t >= 0 && *t < int(remap.size()) ? remap[size_t(*t)] : -1;
    }

  private:
    struct Job {
        enum Kind { None, Embedded, DataUri, File } kind = None;
        QString ref, name, role, problem;
        const aiTexture* embedded = nullptr;
        QImage image;
    };

    // Runs on a pool thread: reads only the scene and the job.
    void decode(Job& job) const {
        switch (job.kind) {
        case Job::None:
            return;
        case Job::Embedded:
            job.image = decodeEmbedded(job.embedded, &job.problem);
            break;
        case Job::DataUri:
            job.image = decodeDataUri(job.ref, &job.problem);
            break;
        case Job::File:
            job.image = readFile(job.name, &job.problem);
            break;
        }
        if (!job.image.isNull()) job.image = std::move(job.image).convertToFormat(QImage::Format_RGBA8888);
        if (job.image.isNull() && job.problem.isEmpty()) job.problem = QStringLiteral("out of memory");
    }

    static QImage decodeEmbedded(const aiTexture* tex, QString* problem) {
        if (!tex->pcData) {
            *problem = QStringLiteral("embedded texture without data");
            return {};
        }
        if (tex->mHeight == 0) { // compressed file bytes (PNG, JPEG, ...), mWidth of them
            QImage image = QImage::fromData(reinterpret_cast<const uchar*>(tex->pcData), int(tex->mWidth));
            if (image.isNull()) *problem = QStringLiteral("could not decode the embedded image");
            return image;
        }
        if (qint64(tex->mWidth) * tex->mHeight > kMaxRawTexels) {
            *problem = QStringLiteral("embedded image of %1x%2 texels is too large")
                           .arg(tex->mWidth)
                           .arg(tex->mHeight);
            return {};
        }
        QImage image(int(tex->mWidth), int(tex->mHeight), QImage::Format_RGBA8888);
        if (image.isNull()) {
            *problem = QStringLiteral("out of memory");
            return {};
        }
        for (unsigned y = 0; y < tex->mHeight; ++y) {
            uchar* line = image.scanLine(int(y));
            const aiTexel* texel = tex->pcData + std::size_t(y) * tex->mWidth;
            for (unsigned x = 0; x < tex->mWidth; ++x, ++texel) {
                line[4 * x + 0] = texel->r;
                line[4 * x + 1] = texel->g;
                line[4 * x + 2] = texel->b;
                line[4 * x + 3] = texel->a;
            }
        }
        return image;
    }

    QImage decodeDataUri(const QString& ref, QString* problem) const {
        if (ref.size() > m_maxDataUri) {
            *problem = QStringLiteral("data URI of %1 bytes exceeds the limit of %2")
                           .arg(ref.size())
                           .arg(m_maxDataUri);
            return {};
        }
        const qsizetype comma = ref.indexOf(QLatin1Char(','));
        if (comma < 0) {
            *problem = QStringLiteral("malformed data URI");
            return {};
        }
        const QString header = ref.left(comma);
        const QByteArray payload = ref.mid(comma + 1).toLatin1();
        const QByteArray bytes = header.endsWith(QLatin1String(";base64"), Qt::CaseInsensitive)
                                     ? QByteArray::fromBase64(payload)
                                     : QByteArray::fromPercentEncoding(payload);
        QImage image = QImage::fromData(bytes);
        if (image.isNull()) *problem = QStringLiteral("could not decode the data URI image");
        return image;
    }

    // A readable file for `ref`, trying it as written, percent-decoded, then with another letter case.
    QString findFile(const QString& ref, QString* refusal) {
        QStringList tries{ref};
        const QString decoded = QUrl::fromPercentEncoding(ref.toUtf8());
        if (decoded != ref) tries << decoded;
        for (const QString& t : tries) {
            const QString path = m_folder.resolve(t, refusal);
            if (path.isEmpty()) continue;
            if (QFileInfo(path).isFile()) return path;
            // Files written on Windows or macOS often differ from their references only in case.
            const QFileInfo info(path);
            const QDir dir = info.dir();
            if (!dir.exists()) continue;
            for (const QString& entry : dir.entryList(QDir::Files))
                if (entry.compare(info.fileName(), Qt::CaseInsensitive) == 0) return dir.filePath(entry);
        }
        return {};
    }

    // The file a reference names, or empty with *problem set.
    QString locate(const QString& ref, QString* problem) {
        QString refusal;
        const QString path = findFile(ref, &refusal);
        if (!path.isEmpty()) return path;
        if (refusal.isEmpty()) {
            *problem = QStringLiteral("file not found");
            return {};
        }
        // Not followed; a file of that name beside the model is a safe and common stand-in.
        QString base = ref;
        base.replace(QLatin1Char('\\'), QLatin1Char('/'));
        base = base.section(QLatin1Char('/'), -1);
        QString ignored;
        const QString local = base.isEmpty() ? QString() : findFile(base, &ignored);
        if (local.isEmpty()) {
            *problem = QStringLiteral("refused: %1").arg(refusal);
            const QString decoded = QUrl::fromPercentEncoding(ref.toUtf8());
            if (!m_folder.refusedOutsideFile(ref).isEmpty() ||
                !m_folder.refusedOutsideFile(decoded).isEmpty())
                m_model.texturesOutsideFolder << ref;
            return {};
        }
        m_model.warnings << QStringLiteral("%1: texture %2: %3; using %4 from the model's folder instead")
                                .arg(m_folder.displayName(), ref, refusal, base);
        return local;
    }

    static QImage readFile(const QString& path, QString* problem) {
        noteImportInput(path); // the worker's budget grows with what is read (importbudget.h)
        QImageReader reader(path);
        reader.setAutoTransform(false);
        QImage image = reader.read();
        if (image.isNull()) *problem = reader.errorString();
        return image;
    }

    const aiScene* m_scene;
    const ModelFolder& m_folder;
    qint64 m_maxDataUri;
    Model& m_model;
    QHash<QString, int> m_byRef, m_byFile;
    std::vector<Job> m_jobs;
};

TextureWrap wrapOf(int mode) {
    switch (mode) {
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal:
        return TextureWrap::ClampToEdge;
    case aiTextureMapMode_Mirror:
        return TextureWrap::MirroredRepeat;
    default:
        return TextureWrap::Repeat;
    }
}

// The texture's sampler: wrap modes as Assimp maps them (glTF's sampler, OBJ's -clamp, ...), and glTF's
// magnification filter (9728 NEAREST; Assimp 5.2.5 stores the sampler's value as it is).
TextureSampling samplingOf(const aiMaterial* am, aiTextureType type) {
    TextureSampling s;
    int mode = aiTextureMapMode_Wrap;
    if (am->Get(AI_MATKEY_MAPPINGMODE_U(type, 0), mode) == AI_SUCCESS) s.wrapS = wrapOf(mode);
    if (am->Get(AI_MATKEY_MAPPINGMODE_V(type, 0), mode) == AI_SUCCESS) s.wrapT = wrapOf(mode);
    int mag = 0;
    if (am->Get(AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, 0), mag) == AI_SUCCESS)
        s.nearestMagnification = mag == 9728;
    return s;
}

// The texture reference of one role: its transform and sampling.
struct RoleOut {
    TextureTransform* transform;
    TextureSampling* sampling;
};

// Loads the material's first texture of the first of `types` it has, for one role: -1 with a warning when
// it reads a UV set other than 0 (meshes carry only TEXCOORD_0); `out` gets its UV transform and sampling.
int loadRole(const aiMaterial* am, std::initializer_list<aiTextureType> types, const char* role,
             TextureLoader& textures, const MaterialContext& ctx, RoleOut out) {
    for (aiTextureType type : types) {
        if (am->GetTextureCount(type) == 0) continue;
        int uvSet = 0;
        if (am->Get(AI_MATKEY_UVWSRC(type, 0), uvSet) == AI_SUCCESS && uvSet != 0) {
            ctx.warn(QStringLiteral("%1 texture reads UV set %2; only UV set 0 is supported (not used)")
                         .arg(QLatin1String(role))
                         .arg(uvSet));
            return -1;
        }
        const int index = textures.load(am, type, role);
        if (index < 0) continue;
        aiUVTransform uv;
        if (am->Get(_AI_MATKEY_UVTRANSFORM_BASE, int(type), 0, uv) == AI_SUCCESS)
            *out.transform = textureTransformFromAssimp(uv, QLatin1String(role), ctx);
        *out.sampling = samplingOf(am, type);
        return index;
    }
    return -1;
}

Material convert(const aiMaterial* am, TextureLoader& textures, const MaterialContext& baseCtx,
                 std::size_t index) {
    Material m;
    aiString name;
    if (am->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = QString::fromUtf8(name.C_Str());
    MaterialContext ctx = baseCtx;
    ctx.label = m.name.isEmpty() ? QStringLiteral("material %1").arg(index)
                                 : QStringLiteral("material \"%1\"").arg(m.name);

    aiColor4D c;
    if (am->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS || am->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
        m.baseColor = glm::vec4(c.r, c.g, c.b, c.a);
        float opacity = 1.0f;
        if (am->Get(AI_MATKEY_BASE_COLOR, c) != AI_SUCCESS &&
            am->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS)
            m.baseColor.a = opacity;
    }
    for (int i = 0; i < 3; ++i)
        m.baseColor[i] = std::max(finiteOr(m.baseColor[i], 1.0f), 0.0f);
    m.baseColor.a = std::clamp(finiteOr(m.baseColor.a, 1.0f), 0.0f, 1.0f);
    m.baseColorTexture = loadRole(am, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}, "base colour",
                                  textures, ctx, {&m.baseColorTransform, &m.baseColorSampling});
    m.normalTexture = loadRole(am, {aiTextureType_NORMALS}, "normal", textures, ctx,
                               {&m.normalTransform, &m.normalSampling});

    aiColor3D e(0.0f, 0.0f, 0.0f);
    if (am->Get(AI_MATKEY_COLOR_EMISSIVE, e) == AI_SUCCESS) {
        float strength = 1.0f;
        if (am->Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) != AI_SUCCESS) strength = 1.0f;
        for (int i = 0; i < 3; ++i)
            m.emissive[i] = std::max(finiteOr(e[unsigned(i)] * strength, 0.0f), 0.0f);
    }
    m.emissiveTexture = loadRole(am, {aiTextureType_EMISSIVE, aiTextureType_EMISSION_COLOR}, "emissive",
                                 textures, ctx, {&m.emissiveTransform, &m.emissiveSampling});

    aiColor3D s(1.0f, 1.0f, 1.0f);
    if (am->Get(AI_MATKEY_COLOR_SPECULAR, s) == AI_SUCCESS) {
        float strength = 1.0f;
        if (am->Get(AI_MATKEY_SHININESS_STRENGTH, strength) != AI_SUCCESS || !(strength >= 0.0f))
            strength = 1.0f;
        for (int i = 0; i < 3; ++i)
            m.specular[i] = std::max(finiteOr(s[unsigned(i)] * strength, 1.0f), 0.0f);
    }
    float shininess = 0.0f;
    if (am->Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess) && shininess > 0.0f)
        m.shininess = std::min(shininess, 1e4f);

    int twoSided = 0;
    if (am->Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) m.doubleSided = twoSided != 0;

    // glTF's packed metallicRoughness texture is UNKNOWN (Assimp 5.2.5 also lists it as METALNESS and
    // DIFFUSE_ROUGHNESS); other importers put textures they do not understand there. Other formats'
    // separate single-channel metallic and roughness maps do not fit the packed layout.
    if (ctx.source == MaterialSource::Gltf)
        m.metallicRoughnessTexture =
            loadRole(am, {aiTextureType_UNKNOWN}, "metallic-roughness", textures, ctx,
                     {&m.metallicRoughnessTransform, &m.metallicRoughnessSampling});
    else if (am->GetTextureCount(aiTextureType_METALNESS) ||
             am->GetTextureCount(aiTextureType_DIFFUSE_ROUGHNESS))
        ctx.warn(QStringLiteral("separate metallic and roughness maps are not supported (not used)"));
    // glTF's occlusion arrives as LIGHTMAP; AMBIENT_OCCLUSION is where FBX and others put theirs.
    m.occlusionTexture = loadRole(am,
                                  ctx.source == MaterialSource::Gltf
                                      ? std::initializer_list<aiTextureType>{aiTextureType_LIGHTMAP}
                                      : std::initializer_list<aiTextureType>{aiTextureType_AMBIENT_OCCLUSION},
                                  "occlusion", textures, ctx, {&m.occlusionTransform, &m.occlusionSampling});
    readPhysicalValues(am, ctx, m);
    return m;
}

} // namespace

void convertMaterials(const aiScene* scene, const ModelFolder& folder, qint64 maxDataUriBytes,
                      MaterialSource source, const QByteArray& gltfJson, Model& model) {
    TextureLoader textures(scene, folder, maxDataUriBytes, model);
    MaterialContext ctx{folder.displayName(), {}, source, &model.warnings, {}};
    if (source == MaterialSource::Gltf) ctx.gltfExtras = readGltfMaterialExtras(gltfJson);
    for (unsigned i = 0; i < scene->mNumMaterials && scene->mMaterials; ++i)
        model.materials.push_back(scene->mMaterials[i] ? convert(scene->mMaterials[i], textures, ctx, i)
                                                       : Material{});
    textures.finish();
    bool needDefault = model.materials.empty();
    for (Mesh& mesh : model.meshes) {
        if (mesh.material < 0 || mesh.material >= int(model.materials.size())) {
            mesh.material = int(model.materials.size());
            needDefault = true;
        }
    }
    if (needDefault) {
        Material grey;
        grey.name = QStringLiteral("default");
        grey.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        model.materials.push_back(grey);
    }
}

} // namespace lr::detail
