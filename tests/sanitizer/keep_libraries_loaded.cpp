// Linked into the sanitized executables only (HG_SANITIZE: every test
// executable and hypergarden-full): dlclose leaves the library loaded.
//
// LeakSanitizer looks for leaks at exit, after Mesa's libGLX has dlclosed its
// DRI driver (swrast_dri.so, when the display closes) and the OpenXR loader
// has dlclosed the runtime (our mock, at xrDestroyInstance). Memory that the
// unloaded library's globals still point to is then reachable from nowhere
// and reported as leaked, from an "<unknown module>" that no suppression can
// name. Kept loaded, the globals are scanned (no false report) and every
// frame of a real leak keeps its library's name. The library's memory stays
// mapped, which is all a process that is about to exit loses.
//
// The executable's definition comes first in the lookup of every library
// (the executable exports it: LINKER:--export-dynamic-symbol=dlclose).
extern "C" int dlclose(void* handle);

extern "C" int dlclose(void* handle) {
    (void)handle;
    return 0;
}
