// Batch catalogs of `lightrig render` (issue 17): the items of one call (models × rigs × views × turntable
// frames), their deterministic output names and the machine-readable summary (JSON lines).
//   -o FOLDER (or ending in /)  FOLDER/{model}_{rig}_{view}.png, with _#### before .png for a turntable
//   -o PATTERN                  {model}: the model file's base name, {rig}: the rig file's ("default"
//                               without --rig), {view}: the view ("front", "camera0"; "default" without
//                               --view); the last run of # in the file name: the frame number
// Two items that would write one file are a usage error, as is a turntable of N > 1 frames without #.
#pragma once

#include "renderrun.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

namespace lr::cli {

QString modelName(const RenderRequest& request, int model); // {model}
QString rigName(const RenderRequest& request, int rig);     // {rig}
QString viewName(const RenderRequest& request, int view);   // {view}

// Every item in render order (models, then rigs, views, frames), or nullopt and a usage error message.
std::optional<std::vector<RenderItem>> planRender(const RenderRequest& request, QString* usageError);

// One summary line (JSON, no newline): {"file", "model", "rig", "view", ["frame",] "status": "ok" |
// "failed", "seconds", "error": null | "reason"}; model and rig as given (rig null for the default rule).
// `extra`: more members (a path-traced image's "samples", "noise", "stopped_by").
QByteArray summaryLine(const RenderRequest& request, const RenderItem& item, bool ok, double seconds,
                       const QString& error, const QJsonObject& extra = {});

} // namespace lr::cli
