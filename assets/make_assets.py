#!/usr/bin/env python3
"""Writes the small convex meshes in assets/ (run from anywhere; output is deterministic).

Sizes are in metres. Each mesh in a file is one convex piece of a body (see
src/geometry/mesh_import.h); tests/geometry/test_mesh_import.cpp checks the volumes printed here.
"""
import base64
import json
import math
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0]]


def volume(verts, faces):
    """Divergence theorem: sum of signed tetrahedra (0, a, b, c) over fan triangles."""
    v = 0.0
    for f in faces:
        for i in range(1, len(f) - 1):
            v += dot(verts[f[0]], cross(verts[f[i]], verts[f[i + 1]])) / 6
    return v


def box(lo, hi):
    """8 corners (bit 0: +x, bit 1: +y, bit 2: +z) and 6 quads CCW seen from outside."""
    v = [[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]]
         for i in range(8)]
    f = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]]
    return v, f


def write_obj(path, objects, comment):
    lines = ["# " + c for c in comment] + []
    base = 1
    for name, (v, f) in objects:
        lines.append(f"o {name}")
        lines += [f"v {p[0]:.6f} {p[1]:.6f} {p[2]:.6f}" for p in v]
        lines += ["f " + " ".join(str(i + base) for i in face) for face in f]
        base += len(v)
    open(path, "w").write("\n".join(lines) + "\n")


def t_handle():
    # A crossbar 0.8 x 0.1 x 0.1 along x on top of a shaft 0.1 x 0.1 x 0.5 along z: they touch
    # on the plane z = 0.5 and do not overlap. Three distinct principal moments, so a spin about
    # the middle axis tumbles (Dzhanibekov).
    bar = box([-0.4, -0.05, 0.5], [0.4, 0.05, 0.6])
    shaft = box([-0.05, -0.05, 0.0], [0.05, 0.05, 0.5])
    write_obj(os.path.join(HERE, "t_handle.obj"), [("Crossbar", bar), ("Shaft", shaft)],
              ["T-handle: two convex pieces (crossbar 0.8x0.1x0.1 m, shaft 0.1x0.1x0.5 m)."])
    return volume(*bar) + volume(*shaft)


def wedge():
    # A triangular prism: right triangle (-0.25,0) (0.25,0) (-0.25,0.2) in xz, 0.3 m deep in y.
    a, b = 0.25, 0.15
    v = [[-a, -b, 0], [a, -b, 0], [-a, -b, 0.2], [-a, b, 0], [a, b, 0], [-a, b, 0.2]]
    f = [[0, 1, 2], [3, 5, 4], [0, 3, 4, 1], [0, 2, 5, 3], [1, 4, 5, 2]]
    write_obj(os.path.join(HERE, "wedge.obj"), [("Wedge", (v, f))],
              ["Wedge: right-triangle prism, 0.5 x 0.3 x 0.2 m."])
    return volume(v, f)


def outward(verts, tri):
    """Orders a triangle CCW seen from outside the (convex) point set's centroid."""
    c = [sum(p[i] for p in verts) / len(verts) for i in range(3)]
    a, b, d = (verts[i] for i in tri)
    n = cross(sub(b, a), sub(d, a))
    return tri if dot(n, sub(a, c)) > 0 else [tri[0], tri[2], tri[1]]


def tetra():
    v = [[0, 0, 0], [0.4, 0, 0], [0, 0.3, 0], [0.1, 0.1, 0.35]]
    f = [outward(v, t) for t in ([0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3])]
    lines = ["solid tetra"]
    for t in f:
        p = [v[i] for i in t]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        k = math.sqrt(dot(n, n))
        lines.append(f"  facet normal {n[0]/k:.6f} {n[1]/k:.6f} {n[2]/k:.6f}")
        lines.append("    outer loop")
        lines += [f"      vertex {q[0]:.6f} {q[1]:.6f} {q[2]:.6f}" for q in p]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid tetra")
    open(os.path.join(HERE, "tetra.stl"), "w").write("\n".join(lines) + "\n")
    return volume(v, f)


def hull_by_brute_force(v):
    """Every triple whose plane has all other points behind it is a hull face. O(n^4), fine for
    20 points in general position (random points on an ellipsoid: no four coplanar)."""
    faces = []
    n = len(v)
    for i in range(n):
        for j in range(i + 1, n):
            for k in range(j + 1, n):
                nrm = cross(sub(v[j], v[i]), sub(v[k], v[i]))
                side = [dot(nrm, sub(v[m], v[i])) for m in range(n) if m not in (i, j, k)]
                if all(s < 0 for s in side):
                    faces.append([i, j, k])
                elif all(s > 0 for s in side):
                    faces.append([i, k, j])
    return faces


def gem():
    # 20 points on an ellipsoid of radii 0.15, 0.12, 0.09 m: all are hull vertices, no face is a
    # regular polygon, no two faces are coplanar.
    rng = random.Random(20240601)
    v = []
    for _ in range(20):
        z = rng.uniform(-1, 1)
        t = rng.uniform(0, 2 * math.pi)
        r = math.sqrt(1 - z * z)
        v.append([round(0.15 * r * math.cos(t), 6), round(0.12 * r * math.sin(t), 6),
                  round(0.09 * z, 6)])
    f = hull_by_brute_force(v)
    lines = ["ply", "format ascii 1.0", "comment gem: hull of 20 points on an ellipsoid, metres",
             f"element vertex {len(v)}", "property float x", "property float y",
             "property float z", f"element face {len(f)}", "property list uchar int vertex_indices",
             "end_header"]
    lines += [f"{p[0]:.6f} {p[1]:.6f} {p[2]:.6f}" for p in v]
    lines += ["3 " + " ".join(map(str, t)) for t in f]
    open(os.path.join(HERE, "gem.ply"), "w").write("\n".join(lines) + "\n")
    return volume(v, f), len(v), len(f)


def pyramid():
    # Square base 0.4 x 0.4 m, apex 0.3 m up. glTF is y-up, so "up" is +y here; the node moves
    # it 0.5 m along +x (exercises node transforms).
    v = [[-0.2, 0, -0.2], [0.2, 0, -0.2], [0.2, 0, 0.2], [-0.2, 0, 0.2], [0, 0.3, 0]]
    tris = [outward(v, t) for t in ([0, 1, 2], [0, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4],
                                    [3, 0, 4])]
    pos = b"".join(struct.pack("<3f", *p) for p in v)
    idx = b"".join(struct.pack("<3H", *t) for t in tris)
    data = pos + idx
    gltf = {
        "asset": {"version": "2.0", "generator": "tumble assets/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Pyramid", "mesh": 0, "translation": [0.5, 0, 0]}],
        "meshes": [{"name": "Pyramid", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(data).decode()}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx), "target": 34963}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3",
             "min": [min(p[i] for p in v) for i in range(3)],
             "max": [max(p[i] for p in v) for i in range(3)]},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(tris), "type": "SCALAR"}],
    }
    open(os.path.join(HERE, "pyramid.gltf"), "w").write(json.dumps(gltf, indent=1) + "\n")
    return volume(v, tris)


if __name__ == "__main__":
    print(f"t_handle.obj  volume {t_handle():.9f} m^3")
    print(f"wedge.obj     volume {wedge():.9f} m^3")
    print(f"tetra.stl     volume {tetra():.9f} m^3")
    gv, gn, gf = gem()
    print(f"gem.ply       volume {gv:.9f} m^3, {gn} vertices, {gf} faces")
    print(f"pyramid.gltf  volume {pyramid():.9f} m^3")
