// Three NumberEdits for a position or direction. Edits are reported per component so that, with several
// lights selected, changing x moves every light's x and leaves their y and z alone. The edit of the vector
// finishes (editFinished) when focus leaves all three fields, not when it moves from x to y: typing x, y and
// z is one edit.
#pragma once

#include <QWidget>
#include <array>
#include <glm/vec3.hpp>

namespace lr {

class NumberEdit;

class Vec3Edit : public QWidget {
    Q_OBJECT
  public:
    explicit Vec3Edit(QWidget* parent = nullptr);
    void setLimits(double min, double max);
    void setWhat(const QString& what);
    void setValue(const glm::dvec3& v); // no signal
    glm::dvec3 value() const;
    NumberEdit* component(int axis) const { return m_edits[size_t(axis)]; }

  signals:
    void componentEdited(int axis, double value);
    void editFinished();
    void rejected(const QString& reason);
    void accepted();

  private:
    std::array<NumberEdit*, 3> m_edits{};
};

} // namespace lr
