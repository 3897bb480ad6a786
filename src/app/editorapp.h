// The editor's entry point: `lightrig [MODEL] [--rig RIG]` (see commandline.h).
#pragma once

namespace lr {

// Application identity for QSettings and QStandardPaths (organisation "LightRig", application "lightrig").
// Called by runEditor; tests call it too (with QStandardPaths::setTestModeEnabled) before creating windows.
void setApplicationIdentity();

// Starts the editor (QApplication, main window, event loop) and returns the exit code.
int runEditor(int argc, char** argv);

} // namespace lr
