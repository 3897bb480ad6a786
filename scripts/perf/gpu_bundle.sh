#!/usr/bin/env bash
# gpu_bundle.sh [LIGHTRIG_BINARY] [BUNDLE_DIR]: packs everything `lightrig bench` needs on a bare GPU machine
# (Ubuntu/CUDA image, no network, no X server, no Qt) into BUNDLE_DIR/bundle.tar.xz, to be unpacked and run
# there by scripts/perf/gpu_run.sh. Built on the Debian 12 development machine.
#
# Contents (under one top folder, lightrig-gpu/):
#   bin/lightrig                 the stripped binary (also its own import worker)
#   lib/                         every shared library the binary, the Qt plugins, Xvfb, xkbcomp and Mesa's
#                                swrast need, except glibc and the GL/GLX/EGL dispatch libraries: those must
#                                be the target's glvnd ones, so that GLX dispatches to the NVIDIA driver
#                                (libstdc++ and libgcc_s too: the target's newer ones serve), and with
#                                libz3 replaced by a stub of the same soname whose functions trap: Mesa's
#                                libLLVM links it for clang's analyser only, never called by llvmpipe, and
#                                the real one is 23 MB (6 MB compressed) of a 64 MiB transfer limit
#   plugins/                     Qt plugins: platforms (xcb, minimalegl, offscreen), xcbglintegrations,
#                                imageformats (the helmet's textures are JPEG)
#   xserver/Xvfb, xserver/xkbcomp, xkb/   the virtual X server, its keymap compiler and keymap data
#   dri/swrast_dri.so            Mesa's software DRI driver: Xvfb's GLX extension loads it
#   scenes/DamagedHelmet.glb, scenes/add_lights.py   the helmet_Npt scenes are made there (byte-identical
#                                to ../shared/models/bench/helmet_{1,8,64}pt.glb; saves 20 MB of transfer)
#   scenes/localize_lights.py    makes them localised lights (gpu_run.sh LR_GPU_LOCAL)
# Next to the tarball: glxprobe, a small GLX client (fbconfigs, visuals, a 3.3 core context's GL_RENDERER)
# that gpu_run.sh runs first, to tell a GLX set-up problem from a LightRig one; and eglpbuffer.so, an
# LD_PRELOAD shim for the "egldev" mode (see gpu_run.sh and the shim's comment).
# LR_BUNDLE_EGL_ONLY=1 leaves Mesa out (egldev mode only; see below). LR_BUNDLE_CPU=1 makes the smaller bundle scripts/perf/trace_device.sh needs (the path tracer: no display,
# no GL): the binary, the offscreen platform and image-format plugins, their libraries (the GL dispatch
# libraries included, which the binary links but never calls there) and the scenes; no X server, no Mesa.
# BUNDLE_DIR defaults to .gpubundle (ignored through .git/info/exclude; name it in the device call's carry).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bin="${1:-}"
if [ -z "$bin" ]; then bin="$(find "$root/build/dev" -name lightrig -type f -perm -u+x | head -n1)"; fi
[ -x "$bin" ] || { echo "gpu_bundle.sh: no lightrig binary (give its path as the first argument)" >&2; exit 2; }
bundle="${2:-$root/.gpubundle}"
shared="${LIGHTRIG_SHARED:-$root/../shared}"
helmet="$shared/models/gltf/khronos/DamagedHelmet/glTF-Binary/DamagedHelmet.glb"
addlights="$shared/peers/three/add_lights.py"
qtplugins="$(dirname "$(find /usr/lib/x86_64-linux-gnu/qt6/plugins -name libqxcb.so | head -n1)")/.."
dri=/usr/lib/x86_64-linux-gnu/dri
cpu="${LR_BUNDLE_CPU:-0}"
for f in "$helmet" "$addlights" /usr/bin/Xvfb /usr/bin/xkbcomp "$dri/swrast_dri.so" "$qtplugins/platforms/libqxcb.so"; do
    [ -e "$f" ] || { echo "gpu_bundle.sh: missing $f (apt-get install xvfb x11-xkb-utils libgl1-mesa-dri)" >&2; exit 1; }
done

stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
t="$stage/lightrig-gpu"
mkdir -p "$t"/{bin,lib,plugins,xserver,dri,scenes}
strip -o "$t/bin/lightrig" "$bin"
for d in platforms xcbglintegrations imageformats; do mkdir -p "$t/plugins/$d"; done
cp -L "$qtplugins"/imageformats/*.so "$t/plugins/imageformats/"
if [ "$cpu" = 1 ]; then
    cp -L "$qtplugins"/platforms/libqoffscreen.so "$t/plugins/platforms/"
else
    cp -L "$qtplugins"/platforms/{libqxcb.so,libqminimalegl.so,libqoffscreen.so} "$t/plugins/platforms/"
    cp -L "$qtplugins"/xcbglintegrations/*.so "$t/plugins/xcbglintegrations/"
    cp -L /usr/bin/Xvfb /usr/bin/xkbcomp "$t/xserver/"
    cp -rL /usr/share/X11/xkb "$t/xkb"
    # LR_BUNDLE_EGL_ONLY=1: no Mesa (its swrast and the libLLVM it needs, ~40 MB compressed), for a GPU
    # machine where only the "egldev" mode renders on the GPU (Xvfb then runs without GLX).
    [ "${LR_BUNDLE_EGL_ONLY:-0}" = 1 ] || cp -L "$dri/swrast_dri.so" "$t/dri/"
fi
cp -L "$helmet" "$addlights" "$root/scripts/perf/localize_lights.py" "$t/scenes/"

# Shared libraries: the closure of ldd over every ELF file above, minus what must come from the target.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libpthread|libdl\.|librt\.|libresolv|libutil\.|libanl\.|libGL\.|libGLX|libGLdispatch|libEGL|libOpenGL|libGLES|libvulkan|libstdc\+\+|libgcc_s)'
[ "$cpu" = 1 ] && skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libpthread|libdl\.|librt\.|libresolv|libutil\.|libanl\.|libstdc\+\+|libgcc_s)'
mapfile -t elves < <(find "$t/bin" "$t/plugins" "$t/xserver" "$t/dri" -type f)
missing=0
while read -r name _ path _; do
    [ -n "$name" ] || continue
    if [ "$path" = "not" ]; then echo "gpu_bundle.sh: $name not found" >&2; missing=1; continue; fi
    [[ "$name" =~ $skip ]] && continue
    if [ "$name" = libz3.so.4 ]; then
        # One aborting function per Z3_ symbol libLLVM imports: Mesa's loader dlopens with RTLD_NOW.
        nm -D --undefined-only "$(dirname "$path")"/libLLVM*.so.* | awk '$2 ~ /^Z3_/ {print $2}' | sort -u |
            sed 's/.*/void &(void) { __builtin_trap(); }/' |
            gcc -shared -fPIC -x c - -o "$t/lib/$name" -Wl,-soname,"$name"
    else
        cp -Ln "$path" "$t/lib/$name"
    fi
