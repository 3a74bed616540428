#!/usr/bin/env python3
"""Renders the MuJoCo cases through two libOSMesa builds and compares the images.

Side A is the reference (Mesa's llvmpipe libOSMesa.so.8, GALLIUM_DRIVER=llvmpipe),
side B is softgl's libsoftgl.so used as a drop-in libOSMesa.so.8 (with
--reference-only, side B is Mesa again: that run proves the renders are deterministic).
Each case runs render.py in a fresh subprocess per side; the two sides of one case run
back to back, in alternating order, so both see the same machine load.

Prints a table (also written to OUT/results.md and OUT/results.json): model, size,
offsamples, % of pixels whose largest channel difference from the reference is <= 2,
% identical, max difference, median ms per frame on each side and their ratio.
Exits 1 if a side failed to render (its error is printed), or if --reference-only
found any difference.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np
from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
MESA = "/usr/lib/x86_64-linux-gnu/libOSMesa.so.8"


def lib_dir(out, name, lib):
    """A directory holding libOSMesa.so and libOSMesa.so.8 -> lib.

    Both names are needed: PyOpenGL dlopens "libOSMesa.so" before "libOSMesa.so.8",
    and would find the system's libOSMesa.so (Mesa) if only the .8 name were here."""
    d = os.path.join(out, "lib-" + name)
    os.makedirs(d, exist_ok=True)
    for n in ("libOSMesa.so", "libOSMesa.so.8"):
        p = os.path.join(d, n)
        if os.path.lexists(p):
            os.remove(p)
        os.symlink(os.path.realpath(lib), p)
    return d


def run_side(args, side, case, png):
    model, (w, h), samples = case
    env = dict(os.environ)
    env.update(MUJOCO_GL="osmesa", PYOPENGL_PLATFORM="osmesa",
               LD_LIBRARY_PATH=side["dir"] + (":" + env["LD_LIBRARY_PATH"]
                                               if env.get("LD_LIBRARY_PATH") else ""))
    env.update(side.get("env", {}))
    cmd = [args.python, os.path.join(HERE, "render.py"), "--model", model,
           "--width", str(w), "--height", str(h), "--samples", str(samples),
           "--frames", str(args.frames), "--warmup", str(args.warmup), "--out", png]
    t0 = time.time()
    try:
        p = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return {"ok": False, "error": f"timed out after {args.timeout} s"}
    res = None
    for line in reversed(p.stdout.strip().splitlines()):
        try:
            res = json.loads(line)
            break
        except ValueError:
            continue
    if res is None:
        tail = "\n".join((p.stderr or p.stdout).strip().splitlines()[-15:])
        res = {"ok": False, "error": f"render.py exited {p.returncode} without a result "
                                     f"(signal {-p.returncode} if negative):\n{tail}"}
    if res.get("ok") and p.returncode != 0:
        res = {"ok": False, "error": f"render.py exited {p.returncode} after rendering"}
    want = os.path.realpath(side["lib"])
    if res.get("ok") and res.get("lib") != want:
        res = {"ok": False, "error": f"loaded {res.get('lib')}, not {want}"}
    res["wall_s"] = round(time.time() - t0, 2)
    return res


def compare(a_png, b_png, diff_png=None):
    a = np.asarray(Image.open(a_png).convert("RGB"), dtype=np.int16)
    b = np.asarray(Image.open(b_png).convert("RGB"), dtype=np.int16)
    if a.shape != b.shape:
        return {"error": f"sizes differ: {a.shape} vs {b.shape}"}
    d = np.abs(a - b).max(axis=2)
    n = d.size
    out = {"within2": 100.0 * np.count_nonzero(d <= 2) / n,
           "identical": 100.0 * np.count_nonzero(d == 0) / n, "maxdiff": int(d.max())}
    if diff_png:
        # Reference dimmed to grey; differences 1-2 yellow, larger ones red (brighter = larger).
        grey = (a.mean(axis=2) * 0.35).astype(np.uint8)
        img = np.stack([grey, grey, grey], axis=2)
        small = (d > 0) & (d <= 2)
        img[small] = (200, 200, 0)
        big = d > 2
        img[big, 0] = np.clip(96 + d[big] * 2, 0, 255).astype(np.uint8)
        img[big, 1] = 0
        img[big, 2] = 0
        Image.fromarray(img).save(diff_png)
    return out


