// The one way LightRig writes a file: rigs, autosaves, presets and their thumbnails, screenshots, `render`
// images, bench JSON and charts all end here (images are encoded to bytes first: render/imagefile.h).
//
// writeFileAtomically(PATH, bytes) writes a temporary file beside PATH, checks that every byte reached it
// (each write(2), fdatasync, the size on disk, close), then renames it over PATH. Any failure, a cancel, or
// a kill at any moment leaves PATH as it was, byte for byte. Failures are the system's reason in lower case
// ("no space left on device", "permission denied"), never "Unknown error"; callers add the file name.
//
// Temporaries are named `NAME.lightrig-PID-XXXXXX.tmp` (PID: the writing process). A process killed between
// creating one and the rename (kill -9, a crash, a power cut) leaves it behind; the next write of PATH
// removes every temporary of PATH whose process is gone (or is this process, when the file is not one of its
// writes in progress). Linux/POSIX only, like the rest of LightRig.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <atomic>

namespace lr {

// "" when PATH now holds `data`; else why not (PATH unchanged). A symbolic link is followed: its target is
// replaced, keeping the link. An existing file's permission bits are kept; a new one gets 0666 & ~umask.
// When *cancel is set before the rename nothing is written, *cancelled (if given) is set and the result is
// "cancelled". Thread-safe.
QString writeFileAtomically(const QString& path, const QByteArray& data,
                            const std::atomic<bool>* cancel = nullptr, bool* cancelled = nullptr);

// The stale temporaries of PATH (see above) that the next write would remove, as absolute paths.
QStringList staleTemporaries(const QString& path);

// Whether `fileName` is one of writeFileAtomically's temporaries for a file named `targetName`.
bool isAtomicTemporaryOf(const QString& fileName, const QString& targetName);

} // namespace lr
