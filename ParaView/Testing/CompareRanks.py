"""The deep GI view's still is the same on 1, 2 and 4 MPI ranks and through
a client connected to pvserver: compares the images CheckDeepGIRanks.py
wrote (NAME.png) with the one-rank pvbatch image (ranks-1.png). Each must
equal it within 1/255 in every channel of every pixel; the largest
difference and the share of pixels that differ at all are printed.

    /usr/bin/python3 CompareRanks.py DIR ranks-2 ranks-4 client-server-2
"""
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    columns, rows, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(rows, columns, -1)[:, :, :3]


directory = sys.argv[1]
one = read(os.path.join(directory, "ranks-1.png")).astype(int)
failures = 0
for name in sys.argv[2:]:
    other = read(os.path.join(directory, name + ".png")).astype(int)
    if other.shape != one.shape:
        print("FAILED: %s: %s pixels against %s" % (name, other.shape, one.shape))
        failures += 1
        continue
    difference = numpy.abs(other - one)
    largest = int(difference.max())
    differing = float((difference.max(axis=2) > 0).mean())
    ok = largest <= 1
    print("%s: %s against ranks-1: largest difference %d/255, %.3f %% of the pixels differ"
          % ("ok" if ok else "FAILED", name, largest, 100.0 * differing))
    failures += 0 if ok else 1
print("%d failure(s)" % failures)
sys.exit(1 if failures else 0)
