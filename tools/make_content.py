#!/usr/bin/env python3
"""Writes Bounce's committed glTF scenes to content/ (standard library only).

    python3 tools/make_content.py            # writes into <repo>/content
    python3 tools/make_content.py --out DIR  # writes somewhere else

Every scene is one self-contained .gltf file: its buffer is embedded as a base64 data
URI. Units are metres and radiometric light units (W/sr for point lights, W/m^2 for
directional lights, W/(m^2 sr) for emission), as Bounce's scene model expects; each
asset says so with extras.BounceLightUnits = "radiometric", since KHR_lights_punctual's
own units (candela, lux) are what a glTF file means otherwise.
"""

import argparse
import base64
import json
import math
import os
import struct
import zlib

# --- scene parameters -------------------------------------------------------------------

# Cornell box: interior x in [-1, 1], y in [0, 2], z in [-1, 1], open towards +z.
WALL_THICKNESS = 0.05          # m; solid walls, so voxelization sees them as closed
WHITE = (0.73, 0.73, 0.73)     # albedo of floor, ceiling, back wall, tall box and sphere
RED = (0.63, 0.065, 0.05)      # left wall (-x)
GREEN = (0.14, 0.45, 0.091)    # right wall (+x)
TALL_BOX_SIZE = (0.6, 1.2, 0.6)        # m
TALL_BOX_CENTER = (-0.35, 0.6, -0.35)  # back left, standing on the floor
TALL_BOX_YAW_DEGREES = 17.0
SPHERE_RADIUS = 0.35                   # m
SPHERE_CENTER = (0.45, 0.35, 0.35)     # front right, resting on the floor
SPHERE_ROUGHNESS = 0.3                 # glossy: default specular (F0 = 0.04), GGX
SPHERE_SEGMENTS = 32                   # around the vertical axis
SPHERE_RINGS = 16                      # pole to pole
CORNELL_LIGHT_POSITION = (0.0, 1.85, 0.0)
CORNELL_LIGHT_INTENSITY = 15.0         # W/sr
CORNELL_LIGHT_COLOR = (1.0, 0.95, 0.85)
CORNELL_CAMERA_POSITION = (0.0, 1.0, 3.9)  # looking down -z
CORNELL_CAMERA_YFOV = 0.6911               # rad (39.6 degrees): the box just fills the view
CAMERA_ZNEAR = 0.05                        # m; no zfar: infinite far plane

# Flags read by the VXGI plugin (plugin-declared object parameters).
VOXELIZE_FLAG = {"UsedWithVxgiVoxelization": True}
INDIRECT_LIGHT_FLAG = {"VxgiIndirectLighting": True}

