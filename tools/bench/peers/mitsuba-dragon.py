#!/usr/bin/env python3
"""Mitsuba 3's render of the dragon bench frame (scenes/bench-dragon.yaml), for the whole-process
goal: the same camera (pinhole, vertical field of view, look-at), 1920x1080, 1 sample per pixel
with the box filter, the mesh (flat triangles, as ours: face_normals) and the floor plane (a square
of side 2 x --plane-size around the plane's point) with diffuse BSDFs of reflectance kd x color,
the point lights at their positions with intensity ls x color (Mitsuba's point light and ours both
give I cos / r^2), the direct integrator with --emitter-samples light samples and no BSDF sample,
written as an 8-bit sRGB PNG (or EXR, by the name's ending).

Not translated: the ambient term (ka cd La: Mitsuba has no ambient light; it would be a constant
environment that needs rays of its own) and the background colour (the floor fills the frame).
Each of Mitsuba's light samples picks one of the two lights at random, so --emitter-samples 2 traces
two shadow rays per pixel as ours does (ours skips those towards a light behind the surface:
3,976,826 of 4,147,200), --emitter-samples 1 one; the pixel's sample is random in the pixel, not
its centre (the same work).

    mitsuba-dragon.py [--scene scenes/bench-dragon.yaml] [--variant llvm_ad_rgb] [--emitter-samples 2]
                      [--threads 2] [-o out.png]

Prints one line: "mitsuba 3.x.y VARIANT es=N: import S s, load S s, render S s, write S s, script S s"
(load: reading the OBJ and building the scene's acceleration structure; render: mi.render until its
result is evaluated; script: from the script's first line to the written image). The whole process,
Python's start included, is what tools/bench/peers/dragon times from outside.
"""
import time

SCRIPT_START = time.perf_counter()

import argparse  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peers  # noqa: E402


def to_world_plane(mi, point, normal, size):
    """Mitsuba's rectangle ([-1, 1]^2 in z = 0, facing +z) onto the plane: its +z along the normal."""
    n = normal
    up = [0, 0, 1] if abs(n[2]) < 0.9 else [1, 0, 0]
    target = [point[i] + n[i] for i in range(3)]
    return mi.ScalarTransform4f().look_at(origin=point, target=target, up=up) @ mi.ScalarTransform4f().scale([size, size, 1])


def scene_dict(mi, s, mesh_path, emitter_samples, spp, plane_size):
    img = s["image"]
    cam = s["camera"]
    rgb = lambda v: {"type": "rgb", "value": [float(x) for x in v]}
    diffuse = lambda m: {"type": "diffuse", "reflectance": rgb([m["kd"] * c for c in m["color"]])}
    d = {
        "type": "scene",
        "integrator": {"type": "direct", "emitter_samples": emitter_samples, "bsdf_samples": 0},
        "sensor": {
            "type": "perspective",
            "fov": cam["fov"], "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["eye"], target=cam["look_at"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": img["width"], "height": img["height"], "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": "independent", "sample_count": spp},
        },
        "mesh": {"type": "obj", "filename": mesh_path, "face_normals": True, "bsdf": diffuse(s["mesh"]["material"])},
    }
    if s["plane"]:
        p = s["plane"]
        d["floor"] = {"type": "rectangle", "to_world": to_world_plane(mi, p["point"], p["normal"], plane_size),
                      "bsdf": diffuse(p["material"])}
    for i, light in enumerate(s["lights"]):
        d[f"light{i}"] = {"type": "point", "position": light["position"], "intensity": rgb([light["ls"] * c for c in light["color"]])}
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=os.path.join(peers.REPO, "scenes", "bench-dragon.yaml"))
    ap.add_argument("--mesh", help="plain .obj to load (default: the scene's mesh, decompressed once into the peers cache)")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--emitter-samples", type=int, default=2)
    ap.add_argument("--spp", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--plane-size", type=float, default=10.0)
    ap.add_argument("-o", "--output", default="/tmp/mitsuba-dragon.png")
    a = ap.parse_args()

    s = peers.dragon(a.scene)
    mesh_path = a.mesh or peers.plain_obj(s["mesh"]["file"])
    t0 = time.perf_counter()
    import drjit as dr
    import mitsuba as mi
    mi.set_variant(a.variant)
    dr.set_thread_count(a.threads)
    t1 = time.perf_counter()
    scene = mi.load_dict(scene_dict(mi, s, mesh_path, a.emitter_samples, a.spp, a.plane_size))
    t2 = time.perf_counter()
    image = mi.render(scene, spp=a.spp)
    dr.eval(image)
    dr.sync_thread()
    t3 = time.perf_counter()
    bitmap = mi.Bitmap(image)
    if a.output.endswith(".png"):
        bitmap = bitmap.convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.UInt8, srgb_gamma=True)
    bitmap.write(a.output)
    t4 = time.perf_counter()
    print(f"mitsuba {mi.__version__} {a.variant} es={a.emitter_samples}: import {t1 - t0:.3f} s, load {t2 - t1:.3f} s, "
          f"render {t3 - t2:.3f} s, write {t4 - t3:.3f} s, script {t4 - SCRIPT_START:.3f} s", flush=True)


if __name__ == "__main__":
    peers.use_venv()
    peers.apply_peer_env()
    main()
