// Reading modelcodec.h's encoding without trusting it (writing: modelcodec.cpp).
#include "modelcodec.h"

#include <QColorSpace>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace lr {

namespace {

// The fewest bytes each part takes (empty strings and arrays): counts are checked against them.
constexpr std::size_t kMinMeshBytes = 4 + 4 + 8 + 8 + 4 + 1 + 1; // name, node, ...
constexpr std::size_t kMinMaterialBytes =
    4 + 16 + 3 * 4 + 12 + 12 + 4 + 1 + 1 + 2 * 4 + 2 * 4 + 2 * 4 + 1 + 4 + 5 * 20 + 5 * 3 + 8;
constexpr std::size_t kMinExtensionBytes = 4 + 4; // two empty strings
constexpr std::size_t kMinTextureBytes = 4 + 4 + 4 + 4;
constexpr std::size_t kMinCameraBytes = 4 + 3 * 24 + 4 * 8;
constexpr std::size_t kMinLightBytes = 4 + 1 + 1 + 24 + 8 + 1 + 8 + 24 + 24 + 1 + 5 * 8 + 1 + 3 * 8 + 1 + 1 +
                                       24 + 1 + 24 + 8 + 4 * 8 + 1 + 4 * 8 + 3;

bool finiteBits(float f) {
    return (std::bit_cast<quint32>(f) & 0x7f800000u) != 0x7f800000u;
}
template <int N, typename T, glm::qualifier Q> bool finite(const glm::vec<N, T, Q>& v) {
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

class Reader {
  public:
    // `origin`: the start of the encoding (alignment is counted from there); `lend`: may be empty.
    Reader(const char* origin, const char* begin, const char* end, const ModelCodecLimits& limits,
           const ImageLender& lend)
        : m_origin(origin), m_p(begin), m_end(end), m_limits(limits), m_lend(lend) {}

    bool failed() const { return !m_error.isEmpty(); }
    const QString& error() const { return m_error; }
    std::size_t remaining() const { return std::size_t(m_end - m_p); }
    bool fail(const QString& what) {
        if (m_error.isEmpty()) m_error = what;
        return false;
    }
    bool need(std::size_t n, const QString& what) {
        if (failed()) return false;
        if (n > remaining()) return fail(QStringLiteral("truncated in %1").arg(what));
        return true;
    }
    bool raw(void* out, std::size_t n, const QString& what) {
        if (!need(n, what)) return false;
        if (n) std::memcpy(out, m_p, n);
        m_p += n;
        return true;
    }
    template <typename T> bool pod(T& out, const QString& what) { return raw(&out, sizeof out, what); }
    // A finite double, float or glm vector of them.
    template <typename T> bool number(T& out, const QString& what) {
        if (!pod(out, what)) return false;
        bool ok;
        if constexpr (std::is_floating_point_v<T>)
            ok = std::isfinite(out);
        else
            ok = finite(out);
        return ok || fail(QStringLiteral("%1 is not finite").arg(what));
    }
    bool flag(bool& out, const QString& what) {
        quint8 v = 0;
        if (!pod(v, what)) return false;
        if (v > 1) return fail(QStringLiteral("%1 is not 0 or 1").arg(what));
        out = v == 1;
        return true;
    }
    template <typename E> bool enumeration(E& out, const QString& what) {
        quint8 v = 0;
        if (!pod(v, what)) return false;
        if (v >= enumCount<E>()) return fail(QStringLiteral("%1 out of range (%2)").arg(what).arg(v));
        out = E(v);
        return true;
    }
    // A count of elements that take at least `minBytes` each: no more than the remaining bytes hold.
    bool count(std::size_t& out, std::size_t minBytes, const QString& what) {
        quint64 n = 0;
        if (!pod(n, what + QStringLiteral(" count"))) return false;
        if (n > remaining() / std::max<std::size_t>(minBytes, 1))
            return fail(
                QStringLiteral("%1 count %2 exceeds the %3 bytes left").arg(what).arg(n).arg(remaining()));
        out = std::size_t(n);
        return true;
    }
    bool string(QString& out, const QString& what) {
        quint32 n = 0;
        if (!pod(n, what)) return false;
        if (qint64(n) > m_limits.maxStringBytes)
            return fail(QStringLiteral("%1 is too long (%2 bytes)").arg(what).arg(n));
        if (!need(n, what)) return false;
        out = QString::fromUtf8(m_p, qsizetype(n));
        m_p += n;
        return true;
    }
    bool image(QImage& out, const QString& what) {
        quint32 w = 0, h = 0;
        if (!pod(w, what) || !pod(h, what)) return false;
        if (w == 0 && h == 0) {
            out = QImage();
            return colorSpace(out, what);
        }
        const auto side = quint32(m_limits.maxImageSide);
        if (w == 0 || h == 0 || w > side || h > side)
            return fail(QStringLiteral("%1 has a bad size %2x%3").arg(what).arg(w).arg(h));
        if (!padding(kModelCodecPixelAlignment, what)) return false;
        const std::size_t rowBytes = std::size_t(w) * 4;
        if (!need(rowBytes * h, what)) return false;
        QImageCleanupFunction cleanup = nullptr;
        void* cleanupInfo = nullptr;
        if (m_lend && m_lend(m_p, rowBytes * h, &cleanup, &cleanupInfo)) {
            out = QImage(reinterpret_cast<const uchar*>(m_p), int(w), int(h), qsizetype(rowBytes),
                         QImage::Format_RGBA8888, cleanup, cleanupInfo);
            m_p += rowBytes * h;
            return colorSpace(out, what);
        }
        out = QImage(int(w), int(h), QImage::Format_RGBA8888);
        if (out.isNull())
            return fail(QStringLiteral("%1: no memory for a %2x%3 image").arg(what).arg(w).arg(h));
        for (quint32 y = 0; y < h; ++y) {
            std::memcpy(out.scanLine(int(y)), m_p, rowBytes);
            m_p += rowBytes;
        }
        return colorSpace(out, what);
    }
    // Zeros up to the next multiple of `alignment` from the start of the encoding.
    bool padding(std::size_t alignment, const QString& what) {
        const std::size_t n = (alignment - std::size_t(m_p - m_origin) % alignment) % alignment;
        if (!need(n, what)) return false;
        for (std::size_t i = 0; i < n; ++i)
            if (m_p[i] != 0) return fail(QStringLiteral("%1: padding is not zero").arg(what));
        m_p += n;
        return true;
    }
    // The image's colour space as an ICC profile (empty: none); Qt's ICC parser rejects bad profiles.
    bool colorSpace(QImage& image, const QString& what) {
        quint32 n = 0;
        if (!pod(n, what + QStringLiteral(" colour space"))) return false;
        if (n == 0) return true;
        if (qint64(n) > m_limits.maxIccBytes || image.isNull())
            return fail(QStringLiteral("%1 has a bad colour space size (%2 bytes)").arg(what).arg(n));
        if (!need(n, what + QStringLiteral(" colour space"))) return false;
        const QColorSpace space = QColorSpace::fromIccProfile(QByteArray(m_p, qsizetype(n)));
        m_p += n;
        if (!space.isValid()) return fail(QStringLiteral("%1 has an invalid colour space").arg(what));
        image.setColorSpace(space);
        return true;
    }
    bool vertices(std::vector<Vertex>& out, const QString& what) {
        std::size_t n = 0;
        if (!count(n, sizeof(Vertex), what)) return false;
        out.resize(n);
        if (!raw(out.data(), n * sizeof(Vertex), what)) return false;
        constexpr std::size_t kFloats = sizeof(Vertex) / sizeof(float);
        for (std::size_t i = 0; i < n; ++i) {
            float f[kFloats];
            std::memcpy(f, &out[i], sizeof f);
            bool ok = true;
            for (float x : f)
                ok &= finiteBits(x);
            if (!ok) return fail(QStringLiteral("%1: vertex %2 is not finite").arg(what).arg(i));
        }
        return true;
    }
    bool indices(std::vector<std::uint32_t>& out, std::size_t vertexCount, const QString& what) {
        std::size_t n = 0;
        if (!count(n, sizeof(std::uint32_t), what)) return false;
        if (n % 3) return fail(QStringLiteral("%1: %2 indices is not whole triangles").arg(what).arg(n));
        out.resize(n);
        if (!raw(out.data(), n * sizeof(std::uint32_t), what)) return false;
        std::uint32_t largest = 0;
        for (std::uint32_t i : out)
            largest = std::max(largest, i);
        if (n && largest >= vertexCount)
            return fail(QStringLiteral("%1: index %2 out of range (%3 vertices)")
                            .arg(what)
                            .arg(largest)
                            .arg(vertexCount));
        return true;
    }

  private:
    const char* m_origin;
    const char* m_p;
    const char* m_end;
    const ModelCodecLimits& m_limits;
    const ImageLender& m_lend;
    QString m_error;
};

// Light::link, ies, gobo and barnDoors (issues 38, 39).
bool readShaping(Reader& r, Light& l, const QString& at) {
    const auto f = [&](const char* field) { return QStringLiteral("%1 %2").arg(at, QLatin1String(field)); };
    for (PartSet* set : {&l.link.lit, &l.link.shadow})
        for (QStringList* names : {&set->include, &set->exclude}) {
            std::size_t n = 0;
            if (!r.count(n, 4, f("link names"))) return false;
            for (std::size_t i = 0; i < n; ++i) {
                QString name;
                if (!r.string(name, f("link name"))) return false;
                *names << name;
            }
        }
    bool has = false, profileLevel = false;
    if (!r.flag(has, f("ies"))) return false;
    if (has) {
        IesSpec s;
        if (!(r.string(s.file, f("ies file")) && r.string(s.resolved, f("ies file")) &&
              r.number(s.multiplier, f("ies multiplier")) && r.flag(profileLevel, f("ies level")) &&
              r.number(s.rotation, f("ies rotation"))))
            return false;
        s.level = profileLevel ? IesLevel::Profile : IesLevel::Light;
        l.ies = s;
    }
    if (!r.flag(has, f("gobo"))) return false;
    if (has) {
        GoboSpec g;
        if (!(r.string(g.file, f("gobo file")) && r.string(g.resolved, f("gobo file")) &&
              r.number(g.scale, f("gobo scale")) && r.number(g.rotation, f("gobo rotation"))))
            return false;
        l.gobo = g;
    }
    if (!r.flag(has, f("barn doors"))) return false;
    if (has) {
        BarnDoors b;
        if (!(r.number(b.angle, f("barn doors")) && r.number(b.length, f("barn doors")))) return false;
        l.barnDoors = b;
    }
    return true;
}

bool readLight(Reader& r, Light& l, const QString& at) {
    const auto f = [&](const char* field) { return QStringLiteral("%1 %2").arg(at, QLatin1String(field)); };
    bool hasTemperature = false, hasAmbient = false;
    double temperature = 0.0;
    glm::dvec3 ambient(0.0);
    const bool ok =
        r.string(l.name, f("name")) && r.enumeration(l.type, f("type")) && r.flag(l.enabled, f("enabled")) &&
        r.number(l.color, f("color")) && r.number(l.intensity, f("intensity")) &&
        r.flag(hasTemperature, f("temperature")) && r.number(temperature, f("temperature")) &&
        r.number(l.position, f("position")) && r.number(l.direction, f("direction")) &&
        r.enumeration(l.falloff.model, f("falloff")) && r.number(l.falloff.range, f("range")) &&
        r.number(l.falloff.exponent, f("falloff exponent")) && r.number(l.falloff.constant, f("constant")) &&
        r.number(l.falloff.linear, f("linear")) && r.number(l.falloff.quadratic, f("quadratic")) &&
        r.enumeration(l.cone.model, f("cone")) && r.number(l.cone.inner, f("cone inner")) &&
        r.number(l.cone.outer, f("cone outer")) && r.number(l.cone.exponent, f("cone exponent")) &&
        r.enumeration(l.diffuse, f("diffuse")) && r.flag(l.specularIsColor, f("specular kind")) &&
        r.number(l.specular, f("specular")) && r.flag(hasAmbient, f("ambient")) &&
        r.number(ambient, f("ambient")) && r.number(l.rimExponent, f("rim exponent"));
    if (!ok) return false;
    AreaShape& a = l.area;
    if (!(r.number(a.width, f("area width")) && r.number(a.height, f("area height")) &&
          r.number(a.radius, f("area radius")) && r.number(a.roll, f("area roll")) &&
          r.flag(a.twoSided, f("two-sided"))))
        return false;
    if (hasTemperature) l.temperature = temperature;
    if (hasAmbient) l.ambient = ambient;
    return readShaping(r, l, at);
}

bool readModel(Reader& r, Model& m) {
    const auto at = [](const char* what, std::size_t i) {
        return QStringLiteral("%1 %2").arg(QLatin1String(what)).arg(i);
    };
    if (!r.string(m.path, QStringLiteral("path")) || !r.number(m.origin, QStringLiteral("origin")))
        return false;

    std::size_t n = 0;
    if (!r.count(n, kMinMeshBytes, QStringLiteral("meshes"))) return false;
    m.meshes.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Mesh& mesh = m.meshes[i];
        const QString where = at("mesh", i);
        if (!r.string(mesh.name, where + QStringLiteral(" name")) ||
            !r.string(mesh.node, where + QStringLiteral(" node")) ||
            !r.vertices(mesh.vertices, where + QStringLiteral(" vertices")) ||
            !r.indices(mesh.indices, mesh.vertices.size(), where + QStringLiteral(" indices")) ||
            !r.pod(mesh.material, where + QStringLiteral(" material")) ||
            !r.flag(mesh.hasVertexColors, where + QStringLiteral(" vertex colours")) ||
            !r.flag(mesh.hasTangents, where + QStringLiteral(" tangents")))
            return false;
    }

    if (!r.count(n, kMinMaterialBytes, QStringLiteral("materials"))) return false;
    m.materials.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Material& mat = m.materials[i];
        const QString where = at("material", i);
        quint8 doubleSided = 0;
        if (!r.string(mat.name, where + QStringLiteral(" name")) ||
            !r.number(mat.baseColor, where + QStringLiteral(" base colour")) ||
            !r.pod(mat.baseColorTexture, where + QStringLiteral(" base colour texture")) ||
            !r.pod(mat.normalTexture, where + QStringLiteral(" normal texture")) ||
            !r.pod(mat.emissiveTexture, where + QStringLiteral(" emissive texture")) ||
            !r.number(mat.emissive, where + QStringLiteral(" emissive")) ||
            !r.number(mat.specular, where + QStringLiteral(" specular")) ||
            !r.number(mat.shininess, where + QStringLiteral(" shininess")) ||
            !r.pod(doubleSided, where + QStringLiteral(" double-sided")))
            return false;
        if (doubleSided > 1) return r.fail(where + QStringLiteral(" double-sided is not 0 or 1"));
        mat.doubleSided = doubleSided == 1;
        if (!r.flag(mat.pbr, where + QStringLiteral(" pbr")) ||
            !r.number(mat.metallic, where + QStringLiteral(" metallic")) ||
            !r.number(mat.roughness, where + QStringLiteral(" roughness")) ||
            !r.pod(mat.metallicRoughnessTexture, where + QStringLiteral(" metallic-roughness texture")) ||
            !r.pod(mat.occlusionTexture, where + QStringLiteral(" occlusion texture")) ||
            !r.number(mat.occlusionStrength, where + QStringLiteral(" occlusion strength")) ||
            !r.number(mat.normalScale, where + QStringLiteral(" normal scale")) ||
            !r.enumeration(mat.alphaMode, where + QStringLiteral(" alpha mode")) ||
            !r.number(mat.alphaCutoff, where + QStringLiteral(" alpha cutoff")))
            return false;
        for (TextureTransform* t : textureTransforms(mat))
            if (!r.number(t->offset, where + QStringLiteral(" texture offset")) ||
                !r.number(t->rotation, where + QStringLiteral(" texture rotation")) ||
                !r.number(t->scale, where + QStringLiteral(" texture scale")))
                return false;
        for (TextureSampling* s : textureSamplings(mat))
            if (!r.enumeration(s->wrapS, where + QStringLiteral(" texture wrap S")) ||
                !r.enumeration(s->wrapT, where + QStringLiteral(" texture wrap T")) ||
                !r.flag(s->nearestMagnification, where + QStringLiteral(" texture magnification")))
                return false;
        std::size_t extensions = 0;
        if (!r.count(extensions, kMinExtensionBytes, where + QStringLiteral(" extensions"))) return false;
        if (extensions > std::size_t(kMaxMaterialExtensions))
            return r.fail(QStringLiteral("%1 lists %2 extensions (at most %3)")
                              .arg(where)
                              .arg(extensions)
                              .arg(kMaxMaterialExtensions));
        mat.extensions.resize(extensions);
        for (MaterialExtension& x : mat.extensions)
            if (!r.string(x.name, where + QStringLiteral(" extension name")) ||
                !r.string(x.values, where + QStringLiteral(" extension values")))
                return false;
        // The importer clamps these (materials_pbr.cpp); the renderer may rely on it.
        for (auto [value, name] : {std::pair{mat.metallic, "metallic"}, std::pair{mat.roughness, "roughness"},
                                   std::pair{mat.occlusionStrength, "occlusion strength"},
                                   std::pair{mat.alphaCutoff, "alpha cutoff"}})
            if (!(value >= 0.0f && value <= 1.0f))
                return r.fail(
                    QStringLiteral("%1 %2 %3 is outside [0, 1]").arg(where, QLatin1String(name)).arg(value));
    }

