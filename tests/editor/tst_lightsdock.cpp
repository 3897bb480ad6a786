// The Lights dock, driven through its widgets: selection synced both ways, in-place edits of several selected
// rows as one undo step (through the real cell editors), toolbar actions, sorting, drop to reorder.
#include "app/lightsdock.h"
#include "app/lighttableview.h"
#include "editor/lighttablemodel.h"
#include "rigfixture.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMimeData>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>

using namespace lr;
using lrtest::names;

class TestLightsDock : public QObject {
    Q_OBJECT

    std::unique_ptr<QMainWindow> m_window;
    Document* m_doc = nullptr;
    LightsDock* m_dock = nullptr;

    QTableView* view() const { return m_dock->view(); }
    QModelIndex cell(int sourceRow, int column) const {
        return m_dock->proxyModel()->mapFromSource(m_dock->model()->index(sourceRow, column));
    }
    QList<int> viewSelectedSourceRows() const {
        QList<int> rows;
        for (const QModelIndex& i : view()->selectionModel()->selectedRows())
            rows << m_dock->proxyModel()->mapToSource(i).row();
        std::sort(rows.begin(), rows.end());
        return rows;
    }
    void selectInView(const QList<int>& sourceRows) {
        QItemSelection sel;
        for (int r : sourceRows)
            sel.select(cell(r, 0), cell(r, LightTableModel::ColumnCount - 1));
        view()->selectionModel()->select(sel, QItemSelectionModel::ClearAndSelect);
        view()->selectionModel()->setCurrentIndex(cell(sourceRows.first(), 0), QItemSelectionModel::NoUpdate);
    }
    // Whether a cell editor is open (editors are the viewport's direct children; closed ones are hidden).
    bool editorOpen() const {
        for (QWidget* w : view()->viewport()->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (w->isVisible()) return true;
        return false;
    }
    // Opens the cell's editor, types text into its line edit and presses Return.
    void typeIntoCell(int sourceRow, int column, const QString& text) {
        const QModelIndex index = cell(sourceRow, column);
        // Make it current without touching the selection (setCurrentIndex would select only this row).
        view()->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        view()->edit(index);
        QTRY_VERIFY(QApplication::focusWidget() && view()->isAncestorOf(QApplication::focusWidget()));
        auto* edit = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY2(edit, "no line edit has focus");
        edit->selectAll();
        QTest::keyClicks(edit, text);
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_VERIFY(!editorOpen());
    }

  private slots:
    void init() {
        m_window = std::make_unique<QMainWindow>();
        m_doc = new Document(m_window.get());
        m_doc->newRig(lrtest::sampleRig());
        m_dock = new LightsDock(m_doc, m_window.get());
        m_window->addDockWidget(Qt::LeftDockWidgetArea, m_dock);
        m_window->setCentralWidget(new QLabel(QStringLiteral("viewport")));
        m_window->resize(900, 600);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->activateWindow(); // no window manager under Xvfb: ask for focus directly
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QCOMPARE(m_dock->objectName(), QStringLiteral("LightsDock"));
    }
    void cleanup() { m_window.reset(); }

    void selectionSyncedBothWays() {
        m_doc->setSelectedRows({1, 3}, 3);
        QCOMPARE(viewSelectedSourceRows(), (QList<int>{1, 3}));
        QCOMPARE(m_dock->proxyModel()->mapToSource(view()->currentIndex()).row(), 3);
        selectInView({0, 2, 5});
        QCOMPARE(m_doc->selectedRows(), (QList<int>{0, 2, 5}));
        // Clicking a row selects just that light.
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, view()->visualRect(cell(4, 0)).center());
        QCOMPARE(m_doc->selectedRows(), QList<int>{4});
        QCOMPARE(m_doc->currentRow(), 4);
        // Ctrl+click adds.
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, Qt::ControlModifier,
                          view()->visualRect(cell(1, 0)).center());
        QCOMPARE(m_doc->selectedRows(), (QList<int>{1, 4}));
        // Reordering keeps the same lights selected in the view.
        QVERIFY(m_doc->moveLights({4}, 0));
        QCOMPARE(viewSelectedSourceRows(), (QList<int>{0, 2}));
        m_doc->setSelection({});
        QVERIFY(view()->selectionModel()->selectedRows().isEmpty());
    }

    void editingOneOfSeveralSelectedRowsEditsAll() {
        const QByteArray before = lrtest::bytes(*m_doc);
        m_doc->setSelectedRows({0, 2, 4}, 2);
        typeIntoCell(2, LightTableModel::IntensityColumn, QStringLiteral("6.5"));
        QCOMPARE(m_doc->selectedRows(), (QList<int>{0, 2, 4}));
        for (int r : {0, 2, 4})
            QCOMPARE(m_doc->light(r).intensity, 6.5);
        QCOMPARE(m_doc->light(1).intensity, lrtest::sampleRig().lights[1].intensity);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        // Colour as linear HDR text.
        typeIntoCell(0, LightTableModel::ColorColumn, QStringLiteral("15, 0, 0"));
        for (int r : {0, 2, 4})
            QCOMPARE(m_doc->light(r).color, glm::dvec3(15, 0, 0));
        QCOMPARE(m_doc->undoStack()->count(), 2);
        // An invalid value is refused with a reason and stores nothing.
        QSignalSpy refused(m_dock, &LightsDock::editRefused);
        typeIntoCell(4, LightTableModel::IntensityColumn, QStringLiteral("-1"));
        QCOMPARE(refused.count(), 1);
        QVERIFY(refused[0][0].toString().contains(QStringLiteral("intensity")));
        QVERIFY(m_dock->findChild<QLabel*>(QStringLiteral("LightsMessage"))->isVisibleTo(m_dock));
        QCOMPARE(m_doc->undoStack()->count(), 2);
        typeIntoCell(4, LightTableModel::ColorColumn, QStringLiteral("red"));
        QCOMPARE(refused.count(), 2);
        QCOMPARE(m_doc->undoStack()->count(), 2);
        m_doc->undoStack()->setIndex(0);
        QCOMPARE(lrtest::bytes(*m_doc), before);
        // A single selected row: only that row.
        m_doc->setSelectedRows({1}, 1);
        typeIntoCell(1, LightTableModel::FalloffColumn, QStringLiteral("30"));
        QCOMPARE(m_doc->light(1).falloff.range, 30.0);
        QCOMPARE(m_doc->light(0).falloff.range, lrtest::sampleRig().lights[0].falloff.range);
    }

    // Issue 37: typing a group into one of three selected rows puts all three in it, as one step; the cell
    // editor offers the light's own group as its placeholder.
    void groupOfSeveralSelectedRows() {
        m_doc->setSelectedRows({0, 2, 4}, 2);
        const QModelIndex index = cell(2, LightTableModel::GroupColumn);
        view()->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        view()->edit(index);
        QTRY_VERIFY(QApplication::focusWidget() && view()->isAncestorOf(QApplication::focusWidget()));
        auto* edit = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(edit);
        QCOMPARE(edit->placeholderText(), QStringLiteral("L2"));
        QVERIFY(edit->text().isEmpty());
        QTest::keyClicks(edit, QStringLiteral("key"));
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_VERIFY(!editorOpen());
        for (int r : {0, 2, 4})
            QCOMPARE(m_doc->light(r).group, QStringLiteral("key"));
        QVERIFY(m_doc->light(1).group.isEmpty());
        QCOMPARE(m_doc->undoStack()->count(), 1);
        // Cleared again (one step): each its own group, the cells greyed with their names.
        view()->selectionModel()->setCurrentIndex(cell(0, LightTableModel::GroupColumn),
                                                  QItemSelectionModel::NoUpdate);
        view()->edit(cell(0, LightTableModel::GroupColumn));
        QTRY_VERIFY(QApplication::focusWidget() && view()->isAncestorOf(QApplication::focusWidget()));
        edit = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(edit);
        QCOMPARE(edit->text(), QStringLiteral("key"));
        edit->selectAll();
        QTest::keyClick(edit, Qt::Key_Backspace);
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_VERIFY(!editorOpen());
        QCOMPARE(m_doc->undoStack()->count(), 2);
        for (int r : {0, 2, 4}) {
            QVERIFY(m_doc->light(r).group.isEmpty());
            QCOMPARE(cell(r, LightTableModel::GroupColumn).data().toString(), m_doc->light(r).name);
        }
    }

    void checkboxOfSeveralSelectedRows() {
        m_doc->setSelectedRows({0, 1, 2}, 0);
        // The proxy is what the view's check box click writes to.
        QAbstractItemModel* proxy = m_dock->proxyModel();
        QVERIFY(proxy->setData(cell(1, LightTableModel::OnColumn), Qt::Unchecked, Qt::CheckStateRole));
        for (int r : {0, 1, 2})
            QVERIFY(!m_doc->light(r).enabled);
        QVERIFY(m_doc->light(3).enabled);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QVERIFY(proxy->setData(cell(2, LightTableModel::SoloColumn), Qt::Checked, Qt::CheckStateRole));
        for (int r : {0, 1, 2})
            QVERIFY(m_doc->isSoloed(r));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        // A row outside the selection is edited alone.
        QVERIFY(proxy->setData(cell(5, LightTableModel::OnColumn), Qt::Unchecked, Qt::CheckStateRole));
        QVERIFY(!m_doc->light(5).enabled);
        QVERIFY(m_doc->light(4).enabled);
    }

    // Issue 14: the Shadow column's checkbox spreads to the selection as one step (the rim light, which has
    // no checkbox, skipped), and a refused 17th caster shows the limit in the dock's message line.
    void shadowCheckbox() {
        QAbstractItemModel* proxy = m_dock->proxyModel();
        QCOMPARE(proxy->headerData(LightTableModel::ShadowColumn, Qt::Horizontal).toString(),
                 QStringLiteral("Shadow"));
        QVERIFY(!(proxy->flags(cell(3, LightTableModel::ShadowColumn)) & Qt::ItemIsUserCheckable));
        m_doc->setSelectedRows({0, 1, 2, 3}, 0);
        QVERIFY(proxy->setData(cell(1, LightTableModel::ShadowColumn), Qt::Checked, Qt::CheckStateRole));
        for (int r : {0, 1, 2})
            QVERIFY(m_doc->light(r).shadow.enabled);
        QVERIFY(!m_doc->light(3).shadow.enabled && !m_doc->light(4).shadow.enabled);
        QCOMPARE(m_doc->undoStack()->count(), 1);

        Rig full = lrtest::pointRig(kMaxShadowCasters + 1);
        for (int i = 0; i < kMaxShadowCasters; ++i)
            full.lights[size_t(i)].shadow.enabled = true;
        m_doc->newRig(full);
        QSignalSpy refused(m_dock, &LightsDock::editRefused);
        m_doc->setSelectedRows({kMaxShadowCasters}, kMaxShadowCasters);
        QVERIFY(!proxy->setData(cell(kMaxShadowCasters, LightTableModel::ShadowColumn), Qt::Checked,
                                Qt::CheckStateRole));
        QCOMPARE(refused.count(), 1);
        auto* message = m_dock->findChild<QLabel*>(QStringLiteral("LightsMessage"));
        QVERIFY(message->isVisibleTo(m_dock));
        QVERIFY2(message->text().contains(QLatin1String("at most 16")), qPrintable(message->text()));
        QVERIFY(!m_doc->light(kMaxShadowCasters).shadow.enabled);
        QCOMPARE(m_doc->undoStack()->count(), 0);
    }

    // Issue 12: changing the type of several lights must be deliberate, so the table's type combo changes the
    // row it was opened on; the Properties dock changes every selected light.
    void typeComboEditsOnlyItsRow() {
        m_doc->setSelectedRows({0, 4}, 0);
        const QModelIndex index = cell(0, LightTableModel::TypeColumn);
        view()->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
        m_doc->setSelectedRows({0, 4}, 0);
        view()->edit(index);
        auto* combo = view()->viewport()->findChild<QComboBox*>();
        QVERIFY(combo);
        combo->setCurrentIndex(combo->findData(int(LightType::Directional)));
        QTest::keyClick(combo, Qt::Key_Return);
        QTRY_COMPARE(m_doc->light(0).type, LightType::Directional);
        QCOMPARE(m_doc->light(4).type, LightType::Point);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(m_doc->selectedRows(), (QList<int>{0, 4}));
    }

    // Issue 12, item 1: select a point, a spot and a directional light; click the selected spot's Type cell
    // (an inline combo opens); click an empty part of the table. Nothing may change.
    void openingTheTypeComboOnSeveralSelectedChangesNothing() {
        m_doc->newRig();
        m_dock->addLightAction(LightType::Point)->trigger();
        m_dock->addLightAction(LightType::Spot)->trigger();
        m_dock->addLightAction(LightType::Directional)->trigger();
        const int steps = m_doc->undoStack()->count();
        selectInView({0, 1, 2});
        QCOMPARE(m_doc->selectedRows(), (QList<int>{0, 1, 2}));
        const QModelIndex spotType = cell(1, LightTableModel::TypeColumn);
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, view()->visualRect(spotType).center());
        QTRY_VERIFY(view()->viewport()->findChild<QComboBox*>() &&
                    view()->viewport()->findChild<QComboBox*>()->isVisible()); // SelectedClicked, delayed
        QCOMPARE(m_doc->selectedRows(), (QList<int>{0, 1, 2})); // the click kept all three selected
        QCOMPARE(view()->viewport()->findChild<QComboBox*>()->currentData().toInt(), int(LightType::Spot));
        QCOMPARE(view()->viewport()->findChild<QComboBox*>()->currentText(), QStringLiteral("Spot"));
        // An empty part of the table: below the last row.
        const QRect last = view()->visualRect(cell(2, LightTableModel::NameColumn));
        const QPoint empty(last.center().x(), last.bottom() + 3 * last.height());
        QVERIFY(view()->viewport()->rect().contains(empty));
        QVERIFY(!view()->indexAt(empty).isValid());
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, empty);
        QTRY_VERIFY(!editorOpen());
        QCOMPARE(m_doc->undoStack()->count(), steps);
        QCOMPARE(m_doc->light(0).type, LightType::Point);
        QCOMPARE(m_doc->light(1).type, LightType::Spot);
        QCOMPARE(m_doc->light(2).type, LightType::Directional);
        // The same for a number cell of several selected rows: opening and leaving it edits nothing.
        selectInView({0, 1, 2});
        view()->selectionModel()->setCurrentIndex(cell(1, LightTableModel::IntensityColumn),
                                                  QItemSelectionModel::NoUpdate);
        QVERIFY(m_doc->setLightValue({0}, LightProperty::Intensity, 3.0));
        view()->edit(cell(1, LightTableModel::IntensityColumn));
        QTRY_VERIFY(editorOpen());
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, {}, empty);
        QTRY_VERIFY(!editorOpen());
        QCOMPARE(m_doc->undoStack()->count(), steps + 1);
        QCOMPARE(m_doc->light(0).intensity, 3.0);
    }

    void toolbarActions() {
        QVERIFY(m_dock->duplicateAction()->isEnabled() == !m_doc->selection().isEmpty());
        m_dock->addLightAction(LightType::Spot)->trigger();
        QCOMPARE(m_doc->lightCount(), 7);
        QCOMPARE(m_doc->light(6).type, LightType::Spot);
        QCOMPARE(viewSelectedSourceRows(), QList<int>{6});
        QVERIFY(m_dock->deleteAction()->isEnabled());
        m_dock->addLightAction(LightType::Rim)->trigger();
        m_dock->addLightAction(LightType::Point)->trigger();
        m_dock->addLightAction(LightType::Directional)->trigger();
        QCOMPARE(m_doc->lightCount(), 10);
        m_doc->setSelectedRows({0, 1});
        m_dock->duplicateAction()->trigger();
        QCOMPARE(m_doc->lightCount(), 12);
        QCOMPARE(viewSelectedSourceRows(), (QList<int>{2, 3}));
        QCOMPARE(m_doc->light(2).name, QStringLiteral("L0 2")); // numbered like Add, not "L0 copy"
        // Delete key while the table has focus.
        view()->setFocus();
        QTRY_VERIFY(view()->hasFocus());
        QTest::keyClick(view(), Qt::Key_Delete);
        QCOMPARE(m_doc->lightCount(), 10);
        QVERIFY(!names(*m_doc).contains(QStringLiteral("L0 2")));
        QVERIFY(!m_dock->deleteAction()->isEnabled());
        QCOMPARE(m_doc->undoStack()->count(), 6); // 4 adds, duplicate, delete
        // F2 renames the current light in place.
        m_doc->setSelectedRows({2}, 2);
        view()->setFocus();
        QTest::keyClick(view(), Qt::Key_F2);
        QTRY_VERIFY(editorOpen());
        auto* edit = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        QVERIFY(edit);
        edit->selectAll();
        QTest::keyClicks(edit, QStringLiteral("Sun"));
        QTest::keyClick(edit, Qt::Key_Return);
        QTRY_COMPARE(m_doc->light(2).name, QStringLiteral("Sun"));
        QCOMPARE(m_doc->undoStack()->command(m_doc->undoStack()->count() - 1)->text(),
                 QStringLiteral("Rename L2 to Sun"));
    }

    void sortingIsAViewOnly() {
        QVERIFY(m_doc->setLightValues({0, 1, 2, 3, 4, 5}, LightProperty::Intensity,
                                      {5.0, 1.0, 4.0, 2.0, 6.0, 3.0}));
        const QStringList order = names(*m_doc);
        view()->horizontalHeader()->setSortIndicator(LightTableModel::IntensityColumn, Qt::AscendingOrder);
        QStringList shown;
        for (int r = 0; r < 6; ++r)
            shown << view()->model()->index(r, LightTableModel::NameColumn).data().toString();
        QCOMPARE(shown, (QStringList{"L1", "L3", "L5", "L2", "L0", "L4"}));
        QCOMPARE(names(*m_doc), order); // the rig's order is unchanged
        QVERIFY(!view()->dragEnabled());
        // Selection sync maps through the sort.
        m_doc->setSelectedRows({4});
        QCOMPARE(view()->selectionModel()->selectedRows().first().row(), 5);
        // Clearing the sort returns to rig order and enables dragging.
        view()->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
        QCOMPARE(view()->model()->index(0, LightTableModel::NameColumn).data().toString(),
                 QStringLiteral("L0"));
        QVERIFY(view()->dragEnabled());
    }

    void dropReordersWithoutRemoving() {
        m_doc->setSelectedRows({0, 1}, 0);
        std::unique_ptr<QMimeData> mime(m_dock->proxyModel()->mimeData({cell(0, 0), cell(1, 0)}));
        QVERIFY(mime);
        // Drop onto the lower half of row 4: after it.
        const QRect target = view()->visualRect(cell(4, 0));
        const QPoint pos(target.center().x(), target.bottom() - 1);
        QDragEnterEvent enter(pos, Qt::MoveAction, mime.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view()->viewport(), &enter);
        QDragMoveEvent move(pos, Qt::MoveAction, mime.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view()->viewport(), &move);
        QDropEvent drop(pos, Qt::MoveAction, mime.get(), Qt::LeftButton, {});
        QApplication::sendEvent(view()->viewport(), &drop);
        QCOMPARE(names(*m_doc), (QStringList{"L2", "L3", "L4", "L0", "L1", "L5"}));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QVERIFY(drop.dropAction() != Qt::MoveAction); // the view must not remove the dragged rows itself
        QCOMPARE(viewSelectedSourceRows(), (QList<int>{3, 4}));
        m_doc->undoStack()->undo();
        QCOMPARE(m_doc->rig(), lrtest::sampleRig());
    }

    void manyLights() {
        m_doc->newRig(lrtest::pointRig(kMaxRigLights));
        QCOMPARE(view()->model()->rowCount(), kMaxRigLights);
        QList<int> rows;
        for (int i = 0; i < 1000; ++i)
            rows << i;
        m_doc->setSelectedRows(rows, 0);
        QCOMPARE(view()->selectionModel()->selectedRows().size(), 1000);
        QVERIFY(m_dock->proxyModel()->setData(cell(10, LightTableModel::IntensityColumn), 3.0));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(m_doc->light(999).intensity, 3.0);
        QCOMPARE(m_doc->light(1000).intensity, 1.0);
        QVERIFY(!m_dock->addLightAction(LightType::Point)->isEnabled());
    }
};

QTEST_MAIN(TestLightsDock)
#include "tst_lightsdock.moc"
