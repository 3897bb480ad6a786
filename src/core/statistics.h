// Small statistics the benchmarks share.
#pragma once

#include <algorithm>
#include <vector>

namespace lr {

// The median of `v` (the mean of the middle two for an even count); `ifEmpty` for no values.
inline double median(std::vector<double> v, double ifEmpty = -1.0) {
    if (v.empty()) return ifEmpty;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace lr
