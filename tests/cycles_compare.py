"""Glint's path tracer against Blender Cycles on a Lambert scene (docs/path-tracer.md).

Builds the Glint scene file's Lambert planes and spheres, point lights and perspective camera in
Blender (Z up: Glint's (x, y, z) is Blender's (x, -z, y)), renders it with Cycles twice (two
seeds: Cycles' own noise) and prints the display-encoded PSNR of each Glint EXR given against
each Cycles picture. Cycles' settings follow the pitfalls measured for the reference renderer:
no adaptive sampling, no light threshold, no clamping, no denoising, a 1-pixel box filter.

    blender -b --factory-startup -P tests/cycles_compare.py -- SCENE.json OUT_DIR \
        --samples N [--bounces N] [GLINT.exr ...]

Only what a Lambert comparison needs is read: other models, lights or shapes are refused.
"""
import argparse
import json
import math
import os
import sys

import bpy
from mathutils import Vector


def blender_vector(v):
    return (v[0], -v[2], v[1])


def refuse(message):
    sys.exit(f"cycles_compare: {message}")


def lambert_material(name, albedo):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")  # roughness 0: Lambert (Principled's is Burley)
    rgb = albedo if isinstance(albedo, list) else [albedo] * 3
    diffuse.inputs["Color"].default_value = (*rgb, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    output = nodes.new("ShaderNodeOutputMaterial")
    material.node_tree.links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    return material


def add_plane(spec, material):
    size = spec.get("size", [6, 6])
    normal = blender_vector(spec.get("normal", [0, 1, 0]))
    bpy.ops.mesh.primitive_plane_add(size=1.0, location=blender_vector(spec.get("center", [0, -1, 0])))
    plane = bpy.context.object
    plane.scale = (size[0], size[1], 1.0)
    # A square plane: only its normal matters, the turn about it does not.
    plane.rotation_mode = "QUATERNION"
    plane.rotation_quaternion = Vector((0.0, 0.0, 1.0)).rotation_difference(Vector(normal))
    plane.data.materials.append(material)


def add_sphere(spec, material):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=256, ring_count=128, radius=spec.get("radius", 1.0),
                                         location=blender_vector(spec.get("center", [0, 0, 0])))
    bpy.ops.object.shade_smooth()
    bpy.context.object.data.materials.append(material)


def build_scene(glint_scene, width, height):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    world = bpy.data.worlds.new("black")
    world.color = (0.0, 0.0, 0.0)
    scene.world = world
    background = glint_scene.get("background", [0, 0, 0])
    if any(background):
        refuse("only a black background is compared (Cycles would light the scene with it)")
    if glint_scene.get("environment"):
        refuse("environments are not compared yet")

    camera_spec = glint_scene["camera"]
    if camera_spec.get("projection", "perspective") != "perspective":
        refuse("only perspective cameras are compared")
    camera_data = bpy.data.cameras.new("camera")
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle_y = math.radians(camera_spec.get("fov_degrees", 40.0))
    camera = bpy.data.objects.new("camera", camera_data)
    scene.collection.objects.link(camera)
    position = Vector(blender_vector(camera_spec.get("position", [0, 0, 4])))
    target = Vector(blender_vector(camera_spec.get("target", [0, 0, 0])))
    camera.location = position
    camera.rotation_mode = "QUATERNION"
    camera.rotation_quaternion = (target - position).to_track_quat("-Z", "Y")
    scene.camera = camera

    for spec in glint_scene.get("lights", []):
        if spec.get("type") != "point":
            refuse(f"light '{spec.get('name')}': only point lights are compared")
        light_data = bpy.data.lights.new(spec.get("name", "light"), "POINT")
        light_data.energy = spec["power"]  # P [W]: intensity P/(4π) W/sr, as Glint's
        light_data.shadow_soft_size = 0.0
        light_data.color = spec.get("color", [1, 1, 1])
        light = bpy.data.objects.new(light_data.name, light_data)
        light.location = blender_vector(spec["position"])
        scene.collection.objects.link(light)

    materials = {}
    for spec in glint_scene["materials"]:
        if spec.get("model") != "lambert":
            refuse(f"material '{spec['name']}': only lambert is compared")
        materials[spec["name"]] = lambert_material(spec["name"], spec.get("albedo", 0.8))
    for spec in glint_scene["objects"]:
        shape = spec.get("shape")
        if shape == "plane":
            add_plane(spec, materials[spec["material"]])
        elif shape == "sphere":
            add_sphere(spec, materials[spec["material"]])
        else:
            refuse(f"object '{spec.get('name')}': only planes and spheres are compared")


def render(path, samples, bounces, seed):
    scene = bpy.context.scene
    cycles = scene.cycles
    cycles.samples = samples
    cycles.seed = seed
    cycles.use_adaptive_sampling = False
    cycles.light_sampling_threshold = 0.0
    cycles.use_denoising = False
    cycles.sample_clamp_direct = cycles.sample_clamp_indirect = 0.0
    cycles.max_bounces = cycles.diffuse_bounces = bounces
    cycles.pixel_filter_type = "BOX"
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def encoded_pixels(path):
    """The image's RGB, linear radiance clamped to [0, 1] and sRGB-encoded, bottom row first."""
    image = bpy.data.images.load(path)
    values = list(image.pixels)
    bpy.data.images.remove(image)

    def encode(linear):
        linear = min(max(linear, 0.0), 1.0)
        return 12.92 * linear if linear <= 0.0031308 else 1.055 * linear ** (1 / 2.4) - 0.055

    return [encode(v) for i, v in enumerate(values) if i % 4 != 3], [v for i, v in enumerate(values) if i % 4 != 3]


def psnr(a, b):
    squared = sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)
    return math.inf if squared == 0 else 10 * math.log10(1.0 / squared)


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_compare.py")
    parser.add_argument("scene")
    parser.add_argument("out_dir")
    parser.add_argument("--samples", type=int, required=True)
    parser.add_argument("--bounces", type=int, default=64)
    parser.add_argument("glint_exrs", nargs="*")
    options = parser.parse_intermixed_args(arguments)
    with open(options.scene) as file:
        glint_scene = json.load(file)
    output = glint_scene.get("output", {})
    width, height = output.get("width", 512), output.get("height", 512)
    build_scene(glint_scene, width, height)
    os.makedirs(options.out_dir, exist_ok=True)
    cycles_paths = [os.path.abspath(os.path.join(options.out_dir, f"cycles_seed{seed}.exr")) for seed in (1, 2)]
    for seed, path in zip((1, 2), cycles_paths):
        render(path, options.samples, options.bounces, seed)
    cycles = [encoded_pixels(path) for path in cycles_paths]
    print(f"cycles seed 1 against seed 2: {psnr(cycles[0][0], cycles[1][0]):.1f} dB")
    for glint_path in options.glint_exrs:
        encoded, linear = encoded_pixels(os.path.abspath(glint_path))
        if len(encoded) != len(cycles[0][0]):
            refuse(f"{glint_path}: not {width}x{height} (render it with the scene's own size)")
        scores = ", ".join(f"{psnr(encoded, c[0]):.1f} dB" for c in cycles)
        brightness = sum(linear) / sum(cycles[0][1])
        print(f"{glint_path} against cycles seeds 1, 2: {scores}; mean radiance {brightness:.3f} of cycles'")


main()
