// The editor's document: the rig being edited, its file, the undo stack, the light selection and the
// transient solo state. Everything that changes the rig goes through an undo command pushed on undoStack()
// (the convenience methods below create and push them); widgets and models never mutate the rig directly.
//
// Lights are identified by stable LightIds: an id stays with its light through reorders, edits, undo and
// redo (a removed light keeps its id when the removal is undone), so the selection and the solo set, which
// are kept as ids, survive reordering and undo. Ids are not saved; a load or a new rig assigns fresh ones.
#pragma once

#include "core/rig.h"
#include "editor/lightproperty.h"
#include "editor/rigproperty.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QUndoStack>
#include <QVariant>
#include <functional>
#include <optional>
#include <vector>

namespace lr {

using LightId = quint64; // never 0
constexpr int kMaxChangeRuns = 16;

// What a change did, so views update minimally. Rows are light indices in the rig.
struct RigChange {
    enum Kind {
        LightValues, // lights first..last changed their lightProperty (Any: several values). One change per
                     // contiguous run of edited rows, or one span over all of them when there are more than
                     // kMaxChangeRuns runs (some lights in the span may then be unchanged).
        RigValues,   // a rig-wide value (rigProperty) changed
        Inserted,    // lights first..last inserted (indices after the insertion)
        Removed,     // lights first..last removed (indices before the removal)
        Moved, // lights first..last moved before old index destination (QAbstractItemModel::beginMoveRows)
        Reordered, // the lights were permuted: order[i] is the old index of the light now at i (a layout
                   // change: models emit layoutChanged and move their persistent indexes)
        Reset,     // the whole rig was replaced (load, new, preset), or many scattered rows were inserted
                   // or removed at once (more than kMaxChangeRuns runs: one reset beats thousands of signals)
    };
    Kind kind = Reset;
    int first = -1, last = -1;
    int destination = -1;
    QList<int> order; // Reordered only
    LightProperty lightProperty = LightProperty::Any;
    RigProperty rigProperty = RigProperty::Any;
    bool isStructural() const { return kind != LightValues && kind != RigValues; }
};

class Document : public QObject {
    Q_OBJECT
  public:
    explicit Document(QObject* parent = nullptr); // an empty, clean, untitled rig
    ~Document() override;

    // ---- the rig (read-only access) ----
    const Rig& rig() const { return m_rig; }
    int lightCount() const { return int(m_rig.lights.size()); }
    const Light& light(int row) const { return m_rig.lights[size_t(row)]; }
    LightId lightId(int row) const { return m_ids[row]; }
    const QList<LightId>& lightIds() const { return m_ids; }
    int rowOf(LightId id) const; // -1 when no such light
    // The rig with solo applied: when any light is soloed, every light that is not soloed is disabled
    // (indices stay those of rig(), so gizmos and selection still match). Without solo, rig() itself.
    Rig renderRig() const;

    // ---- file ----
    QString filePath() const { return m_filePath; } // empty for an untitled rig
    QString displayName() const;                    // file name, or "Untitled"
    bool isModified() const { return !m_undoStack.isClean(); }
    // Replaces the rig with the file's (fresh ids, empty undo stack, clean, no selection or solo). On failure
    // nothing changes and the error text ("FILE: path: reason", one per line) is returned; empty on success.
    QString load(const QString& filePath, QStringList* warnings = nullptr);
    // save(): to filePath() (an error when untitled). saveAs(): to filePath, which becomes the file path.
    // Atomic; on success the undo stack is marked clean. Return the error text, empty on success.
    QString save();
    QString saveAs(const QString& filePath);
    // The camera view written as the rig's "view" on save (Rig::view; the viewport's camera). Moving the
    // camera is no edit: it does not mark the rig modified. Unset: the rig's view is written as it is.
    std::function<std::optional<RigView>()> currentView;
    // A new untitled document with this rig (default: empty rig), empty undo stack, clean.
    void newRig(const Rig& rig = Rig{});

    // ---- undo ----
    QUndoStack* undoStack() { return &m_undoStack; }
    // Continuous edits (slider and spin-box drags, gizmo drags): between begin and end, consecutive commands
    // of the same kind, property and lights merge into one undo step. Returns a token for endContinuousEdit.
    // Nested begin calls share the outer session.
    int beginContinuousEdit();
    void endContinuousEdit(int token);
    int continuousEditSession() const { return m_editSession; } // 0 when none is open

