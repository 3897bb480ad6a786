// Issue 15 in Render settings: the Environment box (source, image file, intensity, rotation, background,
// blur, classic diffuse, the studio's colours and softboxes) edits the rig's environment as undoable
// document steps (a slider drag is one step), follows undo, redo and loaded rigs, stores a chosen file
// relative to the saved rig; and the background loading (environmentloading.h) feeds the Scene only what
// the rig currently asks for, re-loading for what needs re-filtering and not for intensity or rotation, and
// says which file could not be read without touching the rig.
#include "app/colorbutton.h"
#include "app/environmentbox.h"
#include "app/environmentloading.h"
#include "app/numberedit.h"
#include "app/rendersettingsdock.h"
#include "app/scene.h"
#include "app/softboxeditor.h"
#include "app/viewsettings.h"
#include "core/defaultrig.h"
#include "editor/document.h"
#include "editor/environmentvalue.h"
#include "scene/environmentloader.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;

namespace {
template <typename T> T* child(QObject* parent, const char* name) {
    T* w = parent->findChild<T*>(QLatin1String(name));
    if (!w) qWarning("no child %s", name);
    return w;
}

void activate(QComboBox* combo, int index) {
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

// A slider drag from press to release through these values.
void drag(QSlider* slider, std::initializer_list<int> values) {
    slider->setSliderDown(true);
    for (int v : values)
        slider->setValue(v);
    slider->setSliderDown(false);
}

// A left-button drag by the mouse: press at `from`, move `dx` pixels in a few steps, release.
void mouseDrag(QWidget* w, QPoint from, int dx, int steps = 4) {
    const auto send = [w](QEvent::Type type, QPoint p, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent e(type, QPointF(p), QPointF(w->mapToGlobal(p)), button, buttons, Qt::NoModifier);
        QApplication::sendEvent(w, &e);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i)
        send(QEvent::MouseMove, from + QPoint(dx * i / steps, 0), Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, from + QPoint(dx, 0), Qt::LeftButton, Qt::NoButton);
}

void type(NumberEdit* field, double value) {
    field->setValue(value);
    emit field->editingFinished();
}
} // namespace

class TestEnvironmentBox : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyControlIsOneUndoStep() {
        Document doc;
        doc.newRig(defaultRig());
        ViewSettings settings;
        RenderSettingsDock dock(&doc, &settings);
        EnvironmentBox* box = dock.environmentBox();
        QVERIFY(box && dock.findChild<EnvironmentBox*>() == box);
        auto* source = child<QComboBox>(box, "environmentSource");
        auto* file = child<QComboBox>(box, "environmentFile");
        auto* intensity = child<NumberEdit>(box, "environmentIntensity");
        auto* intensitySlider = child<QSlider>(box, "environmentIntensitySlider");
        auto* rotation = child<NumberEdit>(box, "environmentRotation");
        auto* rotationSlider = child<QSlider>(box, "environmentRotationSlider");
        auto* background = child<QComboBox>(box, "environmentBackground");
        auto* blur = child<NumberEdit>(box, "environmentBlur");
        auto* diffuse = child<QComboBox>(box, "environmentDiffuse");
        auto* zenith = child<ColorButton>(box, "studioZenith");
        auto* horizon = child<ColorButton>(box, "studioHorizon");
        auto* floor = child<ColorButton>(box, "studioFloor");
        QVERIFY(source && file && intensity && intensitySlider && rotation && rotationSlider && background &&
                blur && diffuse && zenith && horizon && floor);
        QCOMPARE(source->count(), enumCount<EnvironmentSource>());
        QCOMPARE(source->currentIndex(), int(EnvironmentSource::None));
        QVERIFY(!intensity->isEnabled()); // nothing to set without an environment
        const Rig before = doc.rig();
        QUndoStack* stack = doc.undoStack();
        int steps = 0;
        // One more undo step, named for the field it changed (issue 41: every edit was "Change environment").
        auto stepped = [&](const char* what, const char* text) {
            ++steps;
            if (stack->count() != steps)
                qWarning("%s: %d undo steps, expected %d", what, int(stack->count()), steps);
            else if (stack->text(steps - 1) != QLatin1String(text))
                qWarning("%s: the history says \"%s\", expected \"%s\"", what,
                         qPrintable(stack->text(steps - 1)), text);
            return stack->count() == steps && stack->text(steps - 1) == QLatin1String(text) &&
                   doc.rig().lights == before.lights;
        };

