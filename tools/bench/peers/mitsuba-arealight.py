#!/usr/bin/env python3
"""Mitsuba 3's render of the area-light spheres (scenes/arealight-spheres.yaml), for the
time-to-error goal: the same pinhole camera, 512x512, the box filter, the spheres and the floor
plane (a square of side 2 x --plane-size around its point: the camera sees the floor some 100 units
away at the top of the frame) with diffuse BSDFs of reflectance kd x color, no ambient light (the
scene's is 0), and the rectangle light as a rectangle shape with an area emitter of the same
radiance, emitting on the side of edge-a x edge-b as ours does. The direct integrator with one
emitter sample and no BSDF sample: one light sample per pixel sample, as the scene's `samples: 1`.
Sampler: --sampler multijitter (Mitsuba's correlated multi-jittered pattern, Kensler 2013; the
closest to our default multi-jittered), independent or stratified.

    mitsuba-arealight.py --spp 64 [--variant llvm_ad_rgb] [--sampler multijitter] [--seed 1]
                         [--repeat 3] [--reference REF.exr] [-o out.exr]
    mitsuba-arealight.py --make-reference REF.exr [--variant scalar_rgb] [--reference-spp 4232] [--chunk 2116]

The first form renders once untimed at --spp (the llvm variants compile their kernel then, or
take it from Dr.Jit's kernel cache), then --repeat timed renders with seeds --seed, --seed + 1, ...
(render time: mi.render until its result is evaluated), each compared with REF.exr when given:
relative RMSE = sqrt(sum (x_i - r_i)^2 / n) / mean(r_i) over all pixels and the three channels of
linear radiance, as `render converge` computes it. Prints one line per render:
"mitsuba 3.x.y VARIANT SAMPLER spp N seed S: render T s, relative RMSE E".

The second form renders the reference: --reference-spp samples per pixel in chunks of --chunk
(seeds 100000 + k, none of which a measured render uses), the two halves averaged; half the
relative RMSE between the halves is the reference's own noise (printed, and kept in REF.json).
By default two chunks of 2116 spp, as converge's own reference (2 x 2116): each chunk is one
stratified pattern, where many small chunks would only average as 1/sqrt(chunks). Render it with
scalar_rgb: an llvm variant holds a chunk's every sample in one wavefront, too many for memory.
"""
import argparse
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peers  # noqa: E402


def rectangle_to_world(mi, corner, a, b):
    """Mitsuba's rectangle ([-1, 1]^2, normal +z) onto corner + u a + v b, u, v in [0, 1]: its normal
    the unit a x b (the side our RectangleEmitter emits on)."""
    n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    ln = sum(x * x for x in n) ** 0.5
    n = [x / ln for x in n]
    c = [corner[i] + 0.5 * a[i] + 0.5 * b[i] for i in range(3)]
    m = [[0.5 * a[i], 0.5 * b[i], n[i], c[i]] for i in range(3)] + [[0, 0, 0, 1]]
    return mi.ScalarTransform4f(m)


def plane_to_world(mi, point, normal, size):
    up = [0, 0, 1] if abs(normal[2]) < 0.9 else [1, 0, 0]
    target = [point[i] + normal[i] for i in range(3)]
    return mi.ScalarTransform4f().look_at(origin=point, target=target, up=up) @ mi.ScalarTransform4f().scale([size, size, 1])


def scene_dict(mi, s, sampler, spp, plane_size):
    img = s["image"]
    cam = s["camera"]
    if any(x != 0 for x in s["ambient"]):
        sys.exit("mitsuba-arealight: the scene has an ambient light, which Mitsuba has not")
    rgb = lambda v: {"type": "rgb", "value": [float(x) for x in v]}
    diffuse = lambda m: {"type": "diffuse", "reflectance": rgb([m["kd"] * c for c in m["color"]])}
    light = s["light"]
    d = {
        "type": "scene",
        "integrator": {"type": "direct", "emitter_samples": 1, "bsdf_samples": 0},
        "sensor": {
            "type": "perspective",
            "fov": cam["fov"], "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=cam["eye"], target=cam["look_at"], up=cam["up"]),
            "film": {"type": "hdrfilm", "width": img["width"], "height": img["height"], "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": sampler, "sample_count": spp},
        },
        "light": {"type": "rectangle", "to_world": rectangle_to_world(mi, light["corner"], light["a"], light["b"]),
                  "emitter": {"type": "area", "radiance": rgb(light["radiance"])}},
    }
    if s["plane"]:
        p = s["plane"]
        d["floor"] = {"type": "rectangle", "to_world": plane_to_world(mi, p["point"], p["normal"], plane_size),
                      "bsdf": diffuse(p["material"])}
    for i, sp in enumerate(s["spheres"]):
        d[f"sphere{i}"] = {"type": "sphere", "center": sp["center"], "radius": sp["radius"], "bsdf": diffuse(sp["material"])}
    if any(x != 0 for x in s["background"]):
        d["background"] = {"type": "constant", "radiance": rgb(s["background"])}
    return d


