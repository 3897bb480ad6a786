// The editor's main window as the app tests start it (tst_mainwindow, tst_friction, tst_newuser,
// tst_screenshotexport each had a copy): no session restore, the bundled Suzanne (the classic showcase the
// tests were written for; the editor itself opens on the Avocado sample) imported through the worker,
// the window shown, exposed and active, and a first frame rendered. Replace the file dialogs before calling
// it when a test must not see one.
#pragma once

#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editorapp.h"
#include "app/mainwindow.h"
#include "app/scene.h"
#include "app/viewport.h"
#include "editor/document.h"
#include "model/isolatedimport.h"

#include <QApplication>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QString>
#include <QTest>

namespace lr::test {

// What every app test does first: settings in Qt's test-mode folders under its own application name, cleared,
// and models imported by the built lightrig.
inline void prepareEditorTest(const QString& applicationName) {
    QStandardPaths::setTestModeEnabled(true);
    setApplicationIdentity();
    QCoreApplication::setApplicationName(applicationName);
    setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
    QSettings().clear();
}

// A new rig of one spot light half-way between the framed model and the camera, a little off-centre (in
// view, in front of the model). False when the light could not be added or placed.
inline bool spotInFrontOfTheModel(MainWindow& window) {
    Document* doc = window.document();
    doc->newRig(Rig{});
    if (!doc->addLight(LightType::Spot)) return false;
    window.viewport()->frameAll();
    const SceneFrame frame = window.scene()->frame();
    const ViewCamera cam = window.viewport()->camera();
    const glm::dvec3 world =
        frame.center + (cam.eye - frame.center) * 0.5 + cam.right() * (0.3 * frame.radius);
    return doc->setLightValue({0}, LightProperty::Position, QVariant::fromValue(world));
}

// An empty string when the window is ready, else what did not happen (for QVERIFY2).
inline QString startMainWindow(MainWindow& window) {
    QSignalSpy loaded(window.files(), &DocumentFiles::modelLoadFinished);
    EditorOptions options;
    options.restoreSession = false;
    options.modelPath = MainWindow::suzannePath();
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

// With LIGHTRIG_SHOTS=FOLDER set, saves the window as FOLDER/NAME.png (the screenshots, looked at by
// a person); otherwise nothing.
inline void shot(QWidget& window, const QString& name) {
    const QString dir = qEnvironmentVariable("LIGHTRIG_SHOTS");
    if (dir.isEmpty()) return;
    QTest::qWait(300); // a settled frame
    window.grab().save(dir + QLatin1Char('/') + name + QStringLiteral(".png"));
}

} // namespace lr::test
