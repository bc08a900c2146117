#!/usr/bin/env python3
"""Writes the visual-mesh test assets in tests/assets/ (run from anywhere; output is deterministic).

- textured_box.gltf: a 0.6 m box whose glTF material has a baseColorTexture embedded as a data URI
  (quadrants red, green, blue, yellow with a white frame, so orientation and mapping show) and a
  baseColorFactor; its node sits under a parent node raised 0.1 m, so the box spans z -0.2 .. 0.4 in the file.
- mtl_box.obj + .mtl + stripes.png: a 0.6 m box with three materials: sides striped by a map_Kd
  file beside it, the top blue (Kd), the bottom grey.
- torus.obj: a torus (R = 0.45 m, r = 0.15 m) with smooth normals (vn) and no material: not convex,
  its hole shows what is under it (its collision piece is its hull, a disc).
- bad_texture.obj + .mtl + not_an_image.png: a box whose map_Kd file is text, not an image.
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) gives (r, g, b) with y = 0 the top row."""
    raw = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def quadrants(x, y, n=32):
    if x < 2 or y < 2 or x >= n - 2 or y >= n - 2:
        return (255, 255, 255)
    top, left = y < n // 2, x < n // 2
    return {(True, True): (220, 30, 30), (True, False): (30, 180, 40),
            (False, True): (30, 60, 220), (False, False): (240, 210, 30)}[(top, left)]


def stripes(x, y):
    return (245, 245, 240) if (x // 4) % 2 == 0 else (200, 60, 20)


def box_faces(h):
    """(normal, 4 corners counter-clockwise from outside, uv per corner) for the 6 faces."""
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u = [0, 0, 0]
            u[(axis + 1) % 3] = 1
            v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
            c = [n[i] * h for i in range(3)]
            corner = lambda a, b: [c[i] + a * h * u[i] + b * h * v[i] for i in range(3)]
            faces.append((n, [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)],
                          [(0, 0), (1, 0), (1, 1), (0, 1)]))
    return faces


def write_gltf():
    pos, nor, uv, idx = [], [], [], []
    for n, corners, uvs in box_faces(0.3):
        base = len(pos)
        for p, t in zip(corners, uvs):
            pos.append(p)
            nor.append(n)
            uv.append((t[0], 1 - t[1]))   # glTF: v = 0 at the image's top
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    blob = b"".join(struct.pack("<3f", *p) for p in pos) + b"".join(struct.pack("<3f", *n) for n in nor) + \
        b"".join(struct.pack("<2f", *t) for t in uv) + b"".join(struct.pack("<H", i) for i in idx)
    n = len(pos)
    views = [(0, 12 * n), (12 * n, 12 * n), (24 * n, 8 * n), (32 * n, 2 * len(idx))]
    doc = {
        "asset": {"version": "2.0", "generator": "tumble tests/assets/make_visual_assets.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Offset", "translation": [0, 0, 0.1], "children": [1]},
                  {"name": "Box", "mesh": 0}],
        "meshes": [{"name": "Box", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                   "indices": 3, "material": 0}]}],
        "materials": [{"name": "Quadrants", "pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 0.9, 0.9, 1.0], "baseColorTexture": {"index": 0},
            "metallicFactor": 0.0}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png(32, 32, quadrants)).decode()}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": l} for o, l in views],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
             "min": [-0.3, -0.3, -0.3], "max": [0.3, 0.3, 0.3]},
            {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": n, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(idx), "type": "SCALAR"}],
    }
    with open(os.path.join(HERE, "textured_box.gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def write_box_obj(name, materials, comment):
    """A box whose faces use materials[face kind]: 'side', 'top' or 'bottom'."""
    lines = ["# " + comment, "mtllib %s.mtl" % name, "o %s" % name]
    faces = box_faces(0.3)
    for _, corners, _ in faces:
        lines += ["v %g %g %g" % tuple(p) for p in corners]
    lines += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1"]
    for k, (n, _, _) in enumerate(faces):
        kind = "top" if n[2] == 1 else "bottom" if n[2] == -1 else "side"
        lines.append("usemtl %s" % materials[kind])
        b = 4 * k + 1
        lines.append("f %d/1 %d/2 %d/3 %d/4" % (b, b + 1, b + 2, b + 3))
    with open(os.path.join(HERE, name + ".obj"), "w") as f:
        f.write("\n".join(lines) + "\n")


def write_mtl_box():
    write_box_obj("mtl_box", {"side": "Striped", "top": "Blue", "bottom": "Grey"},
                  "A 0.6 m box: striped sides (map_Kd), blue top, grey bottom (Kd)")
    with open(os.path.join(HERE, "mtl_box.mtl"), "w") as f:
        f.write("newmtl Striped\nKd 1 1 1\nmap_Kd stripes.png\n\nnewmtl Blue\nKd 0.05 0.2 0.8\n\n"
                "newmtl Grey\nKd 0.3 0.3 0.3\n")
    with open(os.path.join(HERE, "stripes.png"), "wb") as f:
        f.write(png(32, 32, stripes))


def write_bad_texture():
    write_box_obj("bad_texture", {"side": "Broken", "top": "Broken", "bottom": "Broken"},
                  "A 0.6 m box whose texture file is not an image")
    with open(os.path.join(HERE, "bad_texture.mtl"), "w") as f:
        f.write("newmtl Broken\nKd 0.2 0.7 0.3\nmap_Kd not_an_image.png\n")
    with open(os.path.join(HERE, "not_an_image.png"), "w") as f:
        f.write("this is text, not a PNG\n")


def write_torus(big=0.45, small=0.15, around=20, tube=10):
    lines = ["# A torus about z: R = %g m, r = %g m, smooth normals; no material" % (big, small), "o Torus"]
    for i in range(around):
        a = 2 * math.pi * i / around
        for j in range(tube):
            b = 2 * math.pi * j / tube
            n = (math.cos(b) * math.cos(a), math.cos(b) * math.sin(a), math.sin(b))
            p = ((big + small * math.cos(b)) * math.cos(a), (big + small * math.cos(b)) * math.sin(a), small * math.sin(b))
            lines.append("v %.6f %.6f %.6f" % p)
            lines.append("vn %.6f %.6f %.6f" % n)
    k = lambda i, j: (i % around) * tube + (j % tube) + 1
    for i in range(around):
        for j in range(tube):
            a, b, c, d = k(i, j), k(i + 1, j), k(i + 1, j + 1), k(i, j + 1)
            lines.append("f %d//%d %d//%d %d//%d %d//%d" % (a, a, b, b, c, c, d, d))
    with open(os.path.join(HERE, "torus.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")


write_gltf()
write_mtl_box()
write_bad_texture()
write_torus()
