// Not a test: writes the small environment images of tests/data/environment (committed; run it again only
// to change them): `make_environment_data DIR`. Their texel values are the formulas below, which
// tst_environmentdecode checks exactly.
//   tiny.exr       4 × 2 float RGB, no compression: texel (x, y) = ((x + 1) / 4, (y + 1) / 2, 0.125 x y)
//   tiny_zip.exr   the same, ZIP compression, with an alpha channel (ignored)
//   nonfinite.exr  4 × 2 float RGB: texel (x, y) = (1, 2, 3) but (1, 0) R NaN, (2, 0) G +Inf, (3, 1) B −1
//   tiny.hdr       4 × 2 Radiance RGBE, flat: texel (x, y) = (1, 0.5, 0.25) × 2^(x − y)
//   rle.hdr        16 × 2 Radiance RGBE, run-length encoded: row 0 (1, 0.5, 0.25), row 1 (1, 0.5, 2)
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace {

void writeExr(const std::string& path, int w, int h, const std::vector<float>& rgb, Imf::Compression c,
              bool alpha) {
    Imf::Header header(w, h);
    header.compression() = c;
    const char* names[4] = {"R", "G", "B", "A"};
    for (int i = 0; i < (alpha ? 4 : 3); ++i)
        header.channels().insert(names[i], Imf::Channel(Imf::FLOAT));
    std::vector<float> a(size_t(w * h), 0.5f);
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer fb;
    for (int i = 0; i < 3; ++i)
        fb.insert(names[i], Imf::Slice(Imf::FLOAT, (char*)(rgb.data() + i), 12, 12 * size_t(w)));
    if (alpha) fb.insert("A", Imf::Slice(Imf::FLOAT, (char*)a.data(), 4, 4 * size_t(w)));
    file.setFrameBuffer(fb);
    file.writePixels(h);
}

void writeHdr(const std::string& path, int w, int h, const std::string& pixels) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n" << pixels;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_environment_data DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    std::vector<float> tiny;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            tiny.insert(tiny.end(), {(x + 1) / 4.0f, (y + 1) / 2.0f, 0.125f * float(x * y)});
    writeExr(dir + "/tiny.exr", 4, 2, tiny, Imf::NO_COMPRESSION, false);
    writeExr(dir + "/tiny_zip.exr", 4, 2, tiny, Imf::ZIP_COMPRESSION, true);
    std::vector<float> bad;
    for (int i = 0; i < 8; ++i)
        bad.insert(bad.end(), {1.0f, 2.0f, 3.0f});
    bad[3 * 1 + 0] = std::numeric_limits<float>::quiet_NaN();
    bad[3 * 2 + 1] = std::numeric_limits<float>::infinity();
    bad[3 * 7 + 2] = -1.0f;
    writeExr(dir + "/nonfinite.exr", 4, 2, bad, Imf::NO_COMPRESSION, false);
    // RGBE: mantissas 128, 64, 32 with exponent e are (1, 0.5, 0.25) × 2^(e − 129).
    std::string flat;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            flat += std::string{char(128), char(64), char(32), char(129 + x - y)};
    writeHdr(dir + "/tiny.hdr", 4, 2, flat);
    // New-style RLE scanlines: 2, 2, width >> 8, width & 255, then per channel one run of 16 (128 + 16).
    std::string rle;
    const unsigned char rows[2][4] = {{128, 64, 32, 129}, {64, 32, 128, 130}};
    for (const auto& row : rows) {
        rle += std::string{2, 2, 0, 16};
        for (unsigned char c : row)
            rle += std::string{char(128 + 16), char(c)};
    }
    writeHdr(dir + "/rle.hdr", 16, 2, rle);
    return 0;
}
