#!/usr/bin/env python3
"""Writes model.glb, the glTF 2.0 file of the gltf_scene example (Python 3 standard library only).

The file holds: a grey floor; a checker-textured cube; one sphere mesh instanced by three nodes under
a rotated, translated parent ("trio"), each with its own material (gold metal, red plastic, glossy
white); an alpha-masked panel with round holes; a perspective camera; and two KHR_lights_punctual lights, a point light and a dim sun. Run it from any folder:
`python3 examples/gltf_scene/make_model.py` rewrites examples/gltf_scene/model.glb.
"""

import json
import math
import os
import struct
import zlib


class Buffer:
    """One binary buffer with its buffer views and accessors."""

    def __init__(self):
        self.bin = bytearray()
        self.views = []
        self.accessors = []

    def view(self, data):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)})
        self.bin += data
        return len(self.views) - 1

    def floats(self, rows, kind, bounds=False):
        flat = [x for row in rows for x in row]
        acc = {"bufferView": self.view(struct.pack(f"<{len(flat)}f", *flat)),
               "componentType": 5126, "count": len(rows), "type": kind}
        if bounds:
            acc["min"] = [min(r[i] for r in rows) for i in range(len(rows[0]))]
            acc["max"] = [max(r[i] for r in rows) for i in range(len(rows[0]))]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def indices(self, tris):
        flat = [i for t in tris for i in t]
        self.accessors.append({"bufferView": self.view(struct.pack(f"<{len(flat)}H", *flat)),
                               "componentType": 5123, "count": len(flat), "type": "SCALAR"})
        return len(self.accessors) - 1

    def mesh(self, name, positions, normals, uvs, tris, material):
        prim = {"attributes": {"POSITION": self.floats(positions, "VEC3", True),
                               "NORMAL": self.floats(normals, "VEC3"),
                               "TEXCOORD_0": self.floats(uvs, "VEC2")},
                "indices": self.indices(tris), "material": material}
        return {"name": name, "primitives": [prim]}


def box():
    """The cube [-1, 1]^3, four vertices per face, outward normals, uv [0, 1]^2 per face."""
    positions, normals, uvs, tris = [], [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            base = len(positions)
            for (u, v) in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u_axis], p[v_axis] = sign, u, v
                positions.append(p)
                normals.append(n)
                uvs.append([(u + 1) / 2, (1 - v) / 2])
            quad = [(base, base + 1, base + 2), (base, base + 2, base + 3)]
            if sign < 0:  # keep counter-clockwise seen from outside
                quad = [(a, c, b) for (a, b, c) in quad]
            tris += quad
    return positions, normals, uvs, tris


def sphere(rings=16, segments=32):
    """A unit uv sphere."""
    positions, normals, uvs, tris = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
            positions.append(n)
            normals.append(n)
            uvs.append([s / segments, r / rings])
    row = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b = r * row + s, (r + 1) * row + s
            if r > 0:
                tris.append((a, b, a + 1))
            if r < rings - 1:
                tris.append((a + 1, b, b + 1))
    return positions, normals, uvs, tris


def floor():
    """The square [-1, 1]^2 in the xz-plane, normal +y."""
    positions = [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]
    return positions, [[0, 1, 0]] * 4, [[0, 0], [0, 1], [1, 1], [1, 0]], [(0, 1, 2), (0, 2, 3)]


