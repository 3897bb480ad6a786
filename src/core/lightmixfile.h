// Mix files (issue 37, docs/light-mixing.md) read and written by the editor's Mixer dock and lightrig mix:
// read as rig files are (a regular file, at most kMaxRigFileBytes, errors naming the file: "mix.json:
// groups.key.ev: ..."), written atomically (core/atomicwrite.h) in writeLightMix's canonical form.
#pragma once

#include "lightmix.h"

namespace lr {

// readLightMix on the file's bytes; a file that cannot be read is one error "FILE: reason".
LightMixReadResult readLightMixFile(const QString& path, const QStringList& known = {});
// "" when PATH now holds the mix; else "FILE: not saved: reason" (PATH as it was).
QString writeLightMixFile(const QString& path, const LightMix& mix);

} // namespace lr