def parse_sizes(s):
    return [tuple(int(v) for v in x.split("x")) for x in s.split(",") if x]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--python", default=sys.executable,
                   help="the interpreter with mujoco installed (default: this one)")
    p.add_argument("--softgl-lib", default=os.path.join(REPO, "target/release/libsoftgl.so"))
    p.add_argument("--reference-lib", default=MESA)
    p.add_argument("--reference-only", action="store_true",
                   help="render the reference on both sides (a determinism check)")
    p.add_argument("--models", default="humanoid,showcase")
    p.add_argument("--sizes", default="640x480,1920x1080")
    p.add_argument("--samples", default="0,4", help="offsamples values")
    p.add_argument("--frames", type=int, default=7, help="timed frames per case (median)")
    p.add_argument("--warmup", type=int, default=1)
    p.add_argument("--lp-threads", default=None,
                   help="LP_NUM_THREADS for the Mesa side (default: llvmpipe's own choice)")
    p.add_argument("--timeout", type=int, default=600, help="seconds per render.py run")
    p.add_argument("--diff", action="store_true", help="write OUT/*.diff.png")
    p.add_argument("--out", default=os.path.join(REPO, "target/mujoco"))
    p.add_argument("--min-within", type=float, default=None,
                   help="fail unless every case has at least this %% of pixels within "
                        "2/255 of the reference (the test command's real-client check)")
    args = p.parse_args()

    os.makedirs(args.out, exist_ok=True)
    mesa_env = {"GALLIUM_DRIVER": "llvmpipe"}
    if args.lp_threads is not None:
        mesa_env["LP_NUM_THREADS"] = str(args.lp_threads)
    ref = {"name": "mesa", "lib": args.reference_lib, "env": mesa_env,
           "dir": lib_dir(args.out, "mesa", args.reference_lib)}
    if args.reference_only:
        other = dict(ref, name="mesa2")
    else:
        if not os.path.exists(args.softgl_lib):
            sys.exit(f"compare.py: {args.softgl_lib} not found (cargo build --release)")
        other = {"name": "softgl", "lib": args.softgl_lib, "env": {},
                 "dir": lib_dir(args.out, "softgl", args.softgl_lib)}

    cases = [(m, s, n) for m in args.models.split(",") for s in parse_sizes(args.sizes)
             for n in (int(x) for x in args.samples.split(","))]
    rows, failures = [], []
    for i, case in enumerate(cases):
        model, (w, h), samples = case
        tag = f"{model}_{w}x{h}_s{samples}"
        sides = [ref, other] if i % 2 == 0 else [other, ref]
        res = {}
        for side in sides:
            png = os.path.join(args.out, f"{tag}.{side['name']}.png")
            if os.path.exists(png):
                os.remove(png)
            res[side["name"]] = run_side(args, side, case, png)
            r = res[side["name"]]
            state = f"{r['median_ms']:.1f} ms/frame" if r.get("ok") else "FAILED"
            print(f"  {tag:28s} {side['name']:7s} {state} ({r['wall_s']} s)",
                  file=sys.stderr, flush=True)
        ra, rb = res[ref["name"]], res[other["name"]]
        row = {"model": model, "size": f"{w}x{h}", "samples": samples,
               "ref": ra, "other": rb}
        for side, r in ((ref, ra), (other, rb)):
            if not r.get("ok"):
                failures.append((tag, side["name"], r["error"]))
        if ra.get("ok") and rb.get("ok"):
            row.update(compare(os.path.join(args.out, f"{tag}.{ref['name']}.png"),
                               os.path.join(args.out, f"{tag}.{other['name']}.png"),
                               os.path.join(args.out, f"{tag}.diff.png") if args.diff
                               else None))
        rows.append(row)

    def ms(r):
        return f"{r['median_ms']:.1f}" if r.get("ok") else "FAILED"

    head = (f"| model | size | offsamples | % within 2/255 | % identical | max diff "
            f"| ms/frame {ref['name']} | ms/frame {other['name']} | ratio |")
    lines = [head, "|" + "---|" * 9]
    for r in rows:
        ok = r["ref"].get("ok") and r["other"].get("ok") and "within2" in r
        ratio = (f"{r['other']['median_ms'] / r['ref']['median_ms']:.2f}"
                 if r["ref"].get("ok") and r["other"].get("ok") else "-")
        if ok:
            cmp = f"{r['within2']:.3f} | {r['identical']:.3f} | {r['maxdiff']}"
        else:
            cmp = f"- | - | {r.get('error', '-')}"
        lines.append(f"| {r['model']} | {r['size']} | {r['samples']} | {cmp} | "
                     f"{ms(r['ref'])} | {ms(r['other'])} | {ratio} |")
    info = ""
    for r in rows:
        if r["ref"].get("ok"):
            info = f"{ref['name']}: {r['ref'].get('gl_renderer')} ({r['ref'].get('lib')})"
            break
    for r in rows:
        if r["other"].get("ok"):
            info += (f"\n{other['name']}: {r['other'].get('gl_renderer')} "
                     f"({r['other'].get('lib')})")
            break
    unstable = [f"{r['model']} {r['size']} s{r['samples']} ({s})" for r in rows
                for s in ("ref", "other") if r[s].get("ok") and not r[s].get("stable")]
    text = "\n".join(lines) + "\n\n" + info + "\n"
    if unstable:
        text += "frames differed between repeats within one run: " + ", ".join(unstable) + "\n"
    grouped = {}  # the same error on many cases is printed once
    for tag, side, err in failures:
        grouped.setdefault((side, err), []).append(tag)
    for (side, err), tags in grouped.items():
        text += (f"\n{side} failed on {', '.join(tags)}:\n    "
                 + err.replace("\n", "\n    ") + "\n")
    print(text)
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write(text)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)

    status = 0
    if failures:
        status = 1
    if args.min_within is not None:
        low = [f"{r['model']} {r['size']} s{r['samples']}: {r.get('within2', 0):.3f}%"
               for r in rows if r.get("within2", 0) < args.min_within]
        if low:
            print(f"below {args.min_within}% within 2/255: " + ", ".join(low))
            status = 1
    if args.reference_only and any(r.get("identical", 0) != 100.0 for r in rows):
        print("reference-only run: the two reference renders differ (not deterministic)")
        status = 1
    sys.exit(status)


if __name__ == "__main__":
    main()
