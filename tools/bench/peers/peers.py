"""Shared by the peer benchmarks in tools/bench/peers: where things are, the venv that `setup`
made, the two scenes' settings read from their YAML files (so the peers render what the scene
files say, not a copy of it), the exclusive CPU lock, and timed runs of whole processes.

Only what these two scenes use is read; anything else in them (a transform, another kind of
object, light or material) stops the scripts with a message instead of being left out silently.
"""
import contextlib
import fcntl
import gzip
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
PEERS = os.path.abspath(os.path.expanduser(os.environ.get("PEERS_HOME", "~/.cache/raytracer/peers")))
VENV = os.path.join(PEERS, "venv")
VENV_PY = os.path.join(VENV, "bin", "python")
BIN = os.path.join(PEERS, "bin")
CPU_LOCK = os.environ.get("CPU_LOCK", "/tmp/cpu.lock")


def use_venv():
    """Runs this script again under the venv's Python (mitsuba, numpy, PyYAML) unless it already is."""
    if os.path.realpath(sys.prefix) != os.path.realpath(VENV):
        if not os.path.exists(VENV_PY):
            sys.exit(f"no venv at {VENV}: run tools/bench/peers/setup first")
        os.execv(VENV_PY, [VENV_PY] + sys.argv)


def peer_env():
    """os.environ plus what setup recorded in PEERS/env (DRJIT_LIBLLVM_PATH for Mitsuba's llvm variants)."""
    env = dict(os.environ)
    path = os.path.join(PEERS, "env")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                line = line.strip()
                if line and not line.startswith("#") and "=" in line:
                    key, value = line.split("=", 1)
                    env.setdefault(key, value)
    return env


def apply_peer_env():
    for key, value in peer_env().items():
        os.environ.setdefault(key, value)


# ---- the scenes ----

def _yaml(path):
    import yaml
    with open(path) as f:
        return yaml.safe_load(f)


def _vec(v, default=None):
    if v is None:
        return list(default)
    if isinstance(v, (int, float)):
        return [float(v)] * 3
    return [float(x) for x in v]


def _refuse(kind, obj, allowed):
    extra = set(obj) - set(allowed)
    if extra:
        sys.exit(f"peers: the {kind} has keys these scripts do not translate: {sorted(extra)}")


def _camera(doc):
    cam = doc.get("camera", {})
    _refuse("camera", cam, ["type", "eye", "look-at", "up", "fov"])
    if cam.get("type", "pinhole") != "pinhole":
        sys.exit("peers: only the pinhole camera is translated")
    return {"eye": _vec(cam.get("eye"), [0, 1, 6]), "look_at": _vec(cam.get("look-at"), [0, 0.5, 0]),
            "up": _vec(cam.get("up"), [0, 1, 0]), "fov": float(cam.get("fov", 45))}


def _matte(doc, name):
    m = doc.get("materials", {})[name]
    _refuse(f"material {name}", m, ["type", "ka", "kd", "color"])
    if m.get("type", "matte") != "matte":
        sys.exit(f"peers: material {name} is not matte")
    return {"ka": float(m.get("ka", 0.2)), "kd": float(m.get("kd", 0.8)), "color": _vec(m.get("color"), [1, 1, 1])}


def _image(doc):
    img = doc.get("image", {})
    return {"width": int(img.get("width", 640)), "height": int(img.get("height", 360)),
            "samples": int(img.get("samples", 4)), "sampler": img.get("sampler", "multi-jittered"),
            "exposure": float(img.get("exposure", 1.0))}


def _ambient(doc):
    a = doc.get("ambient", {})
    return [float(a.get("radiance", 0.1)) * c for c in _vec(a.get("color"), [1, 1, 1])]


