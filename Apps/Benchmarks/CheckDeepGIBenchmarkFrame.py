"""Test of Apps/Benchmarks/deepgi_benchmark_frame.py: runs it on bunny-floor
at 64x48 with one frame and one round, then checks that benchmark-frame.md
and benchmark-frame.csv were written and hold every method: a row of the
frame table each, a positive frame time, textures and a "G-buffer: layers"
stage for the deep methods, a converged frame count in both scenarios for
the vtkDeepGIPass presets. Exits non-zero on failure.

    CheckDeepGIBenchmarkFrame.py DATA_DIR OUTPUT_DIR
"""
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PLAIN = ["plain VTK", "vtkSSAOPass K16", "vtkSSAOPass K64"]
DEEP = ["vtkDeepGBufferPass 1 layer", "vtkDeepGBufferPass 2 layers",
        "vtkDeepGBufferPass 2 layers DEPTH_PEEL", "vtkDeepGBufferPass 2 layers REPROJECT",
        "vtkDeepAmbientObscurancePass 1 layer",
        "vtkDeepAmbientObscurancePass 2 layers", "vtkDeepRadiosityPass"]
GI = ["vtkDeepGIPass HIGH_PERFORMANCE", "vtkDeepGIPass BALANCED", "vtkDeepGIPass HIGH_QUALITY"]


def check_csv(path):
    with open(path, newline="") as f:
        rows = {row["method"]: row for row in csv.DictReader(f)}
    failures = []
    if sorted(rows) != sorted(PLAIN + DEEP + GI):
        failures.append("the CSV's methods are %s" % sorted(rows))
    for name, row in rows.items():
        if not float(row["frame_ms"]) > 0.0:
            failures.append("%s: frame_ms %s" % (name, row["frame_ms"]))
        deep = name in DEEP + GI
        if deep and not (float(row["texture_mib"] or 0) > 0.0 and row["G-buffer: layers [ms]"]):
            failures.append("%s: no textures or no G-buffer: layers stage" % name)
        for column in ("converge_stop_frames", "converge_jump_frames"):
            if (name in GI) != bool(row[column]):
                failures.append("%s: %s %r" % (name, column, row[column]))
            elif name in GI and not 1 <= int(row[column]) <= 16:
                failures.append("%s: %s %s" % (name, column, row[column]))
    return failures


def check_markdown(path):
    with open(path) as f:
        text = f.read()
    failures = ["no frame-table row for " + name for name in PLAIN + DEEP + GI
                if "\n| %s | " % name not in text]
    for expected in ("OpenGL renderer: ", "| G-buffer: layers | ", "| outside the stages",
                     "| method | scenario | frames | seconds | GI frames |"):
        if expected not in text:
            failures.append("the markdown lacks %r" % expected)
    return failures


def main(argv):
    data, out = argv[0], argv[1]
    paths = [os.path.join(out, "benchmark-frame." + ext) for ext in ("md", "csv")]
    for path in paths:
        if os.path.exists(path):
            os.remove(path)
    subprocess.check_call([sys.executable, os.path.join(HERE, "deepgi_benchmark_frame.py"),
                           "--data", data, "--scenes", "bunny-floor", "--sizes", "64x48",
                           "--frames", "1", "--rounds", "1", "--output", out])
    missing = [p for p in paths if not os.path.exists(p)]
    failures = ["not written: " + p for p in missing]
    if not missing:
        failures += check_markdown(paths[0]) + check_csv(paths[1])
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
