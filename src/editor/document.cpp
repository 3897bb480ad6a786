#include "editor/document.h"

#include "core/rigjson.h"
#include "editor/commands.h"
#include "editor/placement.h"

#include <QFileInfo>
#include <algorithm>
#include <glm/geometric.hpp>

namespace lr {

namespace {
int runCount(const QList<int>& sortedRows) {
    int runs = 0;
    for (int i = 0; i < sortedRows.size(); ++i)
        if (i == 0 || sortedRows[i] != sortedRows[i - 1] + 1) ++runs;
    return runs;
}
} // namespace

Document::Document(QObject* parent) : QObject(parent) {
    qRegisterMetaType<lr::RigChange>();
    connect(&m_undoStack, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() {
    // Commands hold a pointer to this document; delete them before the rig goes away, without signals.
    m_undoStack.blockSignals(true);
    m_undoStack.clear();
}

int Document::rowOf(LightId id) const {
    if (m_rowByIdDirty) {
        m_rowById.clear();
        m_rowById.reserve(m_ids.size());
        for (int i = 0; i < m_ids.size(); ++i)
            m_rowById.insert(m_ids[i], i);
        m_rowByIdDirty = false;
    }
    return m_rowById.value(id, -1);
}

Rig Document::renderRig() const {
    Rig out = m_rig;
    // Issue 39: the files the lights name, against the rig's folder (the current one while untitled).
    resolveLightFiles(out, m_filePath.isEmpty() ? QString() : QFileInfo(m_filePath).absolutePath());
    if (m_solo.isEmpty()) return out;
    for (size_t i = 0; i < out.lights.size(); ++i)
        if (!m_solo.contains(m_ids[int(i)])) out.lights[i].enabled = false;
    return out;
}

QString Document::displayName() const {
    return m_filePath.isEmpty() ? tr("Untitled") : QFileInfo(m_filePath).fileName();
}

QString Document::load(const QString& filePath, QStringList* warnings) {
    RigReadResult result = readRigFile(filePath);
    if (!result.ok()) {
        if (result.errors.isEmpty()) return tr("%1: could not be read").arg(filePath);
        return result.errors.join(QLatin1Char('\n'));
    }
    if (warnings) *warnings = result.warnings;
    resetDocument(*result.rig, filePath);
    return {};
}

QString Document::save() {
    if (m_filePath.isEmpty()) return tr("The rig has no file yet: use Save As");
    return saveAs(m_filePath);
}

QString Document::saveAs(const QString& filePath) {
    QString error;
    Rig rig = m_rig;
    if (currentView) rig.view = currentView();
    if (!saveRigFile(rig, filePath, &error))
        return error.isEmpty() ? tr("%1: could not be saved").arg(filePath) : error;
    m_rig.view = rig.view; // the view as saved (no signal: nothing the views show changed)
    m_undoStack.setClean();
    if (filePath != m_filePath) {
        m_filePath = filePath;
        emit fileChanged(m_filePath);
    }
    return {};
}

void Document::newRig(const Rig& rig) {
    resetDocument(rig, QString());
}

void Document::resetDocument(const Rig& rig, const QString& filePath) {
    m_undoStack.clear(); // clean again (emits cleanChanged when it was modified)
    QList<LightId> ids;
    ids.reserve(qsizetype(rig.lights.size()));
    for (size_t i = 0; i < rig.lights.size(); ++i)
        ids.append(newLightId());
    m_editSession = 0;
    m_editDepth = 0;
    resetRig(rig, ids);
    if (filePath != m_filePath) {
        m_filePath = filePath;
        emit fileChanged(m_filePath);
    }
}

// ---- continuous edits ----

int Document::beginContinuousEdit() {
    if (m_editDepth++ == 0) m_editSession = ++m_lastSession;
    return m_editSession;
}

void Document::endContinuousEdit(int token) {
    if (token == 0 || token != m_editSession || m_editDepth == 0) return;
    if (--m_editDepth == 0) m_editSession = 0;
}

// ---- convenience ----

bool Document::pushChecked(QUndoCommand* command, QString* error, const QString& reason) {
    if (!command) {
        if (error) *error = reason;
        return reason.isEmpty(); // refused with no reason: nothing to do, not a failure
    }
    m_undoStack.push(command);
    return true;
}

bool Document::setLightValue(const QList<int>& rows, LightProperty property, const QVariant& value,
                             QString* error) {
    QString reason;
    auto cmd = ChangeLightValue::create(this, rows, property, value, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::setLightValues(const QList<int>& rows, LightProperty property, const QVariantList& values,
                              QString* error) {
    QString reason;
    auto cmd = ChangeLightValue::create(this, rows, property, values, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::setRigValue(RigProperty property, const QVariant& value, QString* error) {
    QString reason;
    auto cmd = ChangeRigValue::create(this, property, value, &reason);
    return pushChecked(cmd.release(), error, reason);
}

QString Document::uniqueLightName(const QString& base, const QSet<QString>& taken) const {
    QSet<QString> names = taken;
    for (const Light& l : m_rig.lights)
        names.insert(l.name);
    if (!names.contains(base)) return base;
    for (int n = 2;; ++n) {
        const QString candidate = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!names.contains(candidate)) return candidate;
    }
}

bool Document::addLight(LightType type, QString* error) {
    Light light = makeLight(type, uniqueLightName(lightTypeLabel(type)));
    if (m_rig.shading.model == ShadingModel::Pbr) makePhysicallyBased(light, glm::length(light.position));
    return addLights(-1, {light}, tr("Add %1 light").arg(toString(type)), error);
}

bool Document::addLights(int row, const std::vector<Light>& lights, const QString& text, QString* error) {
    QString reason;
    auto cmd = AddLights::create(this, row, lights, text, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::removeLights(const QList<int>& rows, QString* error) {
    QString reason;
    auto cmd = RemoveLights::create(this, rows, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::duplicateLights(const QList<int>& rows, QString* error) {
    QString reason;
    auto cmd = DuplicateLights::create(this, rows, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::moveLights(const QList<int>& rows, int destination, QString* error) {
    QString reason;
    auto cmd = MoveLights::create(this, rows, destination, &reason);
    return pushChecked(cmd.release(), error, reason);
}

bool Document::renameLight(int row, const QString& name, QString* error) {
    return setLightValue({row}, LightProperty::Name, name, error);
}

bool Document::setLightsEnabled(const QList<int>& rows, bool enabled, QString* error) {
    return setLightValue(rows, LightProperty::Enabled, enabled, error);
}

bool Document::replaceRig(const Rig& rig, const QString& text, QString* error) {
    QString reason;
    auto cmd = ReplaceRig::create(this, rig, text, &reason);
    return pushChecked(cmd.release(), error, reason);
}

// ---- selection and solo ----

QList<int> Document::selectedRows() const {
    QList<int> rows;
    rows.reserve(m_selection.size());
    for (LightId id : m_selection)
        if (const int r = rowOf(id); r >= 0) rows.append(r);
    std::sort(rows.begin(), rows.end());
    return rows;
}

void Document::setSelection(const QSet<LightId>& ids, LightId current) {
    QSet<LightId> valid;
    valid.reserve(ids.size());
    for (LightId id : ids)
        if (rowOf(id) >= 0) valid.insert(id);
    LightId cur = 0;
    if (current && valid.contains(current))
        cur = current;
    else if (m_current && valid.contains(m_current))
        cur = m_current;
    else if (!valid.isEmpty()) {
        int best = -1;
        for (LightId id : valid)
            if (const int r = rowOf(id); best < 0 || r < best) {
                best = r;
                cur = id;
            }
    }
    if (valid == m_selection && cur == m_current) return;
    m_selection = std::move(valid);
    m_current = cur;
    emit selectionChanged();
}

void Document::setSelectedRows(const QList<int>& rows, int currentRow) {
    QSet<LightId> ids;
    for (int r : rows)
        if (r >= 0 && r < m_ids.size()) ids.insert(m_ids[r]);
    const LightId cur = currentRow >= 0 && currentRow < m_ids.size() ? m_ids[currentRow] : 0;
    setSelection(ids, cur);
}

void Document::setSoloed(const QList<int>& rows, bool solo) {
    bool changed = false;
    for (int r : rows) {
        if (r < 0 || r >= m_ids.size()) continue;
        changed |= solo ? (m_solo.contains(m_ids[r]) ? false : (m_solo.insert(m_ids[r]), true))
                        : m_solo.remove(m_ids[r]);
    }
    if (changed) emit soloChanged();
}

void Document::clearSolo() {
    if (m_solo.isEmpty()) return;
    m_solo.clear();
    emit soloChanged();
}

void Document::pruneTransientState() {
    QSet<LightId> solo;
    for (LightId id : std::as_const(m_solo))
        if (rowOf(id) >= 0) solo.insert(id);
    if (solo.size() != m_solo.size()) {
        m_solo = std::move(solo);
        emit soloChanged();
    }
    setSelection(m_selection, m_current);
}

// ---- primitives (commands only) ----

void Document::setLightsAt(const QList<int>& rows, const std::vector<Light>& lights, LightProperty property) {
    Q_ASSERT(size_t(rows.size()) == lights.size());
    for (int i = 0; i < rows.size(); ++i)
        m_rig.lights[size_t(rows[i])] = lights[size_t(i)];
    // One signal per contiguous run of rows (rows are sorted); a scattered multi-edit (many runs) is reported
    // as one span first..last instead, so views get a handful of signals rather than thousands.
    const int runs = runCount(rows);
    RigChange c;
    c.kind = RigChange::LightValues;
    c.lightProperty = property;
    if (runs > kMaxChangeRuns) {
        c.first = rows.front();
        c.last = rows.back();
        emit rigChanged(c);
        return;
    }
    for (int i = 0; i < rows.size();) {
        int j = i;
        while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1)
            ++j;
        c.first = rows[i];
        c.last = rows[j];
        emit rigChanged(c);
        i = j + 1;
    }
}

void Document::insertLightsAt(int row, const std::vector<Light>& lights, const QList<LightId>& ids) {
    if (lights.empty()) return;
    RigChange c;
    c.kind = RigChange::Inserted;
    c.first = row;
    c.last = row + int(lights.size()) - 1;
    emit rigAboutToChange(c);
    m_rig.lights.insert(m_rig.lights.begin() + row, lights.begin(), lights.end());
    m_ids.insert(row, ids.size(), 0);
    std::copy(ids.begin(), ids.end(), m_ids.begin() + row);
    m_rowByIdDirty = true;
    emit rigChanged(c);
}

void Document::removeLightsAt(int first, int count) {
    if (count <= 0) return;
    RigChange c;
    c.kind = RigChange::Removed;
    c.first = first;
    c.last = first + count - 1;
    emit rigAboutToChange(c);
    m_rig.lights.erase(m_rig.lights.begin() + first, m_rig.lights.begin() + first + count);
    m_ids.remove(first, count);
    m_rowByIdDirty = true;
    emit rigChanged(c);
    pruneTransientState();
}

void Document::moveLightBlock(int first, int count, int destination) {
    RigChange c;
    c.kind = RigChange::Moved;
    c.first = first;
    c.last = first + count - 1;
    c.destination = destination;
    emit rigAboutToChange(c);
    auto rotate = [&](auto begin) {
        if (destination > first)
            std::rotate(begin + first, begin + first + count, begin + destination);
        else
            std::rotate(begin + destination, begin + first, begin + first + count);
    };
    rotate(m_rig.lights.begin());
    rotate(m_ids.begin());
    m_rowByIdDirty = true;
    emit rigChanged(c);
}

void Document::reorderLights(const QList<int>& order) {
    Q_ASSERT(order.size() == m_ids.size());
    RigChange c;
    c.kind = RigChange::Reordered;
    c.order = order;
    c.first = 0;
    c.last = int(order.size()) - 1;
    emit rigAboutToChange(c);
    std::vector<Light> lights;
    lights.reserve(m_rig.lights.size());
    QList<LightId> ids;
    ids.reserve(m_ids.size());
    for (int old : order) {
        lights.push_back(std::move(m_rig.lights[size_t(old)]));
        ids.append(m_ids[old]);
    }
    m_rig.lights = std::move(lights);
    m_ids = std::move(ids);
    m_rowByIdDirty = true;
    emit rigChanged(c);
}

void Document::insertLightRows(const QList<int>& rows, const std::vector<Light>& lights,
                               const QList<LightId>& ids) {
    if (runCount(rows) <= kMaxChangeRuns) {
        // Runs in ascending order: each run's first row is its final index once the earlier runs are in.
        for (int i = 0; i < rows.size();) {
            int j = i;
            while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1)
                ++j;
            const std::vector<Light> run(lights.begin() + i, lights.begin() + j + 1);
            insertLightsAt(rows[i], run, ids.mid(i, j - i + 1));
            i = j + 1;
        }
        return;
    }
    RigChange c;
    c.kind = RigChange::Reset;
    emit rigAboutToChange(c);
    for (int i = 0; i < rows.size(); ++i) { // ascending: every earlier index is already final
        m_rig.lights.insert(m_rig.lights.begin() + rows[i], lights[size_t(i)]);
        m_ids.insert(rows[i], ids[i]);
    }
    m_rowByIdDirty = true;
    emit rigChanged(c);
    pruneTransientState();
}

void Document::removeLightRows(const QList<int>& rows) {
    if (runCount(rows) <= kMaxChangeRuns) {
        for (int j = int(rows.size()) - 1; j >= 0;) { // last run first, so earlier indices stay valid
            int i = j;
            while (i > 0 && rows[i - 1] == rows[i] - 1)
                --i;
            removeLightsAt(rows[i], j - i + 1);
            j = i - 1;
        }
        return;
    }
    RigChange c;
    c.kind = RigChange::Reset;
    emit rigAboutToChange(c);
    QList<bool> removed(m_ids.size(), false);
    for (int r : rows)
        removed[r] = true;
    std::vector<Light> lights;
    QList<LightId> ids;
    for (int i = 0; i < m_ids.size(); ++i)
        if (!removed[i]) {
            lights.push_back(std::move(m_rig.lights[size_t(i)]));
            ids.append(m_ids[i]);
        }
    m_rig.lights = std::move(lights);
    m_ids = std::move(ids);
    m_rowByIdDirty = true;
    emit rigChanged(c);
    pruneTransientState();
}

void Document::setRigValueNow(RigProperty property, const QVariant& value) {
    applyRigValue(m_rig, property, value);
    RigChange c;
    c.kind = RigChange::RigValues;
    c.rigProperty = property;
    emit rigChanged(c);
}

void Document::resetRig(const Rig& rig, const QList<LightId>& ids) {
    RigChange c;
    c.kind = RigChange::Reset;
    emit rigAboutToChange(c);
    m_rig = rig;
    m_ids = ids;
    m_rowByIdDirty = true;
    emit rigChanged(c);
    pruneTransientState();
}

} // namespace lr
