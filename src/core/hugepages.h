#pragma once
// Transparent huge pages for malloc's large mappings, through glibc's hugetlb tunable (2.35+).
//
// llvmpipe keeps every texture and render target in malloc'd memory that it zeroes or fills on creation,
// and each fresh 4 KiB page costs a fault; in a virtual machine faults are dear. With
// `glibc.malloc.hugetlb=1` malloc asks for transparent huge pages (madvise) on its mmap'd chunks, 512 pages
// a fault. The helmet's first frame went from 1.16-1.17 s to 0.66-0.86 s (its texture upload from 0.44 to
// 0.16-0.30 s) on the 2-core VM (docs/performance.md). glibc reads the tunable only when a process starts,
// so the lightrig executable re-executes itself once with it; the import worker is started with it.
#include <string>

namespace lr {

// GLIBC_TUNABLES with the hugetlb tunable added: "glibc.malloc.hugetlb=1" for an empty value, `current`
// + ":glibc.malloc.hugetlb=1" otherwise. Empty when `current` names the tunable already (the user's own
// setting, 0 included, is kept).
std::string withHugePageTunable(const std::string& current);

// Re-executes the running program (/proc/self/exe, the same argv) with the tunable added to the
// environment, unless it is there already. Returns only when nothing was re-executed: the tunable was set
// already (this is the re-executed process, or the user's choice), or exec failed (the program runs on
// without huge pages). Call it first in main(), before any thread or file exists.
void reexecWithHugePages(char** argv);

} // namespace lr
