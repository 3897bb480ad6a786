// The procedural studio's softbox list in Render settings' Environment box (issue 15, part 3): add, remove
// and select softboxes, and edit the selected one's azimuth, elevation, width, height, colour and intensity.
// It keeps no softboxes of its own: it shows the list it is given (setSoftboxes, from the document's rig)
// and proposes every edit as a whole new list (edited), which the box turns into one undo step; typing and
// arrow steps in a field are one continuous gesture, ended by gestureFinished.
#pragma once

#include "core/environment.h"

#include <QWidget>
#include <vector>

class QListWidget;
class QPushButton;

namespace lr {

class ColorButton;
class NumberEdit;

class SoftboxEditor : public QWidget {
    Q_OBJECT
  public:
    explicit SoftboxEditor(QWidget* parent = nullptr);

    void setSoftboxes(const std::vector<Softbox>& boxes); // keeps the selected row where it can
    int currentRow() const;
    void setCurrentRow(int row);
    QListWidget* list() const { return m_list; }

  signals:
    void edited(const std::vector<lr::Softbox>& boxes, bool continuous);
    void gestureFinished();
    void rejected(const QString& reason);

  private:
    void showCurrent();
    void editCurrent(void (*apply)(Softbox&, double), double value);

    std::vector<Softbox> m_boxes;
    QListWidget* m_list;
    QPushButton *m_add, *m_remove;
    NumberEdit *m_azimuth, *m_elevation, *m_width, *m_height, *m_intensity;
    ColorButton* m_color;
    QWidget* m_fields;
};

// "Softbox 2: 40° × 30° at azimuth 90°, elevation 30°".
QString softboxSummary(const Softbox& box, int index);

} // namespace lr
