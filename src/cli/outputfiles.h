// Output files of the command line (`render`, `bench`): checked before any work starts, written atomically
// (core/atomicwrite.h, render/imagefile.h: a failed or interrupted write leaves any previous file as it
// was). Errors name the file and the system's reason: "cannot write o.png: no space left on device".
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace lr::cli {

// False with "cannot write PATH: the folder F does not exist" / "...: it is a folder".
bool checkOutputPath(const QString& path, QString* error);

bool writeOutputFile(const QString& path, const QByteArray& data, QString* error);

// format: "png" or "jpeg" (quality 92, no alpha).
bool writeOutputImage(const QImage& image, const QString& path, const QByteArray& format, QString* error);

} // namespace lr::cli
