// Every validation rule of docs/rig-format.md, one row each: a file breaking exactly that rule gives
// exactly one error, and it names the rule's JSON path and reason.
#include "rigtest.h"

using namespace lr;
using namespace lr::test;

class TestRigRules : public QObject {
    Q_OBJECT
  private slots:
    void rules_data();
    void rules();
};

void TestRigRules::rules_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected"); // "json.path: start of the reason"
    auto row = [](const char* name, const QByteArray& json, const char* expected) {
        QTest::newRow(name) << json << QString::fromUtf8(expected);
    };
    // The document and its header.
    row("format missing", R"({"version": 1, "lights": []})", "format: missing");
    row("format not a string", R"({"format": 1, "version": 1, "lights": []})",
        "format: must be \"lightrig\"");
    row("version missing", R"({"format": "lightrig", "lights": []})", "version: missing");
    row("version 0", R"({"format": "lightrig", "version": 0, "lights": []})",
        "version: must be an integer from 1 to 4");
    row("version 1.5", R"({"format": "lightrig", "version": 1.5, "lights": []})",
        "version: must be an integer from 1 to 4");
    row("version string", R"({"format": "lightrig", "version": "1", "lights": []})",
        "version: must be an integer from 1 to 4");
    row("version 5", R"({"format": "lightrig", "version": 5, "lights": []})",
        "version: the file is version 5, newer than this LightRig reads (version 4)");
    row("name not a string", rigJson({}, R"("name": 42,)"), "name: must be a string, got 42");
    row("name too long", rigJson({}, "\"name\": \"" + QByteArray(257, 'x') + "\","),
        "name: must be at most 256 characters");
    row("space", rigJson({}, R"("space": "local",)"),
        "space: must be \"world\" or \"model\", got the string \"local\"");
    row("ambient 2 components", rigJson({}, R"("ambient": [1, 1],)"), "ambient: must be an RGB colour");
    row("ambient negative", rigJson({}, R"("ambient": [0, -0.5, 0],)"),
        "ambient[1]: must be a finite number from 0 to 1000000, got -0.5");
    row("shading not object", rigJson({}, R"("shading": "phong",)"), "shading: must be an object");
    row("shading.specular", rigJson({}, R"("shading": {"specular": "gouraud"},)"),
        "shading.specular: must be \"phong\" or \"blinn-phong\"");
    row("shading.viewer", rigJson({}, R"("shading": {"viewer": "ortho"},)"),
        "shading.viewer: must be \"local\" or \"infinite\"");
    row("shading.shininess 0", rigJson({}, R"("shading": {"shininess": 0},)"),
        "shading.shininess: must be a finite number > 0 and <= 10000, got 0");
    row("shading.model", rigJson({}, R"("shading": {"model": "physical"},)"),
        "shading.model: must be \"classic\" or \"pbr\"");
    row("pbr with specular", rigJson({}, R"("shading": {"model": "pbr", "specular": "phong"},)"),
        "shading.specular: physically based shading (\"model\": \"pbr\") has no specular");
    row("pbr with shininess", rigJson({}, R"("shading": {"model": "pbr", "shininess": 8},)"),
        "shading.shininess: physically based shading (\"model\": \"pbr\") has no shininess");
    row("lights missing", R"({"format": "lightrig", "version": 1})", "lights: missing");
    row("lights not array", R"({"format": "lightrig", "version": 1, "lights": {}})",
        "lights: must be an array");
    row("light not object", rigJson("1"), "lights[0]: must be an object");
    // Every light.
    row("type missing", rigJson(R"({"position": [0, 0, 0]})"), "lights[0].type: missing");
    row("type unknown", rigJson(R"({"type": "area"})"),
        "lights[0].type: must be \"point\", \"spot\", \"directional\", \"rim\", \"rect\" or \"disk\"");
    row("light name too long", rigJson(with(kRim, "\"name\": \"" + QByteArray(257, 'y') + '"')),
        "lights[0].name: must be at most 256 characters, got 257");
    row("enabled", rigJson(with(kRim, R"("enabled": "yes")")), "lights[0].enabled: must be true or false");
    row("color 2 components", rigJson(with(kPoint, R"("color": [1, 1])")),
        "lights[0].color: must be an RGB colour");
    row("color string", rigJson(with(kPoint, R"("color": "#ffffff")")),
        "lights[0].color: must be an RGB colour");
    row("color negative", rigJson(with(kPoint, R"("color": [-1, 0, 0])")),
        "lights[0].color[0]: must be a finite number from 0 to 1000000, got -1");
    row("color huge", rigJson(with(kPoint, R"("color": [0, 0, 2e6])")),
        "lights[0].color[2]: must be a finite number from 0 to 1000000, got 2e6");
    row("temperature low", rigJson(with(kPoint, R"("temperature": 999)")),
        "lights[0].temperature: must be a finite number from 1000 to 40000, got 999");
    row("temperature high", rigJson(with(kRim, R"("temperature": 40001)")),
        "lights[0].temperature: must be a finite number from 1000 to 40000");
    row("intensity negative", rigJson(with(kPoint, R"("intensity": -1)")),
        "lights[0].intensity: must be a finite number from 0 to 1000000, got -1");
    row("intensity huge", rigJson(with(kPoint, R"("intensity": 1000001)")),
        "lights[0].intensity: must be a finite number from 0 to 1000000");
    row("position missing", rigJson(R"({"type": "point", "falloff": {"model": "none"}})"),
        "lights[0].position: missing");
    row("position too far",
        rigJson(R"({"type": "point", "position": [1e13, 0, 0], "falloff": {"model": "none"}})"),
        "lights[0].position[0]: must be a finite number from -1e12 to 1e12, got 1e13");
    row("position on directional", rigJson(with(kDirectional, R"("position": [0, 0, 0])")),
        "lights[0].position: a directional light has no position");
    row("position on rim", rigJson(with(kRim, R"("position": [0, 0, 0])")),
        "lights[0].position: a rim light has no position");
    row("direction missing", rigJson(R"({"type": "directional"})"), "lights[0].direction: missing");
    row("direction zero", rigJson(R"({"type": "rim", "direction": [0, 0, 0]})"),
        "lights[0].direction: must not be the zero vector");
    row("direction component", rigJson(R"({"type": "directional", "direction": [0, "down", 0]})"),
        "lights[0].direction[1]: must be a finite number, got the string \"down\"");
    row("direction on point", rigJson(with(kPoint, R"("direction": [0, -1, 0])")),
        "lights[0].direction: a point light has no direction");
    row("falloff missing", rigJson(R"({"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0]})"),
        "lights[0].falloff: missing");
    row("falloff on directional", rigJson(with(kDirectional, R"("falloff": {"model": "none"})")),
        "lights[0].falloff: a directional light has no falloff");
    row("falloff on rim", rigJson(with(kRim, R"("falloff": {"model": "none"})")),
        "lights[0].falloff: a rim light has no falloff");
    row("range on directional", rigJson(with(kDirectional, R"("range": 5)")),
        "lights[0].range: a directional light has no range");
    row("range on point", rigJson(with(kPoint, R"("range": 5)")), "lights[0].range: belongs in \"falloff\"");
    row("quadratic on point", rigJson(with(kPoint, R"("quadratic": 1)")),
        "lights[0].quadratic: belongs in \"falloff\"");
    row("inner on point", rigJson(with(kPoint, R"("inner": 10)")),
        "lights[0].inner: a point light has no inner");
    row("outer on spot", rigJson(with(kSpot, R"("outer": 10)")), "lights[0].outer: belongs in \"cone\"");
    row("model on light", rigJson(with(kPoint, R"("model": "none")")),
        "lights[0].model: belongs in \"falloff\" or \"cone\"");
    row("cone on point", rigJson(with(kPoint, R"("cone": {"model": "hard", "outer": 10})")),
        "lights[0].cone: a point light has no cone");
    row("cone on directional", rigJson(with(kDirectional, R"("cone": {})")),
        "lights[0].cone: a directional light has no cone");
    row("diffuse unknown", rigJson(with(kPoint, R"("diffuse": "oren-nayar")")),
        "lights[0].diffuse: must be \"lambert\" or \"half-lambert\"");
    row("diffuse on rim", rigJson(with(kRim, R"("diffuse": "lambert")")),
        "lights[0].diffuse: a rim light has no diffuse term");
    row("specular negative", rigJson(with(kPoint, R"("specular": -1)")),
        "lights[0].specular: must be a finite number from 0 to 1000000, got -1");
    row("specular string", rigJson(with(kPoint, R"("specular": "white")")),
        "lights[0].specular: must be a factor >= 0 or an RGB colour");
    row("specular colour", rigJson(with(kPoint, R"("specular": [1, -1, 1])")),
        "lights[0].specular[1]: must be a finite number from 0");
    row("specular on rim", rigJson(with(kRim, R"("specular": 1)")),
        "lights[0].specular: a rim light has no specular term");
    row("ambient on rim", rigJson(with(kRim, R"("ambient": [0, 0, 0])")),
        "lights[0].ambient: a rim light has no ambient term");
    row("light ambient", rigJson(with(kDirectional, R"("ambient": [1, 1])")),
        "lights[0].ambient: must be an RGB colour");
    row("exponent on point", rigJson(with(kPoint, R"("exponent": 2)")),
        "lights[0].exponent: only rim lights have an exponent");
    row("rim exponent 0", rigJson(with(kRim, R"("exponent": 0)")),
        "lights[0].exponent: must be a finite number > 0 and <= 10000, got 0");
    row("rim exponent huge", rigJson(with(kRim, R"("exponent": 1e5)")),
        "lights[0].exponent: must be a finite number > 0 and <= 10000, got 1e5");
    // Falloff.
    row("falloff not object", rigJson(pointWithFalloff("\"none\"")), "lights[0].falloff: must be an object");
    row("falloff model missing", rigJson(pointWithFalloff(R"({"range": 5})")),
        "lights[0].falloff.model: missing");
    row("falloff model unknown", rigJson(pointWithFalloff(R"({"model": "linear"})")),
        "lights[0].falloff.model: must be \"none\", \"range-power\"");
    row("range-power no range", rigJson(pointWithFalloff(R"({"model": "range-power", "exponent": 2})")),
        "lights[0].falloff.range: missing");
    row("range-power range -5", rigJson(pointWithFalloff(R"({"model": "range-power", "range": -5})")),
        "lights[0].falloff.range: must be a finite number > 0 and <= 1e12, got -5");
    row("range-power range 0", rigJson(pointWithFalloff(R"({"model": "range-power", "range": 0})")),
        "lights[0].falloff.range: must be a finite number > 0 and <= 1e12, got 0");
    row("range-power exponent 0",
        rigJson(pointWithFalloff(R"({"model": "range-power", "range": 5, "exponent": 0})")),
        "lights[0].falloff.exponent: must be a finite number > 0");
    row("range-power constant",
        rigJson(pointWithFalloff(R"({"model": "range-power", "range": 5, "constant": 1})")),
        "lights[0].falloff.constant: the \"range-power\" falloff has no constant term");
    row("polynomial all zero",
        rigJson(pointWithFalloff(
            R"({"model": "inverse-polynomial", "constant": 0, "linear": 0, "quadratic": 0})")),
        "lights[0].falloff: constant, linear and quadratic are all 0");
    row("polynomial negative",
        rigJson(pointWithFalloff(R"({"model": "inverse-polynomial", "linear": -0.1})")),
        "lights[0].falloff.linear: must be a finite number from 0 to 1e12, got -0.1");
    row("polynomial exponent", rigJson(pointWithFalloff(R"({"model": "inverse-polynomial", "exponent": 2})")),
        "lights[0].falloff.exponent: the \"inverse-polynomial\" falloff has no exponent");
    row("polynomial range 0", rigJson(pointWithFalloff(R"({"model": "inverse-polynomial", "range": 0})")),
        "lights[0].falloff.range: must be a finite number > 0");
    row("range-quadratic no range", rigJson(pointWithFalloff(R"({"model": "range-quadratic"})")),
        "lights[0].falloff.range: missing");
    row("range-quadratic exponent",
        rigJson(pointWithFalloff(R"({"model": "range-quadratic", "range": 5, "exponent": 2})")),
        "lights[0].falloff.exponent: the \"range-quadratic\" falloff has no exponent");
    row("inverse-square exponent", rigJson(pointWithFalloff(R"({"model": "inverse-square", "exponent": 2})")),
        "lights[0].falloff.exponent: the \"inverse-square\" falloff has no exponent");
    row("inverse-square quadratic",
        rigJson(pointWithFalloff(R"({"model": "inverse-square", "quadratic": 1})")),
        "lights[0].falloff.quadratic: the \"inverse-square\" falloff has no quadratic term");
    row("inverse-square range", rigJson(pointWithFalloff(R"({"model": "inverse-square", "range": -1})")),
        "lights[0].falloff.range: must be a finite number > 0");
    row("none range", rigJson(pointWithFalloff(R"({"model": "none", "range": 5})")),
        "lights[0].falloff.range: the \"none\" falloff has no range");
    row("none exponent", rigJson(pointWithFalloff(R"({"model": "none", "exponent": 1})")),
        "lights[0].falloff.exponent: the \"none\" falloff has no exponent");
    row("falloff inner", rigJson(pointWithFalloff(R"({"model": "none", "inner": 1})")),
        "lights[0].falloff.inner: belongs in \"cone\"");
    // Cone.
    row("cone not object", rigJson(spotWithCone("30")), "lights[0].cone: must be an object");
    row("cone model missing", rigJson(spotWithCone(R"({"outer": 30})")), "lights[0].cone.model: missing");
    row("cone model unknown", rigJson(spotWithCone(R"({"model": "soft", "outer": 30})")),
        "lights[0].cone.model: must be \"angle-power\", \"smooth\" or \"hard\"");
    row("smooth inner missing", rigJson(spotWithCone(R"({"model": "smooth", "outer": 30})")),
        "lights[0].cone.inner: missing");
    row("outer missing", rigJson(spotWithCone(R"({"model": "hard"})")), "lights[0].cone.outer: missing");
    row("inner 0", rigJson(spotWithCone(R"({"model": "smooth", "inner": 0, "outer": 30})")),
        "lights[0].cone.inner: must be a finite number > 0 and <= 90, got 0");
    row("outer 91", rigJson(spotWithCone(R"({"model": "angle-power", "outer": 91})")),
        "lights[0].cone.outer: must be a finite number > 0 and <= 90, got 91");
    row("inner > outer", rigJson(spotWithCone(R"({"model": "smooth", "inner": 40, "outer": 35})")),
        "lights[0].cone.inner: must be <= outer (35), got 40");
    row("angle-power inner", rigJson(spotWithCone(R"({"model": "angle-power", "inner": 10, "outer": 30})")),
        "lights[0].cone.inner: the \"angle-power\" cone has no inner angle");
    row("hard inner", rigJson(spotWithCone(R"({"model": "hard", "inner": 10, "outer": 30})")),
        "lights[0].cone.inner: the \"hard\" cone has no inner angle");
    row("hard exponent", rigJson(spotWithCone(R"({"model": "hard", "outer": 30, "exponent": 2})")),
        "lights[0].cone.exponent: the \"hard\" cone has no exponent");
    row("smooth exponent 0",
        rigJson(spotWithCone(R"({"model": "smooth", "inner": 10, "outer": 30, "exponent": 0})")),
        "lights[0].cone.exponent: must be a finite number > 0");
    row("cone range", rigJson(spotWithCone(R"({"model": "hard", "outer": 30, "range": 4})")),
        "lights[0].cone.range: belongs in \"falloff\"");
    row("second light", rigJson(kPoint + ", " + with(kSpot, R"("intensity": -3)")),
        "lights[1].intensity: must be a finite number from 0");
    // Shadow (issue 14).
    row("shadow not object", rigJson(with(kSpot, R"("shadow": true)")),
        "lights[0].shadow: must be an object");
    row("shadow enabled missing", rigJson(with(kSpot, R"("shadow": {"resolution": 512})")),
        "lights[0].shadow.enabled: missing");
    row("shadow enabled string", rigJson(with(kPoint, R"("shadow": {"enabled": "yes"})")),
        "lights[0].shadow.enabled: must be true or false");
    row("shadow resolution 3000", rigJson(with(kSpot, R"("shadow": {"enabled": true, "resolution": 3000})")),
        "lights[0].shadow.resolution: 3000 is not a power of two between 256 and 4096");
    row("shadow resolution 128", rigJson(with(kSpot, R"("shadow": {"enabled": true, "resolution": 128})")),
        "lights[0].shadow.resolution: 128 is not a power of two between 256 and 4096");
    row("shadow resolution 8192",
        rigJson(with(kDirectional, R"("shadow": {"enabled": true, "resolution": 8192})")),
        "lights[0].shadow.resolution: 8192 is not a power of two between 256 and 4096");
    row("shadow resolution 1024.5",
        rigJson(with(kPoint, R"("shadow": {"enabled": false, "resolution": 1024.5})")),
        "lights[0].shadow.resolution: 1024.5 is not a power of two");
    row("shadow resolution string",
        rigJson(with(kSpot, R"("shadow": {"enabled": true, "resolution": "1k"})")),
        "lights[0].shadow.resolution: must be a power of two between 256 and 4096, got the string");
    row("shadow bias negative", rigJson(with(kSpot, R"("shadow": {"enabled": true, "bias": -1})")),
        "lights[0].shadow.bias: must be a finite number from 0 to 16, got -1");
    row("shadow normalOffset 17", rigJson(with(kPoint, R"("shadow": {"enabled": true, "normalOffset": 17})")),
        "lights[0].shadow.normalOffset: must be a finite number from 0 to 16, got 17");
    row("shadow size negative", rigJson(with(kPoint, R"("shadow": {"enabled": true, "size": -0.5})")),
        "lights[0].shadow.size: must be a finite number from 0 to 1e12, got -0.5");
    row("shadow size NaN-like", rigJson(with(kSpot, R"("shadow": {"enabled": true, "size": 1e999})")),
        "lights[0].shadow.size: must be a finite number from 0 to 1e12, got 1e999");
    row("shadow angle 11", rigJson(with(kDirectional, R"("shadow": {"enabled": true, "angle": 11})")),
        "lights[0].shadow.angle: must be a finite number from 0 to 10, got 11");
    row("shadow angle on spot", rigJson(with(kSpot, R"("shadow": {"enabled": true, "angle": 1})")),
        "lights[0].shadow.angle: a spot light's shadow has no angle: its softness is \"size\"");
    row("shadow size on directional",
        rigJson(with(kDirectional, R"("shadow": {"enabled": true, "size": 1})")),
        "lights[0].shadow.size: a directional light's shadow has no size: its softness is \"angle\"");
    row("shadow on rim", rigJson(with(kRim, R"("shadow": {"enabled": true})")),
        "lights[0].shadow: a rim light casts no shadow: it brightens the edges that face away from the "
        "viewer");
    row("shadow off on rim", rigJson(with(kRim, R"("shadow": {"enabled": false})")),
        "lights[0].shadow: a rim light casts no shadow");
    QByteArray casters;
    for (int i = 0; i <= kMaxShadowCasters; ++i) // 17, some of them switched off: they count too
        casters += (i ? ", " : "") + with(i % 2 ? kSpot : kDirectional,
                                          i % 3 ? R"("shadow": {"enabled": true})"
                                                : R"("enabled": false, "shadow": {"enabled": true})");
    row("17 shadow casters", rigJson(casters),
        "lights: 17 lights have \"shadow\": {\"enabled\": true}; at most 16 lights can cast shadows");
    // Ground (issue 14).
    row("ground not object", rigJson({}, R"("ground": "catcher",)"), "ground: must be an object");
    row("ground mode missing", rigJson({}, R"("ground": {"color": [1, 1, 1]},)"), "ground.mode: missing");
    row("ground mode unknown", rigJson({}, R"("ground": {"mode": "shadow"},)"),
        "ground.mode: must be \"off\", \"visible\" or \"catcher\", got the string \"shadow\"");
    row("ground colour above 1", rigJson({}, R"("ground": {"mode": "visible", "color": [1, 1.5, 1]},)"),
        "ground.color[1]: must be a finite number from 0 to 1, got 1.5");
    row("ground colour 2 components", rigJson({}, R"("ground": {"mode": "visible", "color": [1, 1]},)"),
        "ground.color: must be an RGB albedo");
    // Area lights (issue 16, format version 2).
    row("rect in a version 1 file", rigJson(kRect),
        "lights[0].type: rect lights came with version 2 of the format, but the file says \"version\": 1; "
        "write \"version\": 2");
    row("disk in a version 1 file", rigJson(with(kDisk, R"("area": {"radius": 1})")),
        "lights[0].type: disk lights came with version 2 of the format");
    row("rect position missing", rigJson2(R"({"type": "rect", "direction": [0, -1, 0]})"),
        "lights[0].position: missing; a rect light needs a position");
    row("disk direction missing", rigJson2(R"({"type": "disk", "position": [0, 1, 0]})"),
        "lights[0].direction: missing; a disk light needs a direction");
    row("area not object", rigJson2(with(kRect, R"("area": 2)")), "lights[0].area: must be an object");
    row("area width negative", rigJson2(with(kRect, R"("area": {"width": -1})")),
        "lights[0].area.width: must be a finite number from 0 to 1e12, got -1");
    row("area height huge", rigJson2(with(kRect, R"("area": {"height": 2e12})")),
        "lights[0].area.height: must be a finite number from 0 to 1e12, got 2e12");
    row("area width string", rigJson2(with(kRect, R"("area": {"width": "1m"})")),
        "lights[0].area.width: must be a finite number from 0 to 1e12, got the string \"1m\"");
    row("area radius overflow", rigJson2(with(kDisk, R"("area": {"radius": 1e999})")),
        "lights[0].area.radius: must be a finite number from 0 to 1e12, got 1e999");
    row("area roll 181", rigJson2(with(kRect, R"("area": {"roll": 181})")),
        "lights[0].area.roll: must be a finite number from -180 to 180, got 181");
    row("area roll -190", rigJson2(with(kDisk, R"("area": {"roll": -190})")),
        "lights[0].area.roll: must be a finite number from -180 to 180, got -190");
    row("area twoSided string", rigJson2(with(kRect, R"("area": {"twoSided": "yes"})")),
        "lights[0].area.twoSided: must be true or false");
    row("rect with radius", rigJson2(with(kRect, R"("area": {"radius": 1})")),
        "lights[0].area.radius: a rect light has no radius: its size is \"width\" and \"height\" (only "
        "disk lights have a radius)");
    row("disk with width", rigJson2(with(kDisk, R"("area": {"width": 1})")),
        "lights[0].area.width: a disk light has no width: its size is \"radius\" (only rect lights have a "
        "width and a height)");
    row("area on a spot", rigJson2(with(kSpot, R"("area": {"width": 1})")),
        "lights[0].area: a spot light has no area (only rect and disk lights have one");
    row("area on a directional", rigJson(with(kDirectional, R"("area": {})")),
        "lights[0].area: a directional light has no area");
    row("width on a rect itself", rigJson2(with(kRect, R"("width": 1)")),
        "lights[0].width: belongs in \"area\"");
    row("radius on a point", rigJson(with(kPoint, R"("radius": 1)")),
        "lights[0].radius: a point light has no radius (it would belong in \"area\", which only rect and "
        "disk lights have)");
    row("rect with falloff", rigJson2(with(kRect, R"("falloff": {"model": "none"})")),
        "lights[0].falloff: a rect light has no falloff");
    row("disk with cone", rigJson2(with(kDisk, R"("cone": {"model": "hard", "outer": 30})")),
        "lights[0].cone: a disk light has no cone");
    row("rect shadow size", rigJson2(with(kRect, R"("shadow": {"enabled": true, "size": 0.5})")),
        "lights[0].shadow.size: a rect light's shadow has no size: the light's own \"area\" softens its "
        "shadow");
    row("disk shadow angle", rigJson2(with(kDisk, R"("shadow": {"enabled": true, "angle": 1})")),
        "lights[0].shadow.angle: a disk light's shadow has no angle");
    // Environment (issue 15).
    const auto env = [](const QByteArray& members) {
        return rigJson({}, "\"environment\": {" + members + "},");
    };
    row("environment not object", rigJson({}, R"("environment": "studio",)"),
        "environment: must be an object");
    row("environment source missing", env(R"("intensity": 1)"),
        "environment.source: missing; one of \"none\", \"image\" or \"studio\"");
    row("environment source unknown", env(R"("source": "hdri")"),
        "environment.source: must be \"none\", \"image\" or \"studio\", got the string \"hdri\"");
    row("environment image without file", env(R"("source": "image")"),
        "environment.file: missing; an image environment needs \"file\"");
    row("environment file empty", env(R"("source": "image", "file": "")"),
        "environment.file: must not be empty");
    row("environment file not a string", env(R"("source": "image", "file": 3)"),
        "environment.file: must be a file name (a string), got 3");
    row("environment file NUL", env(R"("source": "image", "file": "a\u0000.exr")"),
        "environment.file: must not contain a NUL character");
    row("environment file builtin without name", env(R"("source": "image", "file": "builtin:")"),
        "environment.file: \"builtin:\" needs the name of a bundled environment");
    row("environment file too long", env("\"source\": \"image\", \"file\": \"" + QByteArray(4097, 'f') + '"'),
        "environment.file: must be at most 4096 characters, got 4097");
    row("environment intensity 21", env(R"("source": "studio", "intensity": 21)"),
        "environment.intensity: must be a finite number from -20 to 20, got 21");
    row("environment intensity -20.5", env(R"("source": "studio", "intensity": -20.5)"),
        "environment.intensity: must be a finite number from -20 to 20, got -20.5");
    row("environment rotation string", env(R"("source": "studio", "rotation": "90")"),
        "environment.rotation: must be a finite number, got the string \"90\"");
    row("environment rotation overflow", env(R"("source": "studio", "rotation": 1e999)"),
        "environment.rotation: must be a finite number, got 1e999");
    row("environment background", env(R"("source": "studio", "background": "blur")"),
        "environment.background: must be \"visible\", \"blurred\" or \"color\", got the string \"blur\"");
    row("environment blur 1.5", env(R"("source": "studio", "blur": 1.5)"),
        "environment.blur: must be a finite number from 0 to 1, got 1.5");
    row("environment diffuse", env(R"("source": "studio", "diffuse": "oren-nayar")"),
        "environment.diffuse: must be \"lambert\" or \"half-lambert\", got the string \"oren-nayar\"");
    row("studio not object", env(R"("source": "studio", "studio": [])"),
        "environment.studio: must be an object");
    row("studio zenith negative", env(R"("source": "studio", "studio": {"zenith": [1, -1, 1]})"),
        "environment.studio.zenith[1]: must be a finite number from 0 to 1000000, got -1");
    row("studio floor 2 components", env(R"("source": "studio", "studio": {"floor": [1, 1]})"),
        "environment.studio.floor: must be an RGB colour");
    row("studio softboxes not array", env(R"("source": "studio", "studio": {"softboxes": {}})"),
        "environment.studio.softboxes: must be an array of softboxes");
    QByteArray boxes;
    for (int i = 0; i <= kMaxEnvironmentSoftboxes; ++i)
        boxes += i ? ", {}" : "{}";
    row("33 softboxes", env(R"("source": "studio", "studio": {"softboxes": [)" + boxes + "]}"),
        "environment.studio.softboxes: 33 softboxes; at most 32 are allowed");
    row("softbox not object", env(R"("source": "studio", "studio": {"softboxes": [{}, 2]})"),
        "environment.studio.softboxes[1]: must be an object");
    row("softbox elevation 91", env(R"("source": "studio", "studio": {"softboxes": [{"elevation": 91}]})"),
        "environment.studio.softboxes[0].elevation: must be a finite number from -90 to 90, got 91");
    row("softbox azimuth overflow",
        env(R"("source": "studio", "studio": {"softboxes": [{"azimuth": -1e999}]})"),
        "environment.studio.softboxes[0].azimuth: must be a finite number, got -1e999");
    row("softbox width 0", env(R"("source": "studio", "studio": {"softboxes": [{"width": 0}]})"),
        "environment.studio.softboxes[0].width: must be a finite number > 0 and <= 170, got 0");
    row("softbox height 171", env(R"("source": "studio", "studio": {"softboxes": [{}, {"height": 171}]})"),
        "environment.studio.softboxes[1].height: must be a finite number > 0 and <= 170, got 171");
    row("softbox colour negative",
        env(R"("source": "studio", "studio": {"softboxes": [{"color": [1, 1, -2]}]})"),
        "environment.studio.softboxes[0].color[2]: must be a finite number from 0 to 1000000, got -2");
    row("softbox intensity negative",
        env(R"("source": "studio", "studio": {"softboxes": [{"intensity": -1}]})"),
        "environment.studio.softboxes[0].intensity: must be a finite number from 0 to 1000000, got -1");
    row("spots not array", env(R"("source": "studio", "spots": {"direction": [0, 1, 0]})"),
        "environment.spots: must be an array of spots");
    QByteArray spots;
    for (int i = 0; i <= kMaxEnvironmentSpots; ++i)
        spots += i ? R"(, {"direction": [0, 1, 0]})" : R"({"direction": [0, 1, 0]})";
    row("65 spots", env(R"("source": "studio", "spots": [)" + spots + "]"),
        "environment.spots: 65 spots; at most 64 are allowed");
    row("spot without direction", env(R"("source": "studio", "spots": [{"angle": 5}])"),
        "environment.spots[0].direction: missing; a dimmed spot needs a direction");
    row("spot direction zero", env(R"("source": "studio", "spots": [{"direction": [0, 0, 0]}])"),
        "environment.spots[0].direction: must not be the zero vector");
    row("spot angle 0", env(R"("source": "studio", "spots": [{"direction": [0, 1, 0], "angle": 0}])"),
        "environment.spots[0].angle: must be a finite number > 0 and <= 90, got 0");
    row("spot angle 91",
        env(R"("source": "image", "file": "a.exr", "spots": [{"direction": [1, 0, 0]}, {"direction": [0, 1, 0], "angle": 91}])"),
        "environment.spots[1].angle: must be a finite number > 0 and <= 90, got 91");
    row("spot factor 1.5", env(R"("source": "none", "spots": [{"direction": [0, 1, 0], "factor": 1.5}])"),
        "environment.spots[0].factor: must be a finite number from 0 to 1, got 1.5");
}

// Each row breaks exactly one rule: exactly one error, naming the path; no rig comes back.
void TestRigRules::rules() {
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const QString file = QStringLiteral("rule.json");
    const RigReadResult r = readRigJson(json, file);
    QVERIFY2(!r.ok() && !r.rig.has_value(), qPrintable(describe(r)));
    QVERIFY2(r.errors.size() == 1, qPrintable(describe(r)));
    QVERIFY2(hasMessage(r.errors, file, expected),
             qPrintable(QStringLiteral("expected \"%1: %2...\"\n").arg(file, expected) + describe(r)));
}

QTEST_GUILESS_MAIN(TestRigRules)
#include "tst_rigrules.moc"