def dragon(scene_path):
    """scenes/bench-dragon.yaml: one mesh, one plane, matte materials, point lights, ray-cast."""
    doc = _yaml(scene_path)
    if doc.get("tracer") != "ray-cast":
        sys.exit("peers: the dragon frame is expected to use the ray-cast tracer")
    s = {"image": _image(doc), "camera": _camera(doc), "ambient": _ambient(doc),
         "background": _vec(doc.get("background"), [0, 0, 0]), "lights": [], "mesh": None, "plane": None}
    for light in doc.get("lights", []):
        _refuse("point light", light, ["type", "position", "intensity", "color"])
        if light.get("type") != "point":
            sys.exit("peers: the dragon frame's lights must be point lights")
        s["lights"].append({"position": _vec(light["position"]), "ls": float(light.get("intensity", 1)),
                            "color": _vec(light.get("color"), [1, 1, 1])})
    for obj in doc.get("objects", []):
        if obj.get("type") == "mesh" and s["mesh"] is None:
            _refuse("mesh", obj, ["type", "file", "material"])
            s["mesh"] = {"file": os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(scene_path)), obj["file"])),
                         "material": _matte(doc, obj["material"])}
        elif obj.get("type") == "plane" and s["plane"] is None:
            _refuse("plane", obj, ["type", "point", "normal", "material"])
            s["plane"] = {"point": _vec(obj.get("point"), [0, 0, 0]), "normal": _vec(obj["normal"]),
                          "material": _matte(doc, obj["material"])}
        else:
            sys.exit(f"peers: the dragon frame may have one mesh and one plane, not {obj}")
    return s


def arealight(scene_path):
    """scenes/arealight-spheres.yaml: spheres and a plane, matte, one rectangle light."""
    doc = _yaml(scene_path)
    s = {"image": _image(doc), "camera": _camera(doc), "ambient": _ambient(doc),
         "background": _vec(doc.get("background"), [0, 0, 0]), "spheres": [], "plane": None, "light": None}
    lights = doc.get("lights", [])
    if len(lights) != 1 or lights[0].get("type") != "rectangle":
        sys.exit("peers: the area-light scene must have one rectangle light")
    light = lights[0]
    _refuse("rectangle light", light, ["type", "corner", "edge-a", "edge-b", "radiance", "color", "samples", "visible"])
    s["light"] = {"corner": _vec(light["corner"]), "a": _vec(light["edge-a"]), "b": _vec(light["edge-b"]),
                  "radiance": [float(light.get("radiance", 1)) * c for c in _vec(light.get("color"), [1, 1, 1])],
                  "samples": int(light.get("samples", 16)), "visible": bool(light.get("visible", True))}
    for obj in doc.get("objects", []):
        if obj.get("type") == "sphere":
            _refuse("sphere", obj, ["type", "center", "radius", "material"])
            s["spheres"].append({"center": _vec(obj["center"]), "radius": float(obj.get("radius", 1)),
                                 "material": _matte(doc, obj["material"])})
        elif obj.get("type") == "plane" and s["plane"] is None:
            _refuse("plane", obj, ["type", "point", "normal", "material"])
            s["plane"] = {"point": _vec(obj.get("point"), [0, 0, 0]), "normal": _vec(obj["normal"]),
                          "material": _matte(doc, obj["material"])}
        else:
            sys.exit(f"peers: the area-light scene may have spheres and one plane, not {obj}")
    return s


def embree_args(scene):
    """The embree-trace arguments of the dragon frame (shading arguments included, for --pfm)."""
    c = scene["camera"]
    img = scene["image"]
    j = lambda v: ",".join(repr(float(x)) for x in v)
    args = ["--obj", scene["mesh"]["file"], "--size", f"{img['width']},{img['height']}", "--eye", j(c["eye"]),
            "--look-at", j(c["look_at"]), "--up", j(c["up"]), "--fov", repr(c["fov"])]
    if scene["plane"]:
        args += ["--plane", j(scene["plane"]["point"] + scene["plane"]["normal"])]
    for light in scene["lights"]:
        args += ["--light", j(light["position"] + [light["ls"]] + light["color"])]
    amb = scene["ambient"]
    if len(set(amb)) != 1:
        sys.exit("peers: embree-trace's check image takes a white ambient light")
    args += ["--ambient", repr(amb[0]), "--background", j(scene["background"])]
    m = scene["mesh"]["material"]
    args += ["--mesh-material", j([m["ka"], m["kd"]] + m["color"])]
    if scene["plane"]:
        m = scene["plane"]["material"]
        args += ["--plane-material", j([m["ka"], m["kd"]] + m["color"])]
    return args


