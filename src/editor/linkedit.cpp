#include "editor/linkedit.h"

#include "editor/changelightvalue.h"
#include "editor/document.h"

#include <QCoreApplication>
#include <QHash>

namespace lr {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("lr::LinkEdit", text);
}

std::vector<char> matches(const QString& name, const std::vector<PartNames>& parts) {
    std::vector<char> out(parts.size(), 0);
    for (std::size_t j = 0; j < parts.size(); ++j)
        out[j] = partNameMatches(name, parts[j]);
    return out;
}

bool matchesAny(const QStringList& names, const PartNames& part) {
    for (const QString& n : names)
        if (partNameMatches(n, part)) return true;
    return false;
}

// The row's parts, as a mask over all parts.
std::vector<char> rowMask(const LinkPartRow& row, std::size_t partCount) {
    std::vector<char> in(partCount, 0);
    for (std::size_t p : row.parts)
        if (p < partCount) in[p] = 1;
    return in;
}

// Whether `name` names some of the row's parts and nothing else.
bool namesOnly(const QString& name, const std::vector<PartNames>& parts, const std::vector<char>& inRow) {
    bool any = false;
    for (std::size_t j = 0; j < parts.size(); ++j) {
        if (!partNameMatches(name, parts[j])) continue;
        if (!inRow[j]) return false;
        any = true;
    }
    return any;
}

void append(QStringList& list, const QString& name) {
    if (!name.isEmpty() && !list.contains(name)) list << name;
}

// Exclusions that also name parts outside the row are replaced by names of those other parts, so the row
// comes out of `exclude` and every other part stays as it was.
void narrowExclusions(PartSet& s, const std::vector<PartNames>& parts, const std::vector<char>& inRow) {
    std::vector<char> keepOut(parts.size(), 0);
    QStringList kept;
    bool replaced = false;
    for (const QString& e : std::as_const(s.exclude)) {
        const std::vector<char> m = matches(e, parts);
        bool hitsRow = false;
        for (std::size_t j = 0; j < parts.size(); ++j)
            hitsRow = hitsRow || (m[j] && inRow[j]);
        if (!hitsRow) {
            kept << e;
            continue;
        }
        replaced = true;
        for (std::size_t j = 0; j < parts.size(); ++j)
            if (m[j] && !inRow[j]) keepOut[j] = 1;
    }
    if (!replaced) return;
    s.exclude = kept;
    for (const LinkPartRow& other : linkPartRows(parts)) {
        bool all = !other.parts.empty(), any = false;
        for (std::size_t p : other.parts) {
            all = all && keepOut[p];
            any = any || keepOut[p];
        }
        if (!any) continue;
        if (all) {
            append(s.exclude, other.name);
            continue;
        }
        for (std::size_t p : other.parts) // some of its meshes: by mesh where they have a name
            if (keepOut[p])
                append(s.exclude,
                       parts[p].mesh.isEmpty() ? other.name : QStringLiteral("mesh:") + parts[p].mesh);
    }
}

QString undoText(LinkKind kind, bool on, const QString& lights, const QString& part) {
    if (kind == LinkKind::Lit)
        return on ? tr("Let %1 light %2").arg(lights, part) : tr("Keep %1 off %2").arg(lights, part);
    return on ? tr("Let %2 cast the shadow of %1").arg(lights, part)
              : tr("Keep %2 out of the shadow of %1").arg(lights, part);
}

} // namespace

PartSet& linkSet(LightLink& link, LinkKind kind) {
    return kind == LinkKind::Lit ? link.lit : link.shadow;
}

const PartSet& linkSet(const LightLink& link, LinkKind kind) {
    return kind == LinkKind::Lit ? link.lit : link.shadow;
}

std::vector<LinkPartRow> linkPartRows(const std::vector<PartNames>& parts) {
    // A part's row key: "ground", else the first name it has, with its kind ("node:Body"); none: unnamed.
    const auto keyOf = [](const PartNames& p) -> std::pair<QString, QString> { // prefix, label
        if (p.ground) return {QString(), QStringLiteral("ground")};
        if (!p.node.isEmpty()) return {QStringLiteral("node:"), p.node};
        if (!p.mesh.isEmpty()) return {QStringLiteral("mesh:"), p.mesh};
        if (!p.material.isEmpty()) return {QStringLiteral("material:"), p.material};
        return {};
    };
    std::vector<QString> keys(parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto [prefix, label] = keyOf(parts[i]);
        keys[i] = prefix + label;
    }
    std::vector<LinkPartRow> rows;
    QHash<QString, std::size_t> byKey;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const auto [prefix, label] = keyOf(parts[i]);
        if (!label.isEmpty()) {
            if (const auto it = byKey.constFind(keys[i]); it != byKey.constEnd()) {
                rows[*it].parts.push_back(i);
                continue;
            }
            byKey.insert(keys[i], rows.size());
        }
        LinkPartRow row;
        row.label = label.isEmpty() ? tr("(unnamed)") : label;
        row.ground = parts[i].ground;
        row.parts.push_back(i);
        if (!label.isEmpty()) {
            // The bare label when it names no part of another row (the ground has no other name).
            row.name = label;
            for (std::size_t j = 0; j < parts.size() && !row.ground; ++j)
                if (keys[j] != keys[i] && partNameMatches(label, parts[j])) row.name = prefix + label;
        }
        rows.push_back(std::move(row));
    }
    for (LinkPartRow& row : rows) {
        if (row.ground) {
            row.toolTip = tr("The rig's ground (Render settings › Ground)");
            continue;
        }
        QStringList lines;
        for (std::size_t p : row.parts) {
            const PartNames& n = parts[p];
            const QString line = tr("mesh %1, material %2")
                                     .arg(n.mesh.isEmpty() ? tr("(unnamed)") : n.mesh,
                                          n.material.isEmpty() ? tr("(none)") : n.material);
            if (!lines.contains(line)) lines << line;
        }
        row.toolTip = (row.name.isEmpty() ? tr("%1 (no name: not linkable)").arg(row.label)
                                          : tr("%1 (in a rig: \"%2\")").arg(row.label, row.name)) +
                      QLatin1Char('\n') + lines.join(QLatin1Char('\n'));
    }
    return rows;
}

