#include "app/delegates.h"

#include "core/lighttypes.h"
#include "editor/lightproperty.h"

#include <QColorDialog>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPainter>
#include <QRegularExpression>
#include <QToolButton>

namespace lr {

namespace {

// The text an editor started with: an editor closed with it unchanged writes nothing (so opening a cell of
// one of several selected rows and clicking elsewhere edits no light).
constexpr const char* kInitialText = "lrInitialText";

bool unchanged(const QObject* editor, const QString& text) {
    const QVariant initial = editor->property(kInitialText);
    return initial.isValid() && initial.toString() == text;
}

QString formatVec3(const glm::dvec3& v) {
    return QStringLiteral("%1, %2, %3")
        .arg(QString::number(v.x, 'g', 6), QString::number(v.y, 'g', 6), QString::number(v.z, 'g', 6));
}

// The colour cell's editor: linear RGB as text (HDR allowed) and a button that opens a colour dialog.
class ColorEditor : public QWidget {
  public:
    explicit ColorEditor(QWidget* parent) : QWidget(parent) {
        setAutoFillBackground(true);
        auto* layout = new QHBoxLayout(this);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(0);
        m_edit = new QLineEdit(this);
        m_edit->setObjectName(QStringLiteral("colorText"));
        m_edit->setToolTip(tr("Linear RGB, components >= 0 (values above 1 are HDR)"));
        auto* pick = new QToolButton(this);
        pick->setObjectName(QStringLiteral("colorPick"));
        pick->setText(QStringLiteral("…"));
        pick->setToolTip(tr("Choose a colour"));
        layout->addWidget(m_edit, 1);
        layout->addWidget(pick);
        setFocusProxy(m_edit);
        connect(pick, &QToolButton::clicked, this, [this] {
            double v[3];
            const QColor initial =
                parseVec3(m_edit->text(), v) ? displayColor(glm::dvec3(v[0], v[1], v[2])) : QColor(Qt::white);
            // Parented to this editor, so the view does not close the editor when the dialog takes focus.
            QColorDialog dialog(initial, this);
            if (dialog.exec() == QDialog::Accepted)
                m_edit->setText(formatVec3(linearFromDisplayColor(dialog.selectedColor())));
            m_edit->setFocus();
        });
    }
    QLineEdit* edit() const { return m_edit; }

  private:
    QLineEdit* m_edit;
};

} // namespace

bool parseVec3(const QString& text, double out[3]) {
    const QStringList parts = text.trimmed()
                                  .remove(QLatin1Char('['))
                                  .remove(QLatin1Char(']'))
                                  .split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts);
    if (parts.size() != 3) return false;
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        out[i] = parts[i].toDouble(&ok);
        if (!ok) return false;
    }
    return true;
}

void ColorSwatchDelegate::paint(QPainter* painter, const QStyleOptionViewItem& option,
                                const QModelIndex& index) const {
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    const QColor swatch = index.data(Qt::DecorationRole).value<QColor>();
    opt.features &= ~QStyleOptionViewItem::HasDecoration;
    opt.icon = QIcon();
    QStyledItemDelegate::paint(painter, opt, QModelIndex()); // background and selection only
    if (!swatch.isValid()) return;
    const QRect r = option.rect.adjusted(4, 3, -4, -3);
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(option.palette.color(QPalette::Mid));
    painter->setBrush(swatch);
    painter->drawRoundedRect(r, 3, 3);
    painter->restore();
}

QWidget* ColorSwatchDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                           const QModelIndex&) const {
    return new ColorEditor(parent);
}

void ColorSwatchDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    const QString text = formatVec3(index.data(Qt::EditRole).value<glm::dvec3>());
    static_cast<ColorEditor*>(editor)->edit()->setText(text);
    editor->setProperty(kInitialText, text);
}

void ColorSwatchDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                       const QModelIndex& index) const {
    double v[3];
    const QString text = static_cast<ColorEditor*>(editor)->edit()->text();
    if (unchanged(editor, text)) return;
    // Text that is not three numbers goes to the model as it is, so the refusal carries the model's reason.
    if (parseVec3(text, v))
        model->setData(index, QVariant::fromValue(glm::dvec3(v[0], v[1], v[2])));
    else
        model->setData(index, text);
}

void ColorSwatchDelegate::updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option,
                                               const QModelIndex&) const {
    QRect r = option.rect;
    r.setWidth(std::max(r.width(), editor->sizeHint().width() + 80));
    editor->setGeometry(r);
}

QWidget* NumberDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                      const QModelIndex&) const {
    auto* edit = new QLineEdit(parent);
    edit->setAlignment(Qt::AlignRight);
    return edit;
}

void NumberDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    const QVariant v = index.data(Qt::EditRole);
    const QString text = v.isValid() ? QString::number(v.toDouble(), 'g', 10) : QString();
    static_cast<QLineEdit*>(editor)->setText(text);
    editor->setProperty(kInitialText, text);
}

void NumberDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                  const QModelIndex& index) const {
    // Text goes to the model, which parses and validates it (empty = none where the value is optional).
    const QString text = static_cast<QLineEdit*>(editor)->text().trimmed();
    if (unchanged(editor, text)) return;
    model->setData(index, text);
}

QWidget* GroupDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const {
    auto* edit = new QLineEdit(parent);
    edit->setMaxLength(kMaxLightNameLength);
    return edit;
}

void GroupDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* edit = static_cast<QLineEdit*>(editor);
    const QString text = index.data(Qt::EditRole).toString();
    edit->setText(text);
    edit->setPlaceholderText(index.data(Qt::DisplayRole).toString());
    editor->setProperty(kInitialText, text);
}

void GroupDelegate::setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const {
    const QString text = static_cast<QLineEdit*>(editor)->text().trimmed();
    if (unchanged(editor, text)) return;
    model->setData(index, text);
}

QWidget* LightTypeDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem&,
                                         const QModelIndex&) const {
    auto* combo = new QComboBox(parent);
    for (const LightType t : allLightTypes())
        combo->addItem(lightTypeLabel(t), int(t));
    return combo;
}

void LightTypeDelegate::setEditorData(QWidget* editor, const QModelIndex& index) const {
    auto* combo = static_cast<QComboBox*>(editor);
    combo->setCurrentIndex(combo->findData(index.data(Qt::EditRole).toInt()));
    editor->setProperty(kInitialText, combo->currentText());
}

void LightTypeDelegate::setModelData(QWidget* editor, QAbstractItemModel* model,
                                     const QModelIndex& index) const {
    auto* combo = static_cast<QComboBox*>(editor);
    if (unchanged(editor, combo->currentText())) return;
    model->setData(index, combo->currentData().toInt());
}

} // namespace lr
