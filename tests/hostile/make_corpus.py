#!/usr/bin/env python3
"""Writes the hostile-input corpus (tests/hostile/cases/) and, with --generated DIR, the
large cases that are made at test time instead of being checked in.

  python3 tests/hostile/make_corpus.py             # rewrite the checked-in files
  python3 tests/hostile/make_corpus.py --generated DIR   # big ini, 1 MB key, deep nodes

Every scene is one small quad facing +Z, seen by a camera on +Z, lit by one light; each
case breaks one thing. manifest.txt says what bounce-render must do with each.
"""
import base64
import json
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "cases")


def quad_buffer(positions=None):
    """Positions, normals and indices of a 1 m quad at z=0 facing +Z."""
    if positions is None:
        positions = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    normals = [(0, 0, 1)] * 4
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<3f", *n) for n in normals)
    data += struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    return data


def scene(camera=None, camera_node=None, light=None, light_node=None, extra_nodes=(), material=None,
          positions=None, asset=None, accessors=None, extras=None):
    data = quad_buffer(positions)
    doc = {
        "asset": asset or {"version": "2.0", "generator": "tests/hostile/make_corpus.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2] + [3 + i for i in range(len(extra_nodes))]}],
        "nodes": [
            {"name": "Quad", "mesh": 0},
            dict({"name": "Cam", "translation": [0, 0, 2], "camera": 0}, **(camera_node or {})),
            dict({"name": "Light", "translation": [0, 0, 1],
                  "extensions": {"KHR_lights_punctual": {"light": 0}}}, **(light_node or {})),
        ] + list(extra_nodes),
        "meshes": [{"name": "Quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1},
                                                    "indices": 2, "material": 0}]}],
        "materials": [material or {"name": "Gray", "pbrMetallicRoughness": {
            "baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 1}}],
        "accessors": accessors or [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "cameras": [dict({"name": "Cam", "type": "perspective",
                          "perspective": {"yfov": 0.8, "znear": 0.05, "zfar": 100}}, **(camera or {}))],
        "extensions": {"KHR_lights_punctual": {"lights": [light or {
            "name": "Light", "type": "point", "color": [1, 1, 1], "intensity": 5}]}},
        "extensionsUsed": ["KHR_lights_punctual"],
    }
    if extras is not None:
        doc["asset"]["extras"] = extras
    return doc


def write_json(name, doc):
    with open(os.path.join(CASES, name), "w") as f:
        json.dump(doc, f, indent=1, allow_nan=True)
        f.write("\n")


def write_text(name, text, mode="w"):
    with open(os.path.join(CASES, name), mode) as f:
        f.write(text)


def perspective(**p):
    base = {"yfov": 0.8, "znear": 0.05, "zfar": 100}
    base.update(p)
    return {"perspective": base}


def pp_volume(settings):
    return {"name": "Volume", "extras": {"PostProcessVolume": {"Unbound": True, "Settings": settings}}}


def checked_in():
    os.makedirs(CASES, exist_ok=True)
    write_json("valid.gltf", scene())
    # Item 1: camera ranges.
    for z in ("1e19", "1e30", "1e37"):
        write_json(f"camera_znear_{z}.gltf", scene(camera=perspective(znear=float(z), zfar=float(z) * 10)))
    write_json("camera_znear_infinite_far.gltf", scene(camera={"perspective": {"yfov": 0.8, "znear": 1e30}}))
    write_json("camera_znear_beyond_zfar.gltf", scene(camera=perspective(znear=10, zfar=1)))
    write_json("camera_yfov_zero.gltf", scene(camera=perspective(yfov=0.0)))
    # Item 4: directional light with no rotation (glTF's default, along -Z).
    write_json("directional_no_rotation.gltf",
               scene(light={"name": "Sun", "type": "directional", "intensity": 2}, light_node={"translation": [0, 0, 0]}))
    # Item 5: huge and zero scales.
    write_json("node_scale_1e30.gltf", scene(extra_nodes=[{"name": "Huge", "mesh": 0, "scale": [1e30, 1e30, 1e30]}]))
    write_json("camera_scale_0.gltf", scene(camera={"name": "FlatCam"}, camera_node={"name": "FlatCam", "scale": [0, 0, 0]}))
    write_json("camera_at_1e30.gltf", scene(camera={"name": "FarCam"}, camera_node={"name": "FarCam", "translation": [0, 0, 1e30]}))
    # Item 6: post-process-volume values.
    write_json("pp_sparsity_0.gltf", scene(extra_nodes=[pp_volume({"VxgiDiffuseSparsity": 0})]))
    write_json("pp_sparsity_3.gltf", scene(extra_nodes=[pp_volume({"VxgiDiffuseSparsity": 3})]))
    write_json("pp_cones_3e9.gltf", scene(extra_nodes=[pp_volume({"VxgiDiffuseCones": 3e9})]))
    write_json("pp_nan_string.gltf", scene(extra_nodes=[pp_volume({"VxgiDiffuseCones": "nan"})]))
    # Item 8: huge but finite values, glTF-invalid values.
    write_json("light_1e30.gltf", scene(light={"name": "BrightLight", "type": "point", "intensity": 1e30},
                                        light_node={"name": "BrightLight"}))
    write_json("emissive_1e9.gltf", scene(material={
        "name": "Glow", "emissiveFactor": [1, 1, 1],
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e9}}}))
    write_json("light_range_0.gltf", scene(light={"name": "Light", "type": "point", "intensity": 5, "range": 0}))
    write_json("asset_version_3.gltf", scene(asset={"version": "3.0"}))
    # Item 10: light units as Blender 3.4 exports them (candela, lux).
    write_json("lights_candela.gltf", scene(light={"name": "Light", "type": "point", "intensity": 27176}))
    write_json("lights_lux_sun.gltf", scene(light={"name": "Sun", "type": "directional", "intensity": 1366},
                                            light_node={"rotation": [0, 0.2588, 0, 0.9659]}))
    write_json("lights_radiometric.gltf", scene(light={"name": "Light", "type": "point", "intensity": 40},
                                                extras={"BounceLightUnits": "radiometric"}))
    # Probe classes: accessors.
    good = scene()["accessors"]
    truncated = [dict(good[0], count=4000)] + good[1:]
    write_json("accessor_truncated.gltf", scene(accessors=truncated))
    overflow = [dict(good[0], count=2**31, byteOffset=2**62)] + good[1:]
    write_json("accessor_overflow.gltf", scene(accessors=overflow))
    write_json("accessor_negative_count.gltf", scene(accessors=[dict(good[0], count=-1)] + good[1:]))
    write_json("index_out_of_range.gltf", scene(accessors=good[:2] + [dict(good[2], count=6)]) | {
        "buffers": [{"byteLength": 108, "uri": "data:application/octet-stream;base64," + base64.b64encode(
            quad_buffer()[:96] + struct.pack("<6H", 0, 1, 60000, 0, 2, 3)).decode()}]})
    # NaN / Inf geometry (JSON has no NaN: the floats are in the buffer).
    nan = float("nan")
    inf = float("inf")
    write_json("geometry_nan.gltf", scene(positions=[(nan, 0, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]))
    write_json("geometry_inf.gltf", scene(positions=[(inf, -inf, 0), (0.5, -0.5, 0), (0.5, 0.5, inf), (-0.5, 0.5, 0)]))
    write_json("geometry_huge.gltf", scene(positions=[(-3e38, -3e38, 0), (3e38, -3e38, 0), (3e38, 3e38, 0), (-3e38, 3e38, 0)]))
    # Hierarchy: cycles, self-parenting, out-of-range references.
    cyc = scene(extra_nodes=[{"name": "A", "children": [4]}, {"name": "B", "children": [3]}])
    write_json("node_cycle.gltf", cyc)
    write_json("node_self_child.gltf", scene(extra_nodes=[{"name": "Self", "children": [3]}]))
    write_json("node_two_parents.gltf", scene(extra_nodes=[{"name": "P1", "children": [5]}, {"name": "P2", "children": [5]},
                                                          {"name": "Kid", "mesh": 0}]))
    write_json("mesh_index_out_of_range.gltf", scene(extra_nodes=[{"name": "Bad", "mesh": 99}]))
    write_json("material_index_out_of_range.gltf", scene() | {"meshes": [{"primitives": [
        {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 7}]}]})
    write_json("buffer_missing_file.gltf", scene() | {"buffers": [{"byteLength": 108, "uri": "does-not-exist.bin"}]})
    write_json("buffer_uri_escape.gltf", scene() | {"buffers": [{"byteLength": 108, "uri": "../../../../../../dev/zero"}]})
    # Not glTF at all.
    write_text("empty.gltf", "")
    write_text("truncated.gltf", json.dumps(scene())[:700])
    write_text("garbage.glb", "glTF\x02\x00\x00\x00\xff\xff\xff\xff" + "\x00" * 20, mode="w")
    # Ini files with bad values (item 7). Every value below must be refused.
    bad = {"nan": "r.Shadow.DepthBias=nan", "inf": "r.Shadow.DepthBias=inf", "1e400": "r.Shadow.DepthBias=1e400",
           "negative_size": "r.Shadow.MapSize=-1", "text_for_int": "r.Shadow.MapSize=lots"}
    for name, line in bad.items():
        write_text(f"ini_bad_{name}.ini", f"[SystemSettings]\n{line}\n")
    write_text("ini_bad_nul.ini", "[SystemSettings]\nr.Shadow.MapSize=5\x0012\n")
    write_text("ini_bad_material_defaults.ini", "[MaterialDefaults]\nUsedWithVxgiVoxelization=perhaps\n")
    write_text("ini_control_bytes.ini", "[SystemSettings]\nr.Shadow.MapSize=\x1b[31mred\x1b[0m\n")
    # Issue 45: a DDGIVolume of a billion probes (its atlases alone 1.3 TiB): refused as
    # device memory it would need, naming the setting.
    write_json("ddgi_probe_counts_1e9.gltf", scene(extra_nodes=[
        {"name": "Billion", "extras": {"DDGIVolume": {"ProbeCounts": [1000, 1000, 1000]}}}]))
    # Broken plugins: a folder of each, found through BOUNCE_PLUGIN_PATH.
    plugins = {
        "bad_json": ("BadJson", '{"Name": "BadJson", "EngineApiVersion": '),
        "missing_library": ("MissingLib", json.dumps({"Name": "MissingLib", "EngineApiVersion": 3,
                                                      "Library": "bounce_missing_lib", "EnabledByDefault": False})),
        "wrong_api": ("WrongApi", json.dumps({"Name": "WrongApi", "EngineApiVersion": 999,
                                              "Library": "bounce_wrong_api", "EnabledByDefault": False})),
        "not_a_library": ("NotALib", json.dumps({"Name": "NotALib", "EngineApiVersion": 3,
                                                 "Library": "bounce_not_a_lib", "EnabledByDefault": False})),
    }
    for folder, (name, text) in plugins.items():
        d = os.path.join(CASES, "plugins", folder, name)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, name + ".bplugin"), "w") as f:
            f.write(text + "\n")
    with open(os.path.join(CASES, "plugins", "not_a_library", "NotALib", "libbounce_not_a_lib.so"), "w") as f:
        f.write("this is not an ELF file\n")