done < <(for e in "${elves[@]}"; do ldd "$e" | grep '=>' ; done | sort -u)
[ "$missing" = 0 ] || exit 1
strip --strip-unneeded "$t"/lib/*.so* "$t"/dri/*.so "$t"/plugins/*/*.so "$t"/xserver/* 2>/dev/null || true

mkdir -p "$bundle"
rm -f "$bundle/bundle.tar.xz"
tar -C "$stage" -cf - lightrig-gpu | xz -T0 --x86 --lzma2=preset=9e,dict=64MiB >"$bundle/bundle.tar.xz"
gcc -O1 -o "$bundle/glxprobe" -x c - -lGL -lX11 <<'C'
// glxprobe: what GLX offers on $DISPLAY (fbconfigs, visuals) and whether a 3.3 core context renders.
#include <GL/glx.h>
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>
typedef GLXContext (*CreateCtx)(Display*, GLXFBConfig, GLXContext, Bool, const int*);
static int count(Display* d, int drawable, int* withVisual, GLXFBConfig* first) {
    int attrs[] = {GLX_DRAWABLE_TYPE, drawable, GLX_RENDER_TYPE, GLX_RGBA_BIT, None};
    int n = 0;
    GLXFBConfig* c = glXChooseFBConfig(d, DefaultScreen(d), attrs, &n);
    *withVisual = 0;
    for (int i = 0; i < n; ++i) {
        XVisualInfo* v = glXGetVisualFromFBConfig(d, c[i]);
        if (v) { ++*withVisual; XFree(v); }
    }
    if (n && first) *first = c[0];
    return n;
}
static void tryContext(Display* d, GLXFBConfig cfg, const char* what, int pbuffer) {
    CreateCtx create = (CreateCtx)glXGetProcAddressARB((const GLubyte*)"glXCreateContextAttribsARB");
    int ca[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3,
                GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
    GLXContext ctx = create ? create(d, cfg, 0, True, ca) : 0;
    XSync(d, False);
    if (!ctx) { printf("%s: no 3.3 core context\n", what); return; }
    GLXDrawable dr;
    if (pbuffer) {
        int pa[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
        dr = glXCreatePbuffer(d, cfg, pa);
    } else {
        XVisualInfo* v = glXGetVisualFromFBConfig(d, cfg);
        if (!v) { printf("%s: no visual\n", what); return; }
        XSetWindowAttributes wa = {0};
        wa.colormap = XCreateColormap(d, RootWindow(d, v->screen), v->visual, AllocNone);
        dr = XCreateWindow(d, RootWindow(d, v->screen), 0, 0, 16, 16, 0, v->depth, InputOutput, v->visual,
                           CWColormap | CWBorderPixel, &wa);
    }
    if (!glXMakeContextCurrent(d, dr, dr, ctx)) { printf("%s: makeCurrent failed\n", what); return; }
    printf("%s: GL_RENDERER=%s | GL_VERSION=%s | GL_VENDOR=%s\n", what, glGetString(GL_RENDERER),
           glGetString(GL_VERSION), glGetString(GL_VENDOR));
    glXMakeContextCurrent(d, None, None, 0);
}
static int onError(Display* d, XErrorEvent* e) {
    char text[256];
    XGetErrorText(d, e->error_code, text, sizeof text);
    printf("X error: %s (request %d.%d)\n", text, e->request_code, e->minor_code);
    return 0;
}
int main(void) {
    Display* d = XOpenDisplay(0);
    if (!d) { printf("no display\n"); return 1; }
    XSetErrorHandler(onError);
    int eb, ev;
    printf("GLX extension: %s\n", glXQueryExtension(d, &eb, &ev) ? "yes" : "no");
    printf("server vendor: %s, version %s\n", glXQueryServerString(d, DefaultScreen(d), GLX_VENDOR),
           glXQueryServerString(d, DefaultScreen(d), GLX_VERSION));
    printf("client vendor: %s, version %s\n", glXGetClientString(d, GLX_VENDOR), glXGetClientString(d, GLX_VERSION));
    int all = 0;
    GLXFBConfig* c = glXGetFBConfigs(d, DefaultScreen(d), &all);
    (void)c;
    int wv, pv;
    GLXFBConfig w = 0, p = 0;
    int nw = count(d, GLX_WINDOW_BIT, &wv, &w), np = count(d, GLX_PBUFFER_BIT, &pv, &p);
    printf("fbconfigs: %d in all; window-capable %d (%d with a visual); pbuffer-capable %d (%d with a visual)\n",
           all, nw, wv, np, pv);
    if (np) tryContext(d, p, "pbuffer", 1);
    if (nw) tryContext(d, w, "window", 0);
    return 0;
}
C
gcc -O1 -shared -fPIC -o "$bundle/eglpbuffer.so" -x c - -ldl <<'C'
// eglpbuffer.so (LD_PRELOAD): eglChooseConfig asks for pbuffer-capable configs where the caller asked for
// window-capable ones. Qt's xcb EGL integration picks its context's config with EGL_WINDOW_BIT, which
// NVIDIA's device platform (EGL without an X or DRM display) has none of; LightRig renders into FBOs on a
// QOffscreenSurface (a pbuffer there), so no window surface is ever made.
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <dlfcn.h>
typedef EGLBoolean (*Choose)(EGLDisplay, const EGLint*, EGLConfig*, EGLint, EGLint*);
EGLBoolean eglChooseConfig(EGLDisplay dpy, const EGLint* attribs, EGLConfig* configs, EGLint size, EGLint* n) {
    static Choose real;
    if (!real) real = (Choose)dlsym(RTLD_NEXT, "eglChooseConfig");
    if (!attribs) return real(dpy, attribs, configs, size, n);
    EGLint copy[256];
    int i = 0;
    for (; attribs[i] != EGL_NONE && i < 254; i += 2) {
        copy[i] = attribs[i];
        copy[i + 1] = attribs[i + 1];
        if (attribs[i] == EGL_SURFACE_TYPE && (attribs[i + 1] & EGL_WINDOW_BIT))
            copy[i + 1] = (attribs[i + 1] & ~EGL_WINDOW_BIT) | EGL_PBUFFER_BIT;
    }
    copy[i] = EGL_NONE;
    return real(dpy, copy, configs, size, n);
}
C
echo "gpu_bundle.sh: $(du -sh "$t" | cut -f1) staged, $(du -h "$bundle/bundle.tar.xz" | cut -f1) in $bundle/bundle.tar.xz"