def plain_obj(path):
    """The mesh as a plain .obj (Mitsuba reads no .gz): decompressed once into PEERS/data."""
    if not path.endswith(".gz"):
        return path
    out = os.path.join(PEERS, "data", os.path.basename(path)[:-3])
    if not os.path.exists(out) or os.path.getmtime(out) < os.path.getmtime(path):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        with gzip.open(path, "rb") as src, open(out + ".tmp", "wb") as dst:
            shutil.copyfileobj(src, dst, 1 << 20)
        os.replace(out + ".tmp", out)
    return out


# ---- timing ----

@contextlib.contextmanager
def cpu_lock():
    """The exclusive CPU lock (flock -x on CPU_LOCK, default /tmp/cpu.lock) for one timed run."""
    if CPU_LOCK in ("", "none"):
        yield
        return
    with open(CPU_LOCK, "a") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def timed(cmd, env=None, cwd=REPO, lock=True):
    """Runs cmd to completion under the CPU lock (the wait for the lock is not timed): its wall time
    from fork to exit (of /usr/bin/time running it: its elapsed, at a finer resolution), its peak RSS
    in MiB (/usr/bin/time's %M), its output. Exits with the output's tail if it fails."""
    import tempfile
    # through /usr/bin/time for the peak RSS: a child forked from this (large) Python process would
    # report this process's RSS as its own peak, which exec keeps
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, tempfile.NamedTemporaryFile("r") as rss:
        with cpu_lock() if lock else contextlib.nullcontext():
            start = time.perf_counter()
            p = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss.name] + cmd, stdout=out, stderr=err, env=env, cwd=cwd)
            wall = time.perf_counter() - start
        out.seek(0)
        err.seek(0)
        o = out.read().decode(errors="replace")
        e = err.read().decode(errors="replace")
        lines = rss.read().split()
    if p.returncode != 0:
        sys.stderr.write(o[-3000:] + e[-3000:])
        sys.exit(f"peers: failed ({p.returncode}): {' '.join(cmd)}")
    return {"wall": wall, "rss_mib": int(lines[-1]) / 1024 if lines else float("nan"), "out": o, "err": e}


def spread(values):
    """'median (min-max, n)' of a list of seconds or ratios."""
    if not values:
        return "-"
    return f"{statistics.median(values):.3f} ({min(values):.3f}-{max(values):.3f}, n={len(values)})"


def loglog_time_at(points, target):
    """The x (seconds, or samples per pixel) at which the error falls to target on the log-log line
    through the two measured points (x, error) that bracket it (or through the two nearest ends,
    extrapolated: then the second value is True)."""
    pts = sorted(points)
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if (e0 - target) * (e1 - target) <= 0 and e0 != e1:
            f = math.log(target / e0) / math.log(e1 / e0)
            return math.exp(math.log(t0) + f * math.log(t1 / t0)), False
    ends = pts[:2] if target > pts[0][1] else pts[-2:]
    (t0, e0), (t1, e1) = ends
    f = math.log(target / e0) / math.log(e1 / e0)
    return math.exp(math.log(t0) + f * math.log(t1 / t0)), True


def read_pfm(path):
    """A PFM image as a float32 array of rows from the top (PFM stores the bottom row first)."""
    import numpy as np
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise ValueError(f"{path}: not a colour PFM")
        w, h = map(int, f.readline().split())
        s = float(f.readline())
        data = np.fromfile(f, dtype="<f4" if s < 0 else ">f4", count=w * h * 3).reshape(h, w, 3)
    return data[::-1]
