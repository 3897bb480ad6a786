// Internal to the isolated import: what `lightrig import-worker` (src/cli/importworker.cpp) and its
// parent (isolatedimport.cpp) say to each other.
//
// Request (parent -> worker, stdin, then closed): a JSON object
//   {"path": "...", "allowTexturesOutsideFolder": false, "maxDataUriBytes": 67108864, "sharedFd": 5}
// or, for an environment image (model/environmentdecode.h), {"kind": "environment", "path": "..."}, or for
// Assimp's glTF export of a model (model/gltfexport.h), {"kind": "gltf-export", "path": "..."}, or for a
// multi-layer OpenEXR file (model/exrdecode.h), {"kind": "exr-layers", "path": "..."}, or for a gobo's
// image (model/gobodecode.h), {"kind": "gobo", "path": "..."} (answered with a 'V' frame).
// sharedFd (optional): a memfd the parent created and let this worker inherit; the worker writes the
// encoded model there from offset 0 and answers 'S', or falls back to 'M' when it cannot.
// Reply (worker -> parent, stdout): frames of  u8 type, u64 payload length (host order), payload:
//   'P'  progress: one double in [0, 1]
//   'M'  the model: modelcodec.h's encoding (last frame)
//   'S'  the model is in the shared memfd of the request: u64 byte count (last frame)
//   'V'  the environment image (last frame): u32 width, u32 height, u32 n, n bytes of UTF-8 warnings
//        (one a line), then width × height × 3 floats (RGB, top row first); the parent checks all of it
//   'L'  the layers of an OpenEXR file (last frame): exrimport.cpp's layout; the parent checks all of it
//   'G'  the GLB Assimp's exporter made of the model (last frame); the parent parses it as untrusted
//   'E'  failure: u8 flags (kErrorCancelled | kErrorOutOfMemory) + UTF-8 message (last frame)
//   'O'  (empty) written by the worker's crash handler when an allocation had failed before the crash
//   'B'  the bytes of input read so far (u64; importbudget.h): the parent scales the deadline to it
// The worker points its own fd 1 at stderr before importing, so stray library output cannot corrupt
// the frames; the parent keeps only the tail of stderr for its messages.
#pragma once

#include <QtGlobal>

namespace lr::importprotocol {

inline constexpr char kProgress = 'P';
inline constexpr char kModel = 'M';
inline constexpr char kError = 'E';
inline constexpr char kOutOfMemory = 'O';
inline constexpr char kShared = 'S';
inline constexpr char kEnvironment = 'V';
inline constexpr char kGltf = 'G';
inline constexpr char kExrLayers = 'L';
inline constexpr char kInputBytes = 'B';
inline constexpr int kEnvironmentHeaderSize = 12;
inline constexpr int kFrameHeaderSize = 9;
inline constexpr char kExrLayersKind[] = "exr-layers"; // the request's "kind"
inline constexpr char kGoboKind[] = "gobo";

inline constexpr quint8 kErrorCancelled = 1;
inline constexpr quint8 kErrorOutOfMemory = 2;

inline constexpr qint64 kMaxRequestBytes = 1 << 20;
inline constexpr qint64 kMaxErrorBytes = 64 * 1024;

// The hidden subcommand that runs the worker.
inline constexpr char kSubcommand[] = "import-worker";
// Honoured only by the worker, for tests: segv, abort, hang, oom, garbage, truncate, exit,
// shared-garbage, shared-short, env-nan, env-size.
inline constexpr char kTestCrashVariable[] = "LIGHTRIG_WORKER_TEST_CRASH";

} // namespace lr::importprotocol
