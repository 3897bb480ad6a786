// Decoding a gobo's image (PNG or EXR) in the isolated import worker: the file is untrusted.
#pragma once

#include "core/gobo.h"

#include <QString>
#include <memory>

namespace lr {

// nullptr with *error ("FILE: reason") when the file is not a usable image.
std::shared_ptr<const GoboImage> decodeGoboImage(const QString& path, QString* error);

} // namespace lr
