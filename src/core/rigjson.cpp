// Rig files on disk and the built-in presets. The format itself: rigjson_read.cpp (reader, validation),
// rigjson_write.cpp (canonical writer), rigjson_json.* (strict JSON), docs/rig-format.md.
#include "rigjson.h"

#include "atomicwrite.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QtDebug>
#include <glm/geometric.hpp>

// The presets are compiled into lightrig_core (a static library); make sure their resource is registered
// even where the linker did not keep the automatic initialiser. Registering twice is harmless.
static void initPresetResources() {
    Q_INIT_RESOURCE(lightrig_presets);
}

namespace lr {

namespace {

RigReadResult fileError(const QString& file, const QString& reason) {
    RigReadResult r;
    r.errors << QStringLiteral("%1: %2").arg(file, reason);
    return r;
}

QString tooLarge(qint64 bytes) {
    return QStringLiteral("the file is %1 bytes; rig files are limited to %2 MiB")
        .arg(bytes)
        .arg(kMaxRigFileBytes / (1024 * 1024));
}

const QString kPresetDir = QStringLiteral(":/resources/presets");

// Used only if the embedded default preset were missing or broken (a build problem, reported loudly).
Rig fallbackRig() {
    Rig rig;
    rig.name = QStringLiteral("Fallback");
    rig.space = RigSpace::Model;
    rig.ambient = glm::dvec3(0.03);
    Light key = makeLight(LightType::Directional, QStringLiteral("Key"));
    key.direction = glm::normalize(glm::dvec3(-1.0, -1.0, -1.0));
    Light fill = makeLight(LightType::Directional, QStringLiteral("Fill"));
    fill.direction = glm::normalize(glm::dvec3(1.0, -0.5, -1.0));
    fill.intensity = 0.3;
    rig.lights = {key, fill};
    return rig;
}

} // namespace

RigReadResult readRigFile(const QString& filePath) {
    const QFileInfo info(filePath);
    if (info.isDir()) return fileError(filePath, QStringLiteral("is a directory, not a rig file"));
    // A FIFO, socket or device would block the open or the read (a FIFO without a writer forever):
    // rig files are regular files (symbolic links to them included; ":/" resources count as files).
    if (info.exists() && !info.isFile())
        return fileError(filePath, QStringLiteral("is not a regular file (a FIFO, socket or device); rig "
                                                  "files must be regular files"));
    QFile file(filePath);
    if (!file.open(QIODevice::ReadOnly))
        return fileError(filePath, QStringLiteral("cannot open: %1").arg(file.errorString()));
    if (!file.isSequential() && file.size() > kMaxRigFileBytes)
        return fileError(filePath, tooLarge(file.size()));
    const QByteArray data = file.read(kMaxRigFileBytes + 1); // one byte more shows "too large" on pipes
    if (file.error() != QFileDevice::NoError)
        return fileError(filePath, QStringLiteral("cannot read: %1").arg(file.errorString()));
    RigReadResult r = readRigJson(data, filePath);
    if (r.rig) resolveLightFiles(*r.rig, info.absolutePath());
    return r;
}

bool saveRigFile(const Rig& rig, const QString& filePath, QString* error) {
    auto fail = [&](const QString& reason) {
        if (error) *error = QStringLiteral("%1: not saved: %2").arg(filePath, reason);
        return false;
    };
    const QByteArray data = writeRigJson(rig);
    // Never write a file that would not load: the rig in memory may hold values the editor let through.
    const RigReadResult check = readRigJson(data, filePath);
    if (!check.ok())
        return fail(QStringLiteral("the rig is invalid: ") + check.errors.first().mid(filePath.size() + 2));
    const QString reason = writeFileAtomically(filePath, data); // flushed and size-checked
    if (!reason.isEmpty()) return fail(reason);
    return true;
}

QStringList builtinPresetNames() {
    initPresetResources();
    QStringList names;
    const QStringList files = QDir(kPresetDir).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (const QString& f : files)
        names << f.chopped(5);
    return names;
}

QString builtinPresetPath(const QString& name) {
    return kPresetDir + QLatin1Char('/') + name + QStringLiteral(".json");
}

RigReadResult readBuiltinPreset(const QString& name) {
    initPresetResources();
    const QString display = name + QStringLiteral(".json");
    if (!builtinPresetNames().contains(name))
        return fileError(display, QStringLiteral("no such built-in preset (there are: %1)")
                                      .arg(builtinPresetNames().join(QStringLiteral(", "))));
    QFile file(builtinPresetPath(name));
    if (!file.open(QIODevice::ReadOnly))
        return fileError(display,
                         QStringLiteral("cannot open the built-in preset: %1").arg(file.errorString()));
    return readRigJson(file.readAll(), display);
}

Rig defaultRig() {
    RigReadResult r = readBuiltinPreset(QStringLiteral("default"));
    if (r.ok()) return *r.rig;
    qWarning().noquote() << "LightRig: the built-in default rig is unusable, using a fallback:"
                         << r.errors.join(QLatin1Char('\n'));
    return fallbackRig();
}

} // namespace lr
