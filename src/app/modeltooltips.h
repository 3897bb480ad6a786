// What each lighting model does, in one sentence, and where it comes from: the tooltips of the falloff,
// cone, diffuse, specular and viewer combos. One table (modeltooltips.cpp), written from
// docs/lighting-models.md (the design documents 000-004 in ../shared/seeds and glTF).
#pragma once

#include "core/types.h"

#include <QComboBox>
#include <QString>

namespace lr {

QString modelTooltip(FalloffModel model);
QString modelTooltip(ConeModel model);
QString modelTooltip(DiffuseModel model);
QString modelTooltip(SpecularModel model);
QString modelTooltip(ViewerModel model);

// Keeps a combo's tooltip that of its current item (set when the tooltip is asked for, so changes made with
// signals blocked count too).
void followCurrentItemTooltip(QComboBox* combo);

// Gives a combo filled with E's models in enum order (item i = E(i)) each item's tooltip, and the combo
// itself the tooltip of its current model.
template <typename E> void installModelTooltips(QComboBox* combo) {
    for (int i = 0; i < combo->count() && i < enumCount<E>(); ++i)
        combo->setItemData(i, modelTooltip(E(i)), Qt::ToolTipRole);
    followCurrentItemTooltip(combo);
}

} // namespace lr
