#include "gbuffer.h"

namespace lr::render {

namespace {

QByteArray swizzle(int channel, int width) {
    return QByteArray("xyzw").mid(channel, width);
}

} // namespace

GBufferTexels encodeGBuffer(const lighting::Surface<float>& surface) {
    GBufferTexels t{};
    lighting::Surface<float> s = surface;
    for (const GBufferSlot& slot : kGBufferLayout) {
        const float* v = slot.field(s);
        for (int i = 0; i < slot.width; ++i)
            t[size_t(slot.target)][slot.channel + i] = v[i];
    }
    return t;
}

lighting::Surface<float> decodeGBuffer(const GBufferTexels& texels) {
    lighting::Surface<float> s;
    for (const GBufferSlot& slot : kGBufferLayout) {
        float* v = slot.field(s);
        for (int i = 0; i < slot.width; ++i)
            v[i] = texels[size_t(slot.target)][slot.channel + i];
    }
    return s;
}

QByteArray gbufferGlsl() {
    QByteArray params, args, encode, decode;
    for (int t = 0; t < kGBufferTargets; ++t) {
        params += (t ? ", out vec4 g" : "out vec4 g") + QByteArray::number(t);
        args += (t ? ", vec4 g" : "vec4 g") + QByteArray::number(t);
    }
    for (const GBufferSlot& slot : kGBufferLayout) {
        const QByteArray where =
            "g" + QByteArray::number(slot.target) + '.' + swizzle(slot.channel, slot.width);
        encode += "    " + where + " = s." + slot.member + ";\n";
        decode += "    s." + QByteArray(slot.member) + " = " + where + ";\n";
    }
    return "// The G-buffer codec, generated from src/render/gbuffer.h (kGBufferLayout).\n"
           "void encodeGBuffer(Surface s, " +
           params + ") {\n" + encode + "}\n\nSurface decodeGBuffer(" + args + ") {\n    Surface s;\n" +
           decode + "    return s;\n}\n";
}

void decodeGBufferImages(const FloatImage (&targets)[kGBufferTargets], const std::vector<float>& depth,
                         GBuffer* out) {
    const int w = targets[0].width, h = targets[0].height;
    for (FloatImage* f : {&out->position, &out->normal, &out->albedo, &out->specular, &out->emissive})
        *f = targets[0];
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float covered = depth[size_t(h - 1 - y) * size_t(w) + size_t(x)] < 1.0f;
            GBufferTexels texels;
            for (int t = 0; t < kGBufferTargets; ++t)
                texels[size_t(t)] = targets[t].at(x, y);
            const lighting::Surface<float> s = decodeGBuffer(texels);
            out->position.at(x, y) = glm::vec4(s.position, covered);
            out->normal.at(x, y) = glm::vec4(s.normal, covered);
            out->albedo.at(x, y) = glm::vec4(s.albedo, covered);
            out->specular.at(x, y) = glm::vec4(s.specular, s.shininess);
            out->emissive.at(x, y) = glm::vec4(s.emissive, covered);
        }
    }
}

lighting::Surface<double> surfaceAt(const GBuffer& g, int x, int y) {
    using V = glm::dvec3;
    lighting::Surface<double> s;
    s.position = V(g.position.at(x, y));
    s.normal = V(g.normal.at(x, y));
    s.albedo = V(g.albedo.at(x, y));
    s.specular = V(g.specular.at(x, y));
    s.shininess = g.specular.at(x, y).w;
    s.emissive = V(g.emissive.at(x, y));
    return s;
}

} // namespace lr::render
