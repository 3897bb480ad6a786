#include "hugepages.h"

#include <cstdlib>
#include <unistd.h>

namespace lr {

namespace {
constexpr const char* kTunable = "glibc.malloc.hugetlb";
} // namespace

std::string withHugePageTunable(const std::string& current) {
    if (current.find(kTunable) != std::string::npos) return {};
    const std::string setting = std::string(kTunable) + "=1";
    return current.empty() ? setting : current + ":" + setting;
}

void reexecWithHugePages(char** argv) {
#ifdef __linux__
    const char* current = std::getenv("GLIBC_TUNABLES");
    const std::string tunables = withHugePageTunable(current ? current : "");
    if (tunables.empty() || !argv || !argv[0]) return;
    if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // exec failed: run on as we are. The variable stays set, which is harmless (glibc has read its tunables).
#else
    (void)argv;
#endif
}

} // namespace lr