        activate(source, int(EnvironmentSource::Studio));
        QCOMPARE(int(doc.rig().environment.source), int(EnvironmentSource::Studio));
        QCOMPARE(doc.rig().environment.studio.softboxes.size(), size_t(1)); // a key softbox to start from
        QVERIFY(stepped("source", "Change environment source"));
        QVERIFY(intensity->isEnabled() && box->softboxEditor()->isVisibleTo(box));
        QVERIFY(!file->isVisibleTo(box));

        type(intensity, 1.5);
        QCOMPARE(doc.rig().environment.intensity, 1.5);
        QVERIFY(stepped("intensity", "Change environment intensity"));
        QCOMPARE(intensitySlider->value(), 15); // the slider follows the field (tenths of EV)
        mouseDrag(intensitySlider, intensitySlider->rect().center(), 60); // 40 px per EV
        QCOMPARE(doc.rig().environment.intensity, 3.0);
        QVERIFY(stepped("intensity drag", "Change environment intensity")); // the whole drag: one step
        QCOMPARE(intensity->value(), 3.0);

        drag(rotationSlider, {10, 45, 90, 135});
        QCOMPARE(doc.rig().environment.rotation, 135.0);
        QVERIFY(stepped("rotation drag", "Change environment rotation"));
        type(rotation, 200.0);
        QCOMPARE(doc.rig().environment.rotation, 200.0);
        QVERIFY(stepped("rotation", "Change environment rotation"));
        QCOMPARE(rotationSlider->value(), 200);

        QVERIFY(!blur->isEnabled()); // blur means something only for a blurred background
        activate(background, int(EnvironmentBackground::Blurred));
        QCOMPARE(int(doc.rig().environment.background), int(EnvironmentBackground::Blurred));
        QVERIFY(stepped("background", "Change environment background"));
        QVERIFY(blur->isEnabled());
        type(blur, 0.6);
        QCOMPARE(doc.rig().environment.blur, 0.6);
        QVERIFY(stepped("blur", "Change environment blur"));

        // Classic diffuse: enabled only under classic shading (and where the rig format has it).
        QCOMPARE(diffuse->isEnabled(), EnvironmentBox::hasClassicDiffuse());
        if (EnvironmentBox::hasClassicDiffuse()) {
            activate(diffuse, int(DiffuseModel::HalfLambert));
            QVERIFY(stepped("classic diffuse", "Change environment diffuse model"));
        }
        QVERIFY(doc.setRigValue(RigProperty::ShadingModel, QStringLiteral("pbr")));
        ++steps;
        QVERIFY(!diffuse->isEnabled());
        QVERIFY(doc.setRigValue(RigProperty::ShadingModel, QStringLiteral("classic")));
        ++steps;

        emit zenith->colorPicked(glm::dvec3(0.1, 0.2, 0.9));
        QVERIFY(stepped("zenith", "Change studio zenith colour"));
        emit horizon->colorPicked(glm::dvec3(0.9, 0.8, 0.7));
        QVERIFY(stepped("horizon", "Change studio horizon colour"));
        emit floor->colorPicked(glm::dvec3(0.05));
        QVERIFY(stepped("floor", "Change studio floor colour"));
        QCOMPARE(doc.rig().environment.studio.zenith, glm::dvec3(0.1, 0.2, 0.9));
        QCOMPARE(doc.rig().environment.studio.horizon, glm::dvec3(0.9, 0.8, 0.7));
        QCOMPARE(doc.rig().environment.studio.floor, glm::dvec3(0.05));

