// Issue 37: the Mixer dock on synthetic RenderLayers (one image of known pixels per light group of a small
// rig): its preview is mixGroupImages of the mix its controls make, A/B shows the plain sum, Apply to rig
// changes the lights as applyLightMix does in one undo step keeping their ids, mix files round-trip and a
// bad one leaves the mix as it was; stale layers are said so.
#include "app/colorbutton.h"
#include "app/errordialog.h"
#include "app/mixerdock.h"
#include "app/mixergrouprow.h"
#include "app/mixerpreview.h"
#include "core/colour.h"
#include "core/lightmixfile.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <ctime>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

using namespace lr;

namespace {

// Two lights in group "key", one of its own ("Fill"), an ambient: groups key, Fill, ambient, background.
Rig mixerRig() {
    Rig rig;
    rig.ambient = glm::dvec3(0.02);
    for (const char* name : {"Key A", "Fill", "Key B"}) {
        Light l = makeLight(LightType::Point, QString::fromLatin1(name));
        l.position = {1.0, 2.0, 3.0};
        l.color = {0.9, 0.8, 0.7};
        l.intensity = 5.0;
        if (l.name.startsWith(QLatin1String("Key"))) l.group = QStringLiteral("key");
        rig.lights.push_back(l);
    }
    return rig;
}

// One image per group: group g's pixel (x, y) is a ramp of its own colour, so every group differs.
RenderLayers syntheticLayers(const Rig& rig, int width, int height) {
    RenderLayers layers;
    layers.groups = lightGroups(rig);
    for (size_t g = 0; g < layers.groups.size(); ++g) {
        FloatImage img;
        img.width = width;
        img.height = height;
        img.pixels.resize(size_t(width) * size_t(height));
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                img.at(x, y) = glm::vec4(0.05f * float(g + 1) * float(x + 1) / float(width),
                                         0.1f * float((y + int(g)) % height) / float(height),
                                         0.02f * float(g % 3), 1.0f);
        layers.groupImages.push_back(img);
    }
    layers.beauty = mixGroupImages(layers, LightMix{});
    return layers;
}

bool sameImage(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

// The largest difference of two display images in 8-bit levels (-1 when their sizes differ).
int levels(const QImage& a, const QImage& b) {
    if (a.size() != b.size() || a.isNull()) return -1;
    const QImage x = a.convertToFormat(QImage::Format_RGB888), y = b.convertToFormat(QImage::Format_RGB888);
    int worst = 0;
    for (int r = 0; r < x.height(); ++r)
        for (int c = 0; c < x.width() * 3; ++c)
            worst = std::max(worst, std::abs(int(x.constScanLine(r)[c]) - int(y.constScanLine(r)[c])));
    return worst;
}

} // namespace

class TestMixerDock : public QObject {
    Q_OBJECT

    std::unique_ptr<QMainWindow> m_window;
    Document* m_doc = nullptr;
    MixerDock* m_dock = nullptr;
    RenderLayers m_layers;
    QList<ErrorReport> m_errors;

    // What the dock should show for `mix`: the mixed layers reduced to its preview's size, displayed.
    QImage expectedPreview(const LightMix& mix, double ev, ToneMap toneMap) const {
        const FloatImage mixed = mixGroupImages(m_layers, mix);
        return displayImage(downscaleImage(mixed, m_dock->previewImage().size()), ev, toneMap);
    }
    QPushButton* button(const char* name) const {
        return m_dock->findChild<QPushButton*>(QLatin1String(name));
    }

  private slots:
    void initTestCase() {
        setErrorPresenter([this](const ErrorReport& r) { m_errors << r; });
    }
    void init() {
        m_errors.clear();
        m_window = std::make_unique<QMainWindow>();
        m_doc = new Document(m_window.get());
        m_doc->newRig(mixerRig());
        m_dock = new MixerDock(m_doc, m_window.get());
        m_window->addDockWidget(Qt::RightDockWidgetArea, m_dock);
        m_window->resize(900, 700);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_dock->askOpenPath = [](const QString&, const QString&) {
            qWarning("unexpected file dialog");
            return QString();
        };
        m_dock->askSavePath = [](const QString&, const QString&, const QString&) {
            qWarning("unexpected file dialog");
            return QString();
        };
        m_layers = syntheticLayers(m_doc->rig(), 96, 54);
        m_dock->setLayers(m_layers, QStringLiteral("synthetic, 1 sample"));
    }
    void cleanup() { m_window.reset(); }