def render(mi, dr, scene, spp, seed):
    start = time.perf_counter()
    image = mi.render(scene, spp=spp, seed=seed)
    dr.eval(image)
    dr.sync_thread()
    return time.perf_counter() - start, image


def rel_rmse(np, x, r):
    x = np.asarray(x, dtype=np.float64)[..., :3]
    r = np.asarray(r, dtype=np.float64)[..., :3]
    return float(np.sqrt(np.mean((x - r) ** 2)) / np.mean(r))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scene", default=os.path.join(peers.REPO, "scenes", "arealight-spheres.yaml"))
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--sampler", default="multijitter", choices=["multijitter", "independent", "stratified"])
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--plane-size", type=float, default=1000.0)
    ap.add_argument("--reference", help="EXR to measure the error against")
    ap.add_argument("--make-reference", metavar="REF.exr")
    ap.add_argument("--reference-spp", type=int, default=4232)
    ap.add_argument("--chunk", type=int, default=2116)
    ap.add_argument("-o", "--output", help="write the last render as EXR (linear) or PNG (sRGB)")
    a = ap.parse_args()

    import numpy as np
    import drjit as dr
    import mitsuba as mi
    mi.set_variant(a.variant)
    dr.set_thread_count(a.threads)
    s = peers.arealight(a.scene)
    if s["light"]["samples"] != 1:
        print(f"note: the scene takes {s['light']['samples']} light samples per pixel sample; Mitsuba here takes 1")

    if a.make_reference:
        scene = mi.load_dict(scene_dict(mi, s, a.sampler, a.chunk, a.plane_size))
        chunks = max(2, a.reference_spp // a.chunk)
        chunks += chunks % 2
        halves = [None, None]
        start = time.perf_counter()
        for k in range(chunks):
            _, image = render(mi, dr, scene, a.chunk, 100000 + k)
            arr = np.array(image, dtype=np.float64)
            h = 0 if k < chunks // 2 else 1
            halves[h] = arr if halves[h] is None else halves[h] + arr
        halves = [h / (chunks // 2) for h in halves]
        ref = 0.5 * (halves[0] + halves[1])
        noise = 0.5 * rel_rmse(np, halves[0], halves[1])
        mi.Bitmap(ref.astype(np.float32)).write(a.make_reference)
        info = {"mitsuba": mi.__version__, "variant": a.variant, "sampler": a.sampler, "spp": chunks * a.chunk,
                "chunk": a.chunk, "seeds": f"100000-{100000 + chunks - 1}", "relative_noise": noise,
                "mean": float(np.mean(ref)), "seconds": time.perf_counter() - start}
        with open(os.path.splitext(a.make_reference)[0] + ".json", "w") as f:
            json.dump(info, f, indent=1)
        print(f"mitsuba {mi.__version__} {a.variant} {a.sampler} reference: {chunks * a.chunk} spp in {info['seconds']:.1f} s, "
              f"mean {info['mean']:.5f}, relative noise {noise:.5f} (half the relative RMSE between its halves)")
        return

    ref = np.array(mi.Bitmap(a.reference), dtype=np.float64) if a.reference else None
    scene = mi.load_dict(scene_dict(mi, s, a.sampler, a.spp, a.plane_size))
    warm, _ = render(mi, dr, scene, a.spp, a.seed + 1000)
    print(f"mitsuba {mi.__version__} {a.variant} {a.sampler} spp {a.spp}: untimed first render {warm:.3f} s", flush=True)
    image = None
    for i in range(a.repeat):
        seconds, image = render(mi, dr, scene, a.spp, a.seed + i)
        err = rel_rmse(np, np.array(image), ref) if ref is not None else float("nan")
        print(f"mitsuba {mi.__version__} {a.variant} {a.sampler} spp {a.spp} seed {a.seed + i}: render {seconds:.4f} s, "
              f"relative RMSE {err:.5f}", flush=True)
    if a.output:
        bitmap = mi.Bitmap(image)
        if a.output.endswith(".png"):
            bitmap = bitmap.convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.UInt8, srgb_gamma=True)
        bitmap.write(a.output)


if __name__ == "__main__":
    peers.use_venv()
    peers.apply_peer_env()
    main()
