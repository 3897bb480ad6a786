// The question before textures outside a model's folder are read (app/texturesconsent.h), through
// DocumentFiles::openModel and the import worker: Don't load keeps the model untextured and says so, Load
// imports it again with the textures; models without such textures are not asked about; a newer open
// while the question is up supersedes the asked one. The question is answered through the hook (no modal).
#include "app/documentfiles.h"
#include "app/errordialog.h"
#include "app/recentfiles.h"
#include "app/scene.h"
#include "app/texturesconsent.h"
#include "editor/document.h"
#include "model/isolatedimport.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

using namespace lr;

namespace {
const QString kOutside = QStringLiteral(LIGHTRIG_TEST_DATA "/texture-outside/model/quad.obj");
const QString kInside = QStringLiteral(LIGHTRIG_TEST_DATA "/model/quad.obj");
const QRgb kOrange = qRgb(255, 128, 0); // texture-outside/outside.png
} // namespace

class TestTexturesConsent : public QObject {
    Q_OBJECT

    struct Asked {
        QString path;
        QStringList references;
    };

    struct Editor {
        Document doc;
        Scene scene;
        RecentFiles recent;
        DocumentFiles files{&doc, &scene, &recent, nullptr};
        QList<Asked> asked;
        QStringList status;
        Editor() {
            QObject::connect(&files, &DocumentFiles::statusMessage, &files,
                             [this](const QString& text) { status << text; });
        }
        void answer(bool load) {
            files.askTexturesOutsideFolder = [this, load](const QString& path, const QStringList& refs) {
                asked << Asked{path, refs};
                return load;
            };
        }
        bool open(const QString& path) {
            QSignalSpy finished(&files, &DocumentFiles::modelLoadFinished);
            if (!files.openModel(path)) return false;
            // Load answers start a second import: wait until nothing is loading any more.
            for (int i = 0; i < 4 && files.isLoadingModel(); ++i)
                finished.wait(60'000);
            return !files.isLoadingModel();
        }
    };

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
        setErrorPresenter([this](const ErrorReport& r) { m_errors << r; });
    }
    void cleanup() { m_errors.clear(); }
    void dontLoadKeepsTheModelUntextured();
    void loadImportsAgainWithTheTexture();
    void modelInsideItsFolderIsNotAsked();
    void newerOpenWhileAskingSupersedes();
    void detailsListTenThenHowManyMore();

  private:
    QList<ErrorReport> m_errors;
};

void TestTexturesConsent::dontLoadKeepsTheModelUntextured() {
    Editor e;
    e.answer(false);
    QSignalSpy loaded(&e.files, &DocumentFiles::modelLoaded);
    QVERIFY(e.open(kOutside));
    QCOMPARE(e.asked.size(), 1);
    QCOMPARE(e.asked.at(0).path, kOutside);
    QCOMPARE(e.asked.at(0).references, QStringList{QStringLiteral("../outside.png")});
    QCOMPARE(loaded.size(), 1);
    QCOMPARE(e.scene.path(), kOutside);
    const Model& m = *e.scene.model();
    QVERIFY(m.textures.empty());
    QCOMPARE(m.materials.at(size_t(m.meshes.at(0).material)).baseColorTexture, -1);
    QVERIFY2(e.status.last().contains(QLatin1String("outside the model's folder not loaded")),
             qPrintable(e.status.last()));
    QVERIFY(m_errors.isEmpty());
}

void TestTexturesConsent::loadImportsAgainWithTheTexture() {
    Editor e;
    e.answer(true);
    QSignalSpy started(&e.files, &DocumentFiles::modelLoadStarted);
    QSignalSpy finished(&e.files, &DocumentFiles::modelLoadFinished);
    QSignalSpy loaded(&e.files, &DocumentFiles::modelLoaded);
    QVERIFY(e.open(kOutside));
    QCOMPARE(e.asked.size(), 1); // the second import, allowed, does not ask again
    QCOMPARE(started.size(), 2);
    QCOMPARE(finished.size(), 2);
    QCOMPARE(loaded.size(), 1);
    const Model& m = *e.scene.model();
    QCOMPARE(m.textures.size(), size_t(1));
    const int t = m.materials.at(size_t(m.meshes.at(0).material)).baseColorTexture;
    QCOMPARE(t, 0);
    QCOMPARE(m.textures.at(0).image.pixel(0, 0), kOrange);
    QVERIFY(m.texturesOutsideFolder.isEmpty());
    QVERIFY(m_errors.isEmpty());
}

void TestTexturesConsent::modelInsideItsFolderIsNotAsked() {
    Editor e;
    e.answer(true);
    QVERIFY(e.open(kInside));
    QVERIFY(e.asked.isEmpty());
    QCOMPARE(e.scene.model()->textures.size(), size_t(1));
    QVERIFY(m_errors.isEmpty());
}

void TestTexturesConsent::newerOpenWhileAskingSupersedes() {
    Editor e;
    e.files.askTexturesOutsideFolder = [&e](const QString& path, const QStringList& refs) {
        e.asked << Asked{path, refs};
        e.files.openModel(kInside); // e.g. a recent file chosen meanwhile
        return true;
    };
    QSignalSpy loaded(&e.files, &DocumentFiles::modelLoaded);
    QVERIFY(e.open(kOutside));
    QCOMPARE(e.asked.size(), 1);
    QCOMPARE(loaded.size(), 1);
    QCOMPARE(loaded.at(0).at(0).toString(), kInside);
    QCOMPARE(e.scene.path(), kInside);
    QVERIFY(m_errors.isEmpty());
}

void TestTexturesConsent::detailsListTenThenHowManyMore() {
    QStringList refs;
    for (int i = 0; i < 13; ++i)
        refs << QStringLiteral("../textures/t%1.png").arg(i);
    const QString many = texturesOutsideFolderDetails(QStringLiteral("/models/ship/ship.obj"), refs);
    QVERIFY2(many.contains(QLatin1String("ship.obj")), qPrintable(many));
    QVERIFY(many.contains(QLatin1String("t0.png")) && many.contains(QLatin1String("t9.png")));
    QVERIFY(!many.contains(QLatin1String("t10.png")));
    QVERIFY2(many.contains(QLatin1String("and 3 more")), qPrintable(many));
    const QString two = texturesOutsideFolderDetails(QStringLiteral("/models/ship/ship.obj"), refs.mid(0, 2));
    QVERIFY(two.contains(QLatin1String("t1.png")) && !two.contains(QLatin1String("more")));
}

QTEST_MAIN(TestTexturesConsent)
#include "tst_texturesconsent.moc"