        // Softboxes: add, select, edit each value, remove.
        SoftboxEditor* boxes = box->softboxEditor();
        auto* add = child<QPushButton>(boxes, "addSoftbox");
        auto* remove = child<QPushButton>(boxes, "removeSoftbox");
        QVERIFY(add && remove);
        add->click();
        QVERIFY(stepped("add softbox", "Change studio softboxes"));
        QCOMPARE(doc.rig().environment.studio.softboxes.size(), size_t(2));
        QCOMPARE(boxes->list()->count(), 2);
        QCOMPARE(boxes->currentRow(), 1); // the new one is selected
        const std::pair<const char*, double Softbox::*> fields[] = {
            {"softboxAzimuth", &Softbox::azimuth},
            {"softboxElevation", &Softbox::elevation},
            {"softboxWidth", &Softbox::width},
            {"softboxHeight", &Softbox::height},
            {"softboxIntensity", &Softbox::intensity}};
        double value = 11.0;
        for (const auto& [name, member] : fields) {
            auto* field = child<NumberEdit>(boxes, name);
            QVERIFY(field);
            type(field, value);
            QCOMPARE(doc.rig().environment.studio.softboxes[1].*member, value);
            QVERIFY(stepped(name, "Change studio softboxes"));
            value += 3.0;
        }
        emit child<ColorButton>(boxes, "softboxColor")->colorPicked(glm::dvec3(1.0, 0.5, 0.25));
        QVERIFY(stepped("softbox colour", "Change studio softboxes"));
        QCOMPARE(doc.rig().environment.studio.softboxes[1].color, glm::dvec3(1.0, 0.5, 0.25));
        QCOMPARE(doc.rig().environment.studio.softboxes[0], Softbox{}); // only the selected one changed
        boxes->setCurrentRow(0);
        remove->click();
        QVERIFY(stepped("remove softbox", "Change studio softboxes"));
        QCOMPARE(doc.rig().environment.studio.softboxes.size(), size_t(1));
        QCOMPARE(doc.rig().environment.studio.softboxes[0].color, glm::dvec3(1.0, 0.5, 0.25));

        // An image: a bundled one to start with, the list offers the others.
        activate(source, int(EnvironmentSource::Image));
        QVERIFY(stepped("image source", "Change environment source"));
        QCOMPARE(doc.rig().environment.file, bundledEnvironmentFiles().first());
        QVERIFY(file->isVisibleTo(box) && !box->softboxEditor()->isVisibleTo(box));
        QCOMPARE(file->count(), int(bundledEnvironmentFiles().size()));
        activate(file, 1);
        QCOMPARE(doc.rig().environment.file, bundledEnvironmentFiles().at(1));
        QVERIFY(stepped("bundled file", "Change environment image"));
        const Rig after = doc.rig();

        // Everything undoes back to the rig before, the box showing it at each step; redo restores it all.
        while (stack->canUndo())
            stack->undo();
        QVERIFY(doc.rig() == before);
        QCOMPARE(source->currentIndex(), int(EnvironmentSource::None));
        QCOMPARE(intensity->value(), 0.0);
        QVERIFY(!intensity->isEnabled());
        while (stack->canRedo())
            stack->redo();
        QVERIFY(doc.rig() == after);
        QCOMPARE(source->currentIndex(), int(EnvironmentSource::Image));
        QCOMPARE(file->currentData().toString(), after.environment.file);
        QCOMPARE(intensity->value(), 3.0);
        QCOMPARE(rotation->value(), 200.0);
        stack->undo();
        stack->undo(); // back to the studio: its values in the box again
        QVERIFY(box->softboxEditor()->isVisibleTo(box));
        QCOMPARE(zenith->color(), glm::dvec3(0.1, 0.2, 0.9));
        QCOMPARE(boxes->list()->count(), 1);
    }

