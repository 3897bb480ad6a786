#include "gobodecode.h"

namespace lr {

// SKELETON: the gobo work replaces this with the decoder.
std::shared_ptr<const GoboImage> decodeGoboImage(const QString& path, QString* error) {
    if (error) *error = path + QStringLiteral(": gobo images are not read yet");
    return nullptr;
}

} // namespace lr
