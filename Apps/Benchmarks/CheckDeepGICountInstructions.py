"""Test of Apps/Benchmarks/deepgi_count_instructions.py: runs it (it runs
itself under callgrind) on bunny-floor at 64x48 with one frame of plain VTK
and of a one-layer vtkDeepGBufferPass, with --stages, then checks
count-instructions.md: both rows with a positive count, the G-buffer frame
counting more instructions than plain VTK's (it draws the same triangles
into more targets and resolves them), and the G-buffer's stage table:
building the layers its largest stage, its stages adding up to within
10 % of the frame counted without the stage timer. A second run counts
vtkDeepGIPass HIGH_PERFORMANCE with --converge and checks its converge
table: a row for each scenario with 1 to 16 frames and a positive count,
and fewer instructions than as many full frames where the camera stopped
(Converge keeps the layers there). Exits non-zero on failure.

    CheckDeepGICountInstructions.py DATA_DIR OUTPUT_DIR
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
METHODS = ["plain VTK", "vtkDeepGBufferPass 1 layer"]
LAYERS_STAGE = "G-buffer: layers"
GI_METHOD = "vtkDeepGIPass HIGH_PERFORMANCE"
STOP_SCENARIO = "after the camera stops"
JUMP_SCENARIO = "after a jump from another view"


def tables(path):
    """(method -> millions per frame, stage -> millions per frame of the G-buffer)."""
    rows, stages = {}, {}
    with open(path) as f:
        for line in f:
            frame_row = re.match(r"\| (.+?) \| (\d+) \| ", line)
            stage_row = re.match(r"\| (.+?) \| (\d+(?:\.\d+)?) \|$", line.strip())
            if frame_row:
                rows[frame_row.group(1)] = int(frame_row.group(2))
            elif stage_row:
                stages[stage_row.group(1)] = float(stage_row.group(2))
    return rows, stages


def main(argv):
    data, out = argv[0], argv[1]
    path = os.path.join(out, "count-instructions.md")
    if os.path.exists(path):
        os.remove(path)
    subprocess.check_call(
        [sys.executable, os.path.join(HERE, "deepgi_count_instructions.py"), "--data", data,
         "--scenes", "bunny-floor", "--size", "64x48", "--frames", "1", "--methods",
         ",".join(METHODS), "--stages", "--output", out])
    if not os.path.exists(path):
        print("FAILED: not written:", path)
        return 1
    rows, stages = tables(path)
    print(rows, stages)
    failures = ["no positive count for " + m for m in METHODS if not rows.get(m, 0) > 0]
    if not failures and not rows[METHODS[1]] > rows[METHODS[0]]:
        failures.append("the G-buffer frame counts no more instructions than plain VTK's")
    profiled = stages.pop("profiled frame", 0.0)
    if not stages or max(stages, key=stages.get) != LAYERS_STAGE:
        failures.append("the stage table's largest stage is not %s" % LAYERS_STAGE)
    if not failures and not abs(profiled - rows[METHODS[1]]) <= 0.1 * rows[METHODS[1]]:
        failures.append("the stages add up to %g, the frame %d" % (profiled, rows[METHODS[1]]))
    failures += check_converge(data, out, path)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


def check_converge(data, out, path):
    os.remove(path)
    subprocess.check_call(
        [sys.executable, os.path.join(HERE, "deepgi_count_instructions.py"), "--data", data,
         "--scenes", "bunny-floor", "--size", "64x48", "--frames", "1", "--methods",
         GI_METHOD, "--converge", "--output", out])
    with open(path) as f:
        text = f.read()
    print(text)
    rows, _ = tables(path)
    per_frame = rows.get(GI_METHOD, 0)
    scenarios = {m.group(1): (int(m.group(2)), int(m.group(3))) for m in re.finditer(
        r"^\| %s \| (.+?) \| (\d+) \| (\d+) \| [\d.]+ \|$" % GI_METHOD, text, re.M)}
    failures = []
    for scenario in (STOP_SCENARIO, JUMP_SCENARIO):
        frames, count = scenarios.get(scenario, (0, 0))
        if not (1 <= frames <= 16 and count > 0):
            failures.append("converge %r: %d frames, %d million instructions" % (
                scenario, frames, count))
    frames, count = scenarios.get(STOP_SCENARIO, (0, 0))
    if not failures and not count < frames * per_frame:
        failures.append("Converge after the camera stopped counted %d million instructions, "
                        "no fewer than %d frames of %d" % (count, frames, per_frame))
    return failures


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
