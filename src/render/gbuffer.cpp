#include "gbuffer.h"

namespace lr::render {

namespace {

QByteArray swizzle(int channel, int width) {
    return QByteArray("xyzw").mid(channel, width);
}

} // namespace

GBufferTexels encodeGBuffer(const lighting::Surface<float>& surface, ShadingModel model) {
    GBufferTexels t{};
    lighting::Surface<float> s = surface;
    for (const GBufferSlot& slot : kGBufferLayout) {
        if (!usedUnder(slot, model)) continue;
        const float* v = slot.field(s);
        for (int i = 0; i < slot.width; ++i)
            t[size_t(slot.target)][slot.channel + i] = v[i];
    }
    return t;
}

lighting::Surface<float> decodeGBuffer(const GBufferTexels& texels, ShadingModel model) {
    lighting::Surface<float> s;
    for (const GBufferSlot& slot : kGBufferLayout) {
        if (!usedUnder(slot, model)) continue;
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
        // A slot of one shading model only is wrapped, so the other's program text is what it was.
        const QByteArray open = slot.use == GBufferUse::Pbr       ? "#ifdef LR_PBR\n"
                                : slot.use == GBufferUse::Classic ? "#ifndef LR_PBR\n"
                                                                  : "";
        const QByteArray close = open.isEmpty() ? "" : "#endif\n";
        encode += open + "    " + where + " = s." + slot.member + ";\n" + close;
        decode += open + "    s." + QByteArray(slot.member) + " = " + where + ";\n" + close;
    }
    return "// The G-buffer codec, generated from src/render/gbuffer.h (kGBufferLayout).\n"
           "void encodeGBuffer(Surface s, " +
           params + ") {\n" + encode + "}\n\nSurface decodeGBuffer(" + args + ") {\n    Surface s;\n" +
           decode + "    return s;\n}\n";
}

void decodeGBufferImages(const FloatImage (&targets)[kGBufferTargets], const std::vector<float>& depth,
                         ShadingModel model, GBuffer* out) {
    const int w = targets[0].width, h = targets[0].height;
    const bool pbr = model == ShadingModel::Pbr;
    out->shading = model;
    for (FloatImage* f : {&out->position, &out->normal, &out->albedo, &out->specular, &out->emissive})
        *f = targets[0];
    out->material = pbr ? targets[0] : FloatImage();
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float covered = depth[size_t(h - 1 - y) * size_t(w) + size_t(x)] < 1.0f;
            GBufferTexels texels;
            for (int t = 0; t < kGBufferTargets; ++t)
                texels[size_t(t)] = targets[t].at(x, y);
            const lighting::Surface<float> s = decodeGBuffer(texels, model);
            out->position.at(x, y) = glm::vec4(s.position, covered);
            out->normal.at(x, y) = glm::vec4(s.normal, covered);
            out->albedo.at(x, y) = glm::vec4(s.albedo, covered);
            out->specular.at(x, y) = glm::vec4(s.specular, s.shininess);
            out->emissive.at(x, y) = glm::vec4(s.emissive, covered);
            if (pbr) out->material.at(x, y) = glm::vec4(s.metallic, s.roughness, s.occlusion, covered);
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
    if (g.shading == ShadingModel::Pbr && !g.material.isNull()) {
        const glm::vec4 m = g.material.at(x, y);
        s.metallic = m.x, s.roughness = m.y, s.occlusion = m.z;
    }
    return s;
}

} // namespace lr::render
