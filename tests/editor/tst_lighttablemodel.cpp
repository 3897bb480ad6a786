// LightTableModel under QAbstractItemModelTester (fatal) through inserts, removals, moves, multi-edits,
// resets, undo and redo; its edits become document commands; drag and drop reorders.
#include "core/lightgroups.h"
#include "editor/lighttablemodel.h"
#include "rigfixture.h"

#include <QAbstractItemModelTester>
#include <QMimeData>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTest>
#include <memory>

using namespace lr;
using lrtest::bytes;
using lrtest::names;

class TestLightTableModel : public QObject {
    Q_OBJECT

    std::unique_ptr<Document> m_doc;
    std::unique_ptr<LightTableModel> m_model;
    std::unique_ptr<QAbstractItemModelTester> m_tester;

    // Every cell's display text and check state, for comparing the model with a fresh one over the same rig.
    static QStringList cells(const QAbstractItemModel& m) {
        QStringList out;
        for (int r = 0; r < m.rowCount(); ++r)
            for (int c = 0; c < m.columnCount(); ++c)
                out << m.index(r, c).data().toString() + QLatin1Char('|') +
                           m.index(r, c).data(Qt::CheckStateRole).toString();
        return out;
    }
    void checkMatchesFreshModel() {
        LightTableModel fresh(m_doc.get());
        QCOMPARE(cells(*m_model), cells(fresh));
    }

  private slots:
    void init() {
        m_doc = std::make_unique<Document>();
        m_doc->newRig(lrtest::sampleRig());
        m_model = std::make_unique<LightTableModel>(m_doc.get());
        m_tester = std::make_unique<QAbstractItemModelTester>(
            m_model.get(), QAbstractItemModelTester::FailureReportingMode::Fatal);
    }
    void cleanup() {
        m_tester.reset();
        m_model.reset();
        m_doc.reset();
    }

