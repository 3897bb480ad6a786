// IES photometric profiles (ANSI/IES LM-63-1995, -2002, -2019): the strict reader and the distribution it
// defines. The file is untrusted: every error names the file, the line and the reason.
#pragma once

#include <QString>
#include <memory>
#include <vector>

namespace lr {

// A profile expanded to its full distribution (every symmetry unfolded), candela by vertical angle
// (degrees from the nadir, ascending) and horizontal angle (degrees, ascending).
struct IesProfile {
    std::vector<double> vertical;
    std::vector<double> horizontal;
    std::vector<double> candela; // horizontal-major: candela[h * vertical.size() + v]
    double peak = 0.0;           // the largest candela value
};

// Reads and checks an IES file; nullptr with *error ("FILE:LINE: reason") when it is not a usable profile.
std::shared_ptr<const IesProfile> readIesFile(const QString& path, QString* error);

} // namespace lr
