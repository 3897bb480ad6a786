#include "modeldock.h"

#include "editor/document.h"
#include "modeltreemodel.h"
#include "scene.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QTreeView>
#include <QVBoxLayout>
#include <algorithm>

namespace lr {

ModelDock::ModelDock(QWidget* parent)
    : QDockWidget(tr("Model"), parent), m_model(new ModelTreeModel(this)), m_view(new QTreeView(this)),
      m_summary(new QLabel(this)), m_copy(new QAction(tr("&Copy"), this)) {
    setObjectName(QStringLiteral("ModelDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_summary);
    m_view->setObjectName(QStringLiteral("modelTree"));
    m_view->setModel(m_model);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setUniformRowHeights(false);
    m_view->setWordWrap(true);
    m_view->setAlternatingRowColors(true);
    m_view->header()->setSectionResizeMode(ModelTreeModel::NameColumn, QHeaderView::Interactive);
    m_view->header()->setStretchLastSection(true);
    m_view->setColumnWidth(ModelTreeModel::NameColumn, 220);
    m_view->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_copy->setShortcut(QKeySequence::Copy);
    m_copy->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_copy->setToolTip(tr("Copy the selected rows (name and value, tab-separated)"));
    connect(m_copy, &QAction::triggered, this,
            [this] { QApplication::clipboard()->setText(selectedText()); });
    m_view->addAction(m_copy);
    layout->addWidget(m_view, 1);
    setWidget(body);
    reload();
}

void ModelDock::setScene(Scene* scene) {
    if (m_scene) disconnect(m_scene, nullptr, this, nullptr);
    m_scene = scene;
    if (m_scene) connect(m_scene, &Scene::modelChanged, this, &ModelDock::reload);
    reload();
}

void ModelDock::setDocument(Document* document) {
    if (m_doc) disconnect(m_doc, nullptr, this, nullptr);
    m_doc = document;
    const auto follow = [this] { m_model->setLights(m_doc ? m_doc->rig().lights : std::vector<Light>()); };
    if (m_doc)
        connect(m_doc, &Document::rigChanged, this, [follow](const RigChange& c) {
            // What the counts read: links, on/off, shadows, names, types (not every drag step).
            const LightProperty p = c.lightProperty;
            if (c.kind == RigChange::LightValues && p != LightProperty::Link && p != LightProperty::Enabled &&
                p != LightProperty::ShadowEnabled && p != LightProperty::Name && p != LightProperty::Type &&
                p != LightProperty::Any)
                return;
            if (c.kind == RigChange::RigValues) return;
            follow();
        });
    follow();
}

void ModelDock::reload() {
    const auto model = m_scene ? m_scene->model() : std::shared_ptr<const Model>();
    m_model->setModel(model);
    if (!model || model->meshes.empty()) {
        m_summary->setText(tr("No model loaded."));
    } else {
        const QString name = QFileInfo(m_scene->path()).fileName();
        m_summary->setText(
            tr("%1: %2 triangles, %3 vertices, %n warning(s)", nullptr, int(model->warnings.size()))
                .arg(name.isEmpty() ? tr("the model") : name)
                .arg(model->triangleCount())
                .arg(model->vertexCount()));
    }
    // Short lists open; warnings always (they are what the user came for).
    for (int b = 0; b < ModelTreeModel::BranchCount; ++b) {
        const QModelIndex i = m_model->branchIndex(ModelTreeModel::Branch(b));
        m_view->setExpanded(i, b == ModelTreeModel::Warnings || m_model->rowCount(i) <= 8);
    }
}

void ModelDock::showWarnings() {
    show();
    raise();
    const QModelIndex warnings = m_model->branchIndex(ModelTreeModel::Warnings);
    m_view->expand(warnings);
    m_view->setCurrentIndex(warnings);
    m_view->scrollTo(warnings, QAbstractItemView::PositionAtTop);
    m_view->setFocus(Qt::OtherFocusReason);
}

QString ModelDock::selectedText() const {
    QModelIndexList rows = m_view->selectionModel()->selectedRows(ModelTreeModel::NameColumn);
    std::sort(rows.begin(), rows.end(), [this](const QModelIndex& a, const QModelIndex& b) {
        return m_view->visualRect(a).top() < m_view->visualRect(b).top();
    });
    return m_model->copyText(rows);
}

} // namespace lr
