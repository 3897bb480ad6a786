// Output files of the command line (`render`, `bench`): checked before any work starts, written atomically
// (QSaveFile: a failed or interrupted write leaves any previous file as it was). Errors name the file.
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace lr::cli {

// False with "cannot write PATH: the folder F does not exist" / "...: it is a folder".
bool checkOutputPath(const QString& path, QString* error);

bool writeFileAtomically(const QString& path, const QByteArray& data, QString* error);

// format: "png" or "jpeg" (quality 92, no alpha).
bool writeImageAtomically(const QImage& image, const QString& path, const QByteArray& format, QString* error);

} // namespace lr::cli
