#include "softboxeditor.h"

#include "colorbutton.h"
#include "editor/environmentvalue.h"
#include "numberedit.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lr {

QString softboxSummary(const Softbox& b, int index) {
    return SoftboxEditor::tr("Softbox %1: %2° × %3° at azimuth %4°, elevation %5°")
        .arg(index + 1)
        .arg(b.width, 0, 'g', 4)
        .arg(b.height, 0, 'g', 4)
        .arg(b.azimuth, 0, 'g', 4)
        .arg(b.elevation, 0, 'g', 4);
}

SoftboxEditor::SoftboxEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("softboxList"));
    m_list->setMaximumHeight(90);
    layout->addWidget(m_list);
    auto* buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add softbox"));
    m_add->setObjectName(QStringLiteral("addSoftbox"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("removeSoftbox"));
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch();
    layout->addLayout(buttons);

    m_fields = new QWidget;
    auto* form = new QFormLayout(m_fields);
    form->setContentsMargins(0, 0, 0, 0);
    auto number = [&](const char* key, const QString& label, const QString& suffix, double lo, double hi,
                      bool loOpen) {
        auto* e = new NumberEdit;
        e->setObjectName(QLatin1String(key));
        e->setLimits(lo, hi, loOpen);
        e->setWhat(label.toLower());
        e->setSuffix(suffix);
        form->addRow(label, e);
        connect(e, &QAbstractSpinBox::editingFinished, this, &SoftboxEditor::gestureFinished);
        connect(e, &NumberEdit::rejected, this, &SoftboxEditor::rejected);
        return e;
    };
    m_azimuth = number("softboxAzimuth", tr("Azimuth"), QStringLiteral("°"), -360.0, 360.0, false);
    m_elevation = number("softboxElevation", tr("Elevation"), QStringLiteral("°"), -90.0, 90.0, false);
    m_width = number("softboxWidth", tr("Width"), QStringLiteral("°"), 0.0, envlimits::kMaxSoftbox, true);
    m_height = number("softboxHeight", tr("Height"), QStringLiteral("°"), 0.0, envlimits::kMaxSoftbox, true);
    m_color = new ColorButton;
    m_color->setObjectName(QStringLiteral("softboxColor"));
    form->addRow(tr("Colour"), m_color);
    m_intensity = number("softboxIntensity", tr("Intensity"), QString(), 0.0, 1e6, false);
    m_intensity->setToolTip(tr("Radiance = colour × intensity (1: as bright as a white sky of 1)"));
    layout->addWidget(m_fields);

    connect(m_azimuth, &NumberEdit::valueEdited, this,
            [this](double v) { editCurrent([](Softbox& b, double x) { b.azimuth = x; }, v); });
    connect(m_elevation, &NumberEdit::valueEdited, this,
            [this](double v) { editCurrent([](Softbox& b, double x) { b.elevation = x; }, v); });
    connect(m_width, &NumberEdit::valueEdited, this,
            [this](double v) { editCurrent([](Softbox& b, double x) { b.width = x; }, v); });
    connect(m_height, &NumberEdit::valueEdited, this,
            [this](double v) { editCurrent([](Softbox& b, double x) { b.height = x; }, v); });
    connect(m_intensity, &NumberEdit::valueEdited, this,
            [this](double v) { editCurrent([](Softbox& b, double x) { b.intensity = x; }, v); });
    connect(m_color, &ColorButton::colorPicked, this, [this](const glm::dvec3& c) {
        const int row = currentRow();
        if (row < 0) return;
        std::vector<Softbox> boxes = m_boxes;
        boxes[size_t(row)].color = c;
        emit edited(boxes, false);
    });
    connect(m_add, &QPushButton::clicked, this, [this] {
        std::vector<Softbox> boxes = m_boxes;
        Softbox b; // a new one beside the last, so it does not hide it
        if (!boxes.empty())
            b.azimuth = boxes.back().azimuth + 60.0 - (boxes.back().azimuth + 60.0 > 180.0 ? 360.0 : 0.0);
        boxes.push_back(b);
        emit edited(boxes, false);
        setCurrentRow(int(m_boxes.size()) - 1);
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row = currentRow();
        if (row < 0) return;
        std::vector<Softbox> boxes = m_boxes;
        boxes.erase(boxes.begin() + row);
        emit edited(boxes, false);
    });
    connect(m_list, &QListWidget::currentRowChanged, this, &SoftboxEditor::showCurrent);
    showCurrent();
}

int SoftboxEditor::currentRow() const {
    const int row = m_list->currentRow();
    return row >= 0 && row < int(m_boxes.size()) ? row : -1;
}

void SoftboxEditor::setCurrentRow(int row) {
    m_list->setCurrentRow(std::clamp(row, -1, int(m_boxes.size()) - 1));
    showCurrent();
}

void SoftboxEditor::setSoftboxes(const std::vector<Softbox>& boxes) {
    const int row = m_list->currentRow();
    m_boxes = boxes;
    {
        const QSignalBlocker block(m_list);
        if (m_list->count() != int(boxes.size())) {
            m_list->clear();
            for (size_t i = 0; i < boxes.size(); ++i)
                m_list->addItem(softboxSummary(boxes[i], int(i)));
        } else {
            for (size_t i = 0; i < boxes.size(); ++i)
                m_list->item(int(i))->setText(softboxSummary(boxes[i], int(i)));
        }
        m_list->setCurrentRow(boxes.empty() ? -1 : std::clamp(row < 0 ? 0 : row, 0, int(boxes.size()) - 1));
    }
    showCurrent();
}

void SoftboxEditor::showCurrent() {
    const int row = currentRow();
    m_fields->setEnabled(row >= 0);
    m_remove->setEnabled(row >= 0);
    m_add->setEnabled(m_boxes.size() < size_t(envlimits::kMaxSoftboxes));
    const Softbox b = row >= 0 ? m_boxes[size_t(row)] : Softbox{};
    m_azimuth->setValueQuietly(b.azimuth);
    m_elevation->setValueQuietly(b.elevation);
    m_width->setValueQuietly(b.width);
    m_height->setValueQuietly(b.height);
    m_intensity->setValueQuietly(b.intensity);
    m_color->setColor(b.color);
}

void SoftboxEditor::editCurrent(void (*apply)(Softbox&, double), double value) {
    const int row = currentRow();
    if (row < 0) return;
    std::vector<Softbox> boxes = m_boxes;
    apply(boxes[size_t(row)], value);
    emit edited(boxes, true);
}

} // namespace lr
