// Editing light and shadow linking (issue 38, core/lightlink.h) the way the editor shows it: the model's
// parts as rows, one per node name (a node with several meshes or materials is one row; the rig's ground is
// the row "ground"), and per light and row whether the light lights it and whether it casts the light's
// shadow.
//
// Toggling a row on or off in a light's set keeps the lists minimal and touches nothing else:
//   off in an everything-set        adds the row's name to `exclude`
//   off in an include-set           removes the names that name only this row from `include` (never the
//                                   last one: an empty include means every part), and adds the row to
//                                   `exclude` when something else still includes it
//   on                              removes the names that name only this row from `exclude`; adds the row
//                                   to `include` when there is one and it does not cover the row yet. An
//                                   include that then names every part (and only parts of this model)
//                                   becomes empty: everything. A broader exclusion that also names other
//                                   parts ("material:Metal") is replaced by names of those other parts.
// Names that match nothing in this model are kept as they are (the rig may be meant for another model).
#pragma once

#include "core/lightlink.h"

#include <QList>
#include <QString>
#include <QStringList>
#include <vector>

namespace lr {

class Document;

enum class LinkKind { Lit, Shadow };

PartSet& linkSet(LightLink& link, LinkKind kind);
const PartSet& linkSet(const LightLink& link, LinkKind kind);

// One row of the linking views: the parts (indices into the PartNames they were made from) that answer to
// one node name.
struct LinkPartRow {
    QString label;   // the node's name; a mesh's or material's when the node has none; "ground"
    QString name;    // what a list holds for this row: the label, or "node:LABEL" when the label alone also
                     // names other parts; empty when the parts have no name at all (not editable)
    QString toolTip; // its meshes and materials
    std::vector<std::size_t> parts;
    bool ground = false;
};

// The rows of `parts` (scene/linkparts.h order), in order of first appearance.
std::vector<LinkPartRow> linkPartRows(const std::vector<PartNames>& parts);

enum class LinkState { Off, On, Partly }; // Partly: some of the row's parts
LinkState linkState(const PartSet& set, const std::vector<PartNames>& parts, const LinkPartRow& row);

// The set with the row's parts all in (on) or all out, other parts as they were (see above).
PartSet withRowLinked(const PartSet& set, const std::vector<PartNames>& parts, const LinkPartRow& row,
                      bool on);
LightLink withRowLinked(const LightLink& link, LinkKind kind, const std::vector<PartNames>& parts,
                        const LinkPartRow& row, bool on);

// The names of the set that match no part (kept, shown greyed with a warning).
QStringList unmatchedNames(const PartSet& set, const std::vector<PartNames>& parts);

// Whether every light of `rows` has the row's parts all in its set.
bool rowLinkedForAll(const Document& doc, const QList<int>& rows, LinkKind kind,
                     const std::vector<PartNames>& parts, const LinkPartRow& row);

// One undo step: the row in (on) or out of the `kind` set of every light of `rows` (ChangeLightValue of
// LightProperty::Link, one value per light). False and *error when refused; false with an empty *error when
// no light would change.
bool setRowLinked(Document* doc, const QList<int>& rows, LinkKind kind, const std::vector<PartNames>& parts,
                  const LinkPartRow& row, bool on, QString* error = nullptr);
// One undo step: every light of `rows` back to the default link (lights everything, everything casts).
bool resetLinks(Document* doc, const QList<int>& rows, QString* error = nullptr);

} // namespace lr
