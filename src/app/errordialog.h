// Error reporting the user can copy: a message box whose text is selectable and whose "Show Details"
// holds every error line (FILE: field: reason). Tests replace the presenter to capture messages.
#pragma once

#include <QString>
#include <QStringList>
#include <functional>

class QWidget;

namespace lr {

struct ErrorReport {
    QString title;       // window title, e.g. "Open rig"
    QString summary;     // one line: "Could not open studio.json: 3 errors"
    QStringList details; // each "FILE: json.path: reason"
};

// Shows a modal warning box (text selectable, details copyable). Returns when it is closed.
void showError(QWidget* parent, const ErrorReport& report);

// For tests and headless runs: when set, showError calls this instead of opening a dialog.
using ErrorPresenter = std::function<void(const ErrorReport&)>;
void setErrorPresenter(ErrorPresenter presenter);

} // namespace lr
