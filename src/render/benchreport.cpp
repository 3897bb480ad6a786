#include "benchreport.h"

#include "benchchart.h"
#include "benchoffers.h"
#include "core/areaintegrate.h"
#include "tracebench.h"

#include <QJsonArray>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <algorithm>
#include <cmath>
#include <map>

namespace lr {

namespace {

QString num(double v, int decimals) {
    return QString::number(v, 'f', decimals);
}

QString tierLabel(const BenchResult& r) {
    return r.uberShader ? QStringLiteral("exact/über") : toString(r.quality);
}

QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

double round3(double v) {
    return std::round(v * 1000.0) / 1000.0;
}

QColor tierColor(const BenchResult& r) {
    return r.uberShader ? QColor(140, 80, 170) : chart::tierColor(r.quality);
}

} // namespace

QStringList benchTableHeaders(bool shadows, bool traced) {
    QStringList h{QStringLiteral("scene"),     QStringLiteral("lights"),   QStringLiteral("tier"),
                  QStringLiteral("ms med"),    QStringLiteral("min"),      QStringLiteral("max"),
                  QStringLiteral("cpu ms"),    QStringLiteral("gpu ms"),   QStringLiteral("×exact"),
                  QStringLiteral("cpu×"),      QStringLiteral("first ms"), QStringLiteral("variants"),
                  QStringLiteral("triangles"), QStringLiteral("max err"),  QStringLiteral("mean err"),
                  QStringLiteral("PSNR dB"),   QStringLiteral(">1 lvl"),   QStringLiteral("NaN/Inf")};
    if (shadows) h << QStringLiteral("shadow off") << QStringLiteral("shadow err");
    if (traced) h << QStringLiteral("path PSNR") << QStringLiteral("path err");
    return h;
}

bool benchHasShadows(const BenchReport& report) {
    return std::any_of(report.results.begin(), report.results.end(),
                       [](const BenchResult& r) { return r.hasShadowErrors; });
}

bool benchHasTraced(const BenchReport& report) {
    return std::any_of(report.results.begin(), report.results.end(),
                       [](const BenchResult& r) { return r.hasTracedErrors; });
}

bool benchHasEnvironment(const BenchReport& report) {
    return std::any_of(report.results.begin(), report.results.end(),
                       [](const BenchResult& r) { return r.hasEnvironment; });
}

bool benchHasAreaLights(const BenchReport& report) {
    return std::any_of(report.results.begin(), report.results.end(),
                       [](const BenchResult& r) { return r.hasArea; });
}

QStringList benchTableRow(const BenchResult& r, bool shadows, bool traced) {
    const QString none = QStringLiteral("–");
    QStringList row{r.scene,
                    QStringLiteral("%1/%2").arg(r.lightsUploaded).arg(r.lightsInRig),
                    tierLabel(r),
                    num(r.msMedian, 2),
                    num(r.msMin, 2),
                    num(r.msMax, 2),
                    num(r.cpuMsMedian, 1),
                    r.gpuMsMedian >= 0.0 ? num(r.gpuMsMedian, 2) : none,
                    r.speedUp > 0.0 ? num(r.speedUp, 2) : none,
                    r.cpuSpeedUp > 0.0 ? num(r.cpuSpeedUp, 2) : none,
                    num(r.firstFrameMs, 0),
                    QString::number(r.variants),
                    QString::number(r.triangles)};
    if (r.hasErrors) {
        const ErrorFigures& e = r.errors;
        row << QString::number(e.maxLevels) << num(e.meanLevels, 3)
            << (std::isfinite(e.psnrDb) ? num(e.psnrDb, 1) : QStringLiteral("inf"))
            << QStringLiteral("%1%").arg(num(100.0 * e.shareOver1(), 2)) << QString::number(e.nonFinite);
    } else {
        row << none << none << none << none << none;
    }
    if (shadows && r.hasShadowErrors)
        row << QStringLiteral("%1%").arg(num(100.0 * r.shadow.shareDiffering(), 2))
            << num(r.shadow.meanLevels, 3);
    else if (shadows)
        row << none << none;
    if (traced && r.hasTracedErrors)
        row << (std::isfinite(r.tracedErrors.psnrDb) ? num(r.tracedErrors.psnrDb, 1) : QStringLiteral("inf"))
            << num(r.tracedErrors.meanLevels, 3);
    else if (traced)
        row << none << none;
    return row;
}

QString benchTable(const BenchReport& report) {
    const bool shadows = benchHasShadows(report), traced = benchHasTraced(report);
    QList<QStringList> rows{benchTableHeaders(shadows, traced)};
    for (const BenchResult& r : report.results)
        rows << benchTableRow(r, shadows, traced);
    const int columns = int(rows.first().size());
    std::vector<int> width(size_t(columns), 0);
    for (const QStringList& row : rows)
        for (int c = 0; c < columns; ++c)
            width[size_t(c)] = std::max(width[size_t(c)], int(row[c].size()));
    QString out;
    for (int i = 0; i < rows.size(); ++i) {
        QStringList cells;
        for (int c = 0; c < columns; ++c) {
            const int w = width[size_t(c)];
            cells << (c < 3 ? rows[i][c].leftJustified(w)
                            : rows[i][c].rightJustified(w)); // text left, numbers right
        }
        out += cells.join(QStringLiteral("  ")).trimmed() + QLatin1Char('\n');
    }
    const auto uber = uberComparisons(report);
    if (!uber.empty()) {
        out += QStringLiteral(
            "\nSpecialised shaders against the über-shader (every light model compiled in), exact tier:\n");
        for (const UberComparison& u : uber)
            out +=
                QStringLiteral("  %1: %2 ms/frame specialised, %3 ms über (%4% saved); CPU %5 vs %6 ms (%7% "
                               "saved); first draw %8 vs %9 ms\n")
                    .arg(u.scene, num(u.specialisedMs, 2), num(u.uberMs, 2), num(100.0 * u.saving(), 1),
                         num(u.specialisedCpuMs, 1), num(u.uberCpuMs, 1), num(100.0 * u.cpuSaving(), 1),
                         num(u.specialisedFirstDrawMs, 0), num(u.uberFirstDrawMs, 0));
    }
    if (benchHasEnvironment(report)) {
        out += QStringLiteral(
            "\nEnvironment integrated in the double-precision reference (the errors above include "
            "it; its own estimated error per covered pixel, after exposure, tone map and sRGB):\n");
        QStringList seen;
        for (const BenchResult& r : report.results) {
            if (!r.hasEnvironment || seen.contains(r.scene)) continue;
            seen << r.scene;
            const EnvironmentConvergence& e = r.environment;
            out += QStringLiteral(
                       "  %1: %2, reference %3 s, %4% of %5 pixels above half a level (worst %6, mean %7 "
                       "levels), %8 sample pairs per pixel\n")
                       .arg(r.scene, r.environmentSource, num(r.referenceMs / 1000.0, 2),
                            num(100.0 * e.shareOver(), 2))
                       .arg(e.pixels)
                       .arg(num(e.maxErrorLevels, 2), num(e.meanErrorLevels, 3), num(e.meanSamples, 0));
        }
    }
    if (benchHasAreaLights(report)) {
        out +=
            QStringLiteral("\nArea lights integrated in the double-precision reference by Monte Carlo (the "
                           "errors above are against it; its own estimated error per covered pixel):\n");
        QStringList seen;
        for (const BenchResult& r : report.results) {
            if (!r.hasArea || seen.contains(r.scene)) continue;
            seen << r.scene;
            const EnvironmentConvergence& e = r.area;
            out += QStringLiteral("  %1: reference %2 s, %3 of %4 pixels above half a level (%5%; worst %6, "
                                  "mean %7 levels), %8 points per pixel\n")
                       .arg(r.scene, num(r.referenceMs / 1000.0, 2))
                       .arg(e.over)
                       .arg(e.pixels)
                       .arg(num(100.0 * e.shareOver(), 2), num(e.maxErrorLevels, 2),
                            num(e.meanErrorLevels, 3), num(e.meanSamples, 0));
        }
    }
    out += benchOfferLines(report);
    out += pathBenchTable(report);
    return out;
}

std::vector<UberComparison> uberComparisons(const BenchReport& report) {
    std::vector<UberComparison> out;
    for (const BenchResult& u : report.results) {
        if (!u.uberShader) continue;
        for (const BenchResult& s : report.results) {
            if (s.uberShader || s.scene != u.scene || s.quality != Quality::Exact) continue;
            out.push_back({u.scene, s.msMedian, u.msMedian, s.cpuMsMedian, u.cpuMsMedian, s.firstDrawMs,
                           u.firstDrawMs});
            break;
        }
    }
    return out;
}

QJsonObject benchJson(const BenchReport& report) {
    QJsonArray results;
    for (const BenchResult& r : report.results) {
        QJsonObject o{
            {QStringLiteral("scene"), r.scene},
            {QStringLiteral("lights"), r.lightsInRig},
            {QStringLiteral("lights_uploaded"), r.lightsUploaded},
            {QStringLiteral("quality"), toString(r.quality)},
            {QStringLiteral("shader"), r.uberShader ? QStringLiteral("uber") : QStringLiteral("specialised")},
            {QStringLiteral("width"), r.size.width()},
            {QStringLiteral("height"), r.size.height()},
            {QStringLiteral("msaa_samples"), r.msaaSamples},
            {QStringLiteral("ms_median"), round3(r.msMedian)},
            {QStringLiteral("ms_min"), round3(r.msMin)},
            {QStringLiteral("ms_max"), round3(r.msMax)},
            {QStringLiteral("cpu_ms_median"), round3(r.cpuMsMedian)},
            {QStringLiteral("gpu_ms_median"),
             r.gpuMsMedian >= 0.0 ? QJsonValue(round3(r.gpuMsMedian)) : QJsonValue()},
            {QStringLiteral("cpu_speedup_vs_exact"),
             r.cpuSpeedUp > 0.0 ? QJsonValue(round3(r.cpuSpeedUp)) : QJsonValue()},
            {QStringLiteral("speedup_vs_exact"),
             r.speedUp > 0.0 ? QJsonValue(round3(r.speedUp)) : QJsonValue()},
            {QStringLiteral("first_frame_ms"), round3(r.firstFrameMs)},
            {QStringLiteral("load_ms"), round3(r.loadMs)},
            {QStringLiteral("first_draw_ms"), round3(r.firstDrawMs)},
            {QStringLiteral("second_frame_ms"), round3(r.secondFrameMs)},
            {QStringLiteral("upload_ms"), round3(r.uploadMs)},
            {QStringLiteral("triangles_drawn"), r.trianglesDrawn},
            {QStringLiteral("gbuffer_kept_frames"), r.keptFrames},
            {QStringLiteral("shadow_maps_rendered"), r.shadowMapsRendered},
            {QStringLiteral("variants"), r.variants},
            {QStringLiteral("triangles"), double(r.triangles)}};
        if (r.environmentDecodeMs >= 0.0) {
            o.insert(QStringLiteral("environment_decode_ms"), round3(r.environmentDecodeMs));
            o.insert(QStringLiteral("environment_concurrent"), r.environmentConcurrent);
            o.insert(QStringLiteral("environment_prefilter_ms"), round3(r.environmentPrefilterMs));
        }
        const ErrorFigures& e = r.errors;
        o.insert(QStringLiteral("max_error_levels"), r.hasErrors ? QJsonValue(e.maxLevels) : QJsonValue());
        o.insert(QStringLiteral("mean_error_levels"), r.hasErrors ? QJsonValue(e.meanLevels) : QJsonValue());
        o.insert(QStringLiteral("psnr_db"), r.hasErrors ? finiteOrNull(e.psnrDb) : QJsonValue());
        o.insert(QStringLiteral("share_over_1_level"),
                 r.hasErrors ? QJsonValue(e.shareOver1()) : QJsonValue());
        o.insert(QStringLiteral("nonfinite_pixels"),
                 r.hasErrors ? QJsonValue(double(e.nonFinite)) : QJsonValue());
        o.insert(QStringLiteral("compared_pixels"),
                 r.hasErrors ? QJsonValue(double(e.pixels)) : QJsonValue());
        if (r.hasShadowErrors) {
            o.insert(QStringLiteral("shadow_differing_share"), r.shadow.shareDiffering());
            o.insert(QStringLiteral("shadow_mean_error_levels"), r.shadow.meanLevels);
            o.insert(QStringLiteral("shadow_compared_pixels"), double(r.shadow.compared));
            o.insert(QStringLiteral("shadow_band_pixels"), double(r.shadow.band));
        }
        if (r.hasEnvironment) {
            o.insert(QStringLiteral("environment_source"), r.environmentSource);
            o.insert(QStringLiteral("environment_reference_ms"), round3(r.referenceMs));
            o.insert(QStringLiteral("environment_over_half_level_share"), r.environment.shareOver());
            o.insert(QStringLiteral("environment_max_error_levels"), r.environment.maxErrorLevels);
            o.insert(QStringLiteral("environment_mean_error_levels"), r.environment.meanErrorLevels);
            o.insert(QStringLiteral("environment_mean_samples"), r.environment.meanSamples);
        }
        if (r.hasArea) {
            o.insert(QStringLiteral("area_reference_ms"), round3(r.referenceMs));
            o.insert(QStringLiteral("area_over_half_level_pixels"), double(r.area.over));
            o.insert(QStringLiteral("area_over_half_level_share"), r.area.shareOver());
            o.insert(QStringLiteral("area_max_error_levels"), r.area.maxErrorLevels);
            o.insert(QStringLiteral("area_mean_error_levels"), r.area.meanErrorLevels);
            o.insert(QStringLiteral("area_mean_samples"), r.area.meanSamples);
        }
        const TierOffer offer = benchTierOffer(report, r);
        o.insert(QStringLiteral("offered"), offer.offered);
        o.insert(QStringLiteral("not_offered_why"), offer.offered ? QJsonValue() : QJsonValue(offer.why));
        if (r.hasTracedErrors) {
            o.insert(QStringLiteral("path_max_error_levels"), r.tracedErrors.maxLevels);
            o.insert(QStringLiteral("path_mean_error_levels"), r.tracedErrors.meanLevels);
            o.insert(QStringLiteral("path_psnr_db"), finiteOrNull(r.tracedErrors.psnrDb));
            o.insert(QStringLiteral("path_compared_pixels"), double(r.tracedErrors.pixels));
        }
        results.append(o);
    }
    QJsonArray uber;
    for (const UberComparison& u : uberComparisons(report))
        uber.append(
            QJsonObject{{QStringLiteral("scene"), u.scene},
                        {QStringLiteral("specialised_ms"), round3(u.specialisedMs)},
                        {QStringLiteral("uber_ms"), round3(u.uberMs)},
                        {QStringLiteral("saving"), round3(u.saving())},
                        {QStringLiteral("specialised_cpu_ms"), round3(u.specialisedCpuMs)},
                        {QStringLiteral("uber_cpu_ms"), round3(u.uberCpuMs)},
                        {QStringLiteral("cpu_saving"), round3(u.cpuSaving())},
                        {QStringLiteral("specialised_first_draw_ms"), round3(u.specialisedFirstDrawMs)},
                        {QStringLiteral("uber_first_draw_ms"), round3(u.uberFirstDrawMs)}});
    QJsonArray tiers;
    for (Quality q : report.options.tiers)
        tiers.append(toString(q));
    const BenchOptions& op = report.options;
    QJsonObject doc{{QStringLiteral("tool"), QStringLiteral("lightrig bench")},
                    {QStringLiteral("gl"), report.glDescription},
                    {QStringLiteral("load_average"), report.loadAverage},
                    {QStringLiteral("glibc_tunables"), report.glibcTunables},
                    {QStringLiteral("options"),
                     QJsonObject{{QStringLiteral("width"), op.size.width()},
                                 {QStringLiteral("height"), op.size.height()},
                                 {QStringLiteral("warmup_frames"), op.warmupFrames},
                                 {QStringLiteral("frames"), op.frames},
                                 {QStringLiteral("tiers"), tiers},
                                 {QStringLiteral("exposure_ev"), op.exposureEV},
                                 {QStringLiteral("tonemap"), toString(op.toneMap)},
                                 {QStringLiteral("errors"), op.errors},
                                 {QStringLiteral("orbit_degrees"), op.orbitDegrees},
                                 {QStringLiteral("drag_light"), op.dragLight},
                                 {QStringLiteral("interaction"), toString(benchInteraction(op))},
                                 {QStringLiteral("render_scale"), op.renderScale},
                                 {QStringLiteral("uber_shader"), op.uberShader}}},
                    {QStringLiteral("reference_ms"), round3(report.referenceMs)},
                    {QStringLiteral("results"), results},
                    {QStringLiteral("path"), pathBenchJson(report)},
                    {QStringLiteral("uber_shader"), uber}};
    if (benchHasShadows(report))
        doc.insert(QStringLiteral("shadow_measure"),
                   QJsonObject{{QStringLiteral("threshold_levels"), kShadowThresholdLevels},
                               {QStringLiteral("band_radius_pixels"), kShadowBandRadius},
                               {QStringLiteral("rays"), kShadowSamples},
                               {QStringLiteral("probe_rays"), kShadowProbeSamples},
                               {QStringLiteral("ray_epsilon_model_radii"), kShadowRayEpsilon}});
    if (benchHasEnvironment(report)) {
        const envintegrate::Convergence c;
        doc.insert(QStringLiteral("environment_reference"),
                   QJsonObject{{QStringLiteral("target_levels"), kEnvironmentTargetLevels},
                               {QStringLiteral("replicates"), c.replicates},
                               {QStringLiteral("min_sample_pairs"), c.replicates * c.batch * c.minBatches},
                               {QStringLiteral("max_sample_pairs"), c.replicates * c.batch * c.maxBatches}});
    }
    if (benchHasAreaLights(report)) {
        const envintegrate::Convergence c = areaintegrate::defaultConvergence(op.exposureEV, op.toneMap);
        doc.insert(
            QStringLiteral("area_reference"),
            QJsonObject{{QStringLiteral("target_levels"), kEnvironmentTargetLevels},
                        {QStringLiteral("replicates"), c.replicates},
                        {QStringLiteral("min_points_per_light"), c.replicates * c.batch * c.minBatches},
                        {QStringLiteral("max_points_per_light"), c.replicates * c.batch * c.maxBatches}});
    }
    return doc;
}

QImage benchChart(const BenchReport& report, QSize size) {
    chart::Canvas canvas(size);
    QPainter& p = canvas.painter();
    const QRectF plot = canvas.plot();

    std::vector<const BenchResult*> points;
    for (const BenchResult& r : report.results)
        if (r.msMedian > 0.0) points.push_back(&r);
    const bool errors =
        std::any_of(points.begin(), points.end(), [](const BenchResult* r) { return r->hasErrors; });
    double tMin = 1e300, tMax = 0.0, eMax = 0.0;
    for (const BenchResult* r : points) {
        tMin = std::min(tMin, r->msMedian);
        tMax = std::max(tMax, r->msMedian);
        if (r->hasErrors) eMax = std::max(eMax, r->errors.meanLevels);
    }
    if (points.empty()) tMin = 1.0, tMax = 10.0;
    const bool logX = tMax / tMin > 8.0;
    double x0 = logX ? std::pow(10.0, std::floor(std::log10(tMin))) : 0.0;
    double x1 = logX ? std::pow(10.0, std::ceil(std::log10(tMax))) : tMax * 1.1;
    if (!(x1 > x0)) x1 = x0 + 1.0;
    // y: a "nice" upper bound of the mean error.
    double y1 = 0.1;
    for (double step : {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 255.0})
        if ((y1 = step) >= eMax * 1.05) break;
    auto mapX = [&](double t) {
        const double f = logX ? (std::log10(t) - std::log10(x0)) / (std::log10(x1) - std::log10(x0))
                              : (t - x0) / (x1 - x0);
        return plot.left() + f * plot.width();
    };
    auto mapY = [&](double e) { return plot.bottom() - std::clamp(e / y1, 0.0, 1.0) * plot.height(); };

    // Title, axes, grid, ticks.
    canvas.title(QStringLiteral("Time against error per quality tier (%1×%2)")
                     .arg(report.options.size.width())
                     .arg(report.options.size.height()),
                 report.glDescription);
    std::vector<double> xTicks, yTicks;
    if (logX) {
        for (double d = x0; d <= x1 * 1.0001; d *= 10.0)
            for (double m : {1.0, 2.0, 5.0})
                if (d * m <= x1 * 1.0001) xTicks.push_back(d * m);
    } else {
        const double raw = (x1 - x0) / 8.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
        const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
        for (double t = 0.0; t <= x1; t += step)
            xTicks.push_back(t);
    }
    for (int i = 0; i <= 5; ++i)
        yTicks.push_back(y1 * i / 5);
    const auto label = [](double v) { return QString::number(v, 'g', 3); };
    canvas.axes(xTicks, yTicks, mapX, mapY, label, label,
                QStringLiteral("median ms/frame (wall, glFinish)%1")
                    .arg(logX ? QStringLiteral(", log scale") : QString()),
                errors ? QStringLiteral("mean error against the double reference (8-bit sRGB levels)")
                       : QStringLiteral("error not measured"));

    // One line per scene through its tiers, then the points.
    std::map<QString, std::vector<const BenchResult*>> byScene;
    for (const BenchResult* r : points)
        byScene[r->scene].push_back(r);
    const bool labels = byScene.size() <= 10;
    for (const auto& [scene, rs] : byScene) {
        QPainterPath path;
        bool started = false;
        for (const BenchResult* r : rs) {
            if (r->uberShader) continue;
            const QPointF at(mapX(r->msMedian), mapY(r->hasErrors ? r->errors.meanLevels : 0.0));
            started ? path.lineTo(at) : path.moveTo(at);
            started = true;
        }
        p.setPen(QPen(QColor(170, 170, 170), 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        if (labels && !rs.empty()) {
            p.setPen(QColor(90, 90, 90));
            p.drawText(QPointF(mapX(rs.front()->msMedian) + 8,
                               mapY(rs.front()->hasErrors ? rs.front()->errors.meanLevels : 0.0) - 8),
                       scene);
        }
    }
    for (const BenchResult* r : points) {
        const QPointF at(mapX(r->msMedian), mapY(r->hasErrors ? r->errors.meanLevels : 0.0));
        p.setPen(QPen(Qt::black, 0.8));
        p.setBrush(tierColor(*r));
        if (r->uberShader)
            p.drawRect(QRectF(at.x() - 5, at.y() - 5, 10, 10));
        else
            p.drawEllipse(at, 5.5, 5.5);
    }

    // Legend.
    int row = 0;
    for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
        canvas.legendEntry(row++, toString(q), chart::tierColor(q));
    BenchResult probe;
    probe.uberShader = true;
    if (std::any_of(points.begin(), points.end(), [](const BenchResult* r) { return r->uberShader; }))
        canvas.legendEntry(row++, QStringLiteral("über-shader"), tierColor(probe), true);
    return canvas.finish();
}

} // namespace lr
