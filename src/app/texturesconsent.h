// The question asked when a model's textures were refused because they lie outside the model's folder
// (Model::texturesOutsideFolder, filled by the loader; the files exist there): "Load textures from outside
// the model's folder?" with Load / Don't load. Asked once per opened file, never remembered: DocumentFiles
// asks it through its askTexturesOutsideFolder hook (tests answer there without a modal box) and on Load
// imports the file again with ModelLoadOptions::allowTexturesOutsideFolder. Windows paths ("D:\...") are
// never in the list: they stay refused either way.
#pragma once

#include <QString>
#include <QStringList>

class QWidget;

namespace lr {

// The question's details: the model file and the refused references, the first `listed` of them one a
// line, then "and N more".
QString texturesOutsideFolderDetails(const QString& modelPath, const QStringList& references,
                                     int listed = 10);

// The default hook: a QMessageBox (parent may be null) with Load and Don't load, Don't load the default.
// True means load.
bool askLoadTexturesOutsideFolder(QWidget* parent, const QString& modelPath, const QStringList& references);

} // namespace lr
