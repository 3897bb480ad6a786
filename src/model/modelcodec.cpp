// Writing modelcodec.h's encoding (reading: modelcodec_read.cpp).
#include "modelcodec.h"

#include <QColorSpace>
#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>

namespace lr {

namespace {

static_assert(sizeof(Vertex) == 16 * sizeof(float), "Vertex is written as 16 raw floats");
static_assert(std::is_trivially_copyable_v<Vertex>);
static_assert(std::endian::native == std::endian::little || std::endian::native == std::endian::big);

// ---------------------------------------------------------------------------------------------- writing

// Counts what it is given and, with a sink, passes it on: small fields gathered in a buffer, large
// arrays (vertices, indices, texture rows) straight from the model without a copy.
class Writer {
  public:
    // `offset`: where in the encoding the first byte given to this writer lands (for pad()).
    Writer(const ModelSink* sink, std::size_t offset) : m_sink(sink), m_count(offset) {}
    void raw(const void* data, std::size_t size) {
        m_count += size;
        if (!m_sink || !m_ok) return;
        if (size >= kDirectBytes) {
            flush();
            m_ok = m_ok && (*m_sink)(static_cast<const char*>(data), size);
            return;
        }
        if (m_buffer.size() + qsizetype(size) > kBufferBytes) flush();
        m_buffer.append(static_cast<const char*>(data), qsizetype(size));
    }
    template <typename T> void pod(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        raw(&v, sizeof v);
    }
    void u8(bool b) { pod(quint8(b ? 1 : 0)); }
    void count(std::size_t n) { pod(quint64(n)); }
    void string(const QString& s) {
        const QByteArray utf8 = s.toUtf8();
        pod(quint32(utf8.size()));
        raw(utf8.constData(), std::size_t(utf8.size()));
    }
    template <typename E> void enumeration(E e) { pod(quint8(e)); }
    // Zeros up to the next multiple of `alignment` from the start of the encoding.
    void pad(std::size_t alignment) {
        static constexpr char kZeros[64] = {};
        for (std::size_t n = (alignment - m_count % alignment) % alignment; n > 0;) {
            const std::size_t chunk = std::min(n, sizeof kZeros);
            raw(kZeros, chunk);
            n -= chunk;
        }
    }
    std::size_t offset() const { return m_count; }
    bool finish() {
        flush();
        return m_ok;
    }

