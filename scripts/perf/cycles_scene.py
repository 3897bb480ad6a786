# Blender (3.4, Cycles on the CPU) side of scripts/perf/versus_cycles.sh (issue 36, items 5 and 6a): the
# scene `lightrig render MODEL --quality path --ground visible --environment FILE` traces, rebuilt in
# Cycles as like for like as Blender allows, then rendered once.
#   blender -b --factory-startup --python scripts/perf/cycles_scene.py -- MODEL.glb ENV.exr OUT.png
#       [--size WxH] [--samples N] [--bounces B] [--time-limit S] [--threads T] [--seed S] [--exr OUT.exr]
#       [--ground visible|off] [--ground-bsdf principled|lambert] [--lights on|off] [--calibrate]
# (--lights off deletes the model's lights, ENV "none" makes the world black: each source alone, for
# finding where a difference comes from.)
# What is matched, and how (docs/path-tracing.md, "Against Cycles", lists what cannot be):
#  - Lights: the glTF importer reads KHR_lights_punctual with convert_lighting_mode='COMPAT', i.e. a point
#    or spot light's W = cd × 4π (and a sun's W/m² = lux), not the default 'SPEC' (cd × 4π / 683). LightRig
#    takes candela as radiant intensity (W/sr: radiance = f · cd / d² · N·L, core/lighting.h) and Cycles'
#    point light of P watts has radiant intensity P / 4π, so COMPAT is the like-for-like mapping; --calibrate
#    checks it (a white Lambertian plane 1 m under a 4π W point light must read 1/π). The importer leaves
#    Blender's default radius 0.25 m on the light: it is set to 0 (a punctual light, as LightRig's).
#  - Camera: the model's glTF camera (LightRig's default when the model has one), yfov kept vertical.
#  - Ground: LightRig's visible ground (model/ground.cpp): a square 10 model radii wide (radius = half the
#    bounds' diagonal) centred under the model's bounds at its lowest point, base colour 0.8, metallic 0,
#    roughness 1.
#  - Environment: the equirectangular EXR at strength 1 (LightRig's 0 EV), no rotation (both map the
#    image's centre column to glTF +X), shown as the background, importance sampled at full resolution.
#  - Film: view transform Standard, look None, exposure 0, gamma 1, sRGB, no dither; a box filter one pixel
#    wide (LightRig: a uniform point in the pixel per sample); no denoiser, no adaptive sampling, no sample
#    clamping, no glossy blur, no light threshold, caustics on.
#  - Bounces: LightRig's --bounces B counts surface interactions (1 = direct light only); Cycles'
#    max_bounces counts the bounces after the first hit, so Cycles gets B - 1 for every kind.
import math
import sys
import time

import bpy
from mathutils import Vector


