// A QDoubleSpinBox for the rig's numbers: shown with significant digits ('g') so 1e-6 and 1e6 both read
// well, stepped adaptively, and validated as typed. Input outside the allowed range (optionally with an
// exclusive minimum, "> 0") is refused in place and `rejected` says why; only valid values are emitted.
#pragma once

#include <QDoubleSpinBox>

namespace lr {

class NumberEdit : public QDoubleSpinBox {
    Q_OBJECT
  public:
    explicit NumberEdit(QWidget* parent = nullptr);

    // [min, max], or (min, max] when minExclusive. `what` names the value in reasons ("range").
    void setLimits(double min, double max, bool minExclusive = false);
    void setWhat(const QString& what) { m_what = what; }
    void setValueQuietly(double v); // no valueEdited
    // Shows nothing (no number, no suffix) until cleared: an optional value the light does not have.
    void setBlank(bool blank);
    bool isBlank() const { return m_blank; }
    // "must be a number > 0 and ≤ 1e+30" — the rule the reason texts state.
    QString rule() const;
    // Whether `v` is allowed (finite and in range).
    bool accepts(double v) const;

    QValidator::State validate(QString& input, int& pos) const override;
    QString textFromValue(double value) const override;
    double valueFromText(const QString& text) const override;

  signals:
    void valueEdited(double value);       // the user changed the value (typing, arrows, wheel)
    void rejected(const QString& reason); // the user typed something not allowed; nothing was stored
    void accepted();                      // input is valid again (clears a shown reason)

  private:
    QString stripAffixes(const QString& text) const;
    bool m_minExclusive = false;
    double m_min = -1e30;
    bool m_quiet = false;
    bool m_blank = false;
    QString m_suffix; // while blank
    QString m_what;
};

} // namespace lr