  private:
    static constexpr qsizetype kBufferBytes = 64 * 1024;
    static constexpr std::size_t kDirectBytes = 16 * 1024;
    void flush() {
        if (m_sink && m_ok && !m_buffer.isEmpty())
            m_ok = (*m_sink)(m_buffer.constData(), std::size_t(m_buffer.size()));
        m_buffer.clear();
    }
    const ModelSink* m_sink;
    QByteArray m_buffer;
    std::size_t m_count;
    bool m_ok = true;
};

void writeLight(Writer& w, const Light& l) {
    w.string(l.name);
    w.enumeration(l.type);
    w.u8(l.enabled);
    w.pod(l.color);
    w.pod(l.intensity);
    w.u8(l.temperature.has_value());
    w.pod(l.temperature.value_or(0.0));
    w.pod(l.position);
    w.pod(l.direction);
    w.enumeration(l.falloff.model);
    for (double d :
         {l.falloff.range, l.falloff.exponent, l.falloff.constant, l.falloff.linear, l.falloff.quadratic})
        w.pod(d);
    w.enumeration(l.cone.model);
    for (double d : {l.cone.inner, l.cone.outer, l.cone.exponent})
        w.pod(d);
    w.enumeration(l.diffuse);
    w.u8(l.specularIsColor);
    w.pod(l.specular);
    w.u8(l.ambient.has_value());
    w.pod(l.ambient.value_or(glm::dvec3(0.0)));
    w.pod(l.rimExponent);
    for (double d : {l.area.width, l.area.height, l.area.radius, l.area.roll})
        w.pod(d);
    w.u8(l.area.twoSided);
    // Linking and shaping (issues 38, 39), which a glTF's light nodes carry (model/gltflightextras.cpp).
    for (const PartSet* set : {&l.link.lit, &l.link.shadow})
        for (const QStringList* names : {&set->include, &set->exclude}) {
            w.count(std::size_t(names->size()));
            for (const QString& name : *names)
                w.string(name);
        }
    w.u8(l.ies.has_value());
    if (l.ies) {
        w.string(l.ies->file);
        w.string(l.ies->resolved);
        w.pod(l.ies->multiplier);
        w.u8(l.ies->level == IesLevel::Profile);
        w.pod(l.ies->rotation);
    }
    w.u8(l.gobo.has_value());
    if (l.gobo) {
        w.string(l.gobo->file);
        w.string(l.gobo->resolved);
        w.pod(l.gobo->scale);
        w.pod(l.gobo->rotation);
    }
    w.u8(l.barnDoors.has_value());
    if (l.barnDoors) {
        w.pod(l.barnDoors->angle);
        w.pod(l.barnDoors->length);
    }
}

// ---------------------------------------------------------------------------------------------- reading

void writeBody(Writer& w, const Model& m) {
    w.string(m.path);
    w.pod(m.origin);
    w.count(m.meshes.size());
    for (const Mesh& mesh : m.meshes) {
        w.string(mesh.name);
        w.string(mesh.node);
        w.count(mesh.vertices.size());
        w.raw(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex));
        w.count(mesh.indices.size());
        w.raw(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
        w.pod(qint32(mesh.material));
        w.u8(mesh.hasVertexColors);
        w.u8(mesh.hasTangents);
    }
    w.count(m.materials.size());
    for (const Material& mat : m.materials) {
        w.string(mat.name);
        w.pod(mat.baseColor);
        w.pod(qint32(mat.baseColorTexture));
        w.pod(qint32(mat.normalTexture));
        w.pod(qint32(mat.emissiveTexture));
        w.pod(mat.emissive);
        w.pod(mat.specular);
        w.pod(mat.shininess);
        w.u8(mat.doubleSided);
        w.u8(mat.pbr);
        w.pod(mat.metallic);
        w.pod(mat.roughness);
        w.pod(qint32(mat.metallicRoughnessTexture));
        w.pod(qint32(mat.occlusionTexture));
        w.pod(mat.occlusionStrength);
        w.pod(mat.normalScale);
        w.enumeration(mat.alphaMode);
        w.pod(mat.alphaCutoff);
        for (const TextureTransform* t : textureTransforms(mat)) {
            w.pod(t->offset);
            w.pod(t->rotation);
            w.pod(t->scale);
        }
        for (const TextureSampling* s : textureSamplings(mat)) {
            w.enumeration(s->wrapS);
            w.enumeration(s->wrapT);
            w.u8(s->nearestMagnification);
        }
        w.count(mat.extensions.size());
        for (const MaterialExtension& x : mat.extensions) {
            w.string(x.name);
            w.string(x.values);
        }
    }
    w.count(m.textures.size());
    for (const Texture& t : m.textures) {
        w.string(t.name);
        const QImage img = t.image.isNull() || t.image.format() == QImage::Format_RGBA8888
                               ? t.image
                               : t.image.convertToFormat(QImage::Format_RGBA8888);
        w.pod(quint32(img.width()));
        w.pod(quint32(img.height()));
        if (!img.isNull()) w.pad(kModelCodecPixelAlignment);
        const std::size_t rowBytes = std::size_t(img.width()) * 4;
        if (std::size_t(img.bytesPerLine()) == rowBytes)
            w.raw(img.constBits(), rowBytes * std::size_t(img.height()));
        else
            for (int y = 0; y < img.height(); ++y)
                w.raw(img.constScanLine(y), rowBytes);
        const QByteArray icc = img.isNull() ? QByteArray() : img.colorSpace().iccProfile();
        w.pod(quint32(icc.size()));
        w.raw(icc.constData(), std::size_t(icc.size()));
    }
    w.count(m.cameras.size());
    for (const Camera& c : m.cameras) {
        w.string(c.name);
        w.pod(c.position);
        w.pod(c.forward);
        w.pod(c.up);
        for (double d : {c.yfovDegrees, c.znear, c.zfar, c.aspect})
            w.pod(d);
    }
    w.string(m.lights.name);
    w.enumeration(m.lights.space);
    w.pod(m.lights.ambient);
    w.enumeration(m.lights.shading.model);
    w.enumeration(m.lights.shading.specular);
    w.enumeration(m.lights.shading.viewer);
    w.pod(m.lights.shading.shininess);
    w.count(m.lights.lights.size());
    for (const Light& l : m.lights.lights)
        writeLight(w, l);
    w.pod(m.bounds.min);
    w.pod(m.bounds.max);
    w.count(std::size_t(m.warnings.size()));
    for (const QString& s : m.warnings)
        w.string(s);
    w.count(std::size_t(m.texturesOutsideFolder.size()));
    for (const QString& s : m.texturesOutsideFolder)
        w.string(s);
    w.pod(m.loadMs);
}

void writeHeader(Writer& w, quint64 bodySize) {
    w.raw(kModelCodecMagic, sizeof kModelCodecMagic);
    w.pod(kModelCodecVersion);
    w.pod(kModelCodecByteOrderMark);
    w.pod(quint32(sizeof(Vertex)));
    w.pod(quint32(0));
    w.pod(bodySize);
}

} // namespace

std::size_t encodedModelSize(const Model& model) {
    Writer counter(nullptr, kModelCodecHeaderSize);
    writeBody(counter, model);
    return counter.offset();
}

bool writeModel(const Model& model, const ModelSink& sink) {
    Writer w(&sink, 0);
    writeHeader(w, encodedModelSize(model) - kModelCodecHeaderSize);
    writeBody(w, model);
    return w.finish();
}

QByteArray encodeModel(const Model& model) {
    QByteArray out;
    out.reserve(qsizetype(encodedModelSize(model)));
    writeModel(model, [&out](const char* data, std::size_t size) {
        out.append(data, qsizetype(size));
        return true;
    });
    return out;
}

} // namespace lr