    if (!r.count(n, kMinTextureBytes, QStringLiteral("textures"))) return false;
    m.textures.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const QString where = at("texture", i);
        if (!r.string(m.textures[i].name, where + QStringLiteral(" name")) ||
            !r.image(m.textures[i].image, where))
            return false;
    }

    if (!r.count(n, kMinCameraBytes, QStringLiteral("cameras"))) return false;
    m.cameras.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Camera& c = m.cameras[i];
        const QString where = at("camera", i);
        if (!r.string(c.name, where + QStringLiteral(" name")) ||
            !r.number(c.position, where + QStringLiteral(" position")) ||
            !r.number(c.forward, where + QStringLiteral(" forward")) ||
            !r.number(c.up, where + QStringLiteral(" up")) ||
            !r.number(c.yfovDegrees, where + QStringLiteral(" yfov")) ||
            !r.number(c.znear, where + QStringLiteral(" znear")) ||
            !r.number(c.zfar, where + QStringLiteral(" zfar")) ||
            !r.number(c.aspect, where + QStringLiteral(" aspect")))
            return false;
    }

    Rig& rig = m.lights;
    if (!r.string(rig.name, QStringLiteral("rig name")) ||
        !r.enumeration(rig.space, QStringLiteral("rig space")) ||
        !r.number(rig.ambient, QStringLiteral("rig ambient")) ||
        !r.enumeration(rig.shading.model, QStringLiteral("rig shading model")) ||
        !r.enumeration(rig.shading.specular, QStringLiteral("rig specular model")) ||
        !r.enumeration(rig.shading.viewer, QStringLiteral("rig viewer model")) ||
        !r.number(rig.shading.shininess, QStringLiteral("rig shininess")) ||
        !r.count(n, kMinLightBytes, QStringLiteral("lights")))
        return false;
    rig.lights.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        if (!readLight(r, rig.lights[i], at("light", i))) return false;

    if (!r.number(m.bounds.min, QStringLiteral("bounds")) ||
        !r.number(m.bounds.max, QStringLiteral("bounds")) || !r.count(n, 4, QStringLiteral("warnings")))
        return false;
    m.warnings.reserve(qsizetype(n));
    for (std::size_t i = 0; i < n; ++i) {
        QString w;
        if (!r.string(w, at("warning", i))) return false;
        m.warnings << w;
    }
    if (!r.count(n, 4, QStringLiteral("textures outside the folder"))) return false;
    m.texturesOutsideFolder.reserve(qsizetype(n));
    for (std::size_t i = 0; i < n; ++i) {
        QString t;
        if (!r.string(t, at("texture outside the folder", i))) return false;
        m.texturesOutsideFolder << t;
    }
    if (!r.number(m.loadMs, QStringLiteral("load time"))) return false;
    if (r.remaining())
        return r.fail(QStringLiteral("%1 unexpected bytes after the model").arg(r.remaining()));

    // References between the parts.
    for (std::size_t i = 0; i < m.meshes.size(); ++i)
        if (m.meshes[i].material < 0 || std::size_t(m.meshes[i].material) >= m.materials.size())
            return r.fail(QStringLiteral("mesh %1: material %2 out of range (%3 materials)")
                              .arg(i)
                              .arg(m.meshes[i].material)
                              .arg(m.materials.size()));
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
        const Material& mat = m.materials[i];
        for (int t : textureReferences(mat))
            if (t < -1 || (t >= 0 && std::size_t(t) >= m.textures.size()) ||
                (t >= 0 && m.textures[std::size_t(t)].image.isNull()))
                return r.fail(QStringLiteral("material %1: texture %2 out of range or empty (%3 textures)")
                                  .arg(i)
                                  .arg(t)
                                  .arg(m.textures.size()));
    }
    return true;
}

