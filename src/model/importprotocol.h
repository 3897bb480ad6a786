// Internal to the isolated import: what `lightrig import-worker` (src/cli/importworker.cpp) and its
// parent (isolatedimport.cpp) say to each other.
//
// Request (parent -> worker, stdin, then closed): a JSON object
//   {"path": "...", "allowTexturesOutsideFolder": false, "maxDataUriBytes": 67108864}
// Reply (worker -> parent, stdout): frames of  u8 type, u64 payload length (host order), payload:
//   'P'  progress: one double in [0, 1]
//   'M'  the model: modelcodec.h's encoding (last frame)
//   'E'  failure: u8 flags (kErrorCancelled | kErrorOutOfMemory) + UTF-8 message (last frame)
//   'O'  (empty) written by the worker's crash handler when an allocation had failed before the crash
// The worker points its own fd 1 at stderr before importing, so stray library output cannot corrupt
// the frames; the parent keeps only the tail of stderr for its messages.
#pragma once

#include <QtGlobal>

namespace lr::importprotocol {

inline constexpr char kProgress = 'P';
inline constexpr char kModel = 'M';
inline constexpr char kError = 'E';
inline constexpr char kOutOfMemory = 'O';
inline constexpr int kFrameHeaderSize = 9;

inline constexpr quint8 kErrorCancelled = 1;
inline constexpr quint8 kErrorOutOfMemory = 2;

inline constexpr qint64 kMaxRequestBytes = 1 << 20;
inline constexpr qint64 kMaxErrorBytes = 64 * 1024;

// The hidden subcommand that runs the worker.
inline constexpr char kSubcommand[] = "import-worker";
// Honoured only by the worker, for tests: segv, abort, hang, oom, garbage, truncate, exit.
inline constexpr char kTestCrashVariable[] = "LIGHTRIG_WORKER_TEST_CRASH";

} // namespace lr::importprotocol
