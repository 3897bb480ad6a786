#include "outputfiles.h"

#include "core/atomicwrite.h"
#include "model/model.h"
#include "render/imagefile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <sys/stat.h>

namespace lr::cli {

namespace {

bool cannotWrite(const QString& path, const QString& reason, QString* error) {
    *error = QStringLiteral("cannot write %1: %2").arg(path, reason);
    return false;
}

// What names one file: "inode DEV:INO" for an existing one (stat follows links), else the canonical path
// of its folder and its name (a new file has no inode yet; two spellings of one folder still agree).
QString fileIdentity(const QString& path) {
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) == 0)
        return QStringLiteral("inode %1:%2").arg(qulonglong(st.st_dev)).arg(qulonglong(st.st_ino));
    const QFileInfo info(path);
    QString folder = info.absoluteDir().canonicalPath();
    if (folder.isEmpty()) folder = QDir::cleanPath(info.absolutePath());
    return folder + QLatin1Char('/') + info.fileName();
}

} // namespace

bool checkDistinctFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                        QString* error) {
    std::vector<QString> inputIds, outputIds;
    for (const NamedFile& f : inputs)
        inputIds.push_back(f.path.isEmpty() ? QString() : fileIdentity(f.path));
    for (size_t o = 0; o < outputs.size(); ++o) {
        const NamedFile& out = outputs[o];
        const QString id = fileIdentity(out.path);
        for (size_t i = 0; i < inputs.size(); ++i)
            if (!inputIds[i].isEmpty() && inputIds[i] == id)
                return cannotWrite(out.path,
                                   QStringLiteral("it is %1 %2, which this command reads")
                                       .arg(inputs[i].role, inputs[i].path),
                                   error);
        for (size_t earlier = 0; earlier < o; ++earlier)
            if (outputIds[earlier] == id)
                return cannotWrite(out.path,
                                   QStringLiteral("it is also %1 %2; each output needs a file of its own")
                                       .arg(outputs[earlier].role, outputs[earlier].path),
                                   error);
        outputIds.push_back(id);
    }
    return true;
}

std::vector<NamedFile> textureFilesOf(const Model& model) {
    std::vector<NamedFile> files;
    for (const Texture& t : model.textures)
        if (!t.name.isEmpty() && !t.name.startsWith(QLatin1Char('*')) &&
            !t.name.startsWith(QLatin1String("data:"), Qt::CaseInsensitive) && QFileInfo(t.name).isFile())
            files.push_back({t.name, QStringLiteral("the model's texture")});
    return files;
}

bool checkOutputPath(const QString& path, QString* error) {
    const QFileInfo info(path);
    if (!info.absoluteDir().exists())
        return cannotWrite(path, QStringLiteral("the folder %1 does not exist").arg(info.absolutePath()),
                           error);
    if (info.isDir()) return cannotWrite(path, QStringLiteral("it is a folder"), error);
    return true;
}

bool writeOutputFile(const QString& path, const QByteArray& data, QString* error) {
    const QString reason = writeFileAtomically(path, data);
    return reason.isEmpty() || cannotWrite(path, reason, error);
}

bool writeOutputFiles(const std::vector<OutputBytes>& files, QString* error) {
    struct Previous {
        bool existed = false;
        QByteArray bytes;
    };
    std::vector<Previous> previous;
    for (const OutputBytes& f : files) {
        Previous p;
        QFile file(f.path);
        p.existed = file.exists();
        if (p.existed &&
            (!file.open(QIODevice::ReadOnly) || (p.bytes = file.readAll()).size() != file.size()))
            return cannotWrite(f.path, QStringLiteral("its previous contents cannot be read to keep them"),
                               error);
        previous.push_back(p);
    }
    for (size_t i = 0; i < files.size(); ++i) {
        if (writeOutputFile(files[i].path, files[i].bytes, error)) continue;
        QStringList lost;
        for (size_t k = 0; k < i; ++k) {
            const bool restored = previous[k].existed
                                      ? writeFileAtomically(files[k].path, previous[k].bytes).isEmpty()
                                      : QFile::remove(files[k].path);
            if (!restored) lost << files[k].path;
        }
        if (!lost.isEmpty())
            *error += QStringLiteral(" (and %1 could not be put back as it was)")
                          .arg(lost.join(QStringLiteral(", ")));
        return false;
    }
    return true;
}

bool writeOutputImage(const QImage& image, const QString& path, const QByteArray& format, QString* error) {
    const QString reason = writeImageAtomically(image, path, format);
    return reason.isEmpty() || cannotWrite(path, reason, error);
}

} // namespace lr::cli