    void rowsAndCaption() {
        QVERIFY(m_dock->hasLayers());
        QVERIFY(!m_dock->isStale());
        QCOMPARE(groupNames(m_layers.groups), (QStringList{"key", "Fill", "ambient", "background"}));
        for (const LightGroup& g : m_layers.groups)
            QVERIFY2(m_dock->row(g.name), qPrintable(g.name));
        const QString caption = m_dock->findChild<QLabel*>(QStringLiteral("mixerCaption"))->text();
        QVERIFY2(caption.contains(QStringLiteral("synthetic, 1 sample")) &&
                     caption.contains(QStringLiteral("96×54")),
                 qPrintable(caption));
        QVERIFY(m_dock->mix().isIdentity());
        QVERIFY(sameImage(m_dock->shownImage(), m_layers.beauty));
        QVERIFY(!m_dock->previewImage().isNull());
        QVERIFY(!button("mixerApply")->isEnabled()); // nothing to apply yet
        QSignalSpy capture(m_dock, &MixerDock::captureRequested);
        button("mixerCapture")->click();
        QCOMPARE(capture.count(), 1);
    }

    // The controls make the mix; the preview is that mix of the layers, redrawn at each change.
    void previewFollowsTheControls() {
        QSignalSpy changed(m_dock, &MixerDock::mixChanged);
        MixerGroupRow* key = m_dock->row(QStringLiteral("key"));
        key->evBox()->setValue(1.5);
        emit key->tintButton()->colorPicked(glm::dvec3(1.0, 0.6, 0.3));
        m_dock->row(QStringLiteral("Fill"))->onBox()->click();
        m_dock->row(QStringLiteral("ambient"))->slider()->setValue(-20); // tenths of an EV
        QCOMPARE(changed.count(), 4);
        LightMix want;
        want.groups[QStringLiteral("key")] = {true, 1.5, glm::dvec3(1.0, 0.6, 0.3)};
        want.groups[QStringLiteral("Fill")] = {false, 0.0, glm::dvec3(1.0)};
        want.groups[QStringLiteral("ambient")] = {true, -2.0, glm::dvec3(1.0)};
        QCOMPARE(m_dock->mix(), want);
        QCOMPARE(key->slider()->value(), 15); // the slider follows the spin box
        QVERIFY(sameImage(m_dock->shownImage(), mixGroupImages(m_layers, want)));
        QVERIFY(!sameImage(m_dock->shownImage(), m_layers.beauty));
        QCOMPARE(levels(m_dock->previewImage(), expectedPreview(want, 0.0, ToneMap::Aces)), 0);
        // The viewport's exposure and tone map.
        m_dock->setDisplay(1.0, ToneMap::Reinhard);
        QCOMPARE(levels(m_dock->previewImage(), expectedPreview(want, 1.0, ToneMap::Reinhard)), 0);
        // A double-click on the slider resets the group's EV (only).
        QTest::mouseDClick(key->slider(), Qt::LeftButton);
        QCOMPARE(m_dock->mix().of(QStringLiteral("key")).ev, 0.0);
        QCOMPARE(m_dock->mix().of(QStringLiteral("key")).tint, glm::dvec3(1.0, 0.6, 0.3));
        // Reset: the identity mix, the rows too.
        button("mixerReset")->click();
        QVERIFY(m_dock->mix().isIdentity());
        QVERIFY(m_dock->row(QStringLiteral("Fill"))->onBox()->isChecked());
        QCOMPARE(levels(m_dock->previewImage(), expectedPreview({}, 1.0, ToneMap::Reinhard)), 0);
    }

    // A larger render is reduced to the preview's size: still the mix, within a level of rounding.
    void largeLayersAreReduced() {
        m_layers = syntheticLayers(m_doc->rig(), 1280, 720);
        m_dock->setLayers(m_layers, QStringLiteral("large"));
        const QSize shown = m_dock->previewImage().size();
        QVERIFY2(shown.width() < 1280 && shown.width() > 0, qPrintable(QString::number(shown.width())));
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, 2.0, glm::dvec3(0.5, 1.0, 2.0)};
        m_dock->setMix(mix);
        QVERIFY(levels(m_dock->previewImage(), expectedPreview(mix, 0.0, ToneMap::Aces)) <= 1);
        QVERIFY(sameImage(m_dock->shownImage(), mixGroupImages(m_layers, mix)));
    }

