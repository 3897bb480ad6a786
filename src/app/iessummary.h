// The Properties dock's read-out of a light's IES profile (issue 39, docs/light-shaping.md): its peak
// candela (the file's, × its candela multiplier), beam angle (50 % of the peak) and symmetry, or why the
// file does not read ("FILE:LINE: reason"). A row below the IES profile field, shown while the current
// light has a profile. The file is read again only when its resolved path, size or time changes.
#pragma once

#include <QDateTime>
#include <QLabel>

class QFormLayout;

namespace lr {

class Document;

class IesSummary : public QLabel {
    Q_OBJECT
  public:
    IesSummary(Document* document, QFormLayout* form, QWidget* parent);
    void refresh();

  private:
    Document* m_doc;
    QFormLayout* m_form;
    QString m_path; // what the text describes
    qint64 m_size = -1;
    QDateTime m_modified;
};

// Inserts the read-out below `fileField`'s row of `form`.
IesSummary* addIesSummary(QFormLayout* form, QWidget* fileField, Document* document);

} // namespace lr
