#include "iessummary.h"

#include "core/ies.h"
#include "editor/document.h"

#include <QFileInfo>
#include <QFormLayout>

namespace lr {

IesSummary::IesSummary(Document* document, QFormLayout* form, QWidget* parent)
    : QLabel(parent), m_doc(document), m_form(form) {
    setObjectName(QStringLiteral("iesSummary"));
    // No word wrap: a height-for-width label in a QFormLayout with hidden rows writes out of bounds in Qt
    // 6.4 (valgrind: QFormLayout::heightForWidth); the whole text is the tooltip too.
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    connect(m_doc, &Document::rigChanged, this, &IesSummary::refresh);
    connect(m_doc, &Document::selectionChanged, this, &IesSummary::refresh);
}

void IesSummary::refresh() {
    int current = m_doc->currentRow();
    const QList<int> rows = m_doc->selectedRows();
    if (current < 0 && !rows.isEmpty()) current = rows.first();
    const bool shown = current >= 0 && current < m_doc->lightCount() && m_doc->light(current).ies;
    if (m_form) m_form->setRowVisible(this, shown);
    if (!shown) return;
    const Rig rig = m_doc->renderRig(); // the files resolved against the rig's folder
    const IesSpec& spec = *rig.lights[size_t(current)].ies;
    const QString path = spec.resolved.isEmpty() ? spec.file : spec.resolved;
    const QFileInfo info(path);
    if (path == m_path && info.size() == m_size && info.lastModified() == m_modified) return;
    m_path = path, m_size = info.size(), m_modified = info.lastModified();
    QString error;
    const auto profile = readIesFile(path, &error);
    if (!profile) {
        setText(QStringLiteral("<span style=\"color: #d04030\">%1</span>").arg(error.toHtmlEscaped()));
        setToolTip(error);
        return;
    }
    setText(tr("Peak %1 cd, beam %2° (%3, %4 × %5 angles, %6)")
                .arg(profile->peak, 0, 'g', 6)
                .arg(iesBeamAngle(*profile), 0, 'f', 1)
                .arg(profile->symmetry)
                .arg(profile->fileVertical)
                .arg(profile->fileHorizontal)
                .arg(profile->format));
    setToolTip(text());
}

IesSummary* addIesSummary(QFormLayout* form, QWidget* fileField, Document* document) {
    int row = -1;
    QFormLayout::ItemRole role;
    form->getWidgetPosition(fileField, &row, &role);
    auto* summary = new IesSummary(document, form, fileField->parentWidget());
    if (row >= 0)
        form->insertRow(row + 1, QObject::tr("Profile"), summary);
    else
        form->addRow(QObject::tr("Profile"), summary);
    summary->refresh();
    return summary;
}

} // namespace lr
