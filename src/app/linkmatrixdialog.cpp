#include "linkmatrixdialog.h"

#include "editor/linkmatrixmodel.h"

#include <QButtonGroup>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QRadioButton>
#include <QTableView>
#include <QVBoxLayout>

namespace lr {

LinkMatrixDialog::LinkMatrixDialog(Document* document, QWidget* parent)
    : QDialog(parent), m_model(new LinkMatrixModel(document, this)), m_view(new QTableView(this)),
      m_lit(new QRadioButton(tr("&Lit: the light lights the part"), this)),
      m_shadow(new QRadioButton(tr("&Shadow: the part casts the light's shadow"), this)),
      m_message(new QLabel(this)) {
    setObjectName(QStringLiteral("LinkMatrixDialog"));
    setWindowTitle(tr("Light linking"));
    auto* layout = new QVBoxLayout(this);
    auto* modes = new QHBoxLayout;
    auto* group = new QButtonGroup(this);
    group->addButton(m_lit);
    group->addButton(m_shadow);
    m_lit->setChecked(true);
    modes->addWidget(m_lit);
    modes->addWidget(m_shadow);
    modes->addStretch(1);
    layout->addLayout(modes);
    m_view->setObjectName(QStringLiteral("linkMatrix"));
    m_view->setModel(m_model);
    m_view->setSelectionMode(QAbstractItemView::NoSelection);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setToolTip(
        tr("The model's parts, one per node (mesh and material in the tooltip)"));
    layout->addWidget(m_view, 1);
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #d04030"));
    layout->addWidget(m_message);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    connect(m_lit, &QRadioButton::toggled, this,
            [this](bool lit) { m_model->setMode(lit ? LinkKind::Lit : LinkKind::Shadow); });
    connect(m_model, &LinkMatrixModel::refused, m_message, &QLabel::setText);
    connect(m_model, &QAbstractItemModel::dataChanged, m_message, [this] { m_message->clear(); });
    resize(640, 360);
}

void LinkMatrixDialog::setModelParts(std::vector<PartNames> parts) {
    m_model->setModelParts(std::move(parts));
}

QString LinkMatrixDialog::message() const {
    return m_message->text();
}

} // namespace lr
