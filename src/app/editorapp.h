#pragma once

namespace lr {
// Starts the editor (QApplication, main window, event loop) and returns the exit code.
int runEditor(int argc, char** argv);
}
