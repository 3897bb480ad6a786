#include "viewsettings.h"

#include <QSettings>
#include <algorithm>
#include <cmath>

namespace lr {

ViewSettings::ViewSettings(QObject* parent) : QObject(parent) {}

void ViewSettings::setOptions(const ViewOptions& options) {
    if (options == m_options) return;
    m_options = options;
    save();
    emit changed();
}

void ViewSettings::setExposure(double ev) {
    auto o = m_options;
    o.exposure = std::isfinite(ev) ? std::clamp(ev, -20.0, 20.0) : 0.0;
    setOptions(o);
}
void ViewSettings::setToneMap(ToneMap op) {
    auto o = m_options;
    o.toneMap = op;
    setOptions(o);
}
void ViewSettings::setQuality(Quality q) {
    auto o = m_options;
    o.quality = q;
    setOptions(o);
}
void ViewSettings::setBackground(const QColor& c) {
    auto o = m_options;
    o.background = c.isValid() ? c.toRgb() : ViewOptions{}.background;
    setOptions(o);
}
void ViewSettings::setGrid(bool on) {
    auto o = m_options;
    o.grid = on;
    setOptions(o);
}
void ViewSettings::setGizmos(bool on) {
    auto o = m_options;
    o.gizmos = on;
    setOptions(o);
}

void ViewSettings::setPathTraced(bool on) {
    auto o = m_options;
    o.pathTraced = on;
    setOptions(o);
}
void ViewSettings::setMovingFrameRate(int fps) {
    auto o = m_options;
    o.movingFrameRate = std::clamp(fps, 0, kMaxMovingFrameRate);
    setOptions(o);
}
void ViewSettings::setTraceTargets(int samples, double seconds, double noise) {
    auto o = m_options;
    o.traceSamples = std::max(0, samples);
    o.traceSeconds = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    o.traceNoise = std::isfinite(noise) ? std::max(0.0, noise) : 0.0;
    setOptions(o);
}

void ViewSettings::load() {
    QSettings s;
    s.beginGroup(QStringLiteral("view"));
    ViewOptions o;
    bool ok = false;
    const double ev = s.value(QStringLiteral("exposure"), o.exposure).toDouble(&ok);
    if (ok && std::isfinite(ev)) o.exposure = std::clamp(ev, -20.0, 20.0);
    o.toneMap = fromString<ToneMap>(s.value(QStringLiteral("toneMap")).toString()).value_or(o.toneMap);
    o.quality = fromString<Quality>(s.value(QStringLiteral("quality")).toString()).value_or(o.quality);
    const QColor bg(s.value(QStringLiteral("background")).toString());
    if (bg.isValid()) o.background = bg;
    o.grid = s.value(QStringLiteral("grid"), o.grid).toBool();
    o.gizmos = s.value(QStringLiteral("gizmos"), o.gizmos).toBool();
    o.pathTraced = s.value(QStringLiteral("pathTraced"), o.pathTraced).toBool();
    const int fps = s.value(QStringLiteral("movingFrameRate"), o.movingFrameRate).toInt(&ok);
    if (ok && fps >= 0 && fps <= kMaxMovingFrameRate) o.movingFrameRate = fps;
    const int samples = s.value(QStringLiteral("traceSamples"), o.traceSamples).toInt(&ok);
    if (ok && samples >= 0) o.traceSamples = samples;
    const double seconds = s.value(QStringLiteral("traceSeconds"), o.traceSeconds).toDouble(&ok);
    if (ok && std::isfinite(seconds) && seconds >= 0.0) o.traceSeconds = seconds;
    const double noise = s.value(QStringLiteral("traceNoise"), o.traceNoise).toDouble(&ok);
    if (ok && std::isfinite(noise) && noise >= 0.0) o.traceNoise = noise;
    s.endGroup();
    if (!(o == m_options)) {
        m_options = o;
        emit changed();
    }
}

void ViewSettings::save() const {
    if (!m_persistent) return;
    QSettings s;
    s.beginGroup(QStringLiteral("view"));
    s.setValue(QStringLiteral("exposure"), m_options.exposure);
    s.setValue(QStringLiteral("toneMap"), toString(m_options.toneMap));
    s.setValue(QStringLiteral("quality"), toString(m_options.quality));
    s.setValue(QStringLiteral("background"), m_options.background.name());
    s.setValue(QStringLiteral("grid"), m_options.grid);
    s.setValue(QStringLiteral("gizmos"), m_options.gizmos);
    s.setValue(QStringLiteral("pathTraced"), m_options.pathTraced);
    s.setValue(QStringLiteral("movingFrameRate"), m_options.movingFrameRate);
    s.setValue(QStringLiteral("traceSamples"), m_options.traceSamples);
    s.setValue(QStringLiteral("traceSeconds"), m_options.traceSeconds);
    s.setValue(QStringLiteral("traceNoise"), m_options.traceNoise);
    s.endGroup();
}

} // namespace lr
