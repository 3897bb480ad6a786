// The editor's main window as the app tests start it (tst_mainwindow, tst_friction, tst_newuser,
// tst_screenshotexport each had a copy): no session restore, the bundled model imported through the worker,
// the window shown, exposed and active, and a first frame rendered. Replace the file dialogs before calling
// it when a test must not see one.
#pragma once

#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/mainwindow.h"
#include "app/scene.h"
#include "app/viewport.h"

#include <QApplication>
#include <QSignalSpy>
#include <QString>
#include <QTest>

namespace lr::test {

// An empty string when the window is ready, else what did not happen (for QVERIFY2).
inline QString startMainWindow(MainWindow& window) {
    QSignalSpy loaded(window.files(), &DocumentFiles::modelLoadFinished);
    EditorOptions options;
    options.restoreSession = false;
    window.openInitial(options);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return QStringLiteral("the main window was never exposed");
    QApplication::setActiveWindow(&window);
    if (loaded.count() == 0 && !loaded.wait(60000))
        return QStringLiteral("the bundled model did not load in 60 s");
    if (window.scene()->isEmpty()) return QStringLiteral("the bundled model loaded empty");
    if (!QTest::qWaitFor([&] { return window.viewport()->hasRenderedFrame(); }, 30000))
        return QStringLiteral("the viewport rendered no frame in 30 s");
    return {};
}

} // namespace lr::test
