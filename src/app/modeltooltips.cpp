#include "modeltooltips.h"

#include <QCoreApplication>
#include <QEvent>
#include <array>

namespace lr {

namespace {
// One entry per model, in enum order. The formulas and sources are those of docs/lighting-models.md.
constexpr std::array kFalloff{
    QT_TRANSLATE_NOOP("ModelTooltips", "none: no distance falloff, the light is as bright at any distance."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "range-power: (1 − d/range)^exponent, fading to 0 at the range. From the HLSL shader "
                      "book, chapter 5 (design document 000, §5.1.2)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "inverse-polynomial: 1/(constant + linear·d + quadratic·d²), Direct3D's attenuation, "
                      "optionally faded out smoothly at a range. From the Direct3D 11 point light sample "
                      "(design document 001)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "range-quadratic: 1 − (d/range)², bright near the light and 0 at the range. From the "
                      "DirectX tutorial \"Lighting-3\" (design document 003)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "inverse-square: the physical 1/d², with glTF's smooth window when a range is given. "
                      "From glTF KHR_lights_punctual (as in Filament and UE4)."),
};
constexpr std::array kCone{
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "angle-power: (1 − angle/outer)^exponent, fading with the angle from the axis to 0 at "
                      "the outer angle. From the HLSL shader book (design document 000, §5.2.4)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "smooth: full inside the inner angle, fading between the inner and outer angles' "
                      "cosines (to the exponent). From the Direct3D 11 spot light sample (design document "
                      "001), as in Direct3D and glTF."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "hard: fully lit inside the outer angle, unlit outside, a sharp edge. From the DirectX "
                      "tutorial \"Lighting-3\" (design document 003)."),
};
constexpr std::array kDiffuse{
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "lambert: N·L clamped to 0..1, so surfaces turned away from the light are dark. From "
                      "design documents 000, 003 and 004."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "half-lambert: (N·L/2 + 1/2)², wrapping light past the terminator so the dark side "
                      "still gets some. From the Direct3D 11 sample (design document 001)."),
};
constexpr std::array kSpecular{
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "phong: highlight (R·V)^shininess, R the light reflected about the normal. From the "
                      "HLSL shader book (design document 000)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "blinn-phong: highlight (N·H)^shininess, H halfway between the light and the viewer: a "
                      "broader highlight than Phong's. From the Direct3D 8 SDK (design document 004)."),
};
constexpr std::array kViewer{
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "local: the view vector is computed per pixel towards the eye (accurate). From the "
                      "Direct3D 8 SDK (design document 004)."),
    QT_TRANSLATE_NOOP("ModelTooltips",
                      "infinite: one view vector (+Z in view space) for every pixel, cheaper but less "
                      "accurate (Direct3D's LOCALVIEWER = FALSE, design document 004)."),
};
static_assert(kFalloff.size() == size_t(enumCount<FalloffModel>()));
static_assert(kCone.size() == size_t(enumCount<ConeModel>()));
static_assert(kDiffuse.size() == size_t(enumCount<DiffuseModel>()));
static_assert(kSpecular.size() == size_t(enumCount<SpecularModel>()));
static_assert(kViewer.size() == size_t(enumCount<ViewerModel>()));

template <typename Table> QString entry(const Table& table, int i) {
    return i >= 0 && size_t(i) < table.size() ? QCoreApplication::translate("ModelTooltips", table[size_t(i)])
                                              : QString();
}
} // namespace

namespace {
class CurrentItemTooltip : public QObject {
  public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::ToolTip) {
            auto* combo = static_cast<QComboBox*>(watched);
            combo->setToolTip(combo->currentData(Qt::ToolTipRole).toString());
        }
        return false; // the combo shows it as usual
    }
};
} // namespace

void followCurrentItemTooltip(QComboBox* combo) {
    combo->installEventFilter(new CurrentItemTooltip(combo));
    combo->setToolTip(combo->currentData(Qt::ToolTipRole).toString());
}

QString modelTooltip(FalloffModel model) {
    return entry(kFalloff, int(model));
}
QString modelTooltip(ConeModel model) {
    return entry(kCone, int(model));
}
QString modelTooltip(DiffuseModel model) {
    return entry(kDiffuse, int(model));
}
QString modelTooltip(SpecularModel model) {
    return entry(kSpecular, int(model));
}
QString modelTooltip(ViewerModel model) {
    return entry(kViewer, int(model));
}

} // namespace lr