# Renderer test scenes (content/tests/). All Lambert (specularFactor 0) unless noted.
TEST_PLANE_SIZE = 4.0              # m, square, at y = 0
TEST_PLANE_ALBEDO = 0.5
TEST_DIRECTIONAL_IRRADIANCE = 2.0  # W/m^2 on a surface facing the light
TEST_POINT_INTENSITY = 4.0         # W/sr
TEST_POINT_HEIGHT = 1.0            # m above the plane centre
TEST_OCCLUDER_SIZE = 1.0           # m, square
TEST_OCCLUDER_HEIGHT = 0.5         # m, between the point light and the plane
TEST_OCCLUDER_THICKNESS = 0.02     # m
TEST_MASK_TEXELS = 8               # side of the masked occluder's alpha texture
TEST_MASK_SQUARE = 2               # texels per side of its checker squares (alpha 1 or 0)
TEST_CAMERA_HEIGHT = 2.0           # m; with yfov 0.8 the 4 m plane fills even a 16:9 view
TEST_CAMERA_YFOV = 0.8             # rad
EMISSIVE_QUAD_COLOR = (1.0, 0.5, 0.25)
EMISSIVE_QUAD_STRENGTH = 2.0       # KHR_materials_emissive_strength
EMISSIVE_QUAD_SIZE = 1.0           # m
FURNACE_ALBEDO = 0.5               # white furnace: expected radiance E / (1 - albedo) = 2
FURNACE_EMISSION = (1.0, 1.0, 1.0)
ROOM_SIZE = 2.0                    # m, white furnace and each of the two rooms
THIN_WALL_THICKNESS = 0.02         # m, between the two rooms
TWO_ROOMS_ALBEDO = 0.73
TWO_ROOMS_LIGHT_INTENSITY = 10.0   # W/sr, in the left room only
HDR_PANEL_SIZE = 0.4               # m, square emitter under the ceiling of a furnace room
HDR_PANEL_RADIANCE = 1.0e4         # W/(m^2 sr): 10^4 x the walls' emission
SMALL_EMITTER_SIZE = 0.02          # m, a cube far smaller than any voxel the tests use
SMALL_EMITTER_RADIANCE = 1.0e4     # W/(m^2 sr)
SMALL_EMITTER_HEIGHT = 1.0         # m above the floor
SUNLIT_ROOM_SIZE = (4.0, 2.5, 4.0)   # m, interior (x, y, z)
SUNLIT_WALL_THICKNESS = 0.2        # m: real walls, thick against the probe spacing
SUNLIT_WINDOW = (1.2, 1.0, 1.0)    # m: width, height, sill height; in the +z wall, centred
SUNLIT_ALBEDO = 0.6
SUNLIT_SUN_IRRADIANCE = 10.0       # W/m^2 at normal incidence
SUNLIT_SUN_ELEVATION_DEGREES = 30.0  # the sun shines in towards -z, down at this angle
SUNLIT_THIN_WALL_THICKNESS = 0.1   # m: thinner than the coarse voxels the leak test uses
SUNLIT_WINDOW_OFFSET = 1.0         # m along +x: the opening 0.4 m from the +x wall
SUNLIT_BACK_CAMERA_TILT_DEGREES = -20.0
SUNLIT_HIGH_SUN_ELEVATION_DEGREES = 50.0  # the patch a metre nearer the window wall
TINY_SCENE_SIZE = 0.1              # m, a floor tile with a 4 cm box: inside one 1 m voxel
LIT_FLOOR_SIZE = 30.0              # m, square slab, top at y = 0; the wall across its middle
LIT_FLOOR_WALL_HEIGHT = 8.0        # m, wall 30 m wide and 0.2 m thick, front face at z = 0.1
LIT_FLOOR_ALBEDO = 0.5
LIT_FLOOR_IRRADIANCE = 10.0        # W/m^2: sun straight down, so the wall gets none directly
LIT_FLOOR_CAMERA = (0.0, 1.5, 5.0)  # m, facing the wall (-z)
LIT_FLOOR_CAMERA_YFOV = 1.0        # rad

# --- glTF constants ---------------------------------------------------------------------

FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963


# --- geometry ---------------------------------------------------------------------------