    // Issue 41 item 14: the intensity slider jumped +9.3 EV in 44 px. It steps like the lights' intensity
    // (logslider.h): a drag of 44 px is 1.1 EV, an arrow key ⅓ EV, each one undo step.
    void intensitySliderStepsInEv() {
        Document doc;
        Environment e;
        e.source = EnvironmentSource::Studio;
        e.studio.softboxes = {Softbox{}};
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        EnvironmentBox box(&doc);
        box.resize(420, 600);
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        auto* slider = child<QSlider>(&box, "environmentIntensitySlider");
        QVERIFY(slider && slider->width() > 100);
        const int steps = doc.undoStack()->count();
        mouseDrag(slider, slider->rect().center(), 44); // the handle sits at the centre (0 EV)
        QVERIFY2(std::abs(doc.rig().environment.intensity - 1.1) < 0.02,
                 qPrintable(QStringLiteral("44 px moved %1 EV").arg(doc.rig().environment.intensity)));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        const double dragged = doc.rig().environment.intensity;
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_Right);
        QVERIFY2(std::abs(doc.rig().environment.intensity - (dragged + 1.0 / 3.0)) < 0.01,
                 qPrintable(QString::number(doc.rig().environment.intensity)));
        QCOMPARE(doc.undoStack()->count(), steps + 2);
        QCOMPARE(doc.undoStack()->text(steps + 1), QStringLiteral("Change environment intensity"));
    }

    void outOfRangeIsRefusedWithTheField() {
        Document doc;
        Environment e;
        e.source = EnvironmentSource::Studio;
        e.studio.softboxes.resize(2);
        e.studio.softboxes[1].width = 0.0;
        QString error;
        QVERIFY(!doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e), &error));
        QVERIFY2(error.contains(QLatin1String("environment.studio.softboxes[1].width")), qPrintable(error));
        e.studio.softboxes[1].width = 30.0;
        e.intensity = 25.0;
        QVERIFY(!doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e), &error));
        QVERIFY2(error.contains(QLatin1String("environment.intensity")), qPrintable(error));
        e.intensity = 0.0;
        e.blur = NAN;
        QVERIFY(!doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e), &error));
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(doc.rig().environment.isNone());
    }

    void chosenFileIsRelativeToTheSavedRig() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("hdr")));
        const QString image = dir.filePath(QStringLiteral("hdr/sky.exr"));
        Document doc;
        EnvironmentBox box(&doc);
        box.chooseImageFile(image); // untitled: nothing to be relative to
        QCOMPARE(int(doc.rig().environment.source), int(EnvironmentSource::Image));
        QCOMPARE(doc.rig().environment.file, QDir::cleanPath(image));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.saveAs(dir.filePath(QStringLiteral("rig.json"))), QString());
        box.chooseImageFile(dir.filePath(QStringLiteral("other.hdr")));
        QCOMPARE(doc.rig().environment.file, QStringLiteral("other.hdr"));
        box.chooseImageFile(image);
        QCOMPARE(doc.rig().environment.file, QStringLiteral("hdr/sky.exr"));
        // The list shows the chosen file beside the bundled ones.
        auto* file = child<QComboBox>(&box, "environmentFile");
        QCOMPARE(file->currentData().toString(), QStringLiteral("hdr/sky.exr"));
        QCOMPARE(file->count(), int(bundledEnvironmentFiles().size()) + 1);
    }

    void followsALoadedRig() {
        Rig rig = defaultRig();
        rig.environment.source = EnvironmentSource::Studio;
        rig.environment.intensity = -1.5;
        rig.environment.rotation = 30.0;
        rig.environment.studio.softboxes = {Softbox{}, Softbox{}};
        Document doc;
        EnvironmentBox box(&doc);
        auto shows = [&box](const Rig& r) {
            return child<QComboBox>(&box, "environmentSource")->currentIndex() == int(r.environment.source) &&
                   child<NumberEdit>(&box, "environmentIntensity")->value() == r.environment.intensity &&
                   child<NumberEdit>(&box, "environmentRotation")->value() == r.environment.rotation &&
                   box.softboxEditor()->list()->count() == int(r.environment.studio.softboxes.size());
        };
        doc.newRig(rig); // a whole new rig (what a load, a preset or New does): the box shows it
        QVERIFY(shows(rig));
        doc.newRig(Rig{});
        QVERIFY(shows(Rig{}));
        QCOMPARE(box.softboxEditor()->list()->count(), 0);

        // From a file.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("env.json"));
        {
            Document saved;
            saved.newRig(rig);
            QCOMPARE(saved.saveAs(path), QString());
        }
        QCOMPARE(doc.load(path), QString());
        QVERIFY2(!doc.rig().environment.isNone(), "the saved rig file lost its environment");
        QVERIFY(shows(rig));
    }

    void loadsInTheBackgroundWhatTheRigAsks() {
        Document doc;
        Scene scene;
        EnvironmentLoading loading(&doc, &scene);
        EnvironmentBox box(&doc);
        box.setLoading(&loading);
        auto* status = child<QLabel>(&box, "environmentStatus");
        QSignalSpy busy(&loading, &EnvironmentLoading::loadingChanged);
        QSignalSpy sceneChanged(&scene, &Scene::environmentChanged);
        QVERIFY(!scene.environment());

        Environment e;
        e.source = EnvironmentSource::Studio;
        e.studio.softboxes = {Softbox{}};
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QVERIFY(loading.isLoading()); // not done on the window's thread: still loading right after the edit
        QCOMPARE(status->text(), QStringLiteral("Loading environment…"));
        QTRY_VERIFY_WITH_TIMEOUT(!loading.isLoading(), 30000);
        QVERIFY(scene.environment());
        QVERIFY(scene.environment()->spec.sameRadiance(doc.rig().environment));
        QVERIFY(!scene.environment()->image.isNull());
        QCOMPARE(busy.count(), 2); // started, finished
        QVERIFY(status->text().isEmpty());
        const auto first = scene.environment();

        // Intensity, rotation, background and blur: no new load, the same environment.
        e.intensity = 2.0;
        e.rotation = 90.0;
        e.background = EnvironmentBackground::Blurred;
        e.blur = 0.7;
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QVERIFY(!loading.isLoading());
        QCOMPARE(scene.environment(), first);
        QCOMPARE(busy.count(), 2);

        // Several softbox edits in a row: the last one wins, older results never reach the scene.
        for (int i = 1; i <= 5; ++i) {
            e.studio.softboxes[0].intensity = 4.0 + i;
            QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        }
        QTRY_VERIFY_WITH_TIMEOUT(!loading.isLoading(), 30000);
        QVERIFY(scene.environment() != first);
        QCOMPARE(scene.environment()->spec.studio.softboxes[0].intensity, 9.0);
        // Undo goes back to a load of the earlier studio.
        doc.undoStack()->undo();
        QTRY_VERIFY_WITH_TIMEOUT(!loading.isLoading(), 30000);
        QCOMPARE(scene.environment()->spec.studio.softboxes[0].intensity, 8.0);

        // None: nothing drawn at once.
        e.source = EnvironmentSource::None;
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QVERIFY(!scene.environment());
    }

    void aFileThatCannotBeReadSaysWhichAndLeavesTheRig() {
        QTemporaryDir dir;
        Document doc;
        QCOMPARE(doc.saveAs(dir.filePath(QStringLiteral("rig.json"))), QString());
        Scene scene;
        EnvironmentLoading loading(&doc, &scene);
        EnvironmentBox box(&doc);
        box.setLoading(&loading);
        QSignalSpy failed(&loading, &EnvironmentLoading::failed);
        Environment e;
        e.source = EnvironmentSource::Image;
        e.file = QStringLiteral("hdr/missing-sky.exr");
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        const Rig rig = doc.rig();
        QTRY_VERIFY_WITH_TIMEOUT(failed.count() == 1, 30000);
        const QString error = failed.at(0).at(0).toString();
        QVERIFY2(error.contains(QLatin1String("missing-sky.exr")), qPrintable(error));
        QCOMPARE(loading.lastError(), error);
        QVERIFY(doc.rig() == rig); // the rig keeps what it says
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(!scene.environment()); // nothing drawn for it
        QVERIFY2(child<QLabel>(&box, "environmentStatus")->text().contains(QLatin1String("missing-sky.exr")),
                 qPrintable(child<QLabel>(&box, "environmentStatus")->text()));
        // Changing only the intensity does not try again; the studio then loads fine.
        e.intensity = 1.0;
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QVERIFY(!loading.isLoading());
        e.source = EnvironmentSource::Studio;
        QVERIFY(doc.setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QTRY_VERIFY_WITH_TIMEOUT(scene.environment() != nullptr, 30000);
        QCOMPARE(failed.count(), 1);
        QVERIFY(loading.lastError().isEmpty());
    }
};

QTEST_MAIN(TestEnvironmentBox)
#include "tst_environmentbox.moc"
