"""The all-diffuse Cornell box rendered by Blender's Cycles, to time our path tracer against it.

Not part of the build, the tests or CI: Blender is an outside renderer (Debian's package
`blender`, 3.4 was used), installed only where the comparison is made. Run it as

    blender -b --factory-startup -P lessons/14_path_tracing/cycles_cornell.py -- \\
        --scene lessons/scenes/cornell.json --spp 64 --threads 2 --out /tmp/cycles_64.exr

and time it at two sample counts (say 16 and 64): the difference of the two times is
the rendering of the extra samples alone, Blender's start-up and scene building taken
out. The same for ours, on the same scene, size and settings:

    build/release/bin/14_make_reference --scene cornell --width 256 --height 256 \\
        --batch-spp 64 --threads 2 --out /tmp/ours_64

The scene is read from the workbench's own scene file (the published box, millimetres,
y up), turned into Blender's z-up axes by (x, y, z) -> (-x, z, y), a rotation, so
nothing is mirrored. Settings as the path tracer's defaults: 256 x 256, one box-filtered
pixel each (filter width 1 pixel), paths up to 64 bounces, next-event estimation with
MIS on the light (Cycles' "multiple importance" on an emitting mesh), no clamping, no
adaptive sampling, no denoising, CPU only, a fixed thread count. Cycles' own Russian
roulette and its sampling pattern are left as they are.
"""
import argparse
import json
import math
import sys

import bpy


def options():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_cornell.py")
    parser.add_argument("--scene", required=True, help="the workbench's scene file (lessons/scenes/cornell.json)")
    parser.add_argument("--spp", type=int, default=64, help="samples per pixel")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--size", type=int, default=256, help="width and height in pixels")
    parser.add_argument("--bounces", type=int, default=64)
    parser.add_argument("--out", required=True, help="an OpenEXR file for the linear picture")
    return parser.parse_args(argv)


def to_blender(p):
    """(x, y, z) of the scene file (y up) -> Blender's (z up): a rotation, determinant +1."""
    return (-p[0], p[2], p[1])


def material(spec):
    """A Lambertian surface of the file's reflectance, or an emitter of its radiance L.
    Cycles' emission strength of a white emitter is its radiance (a strength of pi L made
    the picture pi times too bright against lessons/references/), so the colour carries
    L / max(L) and the strength max(L)."""
    m = bpy.data.materials.new(spec["name"])
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if "emission" in spec:
        L = spec["emission"]
        peak = max(L)
        shader = nodes.new("ShaderNodeEmission")
        shader.inputs["Color"].default_value = (L[0] / peak, L[1] / peak, L[2] / peak, 1)
        shader.inputs["Strength"].default_value = peak
        m.cycles.sample_as_light = True  # next-event estimation on it, weighted by MIS
    else:
        rho = spec["diffuse"] if isinstance(spec["diffuse"], list) else [spec["diffuse"]] * 3
        shader = nodes.new("ShaderNodeBsdfDiffuse")
        shader.inputs["Color"].default_value = (rho[0], rho[1], rho[2], 1)
        shader.inputs["Roughness"].default_value = 0  # Lambert
    links.new(shader.outputs[0], out.inputs["Surface"])
    return m


def build(scene_file):
    with open(scene_file) as f:
        data = json.load(f)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    materials = {spec["name"]: material(spec) for spec in data["materials"]}
    for polygon in data["polygons"]:
        mesh = bpy.data.meshes.new(polygon["name"])
        corners = [to_blender(c) for c in polygon["corners"]]
        mesh.from_pydata(corners, [], [list(range(len(corners)))])
        mesh.materials.append(materials[polygon["material"]])
        scene.collection.objects.link(bpy.data.objects.new(polygon["name"], mesh))
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0
    scene.world = world
    c = data["camera"]
    camera = bpy.data.cameras.new("camera")
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(c["fov"])
    camera.clip_end = 1e6  # the scene is in millimetres: Blender's default 100 would cut the back wall off
    eye = bpy.data.objects.new("camera", camera)
    eye.location = to_blender(c["eye"])
    # Blender's camera looks down its -z with +y up; turned 90 degrees about x it looks
    # along +y with +z up: the scene file's +z and +y. (The file's camera looks along +z.)
    eye.rotation_euler = (math.pi / 2, 0, 0)
    scene.collection.objects.link(eye)
    scene.camera = eye
    return scene


def settings(scene, args):
    scene.render.engine = "CYCLES"
    scene.render.resolution_x = scene.render.resolution_y = args.size
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.view_settings.view_transform = "Standard"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = args.spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.max_bounces = cycles.diffuse_bounces = args.bounces
    cycles.glossy_bounces = cycles.transmission_bounces = cycles.transparent_max_bounces = args.bounces
    cycles.sample_clamp_direct = cycles.sample_clamp_indirect = 0
    cycles.caustics_reflective = cycles.caustics_refractive = True
    cycles.blur_glossy = 0


def main():
    args = options()
    scene = build(args.scene)
    settings(scene, args)
    scene.render.filepath = args.out
    bpy.ops.render.render(write_still=True)


main()
