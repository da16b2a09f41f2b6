"""The Cornell box of examples/cornell_path/scene.rt as a Mitsuba 3 scene, rendered for the
error-against-time benchmark (docs/bench/cornell_vs_mitsuba.sh; docs/bench/README.md).

Usage (inside the Mitsuba venv; the shell script sets it up):

    python cornell_mitsuba.py OUT_DIR --size 256x256 --spp-list 1,4,16,64 --ref-spp 4096
    python cornell_mitsuba.py OUT_DIR --means a.exr b.exr   # per-channel means of two images

With --glass, the scene is docs/bench/cornell_glass.rt (a glass ball for the short box), and
--means also reports the means over the pixels that see the ball.

What it writes into OUT_DIR:

- reference.exr: the scene at --ref-spp samples (in passes of at most --pass-spp, each with its
  own seed, averaged): the converged reference both renderers are measured against;
- mitsuba.csv (`spp,seconds,rmse`, the format `rtc bench --against` reads): one render per level
  (with --runs N, N in rounds over the levels and the median time)
  with --sampler (default `independent`; `ldsampler`, Mitsuba's scrambled (0, 2)-sequence, is the
  counterpart of rtc's scrambled Sobol numbers), seeded apart from the reference, timed around
  `mi.render` and the evaluation of its result; a 1-spp warm-up render first so the JIT's kernel
  compile is not in the times (as `rtc bench` leaves out pipeline creation);
- mitsuba_<spp>.exr for the levels of --keep (default: the largest).

The scene matches the .rt file: the same world-space transforms (rtc's `quad_mesh()` is the
square [-1, 1]^2 in the xz-plane with normal +y, Mitsuba's `rectangle` the same square in the
xy-plane with normal +z, so each quad is `M_rtc @ rotate_x(-90)`; `cube_mesh()` and Mitsuba's
`cube` are both [-1, 1]^3); the pinhole camera with rtc's vertical field of view (`fov_axis: y`)
and a box pixel filter; two-sided diffuse walls (rtc's `PathDiffuse` shades both faces); the lamp
a one-sided rectangle of radiance `color * intensity` with a black BSDF (rtc's `Emissive`); and
rtc's `max_depth: 6` (rays after the camera ray; direct light at each of the up to 7 hits) is
Mitsuba's `max_depth: 8` (which counts the emitter's vertex and the camera's segment).
"""

import argparse
import math
import os
import sys
import time

import numpy as np


def parse_size(text):
    w, h = text.lower().split("x")
    return int(w), int(h)


# rtc's transforms (compiler/src/lower/polyfill.rs: right-handed rotations in degrees).
def translate(x, y, z):
    m = np.eye(4)
    m[:3, 3] = [x, y, z]
    return m


def scale(x, y=None, z=None):
    y = x if y is None else y
    z = x if z is None else z
    return np.diag([x, y, z, 1.0])


