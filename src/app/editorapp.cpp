#include "editorapp.h"

#include <QApplication>
#include <QLabel>
#include <QMainWindow>

namespace lr {
int runEditor(int argc, char** argv) {
    QApplication app(argc, argv);
    QMainWindow w;
    w.setCentralWidget(new QLabel(QStringLiteral("LightRig")));
    w.show();
    return app.exec();
}
}  // namespace lr
