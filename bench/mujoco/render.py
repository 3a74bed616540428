#!/usr/bin/env python3
"""Renders one MuJoCo model through whichever libOSMesa the dynamic loader finds.

Run it with MUJOCO_GL=osmesa, PYOPENGL_PLATFORM=osmesa and the library directory first
in LD_LIBRARY_PATH (compare.py does this). The directory must hold both libOSMesa.so
and libOSMesa.so.8: PyOpenGL dlopens "libOSMesa.so" first and falls back to the
versioned names, so a directory with only libOSMesa.so.8 silently loads the system's
Mesa through /usr/lib's libOSMesa.so.

For the case (model, width x height, offsamples) it loads bench/mujoco/models/MODEL.xml,
sets the offscreen buffer size and sample count in the model, resets, applies a
seeded random control for a fixed number of steps (so the pose is the same on every
run), renders WARMUP frames and then FRAMES timed frames of the same scene with
mujoco.Renderer, saves the last one as OUT.png and prints one JSON line:
  {"ok": true, "ms": [...per frame...], "median_ms": ..., "lib": "/path/of/libOSMesa",
   "gl_renderer": ..., "stable": true}
`stable` says whether every timed frame equalled the first. On failure it prints
{"ok": false, "error": "Type: message"} and exits 1.
"""
import argparse
import json
import os
import statistics
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))

# Steps of simulation before the rendered frame, and the seed of the random controls.
MODELS = {
    "humanoid": {"steps": 50, "seed": 7},
    "showcase": {"steps": 150, "seed": 11},
}


def loaded_lib():
    """The libOSMesa file actually mapped into this process (to prove which side ran)."""
    with open("/proc/self/maps") as f:
        for line in f:
            path = line.split()[-1] if len(line.split()) >= 6 else ""
            name = os.path.basename(path)
            if "OSMesa" in name or "softgl" in name:
                return os.path.realpath(path)
    return None


def gl_strings():
    try:
        from OpenGL import GL
        return {
            "gl_vendor": GL.glGetString(GL.GL_VENDOR).decode(),
            "gl_renderer": GL.glGetString(GL.GL_RENDERER).decode(),
            "gl_version": GL.glGetString(GL.GL_VERSION).decode(),
        }
    except Exception as e:  # the strings are informative only
        return {"gl_strings_error": repr(e)}


def render(args):
    import numpy as np
    import mujoco
    from PIL import Image

    spec = MODELS[args.model]
    model = mujoco.MjModel.from_xml_path(os.path.join(HERE, "models", args.model + ".xml"))
    model.vis.global_.offwidth = args.width
    model.vis.global_.offheight = args.height
    model.vis.quality.offsamples = args.samples
    data = mujoco.MjData(model)
    mujoco.mj_resetData(model, data)
    rng = np.random.default_rng(spec["seed"])
    for _ in range(spec["steps"]):
        if model.nu:
            data.ctrl[:] = rng.uniform(-1, 1, model.nu)
        mujoco.mj_step(model, data)

    renderer = mujoco.Renderer(model, args.height, args.width)
    try:
        info = gl_strings()  # the Renderer's context is current now
        renderer.update_scene(data, camera="bench")
        for _ in range(args.warmup):
            renderer.render()
        times, stable, first = [], True, None
        for _ in range(max(1, args.frames)):
            t0 = time.perf_counter()
            img = renderer.render()
            times.append((time.perf_counter() - t0) * 1000.0)
            if first is None:
                first = img.copy()
            else:
                stable = stable and np.array_equal(img, first)
        Image.fromarray(img).save(args.out)
    finally:
        renderer.close()
    return dict(ok=True, ms=[round(t, 3) for t in times],
                median_ms=round(statistics.median(times), 3), stable=stable,
                lib=loaded_lib(), **info)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--model", choices=sorted(MODELS), required=True)
    p.add_argument("--width", type=int, default=640)
    p.add_argument("--height", type=int, default=480)
    p.add_argument("--samples", type=int, default=0, help="offsamples (MSAA samples)")
    p.add_argument("--frames", type=int, default=5, help="timed frames (median reported)")
    p.add_argument("--warmup", type=int, default=1)
    p.add_argument("--out", required=True, help="PNG to write")
    args = p.parse_args()
    if os.environ.get("MUJOCO_GL") != "osmesa":
        sys.exit("render.py: set MUJOCO_GL=osmesa (and PYOPENGL_PLATFORM=osmesa)")
    try:
        result = render(args)
    except BaseException as e:  # mujoco.FatalError derives from Exception; be wide
        if isinstance(e, KeyboardInterrupt):
            raise
        traceback.print_exc(file=sys.stderr)
        print(json.dumps({"ok": False, "error": f"{type(e).__module__}.{type(e).__name__}: {e}",
                          "lib": loaded_lib()}), flush=True)
        sys.exit(1)
    print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
