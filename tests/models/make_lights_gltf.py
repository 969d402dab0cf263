#!/usr/bin/env python3
"""make_lights_gltf.py - writes tests/models/lights.gltf, the course's own glTF 2.0 test scene for the
`model` directive: a node hierarchy, two metallic-roughness materials (one textured, one blended),
an embedded PNG and buffer (data URIs), and KHR_lights_punctual point, spot and directional lights;
and, from the same scene, the broken variants of tests/bad/models/gltf_*.gltf (tests/bad/gltf.expect
says what each breaks). Run it again only to change them: the files it writes are committed.

    /usr/bin/python3 tests/models/make_lights_gltf.py tests/models/lights.gltf tests/bad/models
"""
import base64
import json
import struct
import sys
import zlib


def png_2x2():
    """A 2x2 RGBA PNG: red, green / blue, white."""
    rows = [bytes([0, 255, 0, 0, 255, 0, 255, 0, 255]), bytes([0, 0, 0, 255, 255, 255, 255, 255, 255])]

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"".join(rows))) + \
        chunk(b"IEND", b"")


def png_header(width, height):
    """Only the signature and IHDR of a PNG: enough for a header check, nothing to decode."""
    data = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    ihdr = struct.pack(">I", len(data)) + b"IHDR" + data + struct.pack(">I", zlib.crc32(b"IHDR" + data))
    return b"\x89PNG\r\n\x1a\n" + ihdr


def scene(image_uri):
    # A unit quad in the XY plane facing +Z: positions, normals, UVs, then 16-bit indices.
    pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
    uv = [(0, 1), (1, 1), (1, 0), (0, 0)]
    data = b"".join(struct.pack("<3f", *p) for p in pos)
    data += b"".join(struct.pack("<3f", 0, 0, 1) for _ in pos)
    data += b"".join(struct.pack("<2f", *t) for t in uv)
    data += struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0\0"
    uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    q = 0.7071068  # sin and cos of 45 degrees: a quarter turn about X
    gltf = {
        "asset": {"version": "2.0", "generator": "tests/models/make_lights_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "Bulb", "type": "point", "color": [1.0, 0.9, 0.8], "intensity": 5.0, "range": 10.0},
            {"name": "Spot", "type": "spot", "color": [1.0, 1.0, 1.0], "intensity": 4.0,
             "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}},
            {"name": "Sun", "type": "directional", "color": [1.0, 1.0, 1.0], "intensity": 2.0}]}},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "Root", "translation": [0, 1, 0], "children": [1, 2, 3, 4, 5]},
            {"name": "Floor", "mesh": 0, "rotation": [-q, 0, 0, q], "scale": [4, 4, 4]},
            {"name": "Pane", "mesh": 1, "translation": [0, 0.5, -1]},
            {"name": "Bulb", "translation": [1, 2, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "Spot", "translation": [0, 3, 0], "rotation": [-q, 0, 0, q],
             "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"name": "Sun", "extensions": {"KHR_lights_punctual": {"light": 2}}}],
        "meshes": [
            {"name": "Floor", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                              "indices": 3, "material": 0}]},
            {"name": "Pane", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                             "indices": 3, "material": 1}]}],
        "materials": [
            {"name": "Painted", "emissiveFactor": [0.1, 0.0, 0.0],
             "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0], "metallicFactor": 0.25,
                                      "roughnessFactor": 0.6, "baseColorTexture": {"index": 0}}},
            {"name": "Glass", "alphaMode": "BLEND",
             "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.9, 0.5], "metallicFactor": 0.0,
                                      "roughnessFactor": 0.1}}],
        "textures": [{"source": 0}],
        "images": [{"uri": image_uri}],
        "buffers": [{"byteLength": len(data), "uri": uri}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
            {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    return gltf


def write(path, gltf):
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def main(out, bad):
    png = "data:image/png;base64," + base64.b64encode(png_2x2()).decode()
    write(out, scene(png))
    write(f"{bad}/gltf_texture_missing.gltf", scene("missing.png"))
    write(f"{bad}/gltf_texture_not_image.gltf", scene("gltf_texture_not_image.gltf"))  # itself: JSON
    write(f"{bad}/gltf_texture_absolute.gltf", scene("/etc/hostname.png"))
    write(f"{bad}/gltf_texture_url.gltf", scene("http://example.invalid/a.png"))
    write(f"{bad}/gltf_texture_wide.gltf",
          scene("data:image/png;base64," + base64.b64encode(png_header(16385, 1)).decode()))
    # 70 nodes, each the child of the one before: deeper than model_import.h's MODEL_DEPTH_MAX.
    deep = scene(png)
    deep["nodes"] = [{"name": f"n{i}", "children": [i + 1]} for i in range(70)] + [{"name": "leaf", "mesh": 0}]
    deep["scenes"] = [{"nodes": [0]}]
    write(f"{bad}/gltf_deep_nodes.gltf", deep)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/models/lights.gltf",
         sys.argv[2] if len(sys.argv) > 2 else "tests/bad/models")
