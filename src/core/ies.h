// IES photometric profiles (ANSI/IES LM-63-1995, -2002, -2019): the strict reader and the distribution it
// defines. The file is untrusted: every error names the file, the line and the reason.
//
// Photometric type C only (type A and B files are refused by name). The reader unfolds every symmetry of the
// horizontal angles (one angle: rotational; last 90: quadrant; last 180: bilateral about C0-C180; 90 to 270:
// bilateral about C90-C270; more: full, closed at 360) into a full 0 ... 360 table. The distribution is the
// table interpolated bilinearly in angle (degrees): linear in the vertical angle between its two nearest
// rows, linear in the horizontal angle between its two nearest columns; zero outside the file's vertical
// range (a 0 ... 90 downlight sends nothing upwards); a single vertical angle is the same in every direction.
// TILT data is read and checked, not applied (it describes a lamp tilted away from its test position); the
// ballast factor is not applied (the candela multiplier is).
#pragma once

#include <QString>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace lr {

// Reader limits: angles each way, candela values in the file (before unfolding), the file's size.
constexpr int kMaxIesAngles = 16384;
constexpr long long kMaxIesValues = 1 << 21;
constexpr long long kMaxIesFileBytes = 64LL * 1024 * 1024;

// A profile expanded to its full distribution (every symmetry unfolded), candela by vertical angle
// (degrees from the nadir, ascending) and horizontal angle (degrees, ascending, 0 ... 360).
struct IesProfile {
    std::vector<double> vertical;
    std::vector<double> horizontal;
    std::vector<double>
        candela;       // horizontal-major: candela[h * vertical.size() + v], × the file's multiplier
    double peak = 0.0; // the largest candela value
    QString format;    // "LM-63-2002", ... ("LM-63-1986" without a version line)
    QString symmetry;  // "rotational", "quadrant", "bilateral", "bilateral-90", "full"
    int fileVertical = 0, fileHorizontal = 0; // the angles the file lists
};

// Reads and checks an IES file; nullptr with *error ("FILE:LINE: reason") when it is not a usable profile.
std::shared_ptr<const IesProfile> readIesFile(const QString& path, QString* error);
// The same on the file's bytes (`name` is the FILE of the messages).
std::shared_ptr<const IesProfile> readIesData(const QByteArray& data, const QString& name, QString* error);

// Beam angle (degrees): the full angle within which the intensity stays at or above half the peak, the mean
// of the C0-C180 and C90-C270 planes (each: the outermost vertical angle at 50 % on either side, linear
// between samples). 0 for a profile without light.
double iesBeamAngle(const IesProfile& p);

namespace ies {

// Index i with a[i] <= x <= a[i+1] and the weight of a[i+1] (a ascending, size >= 2, x within).
template <typename T> inline std::size_t bracket(const std::vector<double>& a, T x, T* t) {
    const auto it = std::upper_bound(a.begin() + 1, a.end() - 1, double(x));
    const std::size_t i = std::size_t(it - a.begin()) - 1;
    const T span = T(a[i + 1] - a[i]);
    *t = span > T(0) ? std::clamp((x - T(a[i])) / span, T(0), T(1)) : T(0);
    return i;
}

} // namespace ies

// The candela of the profile at vertical angle `theta` (degrees from the nadir, 0 ... 180) and horizontal
// angle `phi` (degrees, any; taken modulo 360): bilinear in angle, as the header says.
template <typename T> T iesCandela(const IesProfile& p, T theta, T phi) {
    const std::size_t nv = p.vertical.size();
    if (nv == 0 || p.horizontal.empty() || !(theta == theta) || !(phi == phi)) return T(0);
    if (theta < T(p.vertical.front()) || theta > T(p.vertical.back()))
        return nv == 1 ? T(p.candela[0]) : T(0);
    phi = std::fmod(phi, T(360));
    if (phi < T(0)) phi += T(360);
    T tv = T(0), th = T(0);
    const std::size_t v = nv == 1 ? 0 : ies::bracket(p.vertical, theta, &tv);
    const std::size_t h = p.horizontal.size() == 1 ? 0 : ies::bracket(p.horizontal, phi, &th);
    const std::size_t v1 = std::min(v + 1, nv - 1), h1 = std::min(h + 1, p.horizontal.size() - 1);
    const auto at = [&](std::size_t hi, std::size_t vi) { return T(p.candela[hi * nv + vi]); };
    const T a = at(h, v) + (at(h, v1) - at(h, v)) * tv;
    const T b = at(h1, v) + (at(h1, v1) - at(h1, v)) * tv;
    return a + (b - a) * th;
}

// The same for a direction in the light's photometric frame: `w` unit, from the light; nadir the axis of
// vertical angle 0, x the axis of horizontal angle 0 (unit, orthogonal to nadir), y = x × nadir (C90).
template <typename T, typename V>
T iesCandelaToward(const IesProfile& p, const V& w, const V& nadir, const V& x, const V& y) {
    const T c = std::clamp(T(w.x * nadir.x + w.y * nadir.y + w.z * nadir.z), T(-1), T(1));
    const T theta = std::acos(c) * T(57.295779513082320876798);
    const T px = T(w.x * x.x + w.y * x.y + w.z * x.z), py = T(w.x * y.x + w.y * y.y + w.z * y.z);
    const T phi = (px == T(0) && py == T(0)) ? T(0) : std::atan2(py, px) * T(57.295779513082320876798);
    return iesCandela(p, theta, phi);
}

} // namespace lr
