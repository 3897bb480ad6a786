#include "editorapp.h"

#include "commandline.h"
#include "documentfiles.h"
#include "editor/document.h"
#include "mainwindow.h"
#include "presetsdock.h"
#include "render/imagefile.h"
#include "sessionsafety.h"
#include "viewport.h"
#include "viewsettings.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstdio>

namespace lr {

namespace {

// README screenshot mode: wait for the model and a rendered frame, select a spot light (adding one when the
// rig has none), let the window settle, grab it and quit. Exit code 0 on success, 1 when it cannot.
void scheduleScreenshot(MainWindow* window, const QString& path) {
    auto grab = [window, path] {
        Document* doc = window->document();
        int spot = -1;
        for (int i = 0; i < doc->lightCount() && spot < 0; ++i)
            if (doc->light(i).type == LightType::Spot) spot = i;
        if (spot < 0) {
            doc->addLight(LightType::Spot);
            spot = doc->lightCount() - 1;
        }
        doc->setSelectedRows({spot}, spot);
        window->viewport()->frameModelAndLights({spot});
        // Let the preset thumbnails finish and the selection be painted, then grab.
        auto* poll = new QTimer(window);
        poll->setInterval(200);
        QObject::connect(poll, &QTimer::timeout, window, [window, path, poll] {
            if (window->presetsDock()->thumbnailsPending()) return;
            poll->deleteLater();
            window->viewport()->update();
            QTimer::singleShot(400, window, [window, path] {
                const QImage image = window->grab().toImage();
                const QString reason = writeImageAtomically(image, path);
                const bool ok = reason.isEmpty();
                if (ok)
                    std::fprintf(stdout, "lightrig: wrote %s (%dx%d)\n",
                                 qPrintable(QDir::toNativeSeparators(path)), image.width(), image.height());
                else
                    std::fprintf(stderr, "lightrig: could not write %s: %s\n",
                                 qPrintable(QDir::toNativeSeparators(path)), qPrintable(reason));
                QCoreApplication::exit(ok ? 0 : 1);
            });
        });
        poll->start();
    };
    auto waitForFrame = [window, grab] {
        if (window->viewport()->hasRenderedFrame())
            grab();
        else
            QObject::connect(window->viewport(), &Viewport::firstFrame, window, grab,
                             Qt::SingleShotConnection);
    };
    QObject::connect(window->files(), &DocumentFiles::modelLoadFinished, window, waitForFrame,
                     Qt::SingleShotConnection);
    QTimer::singleShot(120000, window, [path] {
        std::fprintf(stderr, "lightrig: gave up on the screenshot %s after 120 s\n", qPrintable(path));
        QCoreApplication::exit(1);
    });
}

// Whether a platform for the GUI is given: a display in the environment, a platform chosen there or with
// Qt's -platform option.
bool displayGiven(int argc, char** argv) {
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        if (qEnvironmentVariableIsSet(name)) return true;
    for (int i = 1; i < argc; ++i)
        if (qstrcmp(argv[i], "-platform") == 0 || qstrcmp(argv[i], "--platform") == 0) return true;
    return false;
}

} // namespace

void setApplicationIdentity() {
    QCoreApplication::setOrganizationName(QStringLiteral("LightRig"));
    QCoreApplication::setOrganizationDomain(QStringLiteral("lightrig.example"));
    QCoreApplication::setApplicationName(QStringLiteral("lightrig"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LIGHTRIG_VERSION));
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        QGuiApplication::setApplicationDisplayName(QStringLiteral("LightRig"));
}

int runEditor(int argc, char** argv) {
    if (!displayGiven(argc, argv)) {
        // Without a display QApplication would abort inside Qt's platform plugin: answer --help, --version
        // and usage errors without a GUI, and say what the editor needs.
        QCoreApplication cli(argc, argv);
        setApplicationIdentity();
        const CommandLineResult cl = parseEditorCommandLine(QCoreApplication::arguments());
        if (!cl.options) {
            std::fputs(qPrintable(cl.message), cl.exitCode == 0 ? stdout : stderr);
            return cl.exitCode;
        }
        std::fputs("lightrig: the editor needs a display (X11 or Wayland); without one, run it under "
                   "xvfb-run -a, or use a subcommand (render, validate, format, bench: lightrig --help)\n",
                   stderr);
        return 1;
    }
    Viewport::setDefaultSurfaceFormat(); // before the QApplication: OpenGL 3.3 core for every context
    QApplication app(argc, argv); // takes Qt's own options (-style, -platform, ...) out of the arguments
    setApplicationIdentity();
    const CommandLineResult cl = parseEditorCommandLine(QCoreApplication::arguments());
    if (!cl.options) {
        std::fputs(qPrintable(cl.message), cl.exitCode == 0 ? stdout : stderr);
        return cl.exitCode;
    }
    MainWindow window;
    window.openInitial(*cl.options);
    // Autosave, crash recovery, on-disk change checks (issue 6; sessionsafety.h). Recovery is offered only in
    // interactive runs: --no-restore and screenshot mode are scripted and must not stop at a question.
    installSessionSafety(&window, cl.options->restoreSession);
    if (!cl.options->screenshotPath.isEmpty()) {
        // The same picture on every machine: default view settings, not the user's (and not saved).
        window.viewSettings()->setPersistent(false);
        window.viewSettings()->setOptions(ViewOptions{});
        window.resize(1600, 1000);
        scheduleScreenshot(&window, QFileInfo(cl.options->screenshotPath).absoluteFilePath());
    }
    window.show();
    return app.exec();
}

} // namespace lr
