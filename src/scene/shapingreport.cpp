#include "shapingreport.h"

#include "lightassets.h"

namespace lr {

QStringList shapingWarnings(const Rig& rig) {
    return loadLightAssets(rig).errors;
}

} // namespace lr