def generated(out):
    """Large cases, made at test time (see manifest.txt)."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "ini_200000_sections.ini"), "w") as f:
        for i in range(200000):
            f.write(f"[Section{i}]\nKey{i}=1\n")
    with open(os.path.join(out, "ini_1mb_key.ini"), "w") as f:
        f.write("[SystemSettings]\n" + "r." + "x" * (1 << 20) + "=1\n")
    # 100,000 nested nodes: each the only child of the one before.
    doc = scene()
    first = len(doc["nodes"])
    n = 100000
    doc["nodes"] += [{"children": [first + i + 1]} for i in range(n - 1)] + [{"name": "Deepest", "mesh": 0}]
    doc["scenes"][0]["nodes"].append(first)
    with open(os.path.join(out, "deep_hierarchy.gltf"), "w") as f:
        json.dump(doc, f, separators=(",", ":"))
    # Many point lights above the quad (issue 45): each 1/N of the one light's intensity.
    for n in (100, 1000):
        doc = scene()
        side = int(math.ceil(n ** (1.0 / 3.0)))
        lights = doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights[0]["intensity"] = 5.0 / n
        for i in range(1, n):
            x, y, z = i % side, (i // side) % side, i // (side * side)
            lights.append({"name": f"Light{i}", "type": "point", "color": [1, 1, 1], "intensity": 5.0 / n})
            doc["nodes"].append({"name": f"Light{i}", "translation": [-0.4 + 0.8 * x / side, -0.4 + 0.8 * y / side,
                                                                      0.2 + 0.8 * z / side],
                                 "extensions": {"KHR_lights_punctual": {"light": i}}})
            doc["scenes"][0]["nodes"].append(len(doc["nodes"]) - 1)
        with open(os.path.join(out, f"lights_{n}.gltf"), "w") as f:
            json.dump(doc, f, separators=(",", ":"))
    # JSON nested 100,000 deep (parsers that recurse overflow the stack).
    with open(os.path.join(out, "json_deep_nesting.gltf"), "w") as f:
        f.write('{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000 + "}")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--generated":
        generated(sys.argv[2])
    elif len(sys.argv) == 1:
        checked_in()
    else:
        sys.exit(__doc__)
