"""Test of Examples/Cxx/OneLineRecipe.cxx: runs it, writing gi.png and the
plain VTK render plain.png, then checks that gi.png exists with plain.png's
size, that the scene covers the contact region (the box around the image
centre, where the camera looks at the point the sphere rests on) and that
GI changes that region measurably: its mean change is more than 8 of 255
and more than three times the mean change of the rest of the image.
Exits non-zero on failure.
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    width, height, _ = reader.GetOutput().GetDimensions()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(float)
    return pixels[:, :3].reshape(height, width, 3)


def main(argv):
    program, out = argv[0], argv[1]
    os.makedirs(out, exist_ok=True)
    gi_png, plain_png = os.path.join(out, "gi.png"), os.path.join(out, "plain.png")
    for f in (gi_png, plain_png):
        if os.path.exists(f):
            os.remove(f)
    subprocess.check_call([program, gi_png, plain_png])
    if not os.path.exists(gi_png) or not os.path.exists(plain_png):
        print("FAILED: gi.png or plain.png was not written")
        return 1
    gi, plain = read(gi_png), read(plain_png)
    if gi.shape != plain.shape:
        print("FAILED: gi.png is %s, plain.png %s" % (gi.shape, plain.shape))
        return 1
    height, width, _ = gi.shape
    contact = np.zeros((height, width), dtype=bool)
    contact[int(0.4 * height):int(0.6 * height), int(0.4 * width):int(0.6 * width)] = True
    change = np.abs(gi - plain).mean(axis=2)
    covered = plain.max(axis=2) > 0  # VTK's default background is black
    print("contact region: %.0f %% covered, mean change %.2f of 255; rest: mean change %.2f" % (
        100.0 * covered[contact].mean(), change[contact].mean(), change[~contact].mean()))
    failures = []
    if covered[contact].mean() < 0.9:
        failures.append("the scene does not cover the contact region")
    if change[contact].mean() < 8.0 or change[contact].mean() < 3.0 * change[~contact].mean():
        failures.append("GI does not change the contact region measurably")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
