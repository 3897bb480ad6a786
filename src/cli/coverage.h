// Never an empty image in silence (issue 18): a model at scale 1e38, or seen through a broken camera,
// rendered as the background alone with exit 0. Before `render` writes a view it checks, on a small probe,
// that the model covers some pixel (render.cpp's items, renderrun.cpp).
#pragma once

#include "sceneoptions.h"

#include "render/offscreen.h"

#include <QSize>
#include <QString>
#include <functional>

namespace lr::cli {

// True when the model covers some pixel from scene->camera. When it covers none, a view chosen by the
// program (viewChosenHere: no --view or --camera-index) moves to the first standard view that shows it,
// with a warning; a view the user chose is kept, with a warning; and when no view shows anything, false
// with the reason ("nothing of PATH can be drawn ..."), as when a probe render fails.
bool showsTheModel(OffscreenRenderer& gl, const QString& modelPath, QSize size,
                   const RenderSettings& settings, bool viewChosenHere, LoadedScene* scene,
                   const std::function<void(const QString&)>& warn, QString* error);

} // namespace lr::cli
