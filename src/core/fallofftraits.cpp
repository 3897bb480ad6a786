#include "fallofftraits.h"

#include <QStringList>

namespace lr {

QString falloffModelsWith(FalloffKey key) {
    QStringList names;
    for (const FalloffTraits& t : kFalloffTraits)
        if (falloffUses(t.model, key)) names << QLatin1Char('"') + toString(t.model) + QLatin1Char('"');
    if (names.size() <= 1) return names.join(QString());
    const QString last = names.takeLast();
    return names.join(QStringLiteral(", ")) + QStringLiteral(" and ") + last;
}

} // namespace lr
