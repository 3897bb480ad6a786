// Linked into every executable of a sanitizer build (LIGHTRIG_SANITIZE; see tests/CMakeLists.txt and the top
// CMakeLists.txt), never into a normal build. It makes dlclose() a no-op, so shared libraries stay mapped
// until the process exits.
//
// Why: Mesa loads its driver (swrast/llvmpipe) with dlopen and unloads it with dlclose when the last GL
// context goes. Memory that only the unloaded driver still pointed to then looks leaked to LeakSanitizer,
// which cannot even name the code that allocated it ("<unknown module>"), so no suppression can match it.
// With the driver kept mapped, those blocks stay reachable and are not reported; real leaks still are.
// The executable's definition wins over libc's for every library (symbol interposition).
extern "C" int dlclose(void*) {
    return 0;
}
