// A light's direction as azimuth and elevation in degrees, a row under the Properties dock's x, y, z
// direction. Rig space is y up (docs/rig-format.md) and a direction is where the light travels:
// elevation = asin(y), −90° shines straight down; azimuth = atan2(x, −z), 0° travels towards −Z (away from
// the default front camera), 90° towards +X, ±180° towards +Z. Editing one angle keeps each selected
// light's other angle; one typing or stepping gesture is one undo step.
#pragma once

#include <QTimer>
#include <QWidget>
#include <glm/vec3.hpp>
#include <memory>

class QFormLayout;

namespace lr {

class ContinuousEdit;
class Document;
class NumberEdit;

struct DirectionAngles {
    double azimuth = 0.0;   // degrees, (−180, 180]
    double elevation = 0.0; // degrees, [−90, 90]
};
// Of a non-zero direction (normalised first); the azimuth of a vertical one is 0.
DirectionAngles directionAngles(const glm::dvec3& direction);
// The unit direction of the angles.
glm::dvec3 directionFromAngles(const DirectionAngles& angles);

class DirectionAnglesEdit : public QWidget {
    Q_OBJECT
  public:
    DirectionAnglesEdit(Document* document, QFormLayout* form, QWidget* parent);
    ~DirectionAnglesEdit() override;
    NumberEdit* azimuth() const { return m_azimuth; }
    NumberEdit* elevation() const { return m_elevation; }
    void refresh(); // from the document: the current light's angles, and the row shown or hidden

  private:
    void apply(bool azimuth, double degrees);
    Document* m_doc;
    QFormLayout* m_form;
    NumberEdit* m_azimuth;
    NumberEdit* m_elevation;
    std::unique_ptr<ContinuousEdit> m_edit;
    QTimer m_idle; // ends the edit a second after the last step (arrows and wheel have no editingFinished)
};

// Inserts the azimuth/elevation row below `directionField`'s row of `form` (the field showing x, y, z);
// the row shows itself only while every selected light has a direction.
DirectionAnglesEdit* addDirectionAngles(QFormLayout* form, QWidget* directionField, Document* document);

} // namespace lr
