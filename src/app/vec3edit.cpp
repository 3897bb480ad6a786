#include "vec3edit.h"

#include "numberedit.h"

#include <QHBoxLayout>

namespace lr {

Vec3Edit::Vec3Edit(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    static const char* const names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        auto* e = new NumberEdit(this);
        e->setObjectName(QString::fromLatin1(names[axis]));
        e->setToolTip(QString::fromLatin1(names[axis]));
        e->setMinimumWidth(40);
        e->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        layout->addWidget(e);
        m_edits[size_t(axis)] = e;
        connect(e, &NumberEdit::valueEdited, this, [this, axis](double v) { emit componentEdited(axis, v); });
        // Moving between x, y and z is one edit: it finishes when focus leaves the three fields.
        // (A spin box reports editingFinished on focus out, when the window's focus has already moved.)
        connect(e, &QAbstractSpinBox::editingFinished, this, [this] {
            const QWidget* focus = window()->focusWidget();
            if (!focus || !isAncestorOf(focus)) emit editFinished();
        });
        connect(e, &NumberEdit::rejected, this, &Vec3Edit::rejected);
        connect(e, &NumberEdit::accepted, this, &Vec3Edit::accepted);
    }
}

void Vec3Edit::setLimits(double min, double max) {
    for (auto* e : m_edits)
        e->setLimits(min, max);
}

void Vec3Edit::setWhat(const QString& what) {
    static const char* const names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis)
        m_edits[size_t(axis)]->setWhat(what + QLatin1Char('.') + QLatin1String(names[axis]));
}

void Vec3Edit::setValue(const glm::dvec3& v) {
    for (int axis = 0; axis < 3; ++axis)
        m_edits[size_t(axis)]->setValueQuietly(v[axis]);
}

glm::dvec3 Vec3Edit::value() const {
    return {m_edits[0]->value(), m_edits[1]->value(), m_edits[2]->value()};
}

} // namespace lr