def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def scale(a, s):
    return tuple(x * s for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normalize(a):
    length = math.sqrt(dot(a, a))
    return scale(a, 1.0 / length)


class Geometry:
    """An indexed triangle list with per-vertex normals (counter-clockwise front faces)."""

    def __init__(self):
        self.positions, self.normals, self.indices = [], [], []
        self.uvs = []  # TEXCOORD_0, written when every vertex has one

    def quad(self, center, u, v, texcoords=False):
        """Rectangle center +- u +- v, facing cross(u, v); with texcoords, UV (0,0) at center - u - v
        and (1,1) at center + u + v."""
        n = normalize(cross(u, v))
        base = len(self.positions)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            self.positions.append(add(center, add(scale(u, su), scale(v, sv))))
            self.normals.append(n)
            if texcoords:
                self.uvs.append(((su + 1) / 2, (sv + 1) / 2))
        self.indices += [base, base + 1, base + 2, base, base + 2, base + 3]
        return self

    def box(self, size, center=(0.0, 0.0, 0.0)):
        """Axis-aligned box, faces pointing out (flat normals, 24 vertices)."""
        hx, hy, hz = (s / 2 for s in size)
        x, y, z = (hx, 0, 0), (0, hy, 0), (0, 0, hz)
        for offset, u, v in ((x, y, z), (scale(x, -1), z, y), (y, z, x), (scale(y, -1), x, z),
                             (z, x, y), (scale(z, -1), y, x)):
            self.quad(add(center, offset), u, v)
        return self

    def uv_sphere(self, radius, segments, rings):
        """Sphere around the origin with smooth normals; pole triangles of zero area are left out."""
        base = len(self.positions)
        for i in range(rings + 1):
            theta = math.pi * i / rings
            for j in range(segments + 1):
                phi = 2 * math.pi * j / segments
                n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
                self.normals.append(n)
                self.positions.append(scale(n, radius))
        row = segments + 1
        for i in range(rings):
            for j in range(segments):
                a, b, c, d = i * row + j, (i + 1) * row + j, (i + 1) * row + j + 1, i * row + j + 1
                for tri in ((a, b, c), (a, c, d)):
                    p = [self.positions[base + k] for k in tri]
                    n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
                    if dot(n, n) < 1e-12:  # the collapsed corner at a pole
                        continue
                    centroid = scale(add(add(p[0], p[1]), p[2]), 1 / 3)
                    if dot(n, centroid) < 0:  # wind counter-clockwise seen from outside
                        tri = (tri[0], tri[2], tri[1])
                    self.indices += [base + t for t in tri]
        return self


def yaw_quaternion(degrees):
    half = math.radians(degrees) / 2
    return [0.0, math.sin(half), 0.0, math.cos(half)]


# Rotates -Z (where cameras look and lights point) to -Y: straight down.
LOOK_DOWN = [-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]


# --- glTF writing -----------------------------------------------------------------------

class GltfScene:
    def __init__(self, generator_note):
        self.bin = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "Bounce tools/make_content.py", "extras": {"note": generator_note, "BounceLightUnits": "radiometric"}},
            "scene": 0,
            "scenes": [{"nodes": []}],
            "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": [], "buffers": [],
        }
        self.extensions = set()

    def _view(self, data, target):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc["bufferViews"].append(
            {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data), "target": target})
        self.bin += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, view, component_type, count, kind, **extra):
        self.doc["accessors"].append(
            {"bufferView": view, "componentType": component_type, "count": count, "type": kind, **extra})
        return len(self.doc["accessors"]) - 1

    def texture(self, width, height, rgba):
        """An embedded PNG (8-bit RGBA rows, top row first) with the default sampler (linear, repeat)."""
        raw = b"".join(b"\0" + bytes(rgba[y * width * 4:(y + 1) * width * 4]) for y in range(height))

        def chunk(kind, data):
            return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

        png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
               chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
        self.doc.setdefault("images", []).append(
            {"uri": "data:image/png;base64," + base64.b64encode(png).decode()})
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def material(self, name, color, roughness=1.0, metallic=0.0, lambert=True, emissive=None,
                 emissive_strength=None, extras=None, base_color_texture=None, alpha_cutoff=None,
                 double_sided=False):
        m = {"name": name,
             "pbrMetallicRoughness": {"baseColorFactor": [*color, 1.0], "metallicFactor": metallic,
                                      "roughnessFactor": roughness}}
        if base_color_texture is not None:
            m["pbrMetallicRoughness"]["baseColorTexture"] = {"index": base_color_texture}
        if alpha_cutoff is not None:
            m["alphaMode"], m["alphaCutoff"] = "MASK", alpha_cutoff
        if double_sided:
            m["doubleSided"] = True
        ext = {}
        if lambert:  # no specular lobe: the BRDF is pure Lambert
            ext["KHR_materials_specular"] = {"specularFactor": 0.0}
        if emissive is not None:
            m["emissiveFactor"] = list(emissive)
        if emissive_strength is not None:
            ext["KHR_materials_emissive_strength"] = {"emissiveStrength": emissive_strength}
        if ext:
            m["extensions"] = ext
            self.extensions.update(ext)
        if extras:
            m["extras"] = dict(extras)
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, name, geometry, material):
        pos, nrm, idx = geometry.positions, geometry.normals, geometry.indices
        pos_view = self._view(b"".join(struct.pack("<3f", *p) for p in pos), ARRAY_BUFFER)
        nrm_view = self._view(b"".join(struct.pack("<3f", *n) for n in nrm), ARRAY_BUFFER)
        wide = len(pos) > 65535
        idx_view = self._view(struct.pack("<%d%s" % (len(idx), "I" if wide else "H"), *idx), ELEMENT_ARRAY_BUFFER)
        lo = [min(p[i] for p in pos) for i in range(3)]
        hi = [max(p[i] for p in pos) for i in range(3)]
        attributes = {"POSITION": self._accessor(pos_view, FLOAT, len(pos), "VEC3", min=lo, max=hi),
                      "NORMAL": self._accessor(nrm_view, FLOAT, len(nrm), "VEC3")}
        if geometry.uvs and len(geometry.uvs) == len(pos):
            uv_view = self._view(b"".join(struct.pack("<2f", *t) for t in geometry.uvs), ARRAY_BUFFER)
            attributes["TEXCOORD_0"] = self._accessor(uv_view, FLOAT, len(pos), "VEC2")
        primitive = {
            "attributes": attributes,
            "indices": self._accessor(idx_view, UNSIGNED_INT if wide else UNSIGNED_SHORT, len(idx), "SCALAR"),
            "material": material, "mode": 4}
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, name, translation=None, rotation=None, scale_=None, **fields):
        node = {"name": name}
        if translation is not None:
            node["translation"] = list(translation)
        if rotation is not None:
            node["rotation"] = list(rotation)
        if scale_ is not None:
            node["scale"] = list(scale_)
        node.update(fields)
        self.doc["nodes"].append(node)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def object(self, name, geometry, material, translation=None, rotation=None):
        return self.node(name, translation, rotation, mesh=self.mesh(name, geometry, material))

    def camera(self, name, translation, rotation=None, yfov=0.8):
        self.doc.setdefault("cameras", []).append(
            {"name": name, "type": "perspective", "perspective": {"yfov": yfov, "znear": CAMERA_ZNEAR}})
        return self.node(name, translation, rotation, camera=len(self.doc["cameras"]) - 1)

    def light(self, name, kind, intensity, translation=None, rotation=None, color=(1.0, 1.0, 1.0), extras=None):
        lights = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        light = {"name": name, "type": kind, "color": list(color), "intensity": intensity}
        if extras:
            light["extras"] = dict(extras)
        lights.append(light)
        self.extensions.add("KHR_lights_punctual")
        return self.node(name, translation, rotation, extensions={"KHR_lights_punctual": {"light": len(lights) - 1}})

    def write(self, path):
        doc = dict(self.doc)
        doc["buffers"] = [{"byteLength": len(self.bin),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()}]
        if self.extensions:
            doc["extensionsUsed"] = sorted(self.extensions)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
        print("wrote", path)


