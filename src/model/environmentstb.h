// Internal to environmentdecode.cpp: the one translation unit that compiles stb_image (HDR only).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace lr::stb {

struct HdrResult {
    int width = 0, height = 0;
    std::vector<float> rgb; // width × height × 3, top row first
    std::string error;      // stb's reason, or truncation; empty on success
};

// Decodes a Radiance RGBE file held in memory. Refuses data that ends early.
HdrResult decodeHdr(const char* data, std::size_t size);

} // namespace lr::stb
