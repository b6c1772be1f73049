"""Test of Examples/Python/deepgi_capture_layers.py: runs it at 200x150,
reads the .vti it wrote back with vtkXMLImageDataReader and checks the
image has the window's dimensions, that every per-layer array of
CaptureLayers (the names of Core/vtkDeepGICaptureNames.h) exists for
layers 0 and 1 with one tuple per pixel, and that both layers hold
surfaces, layer 1 behind layer 0. Exits non-zero on failure.
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

HERE = os.path.dirname(os.path.abspath(__file__))
WIDTH, HEIGHT = 200, 150
# CaptureLayers' per-layer quantities (Reflectivity only while
# WriteReflectivity is on), as Core/vtkDeepGICaptureNames.h names them.
QUANTITIES = ("Radiance", "Albedo", "Normal", "Ambient", "Depth", "Valid")


def main(argv):
    out = argv[0]
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "layers.vti")
    if os.path.exists(path):
        os.remove(path)
    subprocess.check_call([sys.executable, os.path.join(HERE, "deepgi_capture_layers.py"),
                           "--size", "%dx%d" % (WIDTH, HEIGHT), "--output", path])
    if not os.path.exists(path):
        print("FAILED: %s was not written" % path)
        return 1
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    failures = []
    dimensions = image.GetDimensions()
    print("dimensions", dimensions)
    if dimensions != (WIDTH, HEIGHT, 1):
        failures.append("dimensions %s, expected (%d, %d, 1)" % (dimensions, WIDTH, HEIGHT))
    data = image.GetPointData()
    for layer in (0, 1):
        for quantity in QUANTITIES:
            name = "%s_%d" % (quantity, layer)
            array = data.GetArray(name)
            if array is None or array.GetNumberOfTuples() != WIDTH * HEIGHT:
                failures.append("no array %s with %d tuples" % (name, WIDTH * HEIGHT))
    if not failures:
        valid = [vtk_to_numpy(data.GetArray("Valid_%d" % j)) > 0 for j in (0, 1)]
        depth = [vtk_to_numpy(data.GetArray("Depth_%d" % j)) for j in (0, 1)]
        both = valid[0] & valid[1]
        print("surface pixels: layer 0 %d, layer 1 %d" % (valid[0].sum(), valid[1].sum()))
        if valid[0].mean() < 0.2 or valid[1].sum() < 500:
            failures.append("a layer is (nearly) empty")
        elif not (depth[1][both] > depth[0][both]).all():
            failures.append("layer 1 is not behind layer 0 everywhere")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
