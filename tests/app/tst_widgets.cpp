// The editor's value widgets: the logarithmic intensity slider, validated number fields, HDR colours.
#include "app/colorbutton.h"
#include "app/logslider.h"
#include "app/numberedit.h"

#include <QApplication>
#include <QLineEdit>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <glm/geometric.hpp>

using namespace lr;

namespace {
void mouse(QWidget* w, QEvent::Type type, double x, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    const QPointF pos(x, w->height() / 2.0);
    const Qt::MouseButton button = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    const Qt::MouseButtons held = type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent e(type, pos, w->mapToGlobal(pos), button, held, mods);
    QApplication::sendEvent(w, &e);
}
// Drags the slider from x0 to x1 in steps of 5 px (the moves carry `mods`); no release.
void dragSlider(QWidget* w, double x0, double x1, Qt::KeyboardModifiers mods = Qt::NoModifier) {
    const int steps = std::max(1, int(std::abs(x1 - x0) / 5.0));
    for (int i = 1; i <= steps; ++i)
        mouse(w, QEvent::MouseMove, x0 + (x1 - x0) * i / steps, mods);
}
} // namespace

class TestWidgets : public QObject {
    Q_OBJECT
  private slots:
    void logSlider_coversZeroToAMillionMonotonically() {
        LogSliderEdit e;
        e.setLimits(1e-3, 1e6);
        QCOMPARE(e.valueAt(0), 0.0);
        QCOMPARE(e.valueAt(LogSliderEdit::kSteps), 1e6);
        QCOMPARE(e.positionFor(0.0), 0);
        QCOMPARE(e.positionFor(1e6), LogSliderEdit::kSteps);
        double previous = 0.0;
        for (int p = 1; p <= LogSliderEdit::kSteps; ++p) {
            const double v = e.valueAt(p);
            QVERIFY2(v >= previous, qPrintable(QString::number(p)));
            // Round trip within a step: slider -> value -> slider.
            QVERIFY(std::abs(e.positionFor(v) - p) <= 1);
            previous = v;
        }
        // Each decade gets about the same share of the slider (logarithmic, not linear).
        const int d1 = e.positionFor(10.0) - e.positionFor(1.0), d2 = e.positionFor(1e5) - e.positionFor(1e4);
        QVERIFY(std::abs(d1 - d2) <= 2);
    }

    void logSlider_emitsEditsAndGestureEnd() {
        LogSliderEdit e;
        QSignalSpy edited(&e, &LogSliderEdit::valueEdited), finished(&e, &LogSliderEdit::editFinished);
        e.setValue(5.0);
        QCOMPARE(edited.count(), 0); // programmatic: no edit
        QCOMPARE(e.value(), 5.0);
        e.slider()->setValue(e.positionFor(100.0));
        QCOMPARE(edited.count(), 1);
        QVERIFY(std::abs(e.value() - 100.0) / 100.0 < 0.02);
        emit e.slider()->sliderReleased();
        QCOMPARE(finished.count(), 1);
    }

    // Issue 12 item 5: 75 px of drag took 1 to 3620 (absolute log scale over 1e-3..1e6). Now a drag is
    // relative in EV: 40 px doubles, Shift is 10x finer, Ctrl is 4x coarser in whole EV steps.
    void logSlider_dragIsRelativeInEv() {
        LogSliderEdit e;
        e.setLimits(1e-3, 1e6);
        e.resize(400, 30);
        e.show();
        QVERIFY(QTest::qWaitForWindowExposed(&e));
        QWidget* s = e.slider();
        QSignalSpy edited(&e, &LogSliderEdit::valueEdited), finished(&e, &LogSliderEdit::editFinished);

        e.setValue(1.0);
        mouse(s, QEvent::MouseButtonPress, 20); // a press does not jump to the position under the mouse
        QCOMPARE(e.value(), 1.0);
        dragSlider(s, 20, 95); // 75 px: 75/40 EV
        QVERIFY2(std::abs(e.value() - std::exp2(75.0 / 40.0)) < 0.02, qPrintable(QString::number(e.value())));
        QVERIFY(edited.count() > 5); // continuous
        dragSlider(s, 95, 20);       // back where it started: the value it started with
        QCOMPARE(e.value(), 1.0);
        mouse(s, QEvent::MouseButtonRelease, 20);
        QCOMPARE(finished.count(), 1);

        // The same 75 px near 5000 is the same factor: fine at any magnitude.
        e.setValue(5000.0);
        mouse(s, QEvent::MouseButtonPress, 300);
        dragSlider(s, 300, 225);
        QVERIFY2(std::abs(e.value() / 5000.0 - std::exp2(-75.0 / 40.0)) < 0.01,
                 qPrintable(QString::number(e.value())));
        mouse(s, QEvent::MouseButtonRelease, 225);

        // Shift: ten times finer.
        e.setValue(2.0);
        mouse(s, QEvent::MouseButtonPress, 20);
        dragSlider(s, 20, 100, Qt::ShiftModifier); // 80 px = 0.2 EV
        QVERIFY2(std::abs(e.value() - 2.0 * std::exp2(0.2)) < 0.01, qPrintable(QString::number(e.value())));
        mouse(s, QEvent::MouseButtonRelease, 100);

        // Ctrl: coarse, in whole EV steps (powers of two from the start).
        e.setValue(3.0);
        mouse(s, QEvent::MouseButtonPress, 20);
        dragSlider(s, 20, 65, Qt::ControlModifier); // 45 px * 4 / 40 = 4.5 EV: snaps to a whole EV
        const double ev = std::log2(e.value() / 3.0);
        QVERIFY2(std::abs(ev - std::round(ev)) < 0.01 && ev >= 4.0, qPrintable(QString::number(ev)));
        mouse(s, QEvent::MouseButtonRelease, 65);

        // Far drags stop at the limits; arrow keys step a third of an EV, one gesture each.
        e.setValue(1.0);
        mouse(s, QEvent::MouseButtonPress, 0);
        dragSlider(s, 0, 2000, Qt::ControlModifier);
        QCOMPARE(e.value(), 1e6);
        mouse(s, QEvent::MouseButtonRelease, 2000);
        e.setValue(8.0);
        const int before = finished.count();
        QTest::keyClick(s, Qt::Key_Left);
        QVERIFY(std::abs(e.value() - 8.0 * std::exp2(-1.0 / 3.0)) < 0.01);
        QCOMPARE(finished.count(), before + 1);
    }

