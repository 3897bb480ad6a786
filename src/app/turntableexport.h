// "Export turntable" (issue 17) without freezing the editor: frame k of N is the screenshot (same offscreen
// path, size, supersampling and transparency: screenshotexport.h) with the camera turned k·360/N degrees
// about the up axis through the model's centre, or with the rig's lights turned and the camera kept
// (render/turntable.h). A window-modal QProgressDialog advances per tile and frame and has Cancel; the event
// loop runs between tiles and while a frame is written (atomically, on a worker thread), so the window
// keeps repainting. Each frame file is complete or not there: Cancel stops before the next one, and the
// result lists the frames already written.
#pragma once

#include "core/rig.h"
#include "scene/camera.h"

#include <QStringList>
#include <glm/vec3.hpp>

class QWidget;

namespace lr {

class MainWindow;
class Viewport;
struct TurntableOptions;

struct TurntableExportResult {
    QString error; // empty on success and when cancelled
    bool cancelled = false;
    QStringList written; // the frame files written, in order (all N on success)
    bool ok() const { return error.isEmpty() && !cancelled; }
};

// Renders and writes every frame of `rig` seen through `camera`, turning about +Y through `center`, with
// the progress dialog in front of `parent` (object name "turntableProgress", for tests).
TurntableExportResult exportTurntableWithProgress(QWidget* parent, Viewport* viewport, const Rig& rig,
                                                  const ViewCamera& camera, const glm::dvec3& center,
                                                  const TurntableOptions& options);

// File › Export turntable: the dialog, then the export of the window's rig and view; the outcome in the
// status bar (cancelled: how many frames were written) or an error box.
void exportTurntableInteractive(MainWindow* window);

} // namespace lr