def rotate(axis, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    m = np.eye(4)
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


# The glass ball of docs/bench/cornell_glass.rt (in place of the short box).
BALL_CENTER = (0.33, -0.7, 0.3)
BALL_RADIUS = 0.3


def scene_dict(mi, width, height, glass=False, max_depth_rtc=6, sampler="independent"):
    T = mi.ScalarTransform4f

    def quad(m):
        return T(m @ rotate("x", -90.0))

    def diffuse(rgb):
        return {
            "type": "twosided",
            "material": {"type": "diffuse", "reflectance": {"type": "rgb", "value": rgb}},
        }

    white = diffuse([0.73, 0.73, 0.73])
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": max_depth_rtc + 2},
        "sensor": {
            "type": "perspective",
            "fov_axis": "y",
            "fov": 38.0,
            "to_world": T().look_at(origin=[0, 0, 3.4], target=[0, 0, 0], up=[0, 1, 0]),
            "sampler": {"type": sampler},
            "film": {
                "type": "hdrfilm",
                "width": width,
                "height": height,
                "rfilter": {"type": "box"},
                "pixel_format": "rgb",
            },
        },
        "floor": {"type": "rectangle", "to_world": quad(translate(0, -1, 0)), "bsdf": white},
        "ceiling": {
            "type": "rectangle",
            "to_world": quad(translate(0, 1, 0) @ rotate("x", 180)),
            "bsdf": white,
        },
        "back": {
            "type": "rectangle",
            "to_world": quad(translate(0, 0, -1) @ rotate("x", 90)),
            "bsdf": white,
        },
        "left": {
            "type": "rectangle",
            "to_world": quad(translate(-1, 0, 0) @ rotate("z", -90)),
            "bsdf": diffuse([0.63, 0.065, 0.05]),
        },
        "right": {
            "type": "rectangle",
            "to_world": quad(translate(1, 0, 0) @ rotate("z", 90)),
            "bsdf": diffuse([0.14, 0.45, 0.091]),
        },
        "short_box": {
            "type": "cube",
            "to_world": T(translate(0.33, -0.7, 0.3) @ rotate("y", -17) @ scale(0.3)),
            "bsdf": white,
        },
        "tall_box": {
            "type": "cube",
            "to_world": T(translate(-0.33, -0.4, -0.3) @ rotate("y", 17) @ scale(0.3, 0.6, 0.3)),
            "bsdf": white,
        },
        # rtc samples a QuadLight at y = 0.997 and shows an Emissive quad at 0.998; one emitter here.
        "lamp": {
            "type": "rectangle",
            "to_world": quad(translate(0, 0.998, 0) @ rotate("x", 180) @ scale(0.25)),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}},
            "emitter": {
                "type": "area",
                "radiance": {"type": "rgb", "value": [12.0, 10.2, 7.2]},
            },
        },
    }
    if glass:
        del d["short_box"]
        d["glass_ball"] = {
            "type": "sphere",
            "center": list(BALL_CENTER),
            "radius": BALL_RADIUS,
            # rtc's Glass: exact Fresnel between vacuum (1.0, not Mitsuba's default air) and 1.5.
            "bsdf": {"type": "dielectric", "int_ior": 1.5, "ext_ior": 1.0},
        }
    return d


def ball_mask(width, height):
    """Pixels whose four corners all see the glass ball (rtc's pinhole camera, no occluder in front)."""
    h = math.tan(math.radians(38.0) / 2)
    aspect = width / height
    eye = np.array([0.0, 0.0, 3.4])
    c = np.array(BALL_CENTER)

    def hits(px, py):
        nx = px / width * 2 - 1
        ny = py / height * 2 - 1
        d = np.stack([nx * h * aspect, -ny * h, -np.ones_like(nx)], axis=-1)
        d /= np.linalg.norm(d, axis=-1, keepdims=True)
        oc = eye - c
        b = d @ oc
        return b * b - (oc @ oc - BALL_RADIUS**2) > 0

    y, x = np.mgrid[0:height, 0:width].astype(np.float64)
    return hits(x, y) & hits(x + 1, y) & hits(x, y + 1) & hits(x + 1, y + 1)


def render(mi, dr, scene, spp, seed, pass_spp):
    """Renders `spp` samples in passes of at most `pass_spp`; the average as a numpy array."""
    total = None
    done = 0
    k = 0
    while done < spp:
        n = min(pass_spp, spp - done)
        img = mi.render(scene, spp=n, seed=seed * 100003 + k)
        dr.eval(img)
        a = np.array(img, dtype=np.float64)[:, :, :3] * n
        total = a if total is None else total + a
        done += n
        k += 1
    return total / spp


def write_exr(mi, path, a):
    mi.Bitmap(a.astype(np.float32), mi.Bitmap.PixelFormat.RGB).write(path)


