#include "editor/environmentvalue.h"

#include "core/rigjson.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>

namespace lr {

namespace {
QString num(double v) {
    return QString::number(v, 'g', 6);
}

// "FIELD must be between LO and HI, got V" ((LO, HI] when loOpen).
QString range(const QString& field, double v, double lo, double hi, bool loOpen = false) {
    const bool ok = std::isfinite(v) && (loOpen ? v > lo : v >= lo) && v <= hi;
    if (ok) return {};
    return QStringLiteral("%1 must be %2, got %3")
        .arg(field,
             loOpen ? QStringLiteral("> %1 and <= %2").arg(num(lo), num(hi))
                    : QStringLiteral("between %1 and %2").arg(num(lo), num(hi)),
             num(v));
}

QString colour(const QString& field, const glm::dvec3& c, double hi) {
    for (int i = 0; i < 3; ++i)
        if (QString e = range(field, c[i], 0.0, hi); !e.isEmpty()) return e;
    return {};
}

QString checkSoftbox(const Softbox& b, int index) {
    const QString at = QStringLiteral("environment.studio.softboxes[%1].").arg(index);
    QString e = std::isfinite(b.azimuth) ? QString() : at + QStringLiteral("azimuth must be a finite number");
    if (e.isEmpty()) e = range(at + QStringLiteral("elevation"), b.elevation, -90.0, 90.0);
    if (e.isEmpty()) e = range(at + QStringLiteral("width"), b.width, 0.0, envlimits::kMaxSoftbox, true);
    if (e.isEmpty()) e = range(at + QStringLiteral("height"), b.height, 0.0, envlimits::kMaxSoftbox, true);
    if (e.isEmpty()) e = colour(at + QStringLiteral("color"), b.color, kMaxRigIntensity);
    if (e.isEmpty()) e = range(at + QStringLiteral("intensity"), b.intensity, 0.0, kMaxRigIntensity);
    return e;
}

QString checkSpot(const EnvironmentSpot& s, int index) {
    const QString at = QStringLiteral("environment.spots[%1].").arg(index);
    const glm::dvec3& d = s.direction;
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z) ||
        (d.x == 0 && d.y == 0 && d.z == 0))
        return at + QStringLiteral("direction must be a finite, non-zero vector");
    QString e = range(at + QStringLiteral("angle"), s.angle, 0.0, envlimits::kMaxSpotAngle, true);
    if (e.isEmpty()) e = range(at + QStringLiteral("factor"), s.factor, 0.0, 1.0);
    if (e.isEmpty())
        e = range(at + QStringLiteral("threshold"), s.threshold, 0.0, kMaxEnvironmentSpotThreshold);
    return e;
}
} // namespace

QString validateEnvironment(const Environment& env) {
    if (int(env.source) < 0 || int(env.source) >= enumCount<EnvironmentSource>())
        return QStringLiteral("environment.source must be one of %1").arg(allowedNames<EnvironmentSource>());
    if (int(env.background) < 0 || int(env.background) >= enumCount<EnvironmentBackground>())
        return QStringLiteral("environment.background must be one of %1")
            .arg(allowedNames<EnvironmentBackground>());
    if (env.source == EnvironmentSource::Image && env.file.trimmed().isEmpty())
        return QStringLiteral("environment.file must name an image for an image environment");
    if (env.file.size() > envlimits::kMaxFileLength)
        return QStringLiteral("environment.file must be at most %1 characters")
            .arg(envlimits::kMaxFileLength);
    if (QString e = range(QStringLiteral("environment.intensity"), env.intensity, -envlimits::kMaxEv,
                          envlimits::kMaxEv);
        !e.isEmpty())
        return e;
    if (!std::isfinite(env.rotation)) return QStringLiteral("environment.rotation must be a finite number");
    if (QString e = range(QStringLiteral("environment.blur"), env.blur, 0.0, 1.0); !e.isEmpty()) return e;
    const Studio& st = env.studio;
    for (const auto& [name, c] :
         {std::pair{"zenith", st.zenith}, {"horizon", st.horizon}, {"floor", st.floor}})
        if (QString e =
                colour(QStringLiteral("environment.studio.") + QLatin1String(name), c, kMaxRigIntensity);
            !e.isEmpty())
            return e;
    if (st.softboxes.size() > size_t(envlimits::kMaxSoftboxes))
        return QStringLiteral("environment.studio.softboxes holds at most %1 softboxes")
            .arg(envlimits::kMaxSoftboxes);
    for (size_t i = 0; i < st.softboxes.size(); ++i)
        if (QString e = checkSoftbox(st.softboxes[i], int(i)); !e.isEmpty()) return e;
    if (env.spots.size() > size_t(envlimits::kMaxSpots))
        return QStringLiteral("environment.spots holds at most %1 spots").arg(envlimits::kMaxSpots);
    for (size_t i = 0; i < env.spots.size(); ++i)
        if (QString e = checkSpot(env.spots[i], int(i)); !e.isEmpty()) return e;
    return {};
}

QString environmentChangeText(const Environment& a, const Environment& b) {
    const auto tr = [](const char* text) { return QCoreApplication::translate("lr::ChangeRigValue", text); };
    QStringList changed;
    if (a.source != b.source) changed << tr("Change environment source");
    if (a.file != b.file) changed << tr("Change environment image");
    if (a.intensity != b.intensity) changed << tr("Change environment intensity");
    if (a.rotation != b.rotation) changed << tr("Change environment rotation");
    if (a.background != b.background) changed << tr("Change environment background");
    if (a.blur != b.blur) changed << tr("Change environment blur");
    if (a.diffuse != b.diffuse) changed << tr("Change environment diffuse model");
    if (a.studio.zenith != b.studio.zenith) changed << tr("Change studio zenith colour");
    if (a.studio.horizon != b.studio.horizon) changed << tr("Change studio horizon colour");
    if (a.studio.floor != b.studio.floor) changed << tr("Change studio floor colour");
    if (a.studio.softboxes != b.studio.softboxes) changed << tr("Change studio softboxes");
    if (a.spots != b.spots) changed << tr("Change environment dimmed spots");
    // Switching the source fills in its image or first softbox: still a change of source.
    if (a.source != b.source) return changed.first();
    return changed.size() == 1 ? changed.first() : tr("Change environment");
}

} // namespace lr