def checker_png(size=64, cells=8):
    """An RGB PNG of a blue/cream checkerboard."""
    rows = bytearray()
    for y in range(size):
        rows.append(0)
        for x in range(size):
            dark = ((x * cells // size) + (y * cells // size)) % 2
            rows += bytes((40, 70, 160) if dark else (235, 225, 200))
    return png(size, 2, rows)


def lattice_png(size=64, cells=6):
    """An RGBA PNG of a green panel with round holes (alpha 0) on a grid, for alpha masking."""
    rows = bytearray()
    for y in range(size):
        rows.append(0)
        for x in range(size):
            u, v = (x + 0.5) * cells / size % 1.0 - 0.5, (y + 0.5) * cells / size % 1.0 - 0.5
            hole = u * u + v * v < 0.33 ** 2
            rows += bytes((70, 150, 80, 0 if hole else 255))
    return png(size, 6, rows)


def png(size, color_type, rows):
    """A PNG of `size` x `size` 8-bit pixels from filtered scanlines."""

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    header = struct.pack(">IIBBBBB", size, size, 8, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def quat_y(deg):
    half = math.radians(deg) / 2
    return [0.0, math.sin(half), 0.0, math.cos(half)]


def main():
    b = Buffer()
    image_view = b.view(checker_png())
    lattice_view = b.view(lattice_png())
    materials = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1],
                                                    "metallicFactor": 0.0, "roughnessFactor": 0.9}},
        {"name": "checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                      "metallicFactor": 0.0, "roughnessFactor": 0.6}},
        {"name": "gold", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.78, 0.34, 1],
                                                   "metallicFactor": 1.0, "roughnessFactor": 0.5}},
        {"name": "red plastic", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.08, 0.06, 1],
                                                          "metallicFactor": 0.0, "roughnessFactor": 0.3}},
        {"name": "glossy white", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1],
                                                           "metallicFactor": 0.0, "roughnessFactor": 0.15},
         "emissiveFactor": [0.0, 0.0, 0.0]},
        {"name": "lattice", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}, "metallicFactor": 0.0,
                                  "roughnessFactor": 0.8}},
    ]
    # glTF binds a material to a primitive, so each sphere colour is its own mesh sharing the
    # same accessors: the three spheres are three meshes over one set of vertex data.
    sphere_mesh = b.mesh("sphere", *sphere(), 2)
    sphere_prim = sphere_mesh["primitives"][0]
    meshes = [
        b.mesh("floor", *floor(), 0),
        b.mesh("cube", *box(), 1),
        sphere_mesh,
        {"name": "sphere red", "primitives": [dict(sphere_prim, material=3)]},
        {"name": "sphere white", "primitives": [dict(sphere_prim, material=4)]},
    ]
    meshes.append({"name": "lattice", "primitives": [dict(meshes[0]["primitives"][0], material=5)]})
    nodes = [
        {"name": "floor", "mesh": 0, "scale": [6, 1, 6]},
        {"name": "cube", "mesh": 1, "translation": [-1.3, 0.6, 0.2], "rotation": quat_y(30),
         "scale": [0.6, 0.6, 0.6]},
        {"name": "trio", "translation": [1.0, 0.0, -0.2], "rotation": quat_y(-20),
         "children": [3, 4, 5, 6]},
        {"name": "gold ball", "mesh": 2, "translation": [0.0, 0.55, 0.0], "scale": [0.55, 0.55, 0.55]},
        {"name": "red ball", "mesh": 3, "translation": [0.9, 0.35, 0.9], "scale": [0.35, 0.35, 0.35]},
        {"name": "white ball", "mesh": 4, "translation": [-0.4, 0.3, 1.2], "scale": [0.3, 0.3, 0.3]},
        {"name": "small gold ball", "mesh": 2, "translation": [0.8, 0.2, -0.8],
         "scale": [0.2, 0.2, 0.2]},
        {"name": "camera", "camera": 0, "translation": [0.0, 2.2, 6.0],
         "rotation": [-0.1305262, 0.0, 0.0, 0.9914449]},  # 15 degrees down
        {"name": "key light", "translation": [-2.0, 4.5, 3.0],
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        # A cut-out panel: the floor square stood up (normal toward the camera), alpha-masked.
        {"name": "lattice panel", "mesh": 5, "translation": [-0.2, 1.0, -2.0],
         "rotation": [0.7071068, 0.0, 0.0, 0.7071068], "scale": [1.1, 1.0, 0.95]},
        # The sun: its -z points down, away from the camera and a little to the left.
        {"name": "sun", "rotation": [-0.4082483, 0.2705981, 0.1247566, 0.8627299],
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
    ]
    doc = {
        "asset": {"version": "2.0", "generator": "examples/gltf_scene/make_model.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "key", "type": "point", "color": [1.0, 0.95, 0.9], "intensity": 50.0},
            {"name": "sun", "type": "directional", "color": [0.8, 0.85, 1.0], "intensity": 0.8}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 7, 8, 9, 10]}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "textures": [{"source": 0}, {"source": 1}],
        "images": [{"bufferView": image_view, "mimeType": "image/png"},
                   {"bufferView": lattice_view, "mimeType": "image/png"}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}],
        "buffers": [{"byteLength": 0}],
    }
    while len(b.bin) % 4:
        b.bin.append(0)
    doc["buffers"][0]["byteLength"] = len(b.bin)
    doc["bufferViews"] = b.views
    doc["accessors"] = b.accessors
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = (struct.pack("<I", len(text)) + b"JSON" + text
            + struct.pack("<I", len(b.bin)) + b"BIN\x00" + bytes(b.bin))
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "model.glb")
    with open(out, "wb") as f:
        f.write(b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body)
    print(f"wrote {out} ({12 + len(body)} bytes)")


if __name__ == "__main__":
    main()
