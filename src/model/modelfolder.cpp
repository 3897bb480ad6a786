#include "modelfolder.h"

#include "importbudget.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <assimp/IOStream.hpp>
#include <memory>

namespace lr::detail {

namespace {

bool isResourcePath(const QString& p) {
    return p.startsWith(QLatin1Char(':'));
}

// "C:/..." or "//server/..." written on Windows: absolute, and never inside a folder on this system.
bool isForeignAbsolute(const QString& p) {
    return (p.size() >= 3 && p[0].isLetter() && p[1] == QLatin1Char(':') && p[2] == QLatin1Char('/'));
}

class QtIOStream : public Assimp::IOStream {
  public:
    explicit QtIOStream(std::unique_ptr<QFile> file) : m_file(std::move(file)) {}
    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0 || count == 0) return 0;
        if (count > size_t(std::numeric_limits<qint64>::max()) / size) return 0;
        const qint64 want = qint64(size * count);
        const qint64 got = m_file->read(static_cast<char*>(buffer), want);
        return got > 0 ? size_t(got) / size : 0;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        qint64 base = 0;
        switch (origin) {
        case aiOrigin_SET:
            base = 0;
            break;
        case aiOrigin_CUR:
            base = m_file->pos();
            break;
        case aiOrigin_END:
            base = m_file->size();
            break;
        default:
            return aiReturn_FAILURE;
        }
        // Assimp passes negative relative offsets as wrapped size_t values.
        const qint64 target = base + qint64(offset);
        if (target < 0 || target > m_file->size()) return aiReturn_FAILURE;
        return m_file->seek(target) ? aiReturn_SUCCESS : aiReturn_FAILURE;
    }
    size_t Tell() const override { return size_t(m_file->pos()); }
    size_t FileSize() const override { return size_t(m_file->size()); }
    void Flush() override {}

  private:
    std::unique_ptr<QFile> m_file;
};

} // namespace

ModelFolder::ModelFolder(const QString& modelPath, bool allowOutside) : m_allowOutside(allowOutside) {
    const QFileInfo info(modelPath);
    m_file =
        isResourcePath(modelPath) ? QDir::cleanPath(modelPath) : QDir::cleanPath(info.absoluteFilePath());
    m_folder = QFileInfo(m_file).path();
    m_display = info.fileName();
    if (!isResourcePath(m_folder)) m_canonicalFolder = QFileInfo(m_folder).canonicalFilePath();
}

bool ModelFolder::isInside(const QString& cleanPath) const {
    const QString prefix = m_folder.endsWith(QLatin1Char('/')) ? m_folder : m_folder + QLatin1Char('/');
    if (!cleanPath.startsWith(prefix)) return false;
    // Symbolic links inside the folder must not lead out of it.
    if (!m_canonicalFolder.isEmpty() && !isResourcePath(cleanPath)) {
        const QString canonical = QFileInfo(cleanPath).canonicalFilePath();
        if (!canonical.isEmpty()) {
            const QString cprefix = m_canonicalFolder.endsWith(QLatin1Char('/'))
                                        ? m_canonicalFolder
                                        : m_canonicalFolder + QLatin1Char('/');
            return canonical.startsWith(cprefix);
        }
    }
    return true;
}

QString ModelFolder::resolve(const QString& reference, QString* refusal) const {
    QString ref = reference;
    ref.replace(QLatin1Char('\\'), QLatin1Char('/'));
    if (ref.startsWith(QLatin1String("file://"))) ref = ref.mid(7);
    const bool foreign = isForeignAbsolute(ref);
    const bool absolute = foreign || ref.startsWith(QLatin1Char('/')) || isResourcePath(ref);
    const QString clean = QDir::cleanPath(absolute ? ref : m_folder + QLatin1Char('/') + ref);
    if (clean == m_file) return clean;
    if (m_allowOutside ? !foreign : isInside(clean)) return clean;
    if (refusal) {
        *refusal = m_allowOutside ? QStringLiteral("%1 is a Windows path").arg(reference)
                                  : QStringLiteral("%1 lies outside the model's folder; not followed without "
                                                   "permission (allowTexturesOutsideFolder)")
                                        .arg(reference);
    }
    return {};
}

QString ModelFolder::refusedOutsideFile(const QString& reference) const {
    if (m_allowOutside || isResourcePath(m_file)) return {};
    const ModelFolder permissive(m_file, true);
    const QString path = permissive.resolve(reference, nullptr);
    return !path.isEmpty() && !isInside(path) && QFileInfo(path).isFile() ? path : QString();
}

QString QtIOSystem::resolveForAssimp(const char* file) const {
    if (!file) return {};
    QString refusal;
    const QString path = m_folder.resolve(QString::fromUtf8(file), &refusal);
    if (path.isEmpty()) {
        std::lock_guard lock(m_mutex);
        if (!m_refusals.contains(refusal)) m_refusals << refusal;
    }
    return path;
}

bool QtIOSystem::Exists(const char* file) const {
    const QString path = resolveForAssimp(file);
    return !path.isEmpty() && QFileInfo(path).isFile();
}

Assimp::IOStream* QtIOSystem::Open(const char* file, const char* mode) {
    if (!mode || std::string_view(mode).find_first_of("wa+") != std::string_view::npos) return nullptr;
    const QString path = resolveForAssimp(file);
    if (path.isEmpty()) return nullptr;
    auto qfile = std::make_unique<QFile>(path);
    if (!QFileInfo(path).isFile() || !qfile->open(QIODevice::ReadOnly)) return nullptr;
    noteImportInput(path); // the worker's budget grows with what is read (importbudget.h)
    return new QtIOStream(std::move(qfile));
}

void QtIOSystem::Close(Assimp::IOStream* stream) {
    delete stream;
}

bool QtIOSystem::ComparePaths(const char* one, const char* second) const {
    if (!one || !second) return false;
    const QString a = m_folder.resolve(QString::fromUtf8(one), nullptr);
    const QString b = m_folder.resolve(QString::fromUtf8(second), nullptr);
    return !a.isEmpty() && a == b;
}

QStringList QtIOSystem::refusals() const {
    std::lock_guard lock(m_mutex);
    return m_refusals;
}

} // namespace lr::detail
