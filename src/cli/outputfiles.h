// Output files of the command line (`render`, `bench`): checked before any work starts, written atomically
// (core/atomicwrite.h, render/imagefile.h: a failed or interrupted write leaves any previous file as it
// was). Errors name the file and the system's reason: "cannot write o.png: no space left on device".
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>
#include <vector>

namespace lr {
struct Model;
}

namespace lr::cli {

// A file a command names, and what it is to the command ("the model", "the rig", "the --summary file").
struct NamedFile {
    QString path;
    QString role;
};

// Refuses, before anything is written, an output that is one of the command's inputs or another of its
// outputs (issue 41): "cannot write M.glb: it is the model M.glb, which this command reads". Files are
// compared by identity, not spelling: an existing file by device and inode (so a symbolic link, a hard
// link or "./x" names the same file), a new one by its folder's canonical path and its name. Every
// command that writes calls it: render, compare, export, bench.
bool checkDistinctFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                        QString* error);
// The texture files a model read (its Texture::name when that is a file), as inputs ("the model's texture"):
// known once it is imported, checked then against the images still to write.
std::vector<NamedFile> textureFilesOf(const Model& model);

// False with "cannot write PATH: the folder F does not exist" / "...: it is a folder".
bool checkOutputPath(const QString& path, QString* error);

bool writeOutputFile(const QString& path, const QByteArray& data, QString* error);

// Several files, all or none (issue 41): each is written atomically; when one fails, those already written
// get their previous bytes back (or are removed when they did not exist), so the command's exit 1 means
// that nothing was written. The error names the file that failed (and any that could not be restored).
struct OutputBytes {
    QString path;
    QByteArray bytes;
};
bool writeOutputFiles(const std::vector<OutputBytes>& files, QString* error);

// format: "png" or "jpeg" (quality 92, no alpha).
bool writeOutputImage(const QImage& image, const QString& path, const QByteArray& format, QString* error);

} // namespace lr::cli