# --- scenes -----------------------------------------------------------------------------

def cornell_box(flagged):
    """The Cornell box; `flagged` adds the VXGI extras flags to materials and the light."""
    t = WALL_THICKNESS
    material_flags = VOXELIZE_FLAG if flagged else None
    s = GltfScene("Cornell box" + ("" if flagged else " without plugin flags"))
    white = s.material("White", WHITE, extras=material_flags)
    red = s.material("Red", RED, extras=material_flags)
    green = s.material("Green", GREEN, extras=material_flags)
    glossy = s.material("GlossyWhite", WHITE, roughness=SPHERE_ROUGHNESS, lambert=False, extras=material_flags)

    s.object("Floor", Geometry().box((2 + 2 * t, t, 2 + t)), white, (0, -t / 2, -t / 2))
    s.object("Ceiling", Geometry().box((2 + 2 * t, t, 2 + t)), white, (0, 2 + t / 2, -t / 2))
    s.object("BackWall", Geometry().box((2 + 2 * t, 2, t)), white, (0, 1, -1 - t / 2))
    s.object("LeftWall", Geometry().box((t, 2, 2)), red, (-1 - t / 2, 1, 0))
    s.object("RightWall", Geometry().box((t, 2, 2)), green, (1 + t / 2, 1, 0))
    s.object("TallBox", Geometry().box(TALL_BOX_SIZE), white, TALL_BOX_CENTER, yaw_quaternion(TALL_BOX_YAW_DEGREES))
    s.object("Sphere", Geometry().uv_sphere(SPHERE_RADIUS, SPHERE_SEGMENTS, SPHERE_RINGS), glossy, SPHERE_CENTER)

    s.light("CeilingLight", "point", CORNELL_LIGHT_INTENSITY, CORNELL_LIGHT_POSITION, color=CORNELL_LIGHT_COLOR,
            extras=INDIRECT_LIGHT_FLAG if flagged else None)
    s.camera("Main", CORNELL_CAMERA_POSITION, yfov=CORNELL_CAMERA_YFOV)
    s.node("PostProcessVolume", (0, 1, 0), scale_=(1 + t, 1 + t, 1 + t), extras={"PostProcessVolume": {
        "Priority": 0, "BlendRadius": 1.0, "Unbound": True, "Settings": {"ExposureCompensation": 0.0}}})
    return s


def lambert_plane(note):
    s = GltfScene(note)
    gray = s.material("Gray", (TEST_PLANE_ALBEDO,) * 3)
    h = TEST_PLANE_SIZE / 2
    s.object("Plane", Geometry().quad((0, 0, 0), (0, 0, h), (h, 0, 0)), gray)
    s.camera("Top", (0, TEST_CAMERA_HEIGHT, 0), LOOK_DOWN, TEST_CAMERA_YFOV)
    return s, gray


def lambert_plane_directional():
    s, _ = lambert_plane("4 m Lambert plane lit straight from above by a directional light")
    s.light("Sun", "directional", TEST_DIRECTIONAL_IRRADIANCE, rotation=LOOK_DOWN)
    return s


def lambert_plane_point(occluded):
    note = "4 m Lambert plane under a point light" + (" with an occluder half way" if occluded else "")
    s, gray = lambert_plane(note)
    s.light("Bulb", "point", TEST_POINT_INTENSITY, (0, TEST_POINT_HEIGHT, 0))
    if occluded:
        size = (TEST_OCCLUDER_SIZE, TEST_OCCLUDER_THICKNESS, TEST_OCCLUDER_SIZE)
        s.object("Occluder", Geometry().box(size), gray, (0, TEST_OCCLUDER_HEIGHT, 0))
    return s


