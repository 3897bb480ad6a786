#include "ies.h"

namespace lr {

// SKELETON: the IES work replaces this with the LM-63 reader.
std::shared_ptr<const IesProfile> readIesFile(const QString& path, QString* error) {
    if (error) *error = path + QStringLiteral(": IES profiles are not read yet");
    return nullptr;
}

} // namespace lr
