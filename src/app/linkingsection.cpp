#include "linkingsection.h"

#include "editor/document.h"

#include <QApplication>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStyle>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace lr {

namespace {

constexpr int kRowRole = Qt::UserRole;           // int: the part row (-1: an unmatched name)
constexpr int kUnmatchedRole = Qt::UserRole + 1; // QString: the unmatched name

Qt::CheckState checkState(int on, int off) {
    return off == 0 ? Qt::Checked : on == 0 ? Qt::Unchecked : Qt::PartiallyChecked;
}

// Where an unmatched name is listed: "include", "exclude", "include, exclude" or "".
QString listsOf(const PartSet& set, const QString& name) {
    QStringList out;
    if (set.include.contains(name)) out << QStringLiteral("include");
    if (set.exclude.contains(name)) out << QStringLiteral("exclude");
    return out.join(QStringLiteral(", "));
}

} // namespace

LinkingSection::LinkingSection(Document* document, QWidget* parent)
    : QWidget(parent), m_doc(document), m_fold(new QToolButton(this)), m_body(new QWidget(this)),
      m_note(new QLabel(m_body)), m_tree(new QTreeWidget(m_body)),
      m_reset(new QPushButton(tr("Reset linking"), m_body)) {
    setObjectName(QStringLiteral("linking"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_fold->setObjectName(QStringLiteral("linkingFold"));
    m_fold->setText(tr("Linking"));
    m_fold->setCheckable(true);
    m_fold->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_fold->setAutoRaise(true);
    m_fold->setArrowType(Qt::RightArrow);
    m_fold->setToolTip(tr("Which parts of the model the light lights and which cast its shadow; while open, "
                          "the viewport highlights the parts the light lights"));
    layout->addWidget(m_fold);
    auto* body = new QVBoxLayout(m_body);
    body->setContentsMargins(0, 0, 0, 0);
    m_note->setWordWrap(true);
    m_note->setObjectName(QStringLiteral("linkingNote"));
    body->addWidget(m_note);
    m_tree->setObjectName(QStringLiteral("linkingParts"));
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Part"), tr("Lit"), tr("Casts shadow")});
    m_tree->headerItem()->setToolTip(LitColumn, tr("Whether the light lights the part"));
    m_tree->headerItem()->setToolTip(
        ShadowColumn, tr("Whether the part casts the light's shadow (while the light's shadow is on)"));
    m_tree->setRootIsDecorated(false);
    m_tree->setUniformRowHeights(true);
    m_tree->setSelectionMode(QAbstractItemView::NoSelection);
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(PartColumn, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(LitColumn, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(ShadowColumn, QHeaderView::ResizeToContents);
    m_tree->setMinimumHeight(120);
    body->addWidget(m_tree);
    m_reset->setObjectName(QStringLiteral("resetLinking"));
    m_reset->setToolTip(tr("The selected lights light every part again and every part casts their shadow"));
    body->addWidget(m_reset, 0, Qt::AlignLeft);
    layout->addWidget(m_body);
    m_body->setVisible(false);

    connect(m_fold, &QToolButton::toggled, this, [this](bool open) {
        m_fold->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
        m_body->setVisible(open);
        refresh();
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, &LinkingSection::onItemChanged);
    connect(m_reset, &QPushButton::clicked, this, [this] {
        QString error;
        const bool done = resetLinks(m_doc, m_doc->selectedRows(), &error);
        emit refused(done ? QString() : error);
        refresh();
    });
}

bool LinkingSection::isOpen() const {
    return m_fold->isChecked();
}

void LinkingSection::setOpen(bool open) {
    m_fold->setChecked(open);
}

void LinkingSection::setModelParts(std::vector<PartNames> parts) {
    m_modelParts = std::move(parts);
    rebuildRows();
    refresh();
}

void LinkingSection::rebuildRows() {
    m_groundOn = m_doc->rig().ground.mode != GroundMode::Off;
    m_parts = m_modelParts;
    if (m_groundOn) m_parts.push_back(PartNames::theGround());
    m_rows = linkPartRows(m_parts);
    const QSignalBlocker block(m_tree);
    m_tree->clear();
    for (int i = 0; i < int(m_rows.size()); ++i) {
        const LinkPartRow& row = m_rows[size_t(i)];
        auto* item = new QTreeWidgetItem(m_tree);
        item->setText(PartColumn, row.label);
        item->setToolTip(PartColumn, row.toolTip);
        item->setData(PartColumn, kRowRole, i);
        item->setFlags(row.name.isEmpty() ? Qt::ItemIsEnabled : Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    }
}

QTreeWidgetItem* LinkingSection::itemOfRow(int row) const {
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (QTreeWidgetItem* item = m_tree->topLevelItem(i);
            item->data(PartColumn, kRowRole).toInt() == row &&
            !item->data(PartColumn, kUnmatchedRole).isValid())
            return item;
    return nullptr;
}

QTreeWidgetItem* LinkingSection::itemOfUnmatched(const QString& name) const {
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (QTreeWidgetItem* item = m_tree->topLevelItem(i); item->data(PartColumn, kUnmatchedRole) == name)
            return item;
    return nullptr;
}

void LinkingSection::refresh() {
    if (m_groundOn != (m_doc->rig().ground.mode != GroundMode::Off)) rebuildRows();
    const QList<int> rows = m_doc->selectedRows();
    QList<int> casting;
    bool linked = false;
    for (int r : rows) {
        if (m_doc->light(r).castsShadows()) casting << r;
        linked = linked || !m_doc->light(r).link.isDefault();
    }
    m_reset->setEnabled(linked);
    if (!isOpen()) { // folded: the rows are read when it opens (the dock refreshes on every drag step)
        updateHighlight();
        return;
    }
    m_loading = true;
    const QSignalBlocker block(m_tree);
    for (int i = 0; i < int(m_rows.size()); ++i) {
        QTreeWidgetItem* item = m_tree->topLevelItem(i);
        if (m_rows[size_t(i)].name.isEmpty()) continue;
        const auto state = [&](LinkKind kind, const QList<int>& lights) {
            int on = 0, off = 0;
            for (int r : lights)
                (linkState(linkSet(m_doc->light(r).link, kind), m_parts, m_rows[size_t(i)]) == LinkState::On
                     ? on
                     : off)++;
            return checkState(on, off);
        };
        item->setData(LitColumn, Qt::CheckStateRole,
                      rows.isEmpty() ? QVariant() : QVariant(state(LinkKind::Lit, rows)));
        item->setData(ShadowColumn, Qt::CheckStateRole,
                      casting.isEmpty() ? QVariant() : QVariant(state(LinkKind::Shadow, casting)));
        item->setText(ShadowColumn, casting.isEmpty() && !rows.isEmpty() ? QStringLiteral("—") : QString());
        QString noShadow;
        if (casting.isEmpty() && !rows.isEmpty())
            noShadow = rows.size() == 1 ? tr("%1 casts no shadow").arg(m_doc->light(rows[0]).name)
                                        : tr("None of the selected lights casts a shadow");
        item->setToolTip(ShadowColumn, noShadow);
    }
    // The names that match nothing here, after the parts: greyed, with where they are listed.
    while (m_tree->topLevelItemCount() > int(m_rows.size()))
        delete m_tree->takeTopLevelItem(m_tree->topLevelItemCount() - 1);
    QStringList unmatched;
    for (int r : rows)
        for (const PartSet* set : {&m_doc->light(r).link.lit, &m_doc->light(r).link.shadow})
            for (const QString& n : unmatchedNames(*set, m_parts))
                if (!unmatched.contains(n)) unmatched << n;
    const QBrush grey = palette().brush(QPalette::Disabled, QPalette::Text);
    const QIcon warning = style()->standardIcon(QStyle::SP_MessageBoxWarning);
    for (const QString& name : std::as_const(unmatched)) {
        auto* item = new QTreeWidgetItem(m_tree);
        item->setText(PartColumn, name);
        item->setIcon(PartColumn, warning);
        item->setData(PartColumn, kRowRole, -1);
        item->setData(PartColumn, kUnmatchedRole, name);
        QStringList lit, shadow;
        for (int r : rows) {
            if (const QString l = listsOf(m_doc->light(r).link.lit, name); !l.isEmpty() && !lit.contains(l))
                lit << l;
            if (const QString s = listsOf(m_doc->light(r).link.shadow, name);
                !s.isEmpty() && !shadow.contains(s))
                shadow << s;
        }
        item->setText(LitColumn, lit.join(QStringLiteral("; ")));
        item->setText(ShadowColumn, shadow.join(QStringLiteral("; ")));
        const QString tip =
            tr("\"%1\" matches no part of this model. It is kept in the rig (the rig may be meant "
               "for another model); Reset linking removes it.")
                .arg(name);
        for (int c = PartColumn; c <= ShadowColumn; ++c) {
            item->setForeground(c, grey);
            item->setToolTip(c, tip);
        }
        item->setFlags(Qt::ItemIsEnabled);
    }
    m_tree->setEnabled(!rows.isEmpty());
    m_note->setText(m_parts.empty()   ? tr("Load a model to link the light to its parts.")
                    : rows.size() > 1 ? tr("Edits apply to all %1 selected lights.").arg(rows.size())
                                      : QString());
    m_note->setVisible(!m_note->text().isEmpty());
    m_loading = false;
    updateHighlight();
}

void LinkingSection::onItemChanged(QTreeWidgetItem* item, int column) {
    if (m_loading || (column != LitColumn && column != ShadowColumn)) return;
    const int row = item->data(PartColumn, kRowRole).toInt();
    if (row < 0 || row >= int(m_rows.size())) return;
    const bool on = item->checkState(column) == Qt::Checked;
    const LinkKind kind = column == LitColumn ? LinkKind::Lit : LinkKind::Shadow;
    QList<int> rows;
    for (int r : m_doc->selectedRows())
        if (kind == LinkKind::Lit || m_doc->light(r).castsShadows()) rows << r;
    QString error;
    setRowLinked(m_doc, rows, kind, m_parts, m_rows[size_t(row)], on, &error);
    emit refused(error);
    refresh(); // the stored state again (the edit may have been refused or changed nothing)
}

std::vector<std::size_t> LinkingSection::highlightedParts() const {
    std::vector<std::size_t> out;
    int current = m_doc->currentRow();
    if (current < 0 && !m_doc->selectedRows().isEmpty()) current = m_doc->selectedRows().first();
    if (!isOpen() || !isVisible() || current < 0) return out;
    const PartSet& lit = m_doc->light(current).link.lit;
    for (std::size_t i = 0; i < m_parts.size(); ++i)
        if (partSetContains(lit, m_parts[i])) out.push_back(i);
    return out;
}

void LinkingSection::updateHighlight() {
    std::vector<std::size_t> now = highlightedParts();
    if (now == m_highlight) return;
    m_highlight = std::move(now);
    emit highlightChanged();
}

void LinkingSection::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    updateHighlight();
}

void LinkingSection::hideEvent(QHideEvent* event) {
    QWidget::hideEvent(event);
    updateHighlight();
}

} // namespace lr