def masked_occluder_point():
    """The shadowed plane's occluder as a 1 m alpha-masked quad: a checker of 2-texel squares,
    alpha 1 and 0, cutoff 0.5. Half of it casts a shadow and is seen; the rest lets light through."""
    s, gray = lambert_plane("4 m Lambert plane under a point light, an alpha-masked checker quad half way")
    s.light("Bulb", "point", TEST_POINT_INTENSITY, (0, TEST_POINT_HEIGHT, 0))
    n = TEST_MASK_TEXELS
    rgba = []
    for y in range(n):
        for x in range(n):
            kept = (x // TEST_MASK_SQUARE + y // TEST_MASK_SQUARE) % 2 == 0
            rgba += [255, 255, 255, 255 if kept else 0]
    checker = s.material("Checker", (TEST_PLANE_ALBEDO,) * 3, base_color_texture=s.texture(n, n, rgba),
                         alpha_cutoff=0.5, double_sided=True)
    h = TEST_OCCLUDER_SIZE / 2
    s.object("MaskedOccluder", Geometry().quad((0, 0, 0), (0, 0, h), (h, 0, 0), texcoords=True), checker,
             (0, TEST_OCCLUDER_HEIGHT, 0))
    return s


def emissive_quad():
    s = GltfScene("emissive quad facing +z, no lights")
    h = EMISSIVE_QUAD_SIZE / 2
    glow = s.material("Glow", (0.0, 0.0, 0.0), emissive=EMISSIVE_QUAD_COLOR,
                      emissive_strength=EMISSIVE_QUAD_STRENGTH)
    s.object("Quad", Geometry().quad((0, 0, 0), (h, 0, 0), (0, h, 0)), glow)
    s.camera("Front", (0, 0, 2.0), yfov=TEST_CAMERA_YFOV)
    return s


def closed_room(x_min, x_max, thickness, skip_walls=()):
    """Solid walls around the interior x in [x_min, x_max], y in [0, ROOM_SIZE], z in +-ROOM_SIZE/2."""
    t, h, w = thickness, ROOM_SIZE, x_max - x_min
    cx, hz = (x_min + x_max) / 2, ROOM_SIZE / 2
    walls = {
        "Floor": ((w + 2 * t, t, h + 2 * t), (cx, -t / 2, 0)),
        "Ceiling": ((w + 2 * t, t, h + 2 * t), (cx, h + t / 2, 0)),
        "Back": ((w, h, t), (cx, h / 2, -hz - t / 2)),
        "Front": ((w, h, t), (cx, h / 2, hz + t / 2)),
        "Left": ((t, h, h + 2 * t), (x_min - t / 2, h / 2, 0)),
        "Right": ((t, h, h + 2 * t), (x_max + t / 2, h / 2, 0)),
    }
    for name, (size, center) in walls.items():
        if name not in skip_walls:
            yield name, Geometry().box(size), center


def furnace_room(note, emission=FURNACE_EMISSION, albedo=FURNACE_ALBEDO):
    s = GltfScene(note)
    wall = s.material("FurnaceWall", (albedo,) * 3, emissive=emission, extras=VOXELIZE_FLAG)
    r = ROOM_SIZE / 2
    for name, geometry, center in closed_room(-r, r, WALL_THICKNESS):
        s.object(name, geometry, wall, center)
    return s, wall


def white_furnace():
    s, _ = furnace_room("closed emissive room of albedo 0.5: every surface sees radiance 2")
    s.camera("Centre", (0, ROOM_SIZE / 2, 0), yfov=1.2)
    return s


def glossy_furnace():
    """The white furnace with a glossy floor (roughness 0.2, a specular lobe), seen from above:
    every direction sees the walls' emission, so the floor's indirect specular radiance is
    that emission, and the Lambert walls trace none."""
    s = GltfScene("closed emissive room, glossy floor: its mirror direction sees radiance 1 of emission")
    wall = s.material("FurnaceWall", (FURNACE_ALBEDO,) * 3, emissive=FURNACE_EMISSION, extras=VOXELIZE_FLAG)
    floor = s.material("GlossyFloor", (FURNACE_ALBEDO,) * 3, roughness=0.2, lambert=False,
                       emissive=FURNACE_EMISSION, extras=VOXELIZE_FLAG)
    r = ROOM_SIZE / 2
    for name, geometry, center in closed_room(-r, r, WALL_THICKNESS):
        s.object(name, geometry, floor if name == "Floor" else wall, center)
    # 45° down towards −z from above the middle: mostly floor, the back wall at the top.
    s.camera("Down", (0, 0.75 * ROOM_SIZE, 0.3 * ROOM_SIZE), rotation=(-0.38268343, 0.0, 0.0, 0.92387953),
             yfov=1.0)
    return s


def two_rooms_thin_wall():
    s = GltfScene("two closed rooms sharing a 2 cm wall; light only in the left one")
    wall = s.material("Wall", (TWO_ROOMS_ALBEDO,) * 3, extras=VOXELIZE_FLAG)
    gap = THIN_WALL_THICKNESS / 2
    # Left room x in [-2.01, -0.01], right room x in [0.01, 2.01]; the shared wall is
    # the only thing between them.
    for prefix, lo, hi in (("LeftRoom", -gap - ROOM_SIZE, -gap), ("RightRoom", gap, gap + ROOM_SIZE)):
        for name, geometry, center in closed_room(lo, hi, WALL_THICKNESS, skip_walls=("Left", "Right")):
            s.object(prefix + name, geometry, wall, center)
    t = WALL_THICKNESS
    s.object("OuterWallLeft", Geometry().box((t, ROOM_SIZE, ROOM_SIZE + 2 * t)), wall,
             (-gap - ROOM_SIZE - t / 2, ROOM_SIZE / 2, 0))
    s.object("OuterWallRight", Geometry().box((t, ROOM_SIZE, ROOM_SIZE + 2 * t)), wall,
             (gap + ROOM_SIZE + t / 2, ROOM_SIZE / 2, 0))
    s.object("ThinWall", Geometry().box((THIN_WALL_THICKNESS, ROOM_SIZE, ROOM_SIZE + 2 * t)), wall,
             (0, ROOM_SIZE / 2, 0))
    s.light("LeftRoomLight", "point", TWO_ROOMS_LIGHT_INTENSITY, (-gap - ROOM_SIZE / 2, ROOM_SIZE * 0.75, 0),
            extras=INDIRECT_LIGHT_FLAG)
    # Inside the dark room, looking straight down: the view holds only its floor.
    s.camera("DarkRoom", (gap + ROOM_SIZE / 2, ROOM_SIZE * 0.75, 0), LOOK_DOWN, yfov=1.0)
    return s


def hdr_emitter():
    s, _ = furnace_room("furnace room (walls emit 1) with a ceiling panel 10^4 times brighter")
    glow = s.material("Panel", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), emissive_strength=HDR_PANEL_RADIANCE,
                      extras=VOXELIZE_FLAG)
    h = HDR_PANEL_SIZE / 2
    # Facing down (cross(u, v) = -y), 1 cm under the ceiling.
    s.object("Panel", Geometry().quad((0, ROOM_SIZE - 0.01, 0), (h, 0, 0), (0, 0, h)), glow)
    s.camera("Down", (0, ROOM_SIZE / 2, 0), LOOK_DOWN, yfov=1.2)
    return s