def parse(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    if len(args) < 3:
        sys.exit("usage: blender -b --python cycles_scene.py -- MODEL.glb ENV.exr OUT.png [options]")
    o = {"model": args[0], "env": args[1], "out": args[2], "size": "480x270", "samples": "64",
         "bounces": "8", "time-limit": "0", "threads": "0", "seed": "0", "exr": "", "ground": "visible", "lights": "on", "ground-bsdf": "principled"}
    flags = {"calibrate": False}
    i = 3
    while i < len(args):
        key = args[i][2:]
        if key in flags:
            flags[key] = True
            i += 1
            continue
        if key not in o or i + 1 >= len(args):
            sys.exit(f"cycles_scene.py: unknown option or missing value: {args[i]}")
        o[key] = args[i + 1]
        i += 2
    o.update(flags)
    return o


def film(scene, o):
    w, h = (int(v) for v in o["size"].lower().split("x"))
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = w, h, 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1
    r.film_transparent = False
    r.dither_intensity = 0.0
    r.use_persistent_data = False
    r.threads_mode = "FIXED" if int(o["threads"]) > 0 else "AUTO"
    if int(o["threads"]) > 0:
        r.threads = int(o["threads"])
    r.image_settings.file_format = "PNG"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "8"
    vs = scene.view_settings
    scene.display_settings.display_device = "sRGB"
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    vs.use_curve_mapping = False
    scene.sequencer_colorspace_settings.name = "sRGB"
    c = scene.cycles
    c.device = "CPU"
    c.samples = int(o["samples"])
    c.time_limit = float(o["time-limit"])
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_preview_denoising = False
    c.seed = int(o["seed"])
    c.use_animated_seed = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    b = max(0, int(o["bounces"]) - 1)
    c.max_bounces = b
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.volume_bounces = b
    c.transparent_max_bounces = max(b, 8)
    c.min_light_bounces = 0
    c.min_transparent_bounces = 0
    scene.cycles.sample_offset = 0


def world(scene, env):
    w = bpy.data.worlds.new("env")
    scene.world = w
    w.use_nodes = True
    nt = w.node_tree
    nt.nodes.clear()
    tex = nt.nodes.new("ShaderNodeTexEnvironment")
    tex.image = bpy.data.images.load(env)
    tex.image.colorspace_settings.name = "Linear"
    tex.interpolation = "Linear"
    tex.projection = "EQUIRECTANGULAR"
    bg = nt.nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    out = nt.nodes.new("ShaderNodeOutputWorld")
    nt.links.new(tex.outputs["Color"], bg.inputs["Color"])
    nt.links.new(bg.outputs["Background"], out.inputs["Surface"])
    w.cycles.sampling_method = "MANUAL"
    w.cycles.sample_map_resolution = max(tex.image.size[0], 64)
    w.cycles.max_bounces = 1024


def principled(name, base, roughness, metallic):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    p = m.node_tree.nodes["Principled BSDF"]
    p.distribution = "GGX"  # single scattering, as the glTF BRDF
    p.inputs["Base Color"].default_value = (*base, 1.0)
    p.inputs["Roughness"].default_value = roughness
    p.inputs["Metallic"].default_value = metallic
    p.inputs["Specular"].default_value = 0.5  # F0 = 0.08 × 0.5 = 0.04
    return m


def model_bounds(objects):
    lo = Vector((math.inf,) * 3)
    hi = Vector((-math.inf,) * 3)
    deps = bpy.context.evaluated_depsgraph_get()
    for ob in objects:
        if ob.type != "MESH":
            continue
        ev = ob.evaluated_get(deps)
        for v in ev.data.vertices:
            p = ev.matrix_world @ v.co
            lo = Vector(map(min, lo, p))
            hi = Vector(map(max, hi, p))
    return lo, hi


def lambert(albedo):
    m = bpy.data.materials.new("lambert")
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (albedo, albedo, albedo, 1.0)
    d.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(d.outputs["BSDF"], out.inputs["Surface"])
    return m


def ground(scene, lo, hi, bsdf):
    # Blender is Z up (the importer turns glTF's +Y into +Z): LightRig's plane at the lowest y is at lowest z.
    radius = 0.5 * (hi - lo).length
    half = 0.5 * 10.0 * radius
    c = 0.5 * (lo + hi)
    mesh = bpy.data.meshes.new("ground")
    z = lo.z
    mesh.from_pydata([(c.x - half, c.y - half, z), (c.x + half, c.y - half, z), (c.x + half, c.y + half, z),
                      (c.x - half, c.y + half, z)], [], [(0, 1, 2, 3)])
    ob = bpy.data.objects.new("ground", mesh)
    scene.collection.objects.link(ob)
    mesh.materials.append(principled("ground", (0.8, 0.8, 0.8), 1.0, 0.0) if bsdf == "principled" else lambert(0.8))
    print(f"cycles_scene: ground {2 * half:.4f} m square at z {z:.4f}, centre ({c.x:.4f}, {c.y:.4f}), "
          f"model radius {radius:.4f}")


def match_materials():
    for m in bpy.data.materials:
        if not m.use_nodes:
            continue
        for n in m.node_tree.nodes:
            if n.type == "BSDF_PRINCIPLED":
                n.distribution = "GGX"
                n.subsurface_method = "BURLEY"


def calibrate(o):
    # A white Lambertian plane at z = 0, a 4π W point light 1 m above, an orthographic camera looking down:
    # LightRig's 1 cd there gives radiance 1/π = 0.3183.
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    film(scene, dict(o, size="8x8", samples="16", bounces="1"))
    scene.world = bpy.data.worlds.new("black")
    scene.world.use_nodes = False
    scene.world.color = (0, 0, 0)
    bpy.ops.mesh.primitive_plane_add(size=100)
    m = bpy.data.materials.new("white")
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (1, 1, 1, 1)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(d.outputs["BSDF"], out.inputs["Surface"])
    bpy.context.object.data.materials.append(m)
    light = bpy.data.lights.new("p", "POINT")
    light.energy = 4 * math.pi
    light.shadow_soft_size = 0.0
    lo = bpy.data.objects.new("p", light)
    lo.location = (0, 0, 1)
    scene.collection.objects.link(lo)
    cam = bpy.data.cameras.new("c")
    cam.type = "ORTHO"
    cam.ortho_scale = 0.01
    co = bpy.data.objects.new("c", cam)
    co.location = (0, 0, 0.5)
    scene.collection.objects.link(co)
    scene.camera = co
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = o["out"]
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(o["out"])
    px = list(img.pixels)
    mean = sum(px[0::4]) / (len(px) // 4)
    print(f"cycles_scene: calibration: white Lambertian 1 m under a 4π W point light reads {mean:.5f} "
          f"(1/π = {1 / math.pi:.5f}: ratio {mean * math.pi:.4f})")


def main():
    o = parse(sys.argv)
    if o["calibrate"]:
        calibrate(o)
        return
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_enable(module="io_scene_gltf2")
    # Blender 3.4's glTF importer still uses np.bool, which NumPy 1.24 (Debian 12's python3-numpy, which
    # the importer needs) removed: give it back the alias.
    import numpy
    if not hasattr(numpy, "bool"):
        numpy.bool = bool
    scene = bpy.context.scene
    before = set(bpy.data.objects)
    bpy.ops.import_scene.gltf(filepath=o["model"], convert_lighting_mode="COMPAT", import_shading="NORMALS")
    imported = [ob for ob in bpy.data.objects if ob not in before]
    for ob in imported:
        if ob.type == "LIGHT" and o["lights"] == "off":
            bpy.data.objects.remove(ob)
        elif ob.type == "LIGHT":
            ob.data.shadow_soft_size = 0.0
            ob.data.cycles.max_bounces = 1024
            ob.data.cycles.use_multiple_importance_sampling = True
            print(f"cycles_scene: light {ob.name}: {ob.data.type}, {ob.data.energy:.4f} W "
                  f"(= {ob.data.energy / (4 * math.pi):.4f} cd), colour {tuple(round(c, 4) for c in ob.data.color)}")
    imported = [ob for ob in bpy.data.objects if ob not in before]
    cams = [ob for ob in imported if ob.type == "CAMERA"]
    if not cams:
        sys.exit("cycles_scene.py: the model has no camera; LightRig's framing would have to be exported")
    scene.camera = cams[0]
    print(f"cycles_scene: camera {cams[0].name} at {tuple(round(v, 4) for v in cams[0].matrix_world.translation)}, "
          f"vertical fov {math.degrees(cams[0].data.angle_y):.3f} deg")
    match_materials()
    film(scene, o)
    if o["env"] == "none":
        scene.world = bpy.data.worlds.new("black")
        scene.world.color = (0, 0, 0)
    else:
        world(scene, o["env"])
    if o["ground"] == "visible":
        lo, hi = model_bounds([ob for ob in imported if ob.type == "MESH"])
        ground(scene, lo, hi, o["ground-bsdf"])
    scene.render.filepath = o["out"]
    t = time.time()
    bpy.ops.render.render(write_still=True)
    seconds = time.time() - t
    print(f"cycles_scene: rendered {o['out']} ({o['size']}, {scene.cycles.samples} samples requested, "
          f"time limit {scene.cycles.time_limit} s, bounces {scene.cycles.max_bounces} after the first hit) "
          f"in {seconds:.2f} s")
    if o["exr"]:
        result = bpy.data.images["Render Result"]
        scene.render.image_settings.file_format = "OPEN_EXR"
        scene.render.image_settings.color_depth = "32"
        scene.render.image_settings.color_mode = "RGB"
        result.save_render(o["exr"], scene=scene)


main()
