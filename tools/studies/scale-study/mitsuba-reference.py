#!/usr/bin/env python3
"""Mitsuba 3 on the frame tools/studies/scale-study/run renders (docs/performance.md, "Meshes of tens of
millions of triangles"): an OBJ mesh under a pinhole camera (eye (0, 0.12, 0.3), looking at
(0, 0.12, 0), 40 degrees vertically), one point light, a diffuse material, 1 sample per pixel,
direct lighting with one light sample (a camera ray and a shadow ray per pixel, as our ray-cast
frame), written as EXR. A reference for time and memory only: Mitsuba's own loader, BVH and
integrator, not our image.

    python3 tools/studies/scale-study/mitsuba-reference.py MESH.obj [WIDTH HEIGHT] [VARIANT]

Prints one line: "mitsuba VARIANT: load S s, render S s, peak RSS MiB" (load: reading the OBJ and
building the acceleration structure, as mi.load_dict does both).
"""
import resource
import sys
import time

import mitsuba as mi


def main():
    mesh = sys.argv[1]
    width = int(sys.argv[2]) if len(sys.argv) > 2 else 1920
    height = int(sys.argv[3]) if len(sys.argv) > 3 else 1080
    variant = sys.argv[4] if len(sys.argv) > 4 else "llvm_ad_rgb"
    mi.set_variant(variant)
    start = time.perf_counter()
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "direct", "emitter_samples": 1, "bsdf_samples": 0},
        "sensor": {
            "type": "perspective",
            "fov": 40, "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=[0, 0.12, 0.3], target=[0, 0.12, 0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": 1},
        },
        "light": {"type": "point", "position": [1, 2, 2], "intensity": {"type": "rgb", "value": 5}},
        "mesh": {"type": "obj", "filename": mesh, "bsdf": {"type": "diffuse"}},
    })
    loaded = time.perf_counter()
    image = mi.render(scene, spp=1)
    mi.Bitmap(image).write("/tmp/mitsuba-reference.exr")
    rendered = time.perf_counter()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"mitsuba {variant}: load {loaded - start:.3f} s, render {rendered - loaded:.3f} s, peak RSS {rss:.0f} MiB")


if __name__ == "__main__":
    main()
