// Internal to the isolated import (isolatedimport.h, environmentimport.cpp): one run of
// `lightrig import-worker` — start it with a request, read its frames (importprotocol.h) under the time
// limit and the caller's cancel, and turn a crash, abort, hang, memory exhaustion, malformed or missing
// reply into a reason. What the reply means (a model, an environment image) is the caller's to decode
// and validate.
#pragma once

#include "importbudget.h"
#include "isolatedimport.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <functional>
#include <memory>

class QProcess;

namespace lr::isolated {

// The worker after a complete reply is still exiting (freeing a large import can take a while); its
// owner decodes meanwhile, and the destructor reaps it (killing it if it lingers 5 s).
struct ExitingWorker {
    std::unique_ptr<QProcess> process;
    ExitingWorker();
    ExitingWorker(ExitingWorker&&) noexcept;
    ~ExitingWorker();
};

struct WorkerOutcome {
    // Set when there is no reply: "the importer crashed (signal 11)", "cancelled", ... (no file name),
    // or the worker's own complete message (an 'E' frame: it names the file) when `fromWorker`.
    QString failure;
    bool fromWorker = false;
    bool cancelled = false;
    char type = 0;      // the reply's frame type (importprotocol::kModel, kShared, kEnvironment)
    QByteArray payload; // its payload, of at most maxReplyBytes
    ExitingWorker worker;
    bool ok() const { return failure.isEmpty(); }
};

// Runs the worker with `request` (the sharedFd, when >= 0, is inherited by the worker alone).
// keepGoing(fraction) is called every 50 ms at most; returning false cancels. `maxReplyBytes` bounds a
// reply frame (and the memory limit, when set, bounds it too). With limits.scaleWithInput, the worker's
// time and memory are importBudget(kind, input) for the request's file and whatever else it reports
// reading ('B' frames), within the limits' values.
WorkerOutcome runWorker(const QJsonObject& request, const ImportLimits& limits, int sharedFd,
                        const std::function<bool(double)>& keepGoing, qint64 maxReplyBytes,
                        BudgetKind kind = BudgetKind::Model);

} // namespace lr::isolated
