#include "renderexr.h"

#include "model/exrencode.h"
#include "scene/renderlayersexr.h"

namespace lr::cli {

QByteArray encodeRenderExr(const RenderLayers& layers, bool aovs, bool half, const RenderSettings& settings,
                           const QString& quality, std::optional<int> samples, QString* error) {
    std::vector<std::pair<QString, QString>> attributes{
        {QStringLiteral("lightrig/quality"), quality},
        {QStringLiteral("lightrig/exposureEV"), QString::number(settings.exposureEV)},
        {QStringLiteral("lightrig/toneMap"), toString(settings.toneMap)}};
    if (samples) attributes.push_back({QStringLiteral("lightrig/samples"), QString::number(*samples)});
    const ExrPixel pixel = half ? ExrPixel::Half : ExrPixel::Float;
    if (aovs) return encodeRenderLayersExr(layers, attributes, pixel, error);
    RenderLayers beauty;
    beauty.beauty = layers.beauty;
    return encodeRenderLayersExr(beauty, attributes, pixel, error);
}

} // namespace lr::cli
