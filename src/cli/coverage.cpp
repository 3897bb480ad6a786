#include "coverage.h"

namespace lr::cli {

namespace {

// Pixels of the model seen through `camera`, from a small render with a transparent background (alpha is
// 0 where nothing was drawn); -1 when the render failed (*error says why).
int coveredPixels(OffscreenRenderer& gl, const ViewCamera& camera, QSize size, RenderSettings settings,
                  QString* error) {
    settings.transparentBackground = true;
    const QImage probe =
        gl.renderImage(camera, size.scaled(64, 64, Qt::KeepAspectRatio).expandedTo(QSize(1, 1)), settings, 1,
                       error)
            .convertToFormat(QImage::Format_RGBA8888);
    if (probe.isNull()) return -1;
    int covered = 0;
    for (int y = 0; y < probe.height(); ++y)
        for (int x = 0; x < probe.width(); ++x)
            covered += probe.constScanLine(y)[4 * x + 3] > 0 ? 1 : 0;
    return covered;
}

} // namespace

bool showsTheModel(OffscreenRenderer& gl, const QString& path, QSize size, const RenderSettings& settings,
                   bool viewChosenHere, LoadedScene* scene, const std::function<void(const QString&)>& warn,
                   QString* error) {
    const int covered = coveredPixels(gl, scene->camera, size, settings, error);
    if (covered < 0) return false;
    if (covered > 0) return true;
    const Bounds& bounds = scene->model->bounds;
    const double aspect = double(size.width()) / double(size.height());
    for (const QString& view : standardViewNames()) {
        const std::optional<ViewCamera> camera = standardView(view, bounds, aspect);
        if (!camera) continue;
        const int n = coveredPixels(gl, *camera, size, settings, error);
        if (n < 0) return false;
        if (n == 0) continue;
        if (viewChosenHere) {
            warn(QStringLiteral("%1 covers no pixel from %2; rendered from view %3 instead")
                     .arg(path, scene->cameraSource, view));
            scene->camera = *camera;
            scene->cameraSource = QStringLiteral("view ") + view;
        } else {
            warn(QStringLiteral("%1 covers no pixel from %2 (the image shows only the background; it is "
                                "visible from view %3)")
                     .arg(path, scene->cameraSource, view));
        }
        return true;
    }
    *error =
        QStringLiteral("nothing of %1 can be drawn: it covers no pixel from any view (its bounds run from "
                       "[%2, %3, %4] to [%5, %6, %7])")
            .arg(path)
            .arg(bounds.min.x, 0, 'g', 3)
            .arg(bounds.min.y, 0, 'g', 3)
            .arg(bounds.min.z, 0, 'g', 3)
            .arg(bounds.max.x, 0, 'g', 3)
            .arg(bounds.max.y, 0, 'g', 3)
            .arg(bounds.max.z, 0, 'g', 3);
    return false;
}

} // namespace lr::cli