    // ---- convenience: validate, create and push one command. Return false (and *error) when refused. ----
    // One value for every row, or one value per row (values.size() == rows.size()). Rows where the property
    // does not apply (lightPropertyApplies) are skipped; an error when it applies to none.
    bool setLightValue(const QList<int>& rows, LightProperty property, const QVariant& value,
                       QString* error = nullptr);
    bool setLightValues(const QList<int>& rows, LightProperty property, const QVariantList& values,
                        QString* error = nullptr);
    bool setRigValue(RigProperty property, const QVariant& value, QString* error = nullptr);
    // Appends makeLight(type, a unique name like "Spot 2") and selects it (made physically based, as
    // placement.h's makePhysicallyBased, in a physically based rig).
    bool addLight(LightType type, QString* error = nullptr);
    // Inserts lights at row (-1: append) as one step and selects them.
    bool addLights(int row, const std::vector<Light>& lights, const QString& text, QString* error = nullptr);
    bool removeLights(const QList<int>& rows, QString* error = nullptr);
    // Copies inserted as one block after the last of rows, then selected: each named like Add names a new
    // light ("Key" -> "Key 2", "Key 2" -> "Key 3") and, when it has a position, moved a little aside so it
    // does not hide its original.
    bool duplicateLights(const QList<int>& rows, QString* error = nullptr);
    // Moves rows (any set) so they end up contiguous, in their current order, before the light that is now at
    // index destination (0..lightCount(); lightCount() = to the end). Same convention as Qt's drop row.
    bool moveLights(const QList<int>& rows, int destination, QString* error = nullptr);
    // setLightValue for the name (numbered when another light has it: "Key 2") and for on/off.
    bool renameLight(int row, const QString& name, QString* error = nullptr);
    bool setLightsEnabled(const QList<int>& rows, bool enabled, QString* error = nullptr);
    // One undo step replacing the whole rig (apply preset, import lights from a model).
    bool replaceRig(const Rig& rig, const QString& text, QString* error = nullptr);
    // "Spot", "Spot 2", ... : the first "BASE" / "BASE N" no light is called (nor any of `taken`).
    QString uniqueLightName(const QString& base, const QSet<QString>& taken = {}) const;

    // ---- selection (not an undo step) ----
    const QSet<LightId>& selection() const { return m_selection; }
    QList<int> selectedRows() const;                   // sorted
    LightId currentLight() const { return m_current; } // the light last made current (0: none); in selection
    int currentRow() const { return rowOf(m_current); }
    // Unknown ids are dropped. current defaults to one of ids (kept if it was current and still selected).
    void setSelection(const QSet<LightId>& ids, LightId current = 0);
    void setSelectedRows(const QList<int>& rows, int currentRow = -1);
    bool isSelected(int row) const { return m_selection.contains(m_ids[row]); }

    // ---- solo (transient view state: not saved, not an undo step) ----
    bool isSoloed(int row) const { return m_solo.contains(m_ids[row]); }
    bool anySoloed() const { return !m_solo.isEmpty(); }
    const QSet<LightId>& soloed() const { return m_solo; }
    void setSoloed(const QList<int>& rows, bool solo);
    void clearSolo();

  signals:
    // Before a structural change (Inserted, Removed, Moved, Reset) — models call begin*Rows here.
    void rigAboutToChange(const lr::RigChange& change);
    // After every change of the rig, structural or not (undo and redo included).
    void rigChanged(const lr::RigChange& change);
    void selectionChanged();
    void soloChanged();
    void fileChanged(const QString& filePath); // the file path changed (load, save as, new)
    void modifiedChanged(bool modified);       // the undo stack's clean state changed

  private:
    friend class RigCommand; // the mutation interface of every undo command (rigcommand.h)

    // Primitives behind RigCommand. Each emits the RigChange signals and prunes selection/solo as needed.
    LightId newLightId() { return ++m_lastId; }
    void setLightsAt(const QList<int>& rows, const std::vector<Light>& lights, LightProperty property);
    void insertLightsAt(int row, const std::vector<Light>& lights, const QList<LightId>& ids);
    void removeLightsAt(int first, int count);
    void moveLightBlock(int first, int count, int destination); // destination as in beginMoveRows
    void reorderLights(const QList<int>& order);                // order[i] = old index of new light i
    // Any sorted set of rows: per contiguous run, or as one Reset when there are many runs.
    void insertLightRows(const QList<int>& rows, const std::vector<Light>& lights, const QList<LightId>& ids);
    void removeLightRows(const QList<int>& rows);
    void setRigValueNow(RigProperty property, const QVariant& value);
    void resetRig(const Rig& rig, const QList<LightId>& ids);
    void resetDocument(const Rig& rig, const QString& filePath);
    bool pushChecked(QUndoCommand* command, QString* error, const QString& reason);
    void pruneTransientState();

    Rig m_rig;
    QList<LightId> m_ids; // parallel to m_rig.lights
    mutable QHash<LightId, int> m_rowById;
    mutable bool m_rowByIdDirty = true;
    LightId m_lastId = 0;
    QString m_filePath;
    QUndoStack m_undoStack;
    QSet<LightId> m_selection;
    LightId m_current = 0;
    QSet<LightId> m_solo;
    int m_editSession = 0, m_editDepth = 0, m_lastSession = 0;
};

// RAII continuous edit: Document::beginContinuousEdit() in the constructor, end in the destructor.
class ContinuousEdit {
  public:
    explicit ContinuousEdit(Document* document) : m_doc(document), m_token(document->beginContinuousEdit()) {}
    ~ContinuousEdit() { m_doc->endContinuousEdit(m_token); }
    ContinuousEdit(const ContinuousEdit&) = delete;
    ContinuousEdit& operator=(const ContinuousEdit&) = delete;

  private:
    Document* m_doc;
    int m_token;
};

} // namespace lr