def small_emitter(albedo=FURNACE_ALBEDO):
    """A 2 cm emissive cube 1 m above the floor of a closed room. With `albedo` 0 the room
    reflects nothing, so a path tracer's image is the cube's light alone: what VXGI's one
    bounce of it should match."""
    s, _ = furnace_room("dark room of albedo %g lit only by a 2 cm emissive cube" % albedo, emission=None,
                        albedo=albedo)
    glow = s.material("Glow", (0.0, 0.0, 0.0), emissive=(1.0, 1.0, 1.0), emissive_strength=SMALL_EMITTER_RADIANCE,
                      extras=VOXELIZE_FLAG)
    s.object("Emitter", Geometry().box((SMALL_EMITTER_SIZE,) * 3), glow, (0, SMALL_EMITTER_HEIGHT, 0))
    # Looking down past the emitter at the floor under it.
    s.camera("Down", (0.3, ROOM_SIZE * 0.9, 0), LOOK_DOWN, yfov=1.2)
    return s


def degenerate_geometry():
    """The white furnace with a mesh of degenerate triangles and zero normals inside."""
    s, wall = furnace_room("white furnace with degenerate triangles and zero normals inside")
    g = Geometry()
    # A well-shaped quad whose normals are all zero: the loader must recompute them.
    g.quad((0.3, 0.8, 0.2), (0.2, 0, 0), (0, 0.2, 0))
    for i in range(len(g.normals)):
        g.normals[i] = (0.0, 0.0, 0.0)
    base = len(g.positions)
    # Zero-area triangles: repeated corners and collinear corners.
    g.positions += [(0.0, 1.0, 0.0), (0.0, 1.0, 0.0), (0.1, 1.0, 0.0), (0.2, 1.0, 0.0), (0.4, 1.0, 0.0)]
    g.normals += [(0.0, 1.0, 0.0)] * 5
    g.indices += [base, base + 1, base + 2, base + 2, base + 3, base + 4]
    s.object("Degenerate", g, wall)
    s.camera("Centre", (0, ROOM_SIZE / 2, 0), yfov=1.2)
    return s