LinkState linkState(const PartSet& set, const std::vector<PartNames>& parts, const LinkPartRow& row) {
    int in = 0;
    for (std::size_t p : row.parts)
        in += partSetContains(set, parts[p]);
    return in == 0 ? LinkState::Off : in == int(row.parts.size()) ? LinkState::On : LinkState::Partly;
}

PartSet withRowLinked(const PartSet& set, const std::vector<PartNames>& parts, const LinkPartRow& row,
                      bool on) {
    if (row.name.isEmpty()) return set;
    const std::vector<char> inRow = rowMask(row, parts.size());
    const auto only = [&](const QString& n) { return namesOnly(n, parts, inRow); };
    PartSet s = set;
    if (!on) {
        if (!s.include.isEmpty()) {
            QStringList kept = s.include;
            kept.removeIf(only);
            if (!kept.isEmpty()) s.include = kept; // an empty include would mean every part
        }
        if (linkState(s, parts, row) != LinkState::Off) append(s.exclude, row.name);
        return s;
    }
    s.exclude.removeIf(only);
    if (!s.include.isEmpty()) {
        bool covered = true;
        for (std::size_t p : row.parts)
            covered = covered && matchesAny(s.include, parts[p]);
        if (!covered) append(s.include, row.name);
    }
    if (linkState(s, parts, row) != LinkState::On) narrowExclusions(s, parts, inRow);
    if (!s.include.isEmpty() && !parts.empty() && unmatchedNames(PartSet{s.include, {}}, parts).isEmpty()) {
        bool everyPart = true;
        for (const PartNames& p : parts)
            everyPart = everyPart && matchesAny(s.include, p);
        if (everyPart) s.include.clear(); // the include names everything this model has: no include
    }
    return s;
}

LightLink withRowLinked(const LightLink& link, LinkKind kind, const std::vector<PartNames>& parts,
                        const LinkPartRow& row, bool on) {
    LightLink out = link;
    linkSet(out, kind) = withRowLinked(linkSet(link, kind), parts, row, on);
    return out;
}

QStringList unmatchedNames(const PartSet& set, const std::vector<PartNames>& parts) {
    QStringList out;
    for (const QStringList* list : {&set.include, &set.exclude})
        for (const QString& n : *list) {
            bool found = false;
            for (const PartNames& p : parts)
                if ((found = partNameMatches(n, p))) break;
            if (!found) append(out, n);
        }
    return out;
}

bool rowLinkedForAll(const Document& doc, const QList<int>& rows, LinkKind kind,
                     const std::vector<PartNames>& parts, const LinkPartRow& row) {
    for (int r : rows)
        if (linkState(linkSet(doc.light(r).link, kind), parts, row) != LinkState::On) return false;
    return !rows.isEmpty();
}

bool setRowLinked(Document* doc, const QList<int>& rows, LinkKind kind, const std::vector<PartNames>& parts,
                  const LinkPartRow& row, bool on, QString* error) {
    if (error) error->clear();
    if (row.name.isEmpty()) {
        if (error) *error = tr("%1 has no name a rig could link it by").arg(row.label);
        return false;
    }
    QList<int> changed;
    QVariantList values;
    for (int r : rows) {
        if (r < 0 || r >= doc->lightCount()) continue;
        const LightLink& before = doc->light(r).link;
        const LightLink after = withRowLinked(before, kind, parts, row, on);
        if (after == before) continue;
        changed << r;
        values << QVariant::fromValue(after);
    }
    if (changed.isEmpty()) return false; // nothing to do: no step, no error
    auto cmd = ChangeLightValue::create(doc, changed, LightProperty::Link, values, error);
    if (!cmd) return false;
    const QString lights =
        changed.size() == 1 ? doc->light(changed.front()).name : tr("%1 lights").arg(changed.size());
    cmd->setText(undoText(kind, on, lights, row.label));
    doc->undoStack()->push(cmd.release());
    return true;
}

bool resetLinks(Document* doc, const QList<int>& rows, QString* error) {
    return doc->setLightValue(rows, LightProperty::Link, QVariant::fromValue(LightLink{}), error);
}

} // namespace lr
