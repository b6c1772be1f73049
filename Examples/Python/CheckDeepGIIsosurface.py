"""Test of Examples/Python/deepgi_isosurface.py: runs it with a small
window, 4 frames and --plain, then checks that gi.png exists, is not blank
(the iso-surface covers more than 10 % of the image and its pixels vary)
and differs from the plain VTK render (more than 5 % of the surface pixels
by more than 4 of 255). Exits non-zero on failure.
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

HERE = os.path.dirname(os.path.abspath(__file__))


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(float)[:, :3]


def main(argv):
    data, out = argv[0], argv[1]
    os.makedirs(out, exist_ok=True)
    gi_png, plain_png = os.path.join(out, "gi.png"), os.path.join(out, "plain.png")
    for f in (gi_png, plain_png):
        if os.path.exists(f):
            os.remove(f)
    subprocess.check_call([sys.executable, os.path.join(HERE, "deepgi_isosurface.py"),
                           "--data", data, "--frames", "4", "--size", "200x150",
                           "--preset", "high_performance",
                           "--output", gi_png, "--plain", plain_png])
    if not os.path.exists(gi_png):
        print("FAILED: gi.png was not written")
        return 1
    gi, plain = read(gi_png), read(plain_png)
    background = np.array([0.32, 0.34, 0.43]) * 255.0
    surface = np.abs(plain - background).max(axis=1) > 3
    changed = np.abs(gi - plain).max(axis=1) > 4
    print("surface %.1f %% of the image, gi std %.1f, %.1f %% of the surface changed by GI" % (
        100.0 * surface.mean(), gi[surface].std(), 100.0 * changed[surface].mean()))
    failures = []
    if surface.mean() < 0.10 or gi[surface].std() < 5.0:
        failures.append("gi.png is blank")
    if changed[surface].mean() < 0.05:
        failures.append("gi.png does not differ from the plain render")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