def tiny_scene():
    """A 10 cm floor tile with a 4 cm box and a point light, all inside one 1 m voxel."""
    s = GltfScene("a 10 cm scene: floor tile, box, point light; within one voxel of 1 m")
    gray = s.material("Gray", (0.5,) * 3, extras=VOXELIZE_FLAG)
    h = TINY_SCENE_SIZE / 2
    c = (0.5, 0.5, 0.5)
    s.object("Tile", Geometry().quad(c, (0, 0, h), (h, 0, 0)), gray)
    s.object("Box", Geometry().box((0.04,) * 3), gray, (c[0], c[1] + 0.02, c[2]))
    # Beside the box, low: its +x face is lit and throws light back onto the tile.
    s.light("Bulb", "point", 0.01, (c[0] + 0.045, c[1] + 0.03, c[2]), extras=INDIRECT_LIGHT_FLAG)
    s.camera("Top", (c[0], c[1] + 0.12, c[2]), LOOK_DOWN, yfov=1.0)
    return s


def lit_floor_and_wall():
    """A sunlit floor and a wall standing on it that the sun does not reach: the wall's one
    bounce is the floor's radiance times the floor's view factor, an integral with a closed
    form along the wall (vxgi_render_test.cpp)."""
    s = GltfScene("30 m floor lit straight from above, an unlit 8 m wall across it")
    gray = s.material("Gray", (LIT_FLOOR_ALBEDO,) * 3, extras=VOXELIZE_FLAG)
    f, h = LIT_FLOOR_SIZE, LIT_FLOOR_WALL_HEIGHT
    s.object("Floor", Geometry().box((f, 0.2, f)), gray, (0, -0.1, 0))
    s.object("Wall", Geometry().box((f, h, 0.2)), gray, (0, h / 2, 0))
    s.light("Sun", "directional", LIT_FLOOR_IRRADIANCE, (0, 10, 5), LOOK_DOWN, extras=INDIRECT_LIGHT_FLAG)
    s.camera("Main", LIT_FLOOR_CAMERA, None, LIT_FLOOR_CAMERA_YFOV)
    return s


def x_rotation(degrees):
    """A glTF quaternion [x, y, z, w] turning by `degrees` about +x (negative tilts -z down)."""
    half = math.radians(degrees) / 2
    return [math.sin(half), 0.0, 0.0, math.cos(half)]


def sunlit_room(thickness=SUNLIT_WALL_THICKNESS, window_x=0, look_at_window=False,
                sun_elevation=SUNLIT_SUN_ELEVATION_DEGREES):
    """A closed room lit only by the sun through a window in the +z wall: the light enters
    as a patch on the floor and reaches the rest by bouncing; the sunlit outer faces (the
    window wall's and the roof's) must not leak in. `window_x` moves the opening along x;
    `look_at_window` puts the camera in the back of the room, facing the window wall;
    `sun_elevation` (degrees) moves the patch: a higher sun puts it nearer the window wall."""
    t = thickness
    note = "closed room, %g cm walls, lit only by the sun through a window in the +z wall" % round(t * 100, 3)
    if window_x:
        note += ", the window %g m off centre" % window_x
    if sun_elevation != SUNLIT_SUN_ELEVATION_DEGREES:
        note += ", the sun %g degrees high" % sun_elevation
    s = GltfScene(note)
    wall = s.material("Wall", (SUNLIT_ALBEDO,) * 3, extras=VOXELIZE_FLAG)
    w, h, d = SUNLIT_ROOM_SIZE
    ww, wh, sill = SUNLIT_WINDOW
    hx, hz = w / 2, d / 2
    s.object("Floor", Geometry().box((w + 2 * t, t, d + 2 * t)), wall, (0, -t / 2, 0))
    s.object("Ceiling", Geometry().box((w + 2 * t, t, d + 2 * t)), wall, (0, h + t / 2, 0))
    s.object("Back", Geometry().box((w, h, t)), wall, (0, h / 2, -hz - t / 2))
    s.object("Left", Geometry().box((t, h, d + 2 * t)), wall, (-hx - t / 2, h / 2, 0))
    s.object("Right", Geometry().box((t, h, d + 2 * t)), wall, (hx + t / 2, h / 2, 0))
    # The window wall in four pieces around the opening (x in window_x +- ww / 2).
    z = hz + t / 2
    left, right = window_x - ww / 2 + hx, hx - (window_x + ww / 2)  # widths beside the opening
    s.object("FrontLeft", Geometry().box((left, h, t)), wall, (-hx + left / 2, h / 2, z))
    s.object("FrontRight", Geometry().box((right, h, t)), wall, (hx - right / 2, h / 2, z))
    s.object("BelowWindow", Geometry().box((ww, sill, t)), wall, (window_x, sill / 2, z))
    top = h - sill - wh
    s.object("AboveWindow", Geometry().box((ww, top, t)), wall, (window_x, sill + wh + top / 2, z))
    s.light("Sun", "directional", SUNLIT_SUN_IRRADIANCE, (0, h + 2, hz + 3),
            x_rotation(-sun_elevation), extras=INDIRECT_LIGHT_FLAG)
    if look_at_window:
        # From the back of the room, turned round and tilted down (the quaternion product
        # y(180) x(tilt)): the window wall, the floor in front of it with the sun patch, and
        # both side walls.
        half = math.radians(SUNLIT_BACK_CAMERA_TILT_DEGREES) / 2
        s.camera("Back", (0, 1.6, -hz + 0.2), [0.0, math.cos(half), -math.sin(half), 0.0], yfov=1.2)
    else:
        s.camera("Inside", (0, 1.6, hz - 0.2), x_rotation(-20.0), yfov=1.2)
    return s


