// Issue 39: the Properties dock's file rows (an IES profile, a gobo image) have a "…" button that chooses
// the file: it starts in the rig's folder, offers the row's file types, stores the file relative to the
// rig's folder when it lies there (else absolute), and is one undo step; cancelling changes nothing.
#include "app/propertiesdock.h"
#include "app/propertyfields.h"
#include "editor/document.h"

#include <QDir>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

using namespace lr;

class TestFileFields : public QObject {
    Q_OBJECT
  private slots:
    void theValueIsRelativeInsideTheRigsFolder() {
        QCOMPARE(fileFieldValue(QStringLiteral("/a/b/ies/down.ies"), QStringLiteral("/a/b/rig.json")),
                 QStringLiteral("ies/down.ies"));
        QCOMPARE(fileFieldValue(QStringLiteral("/a/b/down.ies"), QStringLiteral("/a/b/rig.json")),
                 QStringLiteral("down.ies"));
        QCOMPARE(fileFieldValue(QStringLiteral("/a/c/down.ies"), QStringLiteral("/a/b/rig.json")),
                 QStringLiteral("/a/c/down.ies")); // outside: absolute, never "../"
        QCOMPARE(fileFieldValue(QStringLiteral("/a/b/x/../down.ies"), QString()),
                 QStringLiteral("/a/b/down.ies"));
    }

    void theButtonChoosesTheFileInOneStep() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Document doc;
        QVERIFY(doc.addLight(LightType::Spot));
        const QString rigPath = dir.filePath(QStringLiteral("rig.json"));
        QVERIFY2(doc.saveAs(rigPath).isEmpty(), "saving the rig");
        PropertiesDock dock(&doc);
        dock.show();
        doc.setSelectedRows({0}, 0);
        QString askedFolder, askedFilter;
        QString answer = dir.filePath(QStringLiteral("gobos/window.png"));
        dock.askOpenFile = [&](const QString&, const QString& folder, const QString& filter) {
            askedFolder = folder, askedFilter = filter;
            return answer;
        };
        auto* browse = dock.findChild<QToolButton*>(QStringLiteral("goboFileBrowse"));
        QVERIFY(browse && browse->isVisibleTo(&dock));
        const int steps = doc.undoStack()->count();
        browse->click();
        QCOMPARE(QDir(askedFolder).canonicalPath(), QDir(dir.path()).canonicalPath()); // the rig's folder
        QVERIFY2(askedFilter.contains(QStringLiteral("*.png")) &&
                     askedFilter.contains(QStringLiteral("*.exr")),
                 qPrintable(askedFilter));
        QVERIFY(doc.light(0).gobo);
        QCOMPARE(doc.light(0).gobo->file, QStringLiteral("gobos/window.png"));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        auto* line = dock.field(LightProperty::GoboFile)->findChild<QLineEdit*>();
        QVERIFY(line);
        QCOMPARE(line->text(), QStringLiteral("gobos/window.png"));

        answer.clear(); // cancelled: nothing changes, and the dialog started beside the current file
        browse->click();
        QCOMPARE(QFileInfo(askedFolder).fileName(), QStringLiteral("gobos"));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QCOMPARE(doc.light(0).gobo->file, QStringLiteral("gobos/window.png"));

        // The IES row offers IES files.
        answer = QStringLiteral("/elsewhere/down.ies");
        auto* ies = dock.findChild<QToolButton*>(QStringLiteral("iesFileBrowse"));
        QVERIFY(ies && ies->isVisibleTo(&dock));
        ies->click();
        QVERIFY2(askedFilter.contains(QStringLiteral("*.ies")), qPrintable(askedFilter));
        QVERIFY(doc.light(0).ies);
        QCOMPARE(doc.light(0).ies->file, QStringLiteral("/elsewhere/down.ies"));
    }
};

QTEST_MAIN(TestFileFields)
#include "tst_filefields.moc"
