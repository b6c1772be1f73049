"""Checks what the main job (deepgi-render) writes, numerically.

    CheckDeepGIRender.py DEEPGI_RENDER OUTPUT_DIR

1. Defaults at 200 x 150 (at most 6 GI frames): plain.png and gi.png of
   the window's size, compare.png 2 x 2 panels, gbuffer.png one row of 4
   half-size panels per layer (2 layers); the GI image differs from plain
   VTK on the surfaces; the ambient-visibility panel shows occlusion and
   the indirect-light panel shows light; no partial file is left.
2. --preset off into the same folder: plain.png and gbuffer.png only; the
   GI files of the first run are gone, not left beside the new ones.
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

W, H = 200, 150


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)
    return pixels.reshape(h, w, -1)[::-1]  # rows top to bottom


def main(argv):
    exe, out = argv
    failures = []

    def check(ok, what):
        print("%s: %s" % ("ok" if ok else "FAILED", what))
        if not ok:
            failures.append(what)

    run = subprocess.run([exe, "--size", "%dx%d" % (W, H), "--max-frames", "6",
                          "--output", out], capture_output=True, text=True)
    print(run.stdout, run.stderr)
    check(run.returncode == 0, "deepgi-render exits 0")
    names = sorted(os.listdir(out))
    check(names == ["compare.png", "gbuffer.png", "gi.png", "plain.png"],
          "exactly the four files, no partial one: %s" % names)
    plain, gi = read(os.path.join(out, "plain.png")), read(os.path.join(out, "gi.png"))
    compare, sheet = read(os.path.join(out, "compare.png")), read(os.path.join(out, "gbuffer.png"))
    check(plain.shape == (H, W, 3) and gi.shape == (H, W, 3), "plain and GI are %dx%d" % (W, H))
    check(compare.shape == (2 * H, 2 * W, 3), "compare.png is 2 x 2 panels")
    check(sheet.shape == (2 * (H // 2), 4 * (W // 2), 3), "gbuffer.png: 2 layers x 4 quantities")
    check(np.array_equal(compare[30:H, :W], plain[30:H]),
          "compare.png's top-left panel is plain.png (below its label)")
    surface = plain.max(axis=2) > 0
    changed = np.abs(gi - plain).max(axis=2) > 2
    fraction = changed[surface].mean()
    check(fraction > 0.3, "GI changes %.0f %% of the surface pixels by more than 2 levels"
          % (100 * fraction))
    visibility = compare[H + 30:, :W].mean(axis=2)
    check((visibility < 160).mean() > 0.02,
          "the ambient-visibility panel is dark (occluded) on %.1f %% of its pixels"
          % (100 * (visibility < 160).mean()))
    indirect = compare[H + 30:, W:].max(axis=2)
    check((indirect > 64).mean() > 0.05,
          "the indirect-light panel is lit on %.1f %% of its pixels" % (100 * (indirect > 64).mean()))

    run = subprocess.run([exe, "--preset", "off", "--size", "%dx%d" % (W, H), "--output", out],
                         capture_output=True, text=True)
    print(run.stdout, run.stderr)
    names = sorted(os.listdir(out))
    check(run.returncode == 0 and names == ["gbuffer.png", "plain.png"],
          "--preset off leaves only its own files: %s" % names)

    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
