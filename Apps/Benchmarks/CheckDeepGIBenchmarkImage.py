"""Test of Apps/Benchmarks/deepgi_benchmark_image.py: runs it on headsq at
64x48 with 4 rays per pixel, one bounce, one frame and one round, then
checks that benchmark-image.md holds a row for every method with an RMSE in
[0, 1] (on the pixels the second layer changes: in [0, 1] or nan when
there are none) and a positive frame time, that the scene's strip was written, and
that benchmark-image-plot.png shows the curves of vtkSSAOPass and of the
vtkDeepGIPass presets (pixels of their colours). Exits non-zero on failure.

    CheckDeepGIBenchmarkImage.py DATA_DIR OUTPUT_DIR
"""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

HERE = os.path.dirname(os.path.abspath(__file__))
METHODS = ["plain VTK", "vtkSSAOPass K16", "vtkSSAOPass K64", "vtkDeepGIPass BALANCED 1 layer",
           "vtkDeepGIPass HIGH_PERFORMANCE", "vtkDeepGIPass BALANCED", "vtkDeepGIPass HIGH_QUALITY",
           "vtkDeepGIPass BALANCED interactive"]
# The plot's colours of the vtkSSAOPass curve and of the presets' curve
# (deepgi_benchmark_image.save_plot: the families in the order of the rows).
CURVES = {"vtkSSAOPass": (40, 90, 200), "vtkDeepGIPass presets": (230, 140, 20)}


def check_markdown(path):
    rows = {}
    with open(path) as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) == 9 and cells[0] == "headsq" and cells[1] in METHODS:
                rows[cells[1]] = cells
    failures = ["no row for " + m for m in METHODS if m not in rows]
    for name, cells in rows.items():
        ms, rmse, rmse_changed = float(cells[2]), float(cells[4]), float(cells[8])
        if not (ms > 0.0 and 0.0 <= rmse <= 1.0):
            failures.append("%s: %s ms, RMSE %s" % (name, cells[2], cells[4]))
        # No pixel the second layer changes gives nan.
        if not (np.isnan(rmse_changed) or 0.0 <= rmse_changed <= 1.0):
            failures.append("%s: RMSE on changed pixels %s" % (name, cells[8]))
    return failures


def check_plot(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    failures = []
    if image.GetDimensions()[:2] != (900, 600):
        failures.append("the plot is %s pixels" % (image.GetDimensions()[:2],))
    for name, colour in CURVES.items():
        count = int((np.abs(pixels - np.array(colour)).max(axis=1) <= 12).sum())
        if count < 40:
            failures.append("the plot shows %d pixels of the %s curve" % (count, name))
    return failures


def main(argv):
    data, out = argv[0], argv[1]
    paths = [os.path.join(out, name) for name in
             ("benchmark-image.md", "benchmark-image-plot.png", "headsq.png")]
    for path in paths:
        if os.path.exists(path):
            os.remove(path)
    subprocess.check_call([sys.executable, os.path.join(HERE, "deepgi_benchmark_image.py"),
                           "--data", data, "--scenes", "headsq", "--size", "64x48",
                           "--samples", "4", "--bounces", "1", "--frames", "1", "--rounds", "1",
                           "--output", out])
    missing = [p for p in paths if not os.path.exists(p)]
    failures = ["not written: " + p for p in missing]
    if not missing:
        failures += check_markdown(paths[0]) + check_plot(paths[1])
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