    // A/B: the button (toggled) and holding the mouse on the image show the plain sum of the groups.
    void abShowsTheSum() {
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, -3.0, glm::dvec3(1.0)};
        m_dock->setMix(mix);
        const QImage mixed = m_dock->previewImage();
        FloatImage sum = m_layers.groupImages.front();
        for (size_t g = 1; g < m_layers.groupImages.size(); ++g)
            for (size_t i = 0; i < sum.pixels.size(); ++i)
                sum.pixels[i] += glm::vec4(glm::vec3(m_layers.groupImages[g].pixels[i]), 0.0f);
        button("mixerAB")->click();
        QVERIFY(m_dock->showsUnmixed());
        for (size_t i = 0; i < sum.pixels.size(); ++i)
            QVERIFY(glm::all(glm::lessThanEqual(
                glm::abs(glm::vec3(m_dock->shownImage().pixels[i]) - glm::vec3(sum.pixels[i])),
                glm::vec3(1e-6f))));
        QCOMPARE(levels(m_dock->previewImage(), expectedPreview({}, 0.0, ToneMap::Aces)), 0);
        QCOMPARE(m_dock->mix(), mix); // A/B shows, it does not change the mix
        button("mixerAB")->click();
        QCOMPARE(levels(m_dock->previewImage(), mixed), 0);
        auto* preview = m_dock->findChild<MixerPreview*>(QStringLiteral("mixerPreview"));
        QTest::mousePress(preview, Qt::LeftButton);
        QVERIFY(m_dock->showsUnmixed());
        QCOMPARE(levels(m_dock->previewImage(), expectedPreview({}, 0.0, ToneMap::Aces)), 0);
        QTest::mouseRelease(preview, Qt::LeftButton);
        QVERIFY(!m_dock->showsUnmixed());
        QCOMPARE(levels(m_dock->previewImage(), mixed), 0);
    }

    // Apply to rig: applyLightMix on the document's rig with the layers' groups, one undo step that undo
    // takes back exactly, ids (and the selection) kept; the mix is then the identity and the layers hold it.
    void applyToRig() {
        const Rig before = m_doc->rig();
        const QList<LightId> ids = m_doc->lightIds();
        m_doc->setSelectedRows({1}, 1);
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, 1.0, glm::dvec3(1.0, 0.5, 0.5)};
        mix.groups[QStringLiteral("Fill")] = {false, 0.0, glm::dvec3(1.0)};
        mix.groups[QStringLiteral("ambient")] = {true, -1.0, glm::dvec3(1.0)};
        m_dock->setMix(mix);
        QStringList notes;
        const Rig expected = applyLightMix(before, m_layers.groups, mix, &notes);
        QVERIFY(button("mixerApply")->isEnabled());
        button("mixerApply")->click();
        QCOMPARE(m_doc->rig(), expected);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(m_doc->lightIds(), ids);
        QCOMPARE(m_doc->selectedRows(), QList<int>{1});
        QCOMPARE(m_dock->notApplied(), notes);
        QVERIFY(m_dock->mix().isIdentity());
        // Everything was applied: the layers now hold the mix, current for the new rig.
        QVERIFY(!m_dock->isStale());
        const FloatImage want = mixGroupImages(m_layers, mix);
        const FloatImage shown = m_dock->shownImage();
        QCOMPARE(shown.pixels.size(), want.pixels.size());
        for (size_t i = 0; i < want.pixels.size(); ++i)
            QVERIFY(
                glm::all(glm::lessThanEqual(glm::abs(shown.pixels[i] - want.pixels[i]), glm::vec4(1e-6f))));
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->rig(), before);
        QCOMPARE(m_doc->lightIds(), ids);
        QVERIFY(m_dock->isStale()); // the layers took the mix; the rig no longer has it
        // What a rig cannot hold is listed: the background's tint.
        m_dock->setLayers(m_layers, QStringLiteral("again"));
        LightMix background;
        background.groups[QStringLiteral("background")] = {true, 0.0, glm::dvec3(0.5)};
        background.groups[QStringLiteral("key")] = {true, 1.0, glm::dvec3(1.0)};
        m_dock->setMix(background);
        QVERIFY(m_dock->applyToRig());
        QCOMPARE(m_dock->notApplied().size(), 1);
        QVERIFY(m_dock->notApplied()[0].startsWith(QStringLiteral("background")));
        QVERIFY(m_dock->findChild<QLabel*>(QStringLiteral("mixerNotes"))->isVisibleTo(m_dock));
        QVERIFY(m_dock->isStale()); // not all of it in the rig: the layers stay as rendered
    }

    void staleAfterARigEdit() {
        QLabel* stale = m_dock->findChild<QLabel*>(QStringLiteral("mixerStale"));
        QVERIFY(!stale->isVisibleTo(m_dock));
        QVERIFY(m_doc->setLightValue({1}, LightProperty::Intensity, 9.0));
        QVERIFY(m_dock->isStale());
        QVERIFY(stale->isVisibleTo(m_dock));
        // It keeps working: a mix still applies, to the lights by their ids.
        QVERIFY(m_doc->moveLights({1}, 0)); // Fill first now
        LightMix mix;
        mix.groups[QStringLiteral("Fill")] = {true, 1.0, glm::dvec3(1.0)};
        m_dock->setMix(mix);
        QVERIFY(m_dock->applyToRig());
        QCOMPARE(m_doc->light(0).name, QStringLiteral("Fill"));
        QCOMPARE(m_doc->light(0).intensity, 18.0);
        m_doc->undoStack()->setIndex(0);
        QVERIFY(!m_dock->isStale());
        QVERIFY(!stale->isVisibleTo(m_dock));
    }

    void saveThenOpenRoundTrips() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("look.mix.json"));
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, 0.7, glm::dvec3(1.0, 0.9, 0.8)};
        mix.groups[QStringLiteral("background")] = {false, 0.0, glm::dvec3(1.0)};
        m_dock->setMix(mix);
        m_dock->askSavePath = [&](const QString&, const QString&, const QString&) { return path; };
        QVERIFY(m_dock->saveMix());
        QVERIFY(QFile::exists(path));
        m_dock->resetMix();
        QVERIFY(m_dock->mix().isIdentity());
        m_dock->askOpenPath = [&](const QString&, const QString&) { return path; };
        QVERIFY(m_dock->openMix());
        QCOMPARE(m_dock->mix(), mix);
        QCOMPARE(m_dock->row(QStringLiteral("key"))->evBox()->value(), 0.7);
        QVERIFY(!m_dock->row(QStringLiteral("background"))->onBox()->isChecked());
        QVERIFY(m_errors.isEmpty());
    }

    void badMixFileLeavesTheMix() {
        QTemporaryDir dir;
        LightMix mix;
        mix.groups[QStringLiteral("Fill")] = {true, -1.0, glm::dvec3(1.0)};
        m_dock->setMix(mix);
        const auto write = [&](const char* name, const QByteArray& bytes) {
            QFile f(dir.filePath(QLatin1String(name)));
            if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", name);
            f.write(bytes);
            return f.fileName();
        };
        const QString badEv = write("ev.json", R"({"format": "lightrig-mix", "version": 1,
            "groups": {"key": {"enabled": true, "ev": 40, "tint": [1, 1, 1]}}})");
        const QString unknown = write("unknown.json", R"({"format": "lightrig-mix", "version": 1,
            "groups": {"rim": {"ev": 1}}})");
        QSignalSpy changed(m_dock, &MixerDock::mixChanged);
        QVERIFY(!m_dock->openMix(badEv));
        QVERIFY(!m_dock->openMix(unknown));
        QVERIFY(!m_dock->openMix(dir.filePath(QStringLiteral("missing.json"))));
        QCOMPARE(m_dock->mix(), mix);
        QCOMPARE(changed.count(), 0);
        QCOMPARE(m_errors.size(), 3);
        QVERIFY2(m_errors[0].details.join('\n').contains(QStringLiteral("groups.key.ev")),
                 qPrintable(m_errors[0].details.join('\n')));
        QVERIFY2(m_errors[1].details.join('\n').contains(QStringLiteral("key, Fill, ambient, background")),
                 qPrintable(m_errors[1].details.join('\n')));
        QVERIFY(m_errors[2].details.join('\n').contains(QStringLiteral("missing.json")));
    }

    // The preview's display is colour::displayColour's, byte for byte but where a value falls on a step's
    // edge, for every tone map and exposure, zero, negative, NaN and huge values included.
    void displayIsDisplayColour() {
        FloatImage img;
        img.width = 1024;
        img.height = 3;
        img.pixels.resize(size_t(img.width) * 3);
        for (int x = 0; x < img.width; ++x)
            for (int y = 0; y < 3; ++y)
                img.at(x, y) = glm::vec4(std::exp2(float(x - 512) / 24.0f), float(x) / 1024.0f * float(y),
                                         x % 97 == 0 ? -1.0f : float(y) * 0.01f, 1.0f);
        img.at(0, 0).x = std::nanf("");
        img.at(1, 0).x = 1e30f;
        int worst = 0, off = 0;
        for (ToneMap op : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces, ToneMap::Neutral, ToneMap::Agx})
            for (double ev : {-2.0, 0.0, 1.5}) {
                const QImage shown = displayImage(img, ev, op);
                for (int y = 0; y < 3; ++y)
                    for (int x = 0; x < img.width; ++x) {
                        const glm::dvec3 c =
                            colour::displayColour(glm::dvec3(img.at(x, y)), colour::exposureScale(ev), op);
                        for (int k = 0; k < 3; ++k) {
                            const int want = int(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
                            const int d = std::abs(int(shown.constScanLine(y)[3 * x + k]) - want);
                            worst = std::max(worst, d);
                            off += d > 0;
                        }
                    }
            }
        QVERIFY2(worst <= 1 && off < 20, qPrintable(QStringLiteral("worst %1, %2 off").arg(worst).arg(off)));
    }

    // Not an assertion (no timing asserts): how long a redraw takes at 640×360 with 8 groups, printed.
    void redrawTimeIsReported() {
        Rig rig;
        for (int i = 0; i < 7; ++i)
            rig.lights.push_back(makeLight(LightType::Point, QStringLiteral("L%1").arg(i)));
        m_doc->newRig(rig);
        m_layers = syntheticLayers(rig, 640, 360);
        QCOMPARE(int(m_layers.groups.size()), 8);
        m_dock->setLayers(m_layers, QStringLiteral("timing"));
        LightMix mix;
        mix.groups[QStringLiteral("L0")] = {true, 1.0, glm::dvec3(1.0)};
        // Wall and processor time per call (the processor's on a loaded machine).
        const int n = 20;
        const auto timed = [&](const auto& work) {
            QElapsedTimer t;
            t.start();
            const std::clock_t c = std::clock();
            for (int i = 0; i < n; ++i)
                work(i);
            return std::pair(t.nsecsElapsed() / 1e6 / n, double(std::clock() - c) * 1e3 / CLOCKS_PER_SEC / n);
        };
        const auto dock = timed([&](int i) {
            mix.groups[QStringLiteral("L0")].ev = 0.1 * i;
            m_dock->setMix(mix);
        });
        FloatImage mixed;
        const auto mixing = timed([&](int) { mixed = mixGroupImages(m_layers, mix); });
        const auto display = timed([&](int) { displayImage(mixed, 0.0, ToneMap::Aces); });
        QImage exact(mixed.width, mixed.height, QImage::Format_RGB888); // displayColour per channel
        const auto perChannel = timed([&](int) {
            for (int y = 0; y < mixed.height; ++y)
                for (int x = 0; x < mixed.width; ++x) {
                    const glm::dvec3 c =
                        colour::displayColour(glm::dvec3(mixed.at(x, y)), 1.0, ToneMap::Aces);
                    for (int k = 0; k < 3; ++k)
                        exact.scanLine(y)[3 * x + k] = uchar(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
                }
        });
        qInfo("a redraw at the preview's %dx%d: %.2f ms (%.2f ms processor); at 640x360: mixing 8 groups "
              "%.2f ms (%.2f), displaying %.2f ms (%.2f; with a pow per channel %.2f ms, %.2f)",
              m_dock->previewImage().width(), m_dock->previewImage().height(), dock.first, dock.second,
              mixing.first, mixing.second, display.first, display.second, perChannel.first,
              perChannel.second);
        // The dock as wide as in the editor's default layout (a tab in the 390 px right column).
        m_window->resize(390, 700);
        QTRY_VERIFY2(m_dock->previewImage().width() <= 390,
                     qPrintable(QStringLiteral("preview %1 px, dock %2 px, window %3 px")
                                    .arg(m_dock->previewImage().width())
                                    .arg(m_dock->width())
                                    .arg(m_window->width())));
        const auto narrow = timed([&](int i) {
            mix.groups[QStringLiteral("L0")].ev = -0.1 * i;
            m_dock->setMix(mix);
        });
        qInfo("a redraw at the preview's %dx%d: %.2f ms (%.2f ms processor)", m_dock->previewImage().width(),
              m_dock->previewImage().height(), narrow.first, narrow.second);
        QVERIFY(!m_dock->previewImage().isNull());
    }
};

QTEST_MAIN(TestMixerDock)
#include "tst_mixerdock.moc"
