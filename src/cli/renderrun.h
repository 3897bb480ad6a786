// `lightrig render` after parsing (render.cpp): every model × rig × view (× turntable frame) of one call,
// rendered in that order with one OpenGL context (or, with --quality path, traced on the CPU with no OpenGL:
// rendertraced.h); each model imported once, each rig loaded once per model.
// Items that fail (a model that does not import, a rig that does not read, a camera out of range, an
// output that cannot be written) are reported and skipped; the rest still render (issue 17).
#pragma once

#include "rendertraced.h"
#include "sceneoptions.h"

#include "render/turntable.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <vector>

namespace lr::cli {

struct RenderRequest {
    QStringList models;   // as given
    QStringList rigs;     // --rig, as given; empty: the default rule (core/defaultrig.h)
    SceneOptions options; // options.views: --view list (empty: the model's camera 0, else three-quarter)
    QString output;       // -o: a file, a pattern with {model} {rig} {view} and #, or a folder
    bool outputIsFolder = false;
    QByteArray format = "png"; // "png", "jpeg" or "exr" (scene-linear)
    bool aovs = false;         // --aovs: the exr holds every layer (scene/renderlayersexr.h)
    bool half = false;         // --half: the exr's values as 16-bit floats
    int supersample = 1;
    int msaa = 4;
    bool transparent = false;
    int timedFrames = 0; // hidden --frames N
    int turntable = 0;   // --turntable N: frames; 0 none
    TurntableRotation rotate = TurntableRotation::Camera;
    QString summary;            // --summary: empty none, "-" stdout, else a file
    TracedRenderOptions traced; // with options.pathTraced: every image path traced on the CPU, no OpenGL
};

// One image of the call (catalog.h plans them).
struct RenderItem {
    int model = 0;  // index into RenderRequest::models
    int rig = -1;   // index into rigs; -1: the default rule
    int view = -1;  // index into options.views; -1: the default camera (or --camera-index)
    int frame = -1; // turntable frame; -1: not a turntable
    QString file;
};

// Renders the items (catalog.h's planRender: models, rigs and views in runs); the exit code: 0 all written,
// 1 any item failed (each said on stderr and in the summary). Usage errors come before, in render.cpp.
int runRenderRequest(const RenderRequest& request, const std::vector<RenderItem>& items);

} // namespace lr::cli