def sunlit_room_air_volume():
    """The sunlit room with a DDGI probe volume fitted to its air, not to its walls: the
    walls lie half a cell outside the outermost probes, where the bounce must not be lost."""
    s = sunlit_room()
    w, h, d = SUNLIT_ROOM_SIZE
    s.node("ProbeVolume", (0, h / 2, 0), scale_=(w / 2, h / 2, d / 2),
           extras={"DDGIVolume": {"ProbeCounts": [5, 3, 5]}})
    return s


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(repo, "content"), help="content folder to write into")
    out = parser.parse_args().out
    tests = os.path.join(out, "tests")
    cornell_box(flagged=True).write(os.path.join(out, "cornell_box.gltf"))
    lambert_plane_directional().write(os.path.join(tests, "lambert_plane_directional.gltf"))
    lambert_plane_point(occluded=False).write(os.path.join(tests, "lambert_plane_point.gltf"))
    lambert_plane_point(occluded=True).write(os.path.join(tests, "shadowed_plane_point.gltf"))
    masked_occluder_point().write(os.path.join(tests, "masked_occluder_point.gltf"))
    emissive_quad().write(os.path.join(tests, "emissive_quad.gltf"))
    white_furnace().write(os.path.join(tests, "white_furnace.gltf"))
    glossy_furnace().write(os.path.join(tests, "glossy_furnace.gltf"))
    two_rooms_thin_wall().write(os.path.join(tests, "two_rooms_thin_wall.gltf"))
    cornell_box(flagged=False).write(os.path.join(tests, "no_flagged_materials.gltf"))
    hdr_emitter().write(os.path.join(tests, "hdr_emitter.gltf"))
    small_emitter().write(os.path.join(tests, "small_emitter.gltf"))
    small_emitter(albedo=0.0).write(os.path.join(tests, "small_emitter_black_room.gltf"))
    degenerate_geometry().write(os.path.join(tests, "degenerate_geometry.gltf"))
    tiny_scene().write(os.path.join(tests, "tiny_scene.gltf"))
    sunlit_room().write(os.path.join(tests, "sunlit_room.gltf"))
    sunlit_room_air_volume().write(os.path.join(tests, "sunlit_room_air_volume.gltf"))
    sunlit_room(look_at_window=True).write(os.path.join(tests, "sunlit_room_window_view.gltf"))
    sunlit_room(SUNLIT_THIN_WALL_THICKNESS, look_at_window=True).write(
        os.path.join(tests, "sunlit_room_10cm_window_view.gltf"))
    sunlit_room(SUNLIT_THIN_WALL_THICKNESS).write(os.path.join(tests, "sunlit_room_10cm.gltf"))
    sunlit_room(SUNLIT_THIN_WALL_THICKNESS, window_x=SUNLIT_WINDOW_OFFSET, look_at_window=True).write(
        os.path.join(tests, "sunlit_room_10cm_offset_window.gltf"))
    sunlit_room(look_at_window=True, sun_elevation=SUNLIT_HIGH_SUN_ELEVATION_DEGREES).write(
        os.path.join(tests, "sunlit_room_high_sun_window_view.gltf"))
    lit_floor_and_wall().write(os.path.join(tests, "lit_floor_and_wall.gltf"))


if __name__ == "__main__":
    main()