    void shape() {
        QCOMPARE(m_model->rowCount(), 6);
        QCOMPARE(m_model->columnCount(), int(LightTableModel::ColumnCount));
        QCOMPARE(m_model->index(1, LightTableModel::NameColumn).data().toString(), QStringLiteral("L1"));
        QCOMPARE(m_model->index(1, LightTableModel::TypeColumn).data().toString(), QStringLiteral("Spot"));
        QCOMPARE(m_model->index(1, LightTableModel::OnColumn).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Checked));
        QCOMPARE(m_model->index(1, LightTableModel::SoloColumn).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Unchecked));
        QVERIFY(m_model->index(1, LightTableModel::ColorColumn)
                    .data(Qt::DecorationRole)
                    .value<QColor>()
                    .isValid());
        QCOMPARE(m_model->index(0, LightTableModel::FalloffColumn).data().toString(), QStringLiteral("8"));
        // No range: an em dash, and the cell is not editable for lights without falloff.
        QCOMPARE(m_model->index(2, LightTableModel::FalloffColumn).data().toString(), QStringLiteral("—"));
        QCOMPARE(m_model->index(4, LightTableModel::FalloffColumn).data().toString(), QStringLiteral("—"));
        QVERIFY(!(m_model->flags(m_model->index(2, LightTableModel::FalloffColumn)) & Qt::ItemIsEditable));
        QVERIFY(m_model->flags(m_model->index(4, LightTableModel::FalloffColumn)) & Qt::ItemIsEditable);
        QVERIFY(m_model->flags(m_model->index(0, LightTableModel::OnColumn)) & Qt::ItemIsUserCheckable);
        QCOMPARE(m_model->index(3, LightTableModel::NameColumn)
                     .data(LightTableModel::LightIdRole)
                     .value<LightId>(),
                 m_doc->lightId(3));
        // HDR colour: the swatch is scaled, not clipped to white.
        QVERIFY(m_doc->setLightValue({0}, LightProperty::Color, QVariant::fromValue(glm::dvec3(15, 0, 0))));
        const QColor swatch =
            m_model->index(0, LightTableModel::ColorColumn).data(Qt::DecorationRole).value<QColor>();
        QCOMPARE(swatch.red(), 255);
        QCOMPARE(swatch.green(), 0);
    }

    void editsBecomeCommands() {
        QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);
        QVERIFY(m_model->setData(m_model->index(0, LightTableModel::IntensityColumn), 2.5));
        QCOMPARE(m_doc->light(0).intensity, 2.5);
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(changed.count(), 1);
        // Only the edited cell is reported.
        QCOMPARE(changed[0][0].toModelIndex(), m_model->index(0, LightTableModel::IntensityColumn));
        QCOMPARE(changed[0][1].toModelIndex(), m_model->index(0, LightTableModel::IntensityColumn));

        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::NameColumn), QStringLiteral("Key")));
        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::TypeColumn), int(LightType::Point)));
        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::ColorColumn), QColor(Qt::red)));
        QCOMPARE(m_doc->light(1).color, glm::dvec3(1, 0, 0));
        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::FalloffColumn), QStringLiteral("12")));
        QCOMPARE(m_doc->light(1).falloff.range, 12.0);
        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::OnColumn), Qt::Unchecked,
                                 Qt::CheckStateRole));
        QVERIFY(!m_doc->light(1).enabled);
        QCOMPARE(m_doc->undoStack()->count(), 6);
        // Solo: transient, no undo step.
        QVERIFY(m_model->setData(m_model->index(2, LightTableModel::SoloColumn), Qt::Checked,
                                 Qt::CheckStateRole));
        QVERIFY(m_doc->isSoloed(2));
        QCOMPARE(m_doc->undoStack()->count(), 6);
        checkMatchesFreshModel();
        m_doc->undoStack()->setIndex(0);
        QCOMPARE(m_doc->rig(), lrtest::sampleRig());
        checkMatchesFreshModel();
    }

    void invalidEditsRefused() {
        QSignalSpy refused(m_model.get(), &LightTableModel::editRefused);
        const QByteArray before = bytes(*m_doc);
        QVERIFY(!m_model->setData(m_model->index(0, LightTableModel::IntensityColumn), -3.0));
        QVERIFY(
            !m_model->setData(m_model->index(0, LightTableModel::IntensityColumn), QStringLiteral("nan")));
        QVERIFY(!m_model->setData(m_model->index(0, LightTableModel::NameColumn), QString()));
        QVERIFY(!m_model->setData(m_model->index(0, LightTableModel::FalloffColumn),
                                  QString())); // range-power needs one
        QVERIFY(!m_model->setData(m_model->index(0, LightTableModel::TypeColumn), 42));
        QCOMPARE(refused.count(), 5);
        QVERIFY(!m_model->lastError().isEmpty());
        QCOMPARE(bytes(*m_doc), before);
        QCOMPARE(m_doc->undoStack()->count(), 0);
        // An empty range is "no range" where the model allows it.
        QVERIFY(m_model->setData(m_model->index(4, LightTableModel::FalloffColumn), 5.0));
        QVERIFY(m_model->setData(m_model->index(4, LightTableModel::FalloffColumn), QString()));
        QVERIFY(!m_doc->light(4).falloff.hasRange());
    }

    void multiRowEditIsOneStep() {
        const QByteArray before = bytes(*m_doc);
        QVERIFY(m_model->setDataForRows({0, 2, 4}, LightTableModel::IntensityColumn, 3.0));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        for (int r : {0, 2, 4})
            QCOMPARE(m_doc->light(r).intensity, 3.0);
        QCOMPARE(m_doc->light(1).intensity, lrtest::sampleRig().lights[1].intensity);
        // Range on a mix: lights without falloff are skipped.
        QVERIFY(m_model->setDataForRows({0, 1, 2, 3}, LightTableModel::FalloffColumn, 20.0));
        QCOMPARE(m_doc->light(1).falloff.range, 20.0);
        QVERIFY(
            m_model->setDataForRows({0, 1, 5}, LightTableModel::OnColumn, Qt::Unchecked, Qt::CheckStateRole));
        QVERIFY(
            m_model->setDataForRows({1, 3}, LightTableModel::SoloColumn, Qt::Checked, Qt::CheckStateRole));
        QVERIFY(m_model->setDataForRows({1, 3}, LightTableModel::NameColumn, QStringLiteral("Same")));
        QCOMPARE(m_doc->undoStack()->count(), 4);
        checkMatchesFreshModel();
        m_doc->undoStack()->setIndex(0);
        QCOMPARE(bytes(*m_doc), before);
        QVERIFY(m_doc->isSoloed(1)); // solo untouched by undo
        checkMatchesFreshModel();
    }

    void structuralChangesThroughUndoRedo() {
        QSignalSpy inserted(m_model.get(), &QAbstractItemModel::rowsInserted);
        QSignalSpy removed(m_model.get(), &QAbstractItemModel::rowsRemoved);
        QSignalSpy moved(m_model.get(), &QAbstractItemModel::rowsMoved);
        QSignalSpy reset(m_model.get(), &QAbstractItemModel::modelReset);
        QSignalSpy layout(m_model.get(), &QAbstractItemModel::layoutChanged);
        QVERIFY(m_doc->addLight(LightType::Spot));
        QVERIFY(m_doc->duplicateLights({0, 2}));
        QVERIFY(m_doc->removeLights({1, 4, 5}));
        QVERIFY(m_doc->moveLights({0, 3}, 5));
        QVERIFY(m_doc->moveLights({4}, 0));
        QVERIFY(m_doc->replaceRig(lrtest::pointRig(3), QStringLiteral("Preset")));
        QVERIFY(inserted.count() >= 2);
        QVERIFY(removed.count() >= 1);
        QCOMPARE(moved.count(), 1);  // one block: rowsMoved
        QCOMPARE(layout.count(), 1); // two blocks: one layout change
        QCOMPARE(reset.count(), 1);
        checkMatchesFreshModel();
        // Undo everything, step by step, checking the model each time; then redo.
        const int steps = m_doc->undoStack()->count();
        for (int i = steps; i > 0; --i) {
            m_doc->undoStack()->undo();
            checkMatchesFreshModel();
        }
        QCOMPARE(m_doc->rig(), lrtest::sampleRig());
        for (int i = 0; i < steps; ++i) {
            m_doc->undoStack()->redo();
            checkMatchesFreshModel();
        }
        QCOMPARE(m_doc->rig(), lrtest::pointRig(3));
        // A full document load resets the model.
        m_doc->newRig(lrtest::pointRig(4));
        QCOMPARE(m_model->rowCount(), 4);
        checkMatchesFreshModel();
    }

    void scatteredBulkChanges() {
        m_doc->newRig(lrtest::pointRig(200));
        QList<int> every3rd;
        for (int i = 0; i < 200; i += 3)
            every3rd << i;
        QPersistentModelIndex p1 = m_model->index(1, LightTableModel::NameColumn);
        QSignalSpy layout(m_model.get(), &QAbstractItemModel::layoutChanged);
        QSignalSpy moved(m_model.get(), &QAbstractItemModel::rowsMoved);
        // Scattered move: one layout change, persistent indexes follow their lights.
        QVERIFY(m_doc->moveLights(every3rd, 100));
        QCOMPARE(layout.count(), 1);
        QCOMPARE(moved.count(), 0);
        QCOMPARE(p1.data().toString(), QStringLiteral("P1"));
        QCOMPARE(p1.row(), 0);
        checkMatchesFreshModel();
        m_doc->undoStack()->undo();
        QCOMPARE(p1.row(), 1);
        checkMatchesFreshModel();
        // Scattered removal and its undo: one reset each (more runs than kMaxChangeRuns).
        QSignalSpy reset(m_model.get(), &QAbstractItemModel::modelReset);
        QSignalSpy removed(m_model.get(), &QAbstractItemModel::rowsRemoved);
        QVERIFY(m_doc->removeLights(every3rd));
        QCOMPARE(reset.count(), 1);
        QCOMPARE(removed.count(), 0);
        QCOMPARE(m_model->rowCount(), 200 - int(every3rd.size()));
        checkMatchesFreshModel();
        m_doc->undoStack()->undo();
        QCOMPARE(reset.count(), 2);
        QCOMPARE(m_doc->rig(), lrtest::pointRig(200));
        QCOMPARE(m_doc->selectedRows(), every3rd); // undo selects the lights it brought back
        checkMatchesFreshModel();
        m_doc->undoStack()->redo();
        checkMatchesFreshModel();
    }

    // Issue 37: the Group column shows a light's group, or, greyed, the group it is without one (named after
    // it: lightGroupName); an edit of several rows is one undo step; renaming a light renames its own
    // group's cell; sorting by the column keeps a group's lights together.
    void groupColumn() {
        constexpr int kGroup = LightTableModel::GroupColumn;
        const QPersistentModelIndex g1 = m_model->index(1, kGroup);
        QCOMPARE(m_model->headerData(kGroup, Qt::Horizontal).toString(), QStringLiteral("Group"));
        QCOMPARE(g1.data().toString(), QStringLiteral("L1"));
        QVERIFY(g1.data(Qt::EditRole).toString().isEmpty());
        QVERIFY(g1.data(Qt::ForegroundRole).isValid()); // greyed: not the light's own setting
        QVERIFY(m_model->flags(g1) & Qt::ItemIsEditable);
        QVERIFY(m_model->setDataForRows({0, 2, 4}, kGroup, QStringLiteral("key")));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        for (int r : {0, 2, 4}) {
            const QModelIndex g = m_model->index(r, kGroup);
            QCOMPARE(g.data().toString(), QStringLiteral("key"));
            QCOMPARE(g.data(Qt::EditRole).toString(), QStringLiteral("key"));
            QVERIFY(!g.data(Qt::ForegroundRole).isValid());
        }
        QCOMPARE(lightGroups(m_doc->rig()).front().lights, (std::vector<int>{0, 2, 4}));
        // A light's own group follows its name.
        QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);
        QVERIFY(m_model->setData(m_model->index(1, LightTableModel::NameColumn), QStringLiteral("Rim")));
        QCOMPARE(g1.data().toString(), QStringLiteral("Rim"));
        bool reported = false;
        for (const QList<QVariant>& c : changed)
            reported = reported ||
                       (c[0].toModelIndex().row() <= 1 && c[1].toModelIndex().row() >= 1 &&
                        c[0].toModelIndex().column() <= kGroup && c[1].toModelIndex().column() >= kGroup);
        QVERIFY(reported);
        QSortFilterProxyModel proxy;
        proxy.setSourceModel(m_model.get());
        proxy.setSortRole(LightTableModel::SortRole);
        proxy.sort(kGroup);
        QStringList order;
        for (int r = 0; r < proxy.rowCount(); ++r)
            order << proxy.index(r, kGroup).data().toString();
        QCOMPARE(order, (QStringList{"key", "key", "key", "L3", "L5", "Rim"}));
        QVERIFY(!m_model->setData(g1, QString(300, QLatin1Char('x'))));
        QCOMPARE(m_doc->undoStack()->count(), 2);
        checkMatchesFreshModel();
        m_doc->undoStack()->setIndex(0);
        QCOMPARE(m_doc->rig(), lrtest::sampleRig());
        checkMatchesFreshModel();
        // Unnamed lights (from a file) are "light N" by their index, which a removal changes.
        Rig unnamed = lrtest::pointRig(3);
        for (Light& l : unnamed.lights)
            l.name.clear();
        m_doc->newRig(unnamed);
        QCOMPARE(m_model->index(2, kGroup).data().toString(), QStringLiteral("light 3"));
        changed.clear();
        QVERIFY(m_doc->removeLights({0}));
        QCOMPARE(m_model->index(1, kGroup).data().toString(), QStringLiteral("light 2"));
        QVERIFY(!changed.isEmpty());
    }

    void persistentIndexFollowsMoves() {
        QPersistentModelIndex l1 = m_model->index(1, LightTableModel::NameColumn);
        QVERIFY(m_doc->moveLights({1}, 5));
        QCOMPARE(l1.row(), 4);
        QCOMPARE(l1.data().toString(), QStringLiteral("L1"));
        QVERIFY(m_doc->moveLights({0, 2, 5}, 1));
        QCOMPARE(l1.data().toString(), QStringLiteral("L1"));
        m_doc->undoStack()->undo();
        m_doc->undoStack()->undo();
        QCOMPARE(l1.row(), 1);
        QVERIFY(m_doc->removeLights({1}));
        QVERIFY(!l1.isValid());
    }

    void dragAndDropReorders() {
        QModelIndexList dragged{m_model->index(0, 0), m_model->index(0, 3), m_model->index(2, 1)};
        std::unique_ptr<QMimeData> mime(m_model->mimeData(dragged));
        QVERIFY(mime);
        QVERIFY(mime->hasFormat(QString::fromLatin1(LightTableModel::kMimeType)));
        QVERIFY(m_model->canDropMimeData(mime.get(), Qt::MoveAction, 5, 0, {}));
        QVERIFY(!m_model->canDropMimeData(mime.get(), Qt::CopyAction, 5, 0, {}));
        QVERIFY(m_model->dropMimeData(mime.get(), Qt::MoveAction, 5, 0, {}));
        QCOMPARE(names(*m_doc), (QStringList{"L1", "L3", "L4", "L0", "L2", "L5"}));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        // Dropped onto an item: before it. Below everything (row -1, no parent): to the end.
        std::unique_ptr<QMimeData> one(m_model->mimeData({m_model->index(5, 0)}));
        QVERIFY(m_model->dropMimeData(one.get(), Qt::MoveAction, -1, -1, m_model->index(0, 0)));
        QCOMPARE(names(*m_doc).first(), QStringLiteral("L5"));
        std::unique_ptr<QMimeData> first(m_model->mimeData({m_model->index(0, 0)}));
        QVERIFY(m_model->dropMimeData(first.get(), Qt::MoveAction, -1, -1, {}));
        QCOMPARE(names(*m_doc).last(), QStringLiteral("L5"));
        // moveRows is a command too.
        QVERIFY(m_model->moveRows({}, 0, 2, {}, 6));
        QCOMPARE(names(*m_doc), (QStringList{"L4", "L0", "L2", "L5", "L1", "L3"}));
        QCOMPARE(m_doc->undoStack()->count(), 4);
        m_doc->undoStack()->setIndex(0);
        QCOMPARE(m_doc->rig(), lrtest::sampleRig());
        // Garbage mime data is refused.
        QMimeData junk;
        junk.setData(QString::fromLatin1(LightTableModel::kMimeType), QByteArray("\x01\x02", 2));
        QVERIFY(!m_model->dropMimeData(&junk, Qt::MoveAction, 0, 0, {}));
    }

    void soloColumnFollowsDocument() {
        QSignalSpy changed(m_model.get(), &QAbstractItemModel::dataChanged);
        m_doc->setSoloed({2}, true);
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed[0][0].toModelIndex().column(), int(LightTableModel::SoloColumn));
        QCOMPARE(m_model->index(2, LightTableModel::SoloColumn).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Checked));
    }

    void manyLights() {
        m_doc->newRig(lrtest::pointRig(kMaxRigLights));
        QCOMPARE(m_model->rowCount(), kMaxRigLights);
        QList<int> rows;
        for (int i = 0; i < 1000; ++i)
            rows << i * 4;
        QVERIFY(m_model->setDataForRows(rows, LightTableModel::IntensityColumn, 2.0));
        QCOMPARE(m_doc->undoStack()->count(), 1);
        QCOMPARE(m_model->index(3996, LightTableModel::IntensityColumn).data().toString(),
                 QStringLiteral("2"));
    }
};

QTEST_GUILESS_MAIN(TestLightTableModel)
#include "tst_lighttablemodel.moc"
