// A gobo: an image projected through a spot light's cone (issue 39, core/lightshaping.h GoboSpec).
#pragma once

#include <vector>

namespace lr {

// Linear RGB transmission, row 0 at the image's top, as decoded from the file (model/gobodecode.h).
struct GoboImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3
};

} // namespace lr