template <typename T> T readHeaderField(const char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

} // namespace

qint64 modelBodySize(QByteArrayView header, QString* error) {
    const auto bad = [&](const QString& why) {
        if (error) *error = why;
        return qint64(-1);
    };
    if (header.size() < kModelCodecHeaderSize) return bad(QStringLiteral("truncated header"));
    const char* p = header.data();
    if (std::memcmp(p, kModelCodecMagic, sizeof kModelCodecMagic) != 0)
        return bad(QStringLiteral("not a LightRig model"));
    if (readHeaderField<quint32>(p + 12) != kModelCodecByteOrderMark)
        return bad(QStringLiteral("wrong byte order"));
    if (const quint32 v = readHeaderField<quint32>(p + 8); v != kModelCodecVersion)
        return bad(QStringLiteral("version %1, expected %2").arg(v).arg(kModelCodecVersion));
    if (readHeaderField<quint32>(p + 16) != sizeof(Vertex)) return bad(QStringLiteral("wrong vertex size"));
    if (readHeaderField<quint32>(p + 20) != 0) return bad(QStringLiteral("bad reserved header field"));
    const quint64 body = readHeaderField<quint64>(p + 24);
    if (body > quint64(std::numeric_limits<qint64>::max() / 2)) return bad(QStringLiteral("bad body size"));
    return qint64(body);
}

std::shared_ptr<Model> decodeModel(QByteArrayView bytes, QString* error, const ModelCodecLimits& limits,
                                   const ImageLender& lend) {
    const auto bad = [&](const QString& why) {
        if (error) *error = why;
        return std::shared_ptr<Model>();
    };
    QString why;
    const qint64 body = modelBodySize(bytes, &why);
    if (body < 0) return bad(why);
    if (body != bytes.size() - kModelCodecHeaderSize)
        return bad(QStringLiteral("body is %1 bytes, header says %2")
                       .arg(bytes.size() - kModelCodecHeaderSize)
                       .arg(body));
    try {
        auto model = std::make_shared<Model>();
        Reader r(bytes.data(), bytes.data() + kModelCodecHeaderSize, bytes.data() + bytes.size(), limits,
                 lend);
        if (!readModel(r, *model)) return bad(r.error());
        return model;
    } catch (const std::bad_alloc&) {
        return bad(QStringLiteral("out of memory while decoding"));
    }
}

} // namespace lr
