// The editor's value widgets: the logarithmic intensity slider, validated number fields, HDR colours.
#include "app/colorbutton.h"
#include "app/logslider.h"
#include "app/numberedit.h"

#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <glm/geometric.hpp>

using namespace lr;

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
