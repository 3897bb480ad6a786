#include "texturesconsent.h"

#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QObject>
#include <QPushButton>
#include <algorithm>

namespace lr {

QString texturesOutsideFolderDetails(const QString& modelPath, const QStringList& references, int listed) {
    QStringList lines;
    lines << QObject::tr("%1 refers to %n texture(s) outside its folder (%2):", nullptr,
                         int(references.size()))
                 .arg(QFileInfo(modelPath).fileName(),
                      QDir::toNativeSeparators(QFileInfo(modelPath).absolutePath()));
    const int shown = int(std::min<qsizetype>(references.size(), std::max(listed, 0)));
    for (int i = 0; i < shown; ++i)
        lines << QStringLiteral("    ") + references.at(i);
    if (references.size() > shown)
        lines << QObject::tr("    and %n more", nullptr, int(references.size() - shown));
    return lines.join(QLatin1Char('\n'));
}

bool askLoadTexturesOutsideFolder(QWidget* parent, const QString& modelPath, const QStringList& references) {
    QMessageBox box(QMessageBox::Question, QObject::tr("Textures outside the model's folder"),
                    QObject::tr("Load textures from outside the model's folder?"), QMessageBox::NoButton,
                    parent);
    box.setInformativeText(
        texturesOutsideFolderDetails(modelPath, references) + QStringLiteral("\n\n") +
        QObject::tr("LightRig only reads files inside a model's folder unless you allow it. Without them the "
                    "parts that use these textures are shown untextured."));
    QPushButton* load = box.addButton(QObject::tr("&Load"), QMessageBox::AcceptRole);
    QPushButton* skip = box.addButton(QObject::tr("&Don't load"), QMessageBox::RejectRole);
    box.setDefaultButton(skip);
    box.setEscapeButton(skip);
    box.exec();
    return box.clickedButton() == load;
}

} // namespace lr
