// stb_image, compiled once here with only its Radiance RGBE (.hdr) decoder (environmentdecode.cpp).
// It reads through callbacks so that a file ending before its data is noticed: stb_image would
// otherwise decode the missing bytes as zeros.
#include "environmentstb.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#define STBI_NO_GIF
#define STBI_MAX_DIMENSIONS 16384
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cstring>

namespace lr::stb {

namespace {

struct Reader {
    const char* data;
    std::size_t size, pos = 0;
    bool overrun = false; // stb asked for bytes past the end
};

int readCallback(void* user, char* out, int n) {
    auto* r = static_cast<Reader*>(user);
    const std::size_t left = r->size - r->pos;
    if (left == 0) {
        r->overrun = true;
        return 0;
    }
    const std::size_t take = std::min(left, std::size_t(std::max(n, 0)));
    std::memcpy(out, r->data + r->pos, take);
    r->pos += take;
    return int(take);
}
void skipCallback(void* user, int n) {
    auto* r = static_cast<Reader*>(user);
    if (n < 0) n = 0; // stb never rewinds through callbacks
    if (std::size_t(n) > r->size - r->pos) r->overrun = true;
    r->pos = std::min(r->size, r->pos + std::size_t(n));
}
int eofCallback(void* user) {
    const auto* r = static_cast<Reader*>(user);
    return r->pos >= r->size;
}

} // namespace

HdrResult decodeHdr(const char* data, std::size_t size) {
    HdrResult result;
    Reader reader{data, size};
    const stbi_io_callbacks callbacks{readCallback, skipCallback, eofCallback};
    int w = 0, h = 0, channels = 0;
    float* pixels = stbi_loadf_from_callbacks(&callbacks, &reader, &w, &h, &channels, 3);
    if (!pixels) {
        result.error = stbi_failure_reason() ? stbi_failure_reason() : "unknown error";
        return result;
    }
    if (reader.overrun) {
        stbi_image_free(pixels);
        result.error = "the file ends before its pixel data does";
        return result;
    }
    result.width = w;
    result.height = h;
    try {
        result.rgb.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 3);
    } catch (...) {
        stbi_image_free(pixels);
        throw;
    }
    stbi_image_free(pixels);
    return result;
}

} // namespace lr::stb