def read_exr(mi, path):
    b = mi.Bitmap(path)
    return np.array(b, dtype=np.float64)[:, :, :3]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out")
    p.add_argument("--size", default="256x256")
    p.add_argument("--spp-list", default="1,4,16,64")
    p.add_argument("--ref-spp", type=int, default=4096)
    p.add_argument("--pass-spp", type=int, default=32)
    p.add_argument("--variant", default=os.environ.get("MITSUBA_VARIANT", "llvm_ad_rgb"))
    p.add_argument("--keep", default="", help="levels whose image to write as mitsuba_<spp>.exr")
    p.add_argument("--glass", action="store_true", help="the scene of docs/bench/cornell_glass.rt")
    p.add_argument(
        "--sampler",
        default=os.environ.get("MITSUBA_SAMPLER", "independent"),
        help="Mitsuba's sampler for the measured levels (the reference always uses independent): "
        "independent, stratified, multijitter, orthogonal or ldsampler",
    )
    p.add_argument(
        "--runs",
        type=int,
        default=1,
        help="render every level this many times, in rounds over all levels, and write the "
        "median time (each run of a level with the same seed, so the same image)",
    )
    p.add_argument("--means", nargs="+", metavar="EXR")
    args = p.parse_args()

    import drjit as dr
    import mitsuba as mi

    mi.set_variant(args.variant)
    if args.means:
        images = [(path, read_exr(mi, path)) for path in args.means]
        regions = [("image", None)]
        if args.glass:
            hgt, wid = images[0][1].shape[:2]
            regions.append(("glass ball", ball_mask(wid, hgt)))
        for name, mask in regions:
            if mask is not None:
                print(f"{name}: {int(mask.sum())} pixels")
            first = None
            for path, a in images:
                m = (a.reshape(-1, 3) if mask is None else a[mask]).mean(axis=0)
                rel = "" if first is None else "  (" + " ".join(
                    f"{(m[c] / first[c] - 1) * 100:+.2f} %" for c in range(3)) + " against the first)"
                first = m if first is None else first
                print(f"{name} mean R G B {m[0]:.5f} {m[1]:.5f} {m[2]:.5f}  {path}{rel}")
        return

    w, h = parse_size(args.size)
    levels = sorted({int(x) for x in args.spp_list.split(",") if x})
    keep = {int(x) for x in args.keep.split(",") if x} or {levels[-1]}
    os.makedirs(args.out, exist_ok=True)
    scene = mi.load_dict(scene_dict(mi, w, h, glass=args.glass))
    measured = scene
    if args.sampler != "independent":
        measured = mi.load_dict(scene_dict(mi, w, h, glass=args.glass, sampler=args.sampler))
    print(
        f"mitsuba {mi.__version__}, variant {args.variant}, sampler {args.sampler}, {w}x{h}",
        flush=True,
    )

    ref_path = os.path.join(args.out, "reference.exr")
    t = time.perf_counter()
    ref = render(mi, dr, scene, args.ref_spp, seed=1, pass_spp=args.pass_spp)
    print(
        f"reference: {args.ref_spp} spp in {time.perf_counter() - t:.1f} s "
        f"(passes of {args.pass_spp})",
        flush=True,
    )
    write_exr(mi, ref_path, ref)
    m = ref.reshape(-1, 3).mean(axis=0)
    print(f"reference mean R G B {m[0]:.5f} {m[1]:.5f} {m[2]:.5f}")

    render(mi, dr, measured, 1, seed=7, pass_spp=1)  # warm-up: the JIT compile
    runs = max(args.runs, 1)
    times = [[] for _ in levels]
    errors = [None for _ in levels]
    print(f"{'spp':>7} {'seconds':>10} {'RMSE':>10}")
    for run in range(runs):
        if runs > 1:
            print(f"run {run + 1} of {runs}", flush=True)
        for i, spp in enumerate(levels):
            t = time.perf_counter()
            img = render(mi, dr, measured, spp, seed=1000 + i, pass_spp=args.pass_spp)
            seconds = time.perf_counter() - t
            rmse = math.sqrt(np.mean((img - ref) ** 2))
            times[i].append(seconds)
            if errors[i] is None:
                errors[i] = rmse
            print(f"{spp:>7} {seconds:>10.3f} {rmse:>10.6f}", flush=True)
            if spp in keep and run == 0:
                write_exr(mi, os.path.join(args.out, f"mitsuba_{spp}.exr"), img)
    rows = [(spp, float(np.median(times[i])), errors[i]) for i, spp in enumerate(levels)]
    if runs > 1:
        print(f"medians of {runs} runs:")
        for i, (spp, seconds, rmse) in enumerate(rows):
            print(
                f"{spp:>7} {seconds:>10.3f} {rmse:>10.6f}  "
                f"({min(times[i]):.3f} to {max(times[i]):.3f})",
                flush=True,
            )
    with open(os.path.join(args.out, "mitsuba.csv"), "w") as f:
        f.write(
            f"# Mitsuba {mi.__version__} {args.variant}, sampler {args.sampler}, {w}x{h}, "
            f"reference {args.ref_spp} spp, median of {runs} run(s)\n"
        )
        f.write("spp,seconds,rmse\n")
        for spp, s, e in rows:
            f.write(f"{spp},{s:.6f},{e:.8f}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
