#include "numberedit.h"

#include <QLineEdit>
#include <cmath>
#include <limits>
#include <utility>

namespace lr {

NumberEdit::NumberEdit(QWidget* parent) : QDoubleSpinBox(parent) {
    setDecimals(323); // no rounding of stored values; display is 'g' (textFromValue)
    setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    setKeyboardTracking(false);
    setAccelerated(true);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
    setRange(-1e30, 1e30);
    connect(this, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (!m_quiet) emit valueEdited(v);
    });
    connect(lineEdit(), &QLineEdit::textEdited, this, [this] {
        QString text = lineEdit()->text();
        int pos = 0;
        if (validate(text, pos) == QValidator::Acceptable) emit accepted();
    });
}

void NumberEdit::setLimits(double min, double max, bool minExclusive) {
    m_minExclusive = minExclusive;
    m_min = min;
    // QDoubleSpinBox rounds its range to `decimals` (323) places, which turns the denormal just above 0
    // into 0: use a small normal number instead. accepts() checks the exclusive bound itself.
    const double lo = !minExclusive ? min
                      : min == 0.0  ? 1e-300
                                    : std::nextafter(min, std::numeric_limits<double>::infinity());
    m_quiet = true;
    setRange(lo, max);
    m_quiet = false;
}

void NumberEdit::setValueQuietly(double v) {
    m_quiet = true;
    setValue(v);
    m_quiet = false;
}

QString NumberEdit::rule() const {
    const double lo = m_min;
    const QString name = m_what.isEmpty() ? tr("value") : m_what;
    return tr("%1 must be a number %2 %3 and ≤ %4")
        .arg(name, m_minExclusive ? QStringLiteral(">") : QStringLiteral("≥"), locale().toString(lo, 'g', 6),
             locale().toString(maximum(), 'g', 6));
}

bool NumberEdit::accepts(double v) const {
    return std::isfinite(v) && (m_minExclusive ? v > m_min : v >= m_min) && v <= maximum();
}

QString NumberEdit::stripAffixes(const QString& text) const {
    QString t = text;
    if (!prefix().isEmpty() && t.startsWith(prefix())) t.remove(0, prefix().size());
    if (!suffix().isEmpty() && t.endsWith(suffix())) t.chop(suffix().size());
    return t.trimmed();
}

QValidator::State NumberEdit::validate(QString& input, int& /*pos*/) const {
    const QString t = stripAffixes(input);
    if (t.isEmpty() || t == QLatin1String("-") || t == QLatin1String("+") || t == locale().decimalPoint() ||
        t.endsWith(QLatin1Char('e'), Qt::CaseInsensitive) || t.endsWith(QLatin1String("e-")) ||
        t.endsWith(QLatin1String("e+")))
        return QValidator::Intermediate;
    bool ok = false;
    const double v = locale().toDouble(t, &ok);
    auto refuse = [&](const QString& why) {
        emit const_cast<NumberEdit*>(this)->rejected(why);
        return QValidator::Invalid;
    };
    if (!ok) return refuse(tr("\"%1\" is not a number; %2").arg(t, rule()));
    if (!std::isfinite(v)) return refuse(tr("%1 is not finite; %2").arg(t, rule()));
    if (accepts(v)) return QValidator::Acceptable;
    // A value below a positive minimum may still grow into range as digits are typed ("0" → "0.5").
    if (v >= 0.0 && !(v > m_min && v >= minimum()) && maximum() > 0.0) {
        emit const_cast<NumberEdit*>(this)->rejected(rule());
        return QValidator::Intermediate;
    }
    return refuse(tr("%1 is out of range: %2").arg(t, rule()));
}

void NumberEdit::setBlank(bool blank) {
    if (blank == m_blank) return;
    m_blank = blank;
    // Changing the suffix re-renders the text (textFromValue).
    if (blank) {
        m_suffix = suffix();
        setSuffix(QString());
    } else {
        setSuffix(std::exchange(m_suffix, QString()));
    }
}

QString NumberEdit::textFromValue(double value) const {
    if (m_blank) return QString();
    QString s = locale().toString(value, 'g', 7);
    s.remove(locale().groupSeparator());
    return s;
}

double NumberEdit::valueFromText(const QString& text) const {
    // The shown text of the current value is rounded to 7 digits: reading it back (Return, focus out) must
    // keep the exact stored value, not replace it with the rounded one (tests/safety/tst_uivalues.cpp).
    if (stripAffixes(text) == textFromValue(value()).trimmed()) return value();
    bool ok = false;
    const double v = locale().toDouble(stripAffixes(text), &ok);
    return ok && std::isfinite(v) ? v : value();
}

} // namespace lr