    // The typed field keeps exactly what was typed (no rounding to a slider step).
    void logSlider_typedValueIsExact() {
        LogSliderEdit e;
        e.setLimits(1e-3, 1e6);
        e.show();
        QVERIFY(QTest::qWaitForWindowExposed(&e));
        QSignalSpy edited(&e, &LogSliderEdit::valueEdited);
        QLineEdit* line = e.spinBox()->findChild<QLineEdit*>();
        QVERIFY(line);
        e.spinBox()->setFocus();
        line->selectAll();
        QTest::keyClicks(line, QStringLiteral("1234.5678"));
        QTest::keyClick(line, Qt::Key_Return);
        QCOMPARE(e.value(), 1234.5678);
        QVERIFY(edited.count() > 0);
        QCOMPARE(edited.last().at(0).toDouble(), 1234.5678);
        QCOMPARE(e.slider()->value(), e.positionFor(1234.5678)); // the handle shows it
    }

    void numberEdit_validatesAsTyped() {
        NumberEdit e;
        e.setLimits(0.0, 90.0, true);
        e.setWhat(QStringLiteral("outer"));
        QSignalSpy rejected(&e, &NumberEdit::rejected);
        int pos = 0;
        QString t = QStringLiteral("45");
        QCOMPARE(e.validate(t, pos), QValidator::Acceptable);
        t = QStringLiteral("91");
        QCOMPARE(e.validate(t, pos), QValidator::Invalid);
        t = QStringLiteral("abc");
        QCOMPARE(e.validate(t, pos), QValidator::Invalid);
        t = QStringLiteral("inf");
        QCOMPARE(e.validate(t, pos), QValidator::Invalid);
        t = QStringLiteral("nan");
        QCOMPARE(e.validate(t, pos), QValidator::Invalid);
        t = QStringLiteral("0"); // the minimum is exclusive, but "0.5" may follow
        QCOMPARE(e.validate(t, pos), QValidator::Intermediate);
        t = QStringLiteral("-");
        QCOMPARE(e.validate(t, pos), QValidator::Intermediate);
        QVERIFY(rejected.count() >= 4);
        QVERIFY(rejected.last().at(0).toString().contains(QLatin1String("outer")));
        QVERIFY(!e.accepts(0.0) && e.accepts(1e-9) && e.accepts(90.0) && !e.accepts(90.0001));

        e.setSuffix(QStringLiteral("°"));
        t = QStringLiteral("30°");
        QCOMPARE(e.validate(t, pos), QValidator::Acceptable);
        QCOMPARE(e.valueFromText(t), 30.0);
    }

    void numberEdit_showsWideRangesReadably_andKeepsExactValues() {
        NumberEdit e;
        e.setLimits(0.0, 1e12);
        e.setValueQuietly(1234567.891);
        QCOMPARE(e.value(), 1234567.891); // no rounding to a fixed number of decimals
        QVERIFY(e.textFromValue(1e-7).contains(QLatin1String("e-07")));
        QVERIFY(!e.textFromValue(1234567.0).contains(QLatin1Char(',')));
    }

    void colorButton_keepsHdrBrightness() {
        const glm::dvec3 hdr(15.0, 0.0, 0.0); // the book's red point light
        QCOMPARE(ColorButton::hdrScale(hdr), 15.0);
        const QColor shown = ColorButton::toDisplay(hdr);
        QCOMPARE(shown, QColor(255, 0, 0));
        const glm::dvec3 back = ColorButton::fromDisplay(shown, ColorButton::hdrScale(hdr));
        QVERIFY(std::abs(back.r - 15.0) < 1e-9 && back.g == 0.0);
        // 8-bit sRGB round trip of an LDR colour stays within a code value.
        const glm::dvec3 ldr(0.2, 0.5, 0.9);
        const glm::dvec3 rt = ColorButton::fromDisplay(ColorButton::toDisplay(ldr), 1.0);
        QVERIFY(glm::length(rt - ldr) < 0.01);
    }
};

QTEST_MAIN(TestWidgets)
#include "tst_widgets.moc"
