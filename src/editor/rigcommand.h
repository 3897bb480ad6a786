// The narrow mutation interface: the only way anything changes a Document's rig. Every undo command derives
// from RigCommand and changes the rig through its protected primitives (Document befriends this class
// alone); widgets and models push commands and never reach the primitives. Each primitive emits the
// Document's RigChange signals (rigAboutToChange before a structural change, rigChanged after) and prunes the
// selection and the solo set of lights that are gone.
#pragma once

#include "editor/document.h"

#include <QUndoCommand>
#include <vector>

namespace lr {

class RigCommand : public QUndoCommand {
  protected:
    explicit RigCommand(Document* document) : m_doc(document) {}
    Document* document() const { return m_doc; }

    LightId newLightId();
    // The lights with these ids become `lights` (parallel lists, any order; ids no longer in the rig are
    // skipped). `property` tells views what changed (Any: several values).
    void setLights(const QList<LightId>& ids, const std::vector<Light>& lights, LightProperty property);
    // Inserts lights so that they end up at `rows` (sorted ascending, indices after the insertion).
    void insertLights(const QList<int>& rows, const std::vector<Light>& lights, const QList<LightId>& ids);
    void removeLights(const QList<LightId>& ids);
    void moveLightBlock(int first, int count, int destination); // destination as in beginMoveRows
    void reorderLights(const QList<int>& order);                // order[i] = old index of new light i
    void setRigValue(RigProperty property, const QVariant& value);
    void resetRig(const Rig& rig, const QList<LightId>& ids);
    void select(const QList<LightId>& ids); // the new selection, its first id current

  private:
    Document* m_doc;
};

} // namespace lr
