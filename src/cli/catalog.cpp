#include "catalog.h"

#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

namespace lr::cli {

namespace {

QString defaultPattern(const RenderRequest& r) {
    QString name = QStringLiteral("{model}_{rig}_{view}");
    if (r.turntable > 1) name += QStringLiteral("_####");
    return QDir(r.output).filePath(name +
                                   (r.format == "exr" ? QStringLiteral(".exr") : QStringLiteral(".png")));
}

QString expand(QString pattern, const RenderRequest& r, const RenderItem& item) {
    pattern.replace(QLatin1String("{model}"), modelName(r, item.model));
    pattern.replace(QLatin1String("{rig}"), rigName(r, item.rig));
    pattern.replace(QLatin1String("{view}"), viewName(r, item.view));
    return item.frame >= 0 ? framePath(pattern, item.frame) : pattern;
}

} // namespace

QString modelName(const RenderRequest& r, int model) {
    return QFileInfo(r.models.value(model)).completeBaseName();
}

QString rigName(const RenderRequest& r, int rig) {
    return rig < 0 ? QStringLiteral("default") : QFileInfo(r.rigs.value(rig)).completeBaseName();
}

QString viewName(const RenderRequest& r, int view) {
    return view < 0 ? QStringLiteral("default") : r.options.views.value(view);
}

std::optional<std::vector<RenderItem>> planRender(const RenderRequest& r, QString* usageError) {
    const QString pattern = r.outputIsFolder ? defaultPattern(r) : r.output;
    if (r.turntable > 1 && !hasFrameField(pattern)) {
        *usageError =
            QStringLiteral("--turntable %1 needs a run of # in the output's file name for the frame "
                           "number, e.g. out_####.png; got %2")
                .arg(r.turntable)
                .arg(r.output);
        return std::nullopt;
    }
    std::vector<RenderItem> items;
    const int rigs = std::max(1, int(r.rigs.size())), views = std::max(1, int(r.options.views.size()));
    for (int m = 0; m < r.models.size(); ++m)
        for (int g = 0; g < rigs; ++g)
            for (int v = 0; v < views; ++v)
                for (int f = 0; f < std::max(1, r.turntable); ++f) {
                    RenderItem item;
                    item.model = m;
                    item.rig = r.rigs.isEmpty() ? -1 : g;
                    item.view = r.options.views.isEmpty() ? -1 : v;
                    item.frame = r.turntable > 0 ? f : -1;
                    item.file = expand(pattern, r, item);
                    items.push_back(item);
                }
    QHash<QString, int> seen; // absolute path -> item
    for (int i = 0; i < int(items.size()); ++i) {
        const QString key = QFileInfo(items[size_t(i)].file).absoluteFilePath();
        if (!seen.contains(key)) {
            seen.insert(key, i);
            continue;
        }
        const RenderItem& a = items[size_t(seen.value(key))];
        const RenderItem& b = items[size_t(i)];
        if (r.models.size() > 1 && r.rigs.size() <= 1 && r.options.views.size() <= 1 && r.turntable <= 1 &&
            !r.outputIsFolder && !r.output.contains(QLatin1String("{model}")))
            *usageError = QStringLiteral("several models need -o FOLDER or a pattern with {model}, got %1")
                              .arg(r.output);
        else
            *usageError =
                QStringLiteral("-o %1: %2 (%3, %4) and %5 (%6, %7) would both write %8; use a folder or a "
                               "pattern with {model}, {rig} and {view}")
                    .arg(r.output, r.models.value(a.model), rigName(r, a.rig), viewName(r, a.view),
                         r.models.value(b.model), rigName(r, b.rig), viewName(r, b.view), b.file);
        return std::nullopt;
    }
    return items;
}

QByteArray summaryLine(const RenderRequest& r, const RenderItem& item, bool ok, double seconds,
                       const QString& error, const QJsonObject& extra) {
    QJsonObject o = extra;
    o.insert(QStringLiteral("file"), item.file);
    o.insert(QStringLiteral("model"), r.models.value(item.model));
    o.insert(QStringLiteral("rig"), item.rig < 0 ? QJsonValue() : QJsonValue(r.rigs.value(item.rig)));
    o.insert(QStringLiteral("view"), viewName(r, item.view));
    if (item.frame >= 0) o.insert(QStringLiteral("frame"), item.frame);
    o.insert(QStringLiteral("status"), ok ? QStringLiteral("ok") : QStringLiteral("failed"));
    o.insert(QStringLiteral("seconds"), std::round(seconds * 1000.0) / 1000.0);
    o.insert(QStringLiteral("error"), ok ? QJsonValue() : QJsonValue(error));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

} // namespace lr::cli
