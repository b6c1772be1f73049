"""Test of Apps/Benchmarks/deepgi_count_instructions.py: runs it under
callgrind, as scripts/count-instructions.sh does, on bunny-floor at 64x48
with one frame of plain VTK and of a one-layer vtkDeepGBufferPass, then
checks that count-instructions.md holds both rows with a positive count,
and that the G-buffer frame counts more instructions than plain VTK's (it
draws the same triangles into more targets and resolves them). Exits
non-zero on failure.

    CheckDeepGICountInstructions.py DATA_DIR OUTPUT_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
METHODS = ["plain VTK", "vtkDeepGBufferPass 1 layer"]


def counts(path):
    """method -> millions of instructions per frame, from the Markdown table."""
    rows = {}
    with open(path) as f:
        for line in f:
            match = re.match(r"\| (.+?) \| (\d+) \| ", line)
            if match:
                rows[match.group(1)] = int(match.group(2))
    return rows


def main(argv):
    data, out = argv[0], argv[1]
    path = os.path.join(out, "count-instructions.md")
    if os.path.exists(path):
        os.remove(path)
    dumps = tempfile.mkdtemp()
    try:
        env = dict(os.environ, LP_NUM_THREADS="0")
        subprocess.check_call(
            ["valgrind", "--tool=callgrind", "--instr-atstart=no", "--log-file=" +
             os.path.join(dumps, "valgrind.log"),
             "--callgrind-out-file=" + os.path.join(dumps, "callgrind.out"), sys.executable,
             os.path.join(HERE, "deepgi_count_instructions.py"), "--data", data,
             "--callgrind-output", os.path.join(dumps, "callgrind.out"), "--scenes",
             "bunny-floor", "--size", "64x48", "--frames", "1", "--methods", ",".join(METHODS),
             "--output", out], env=env)
    finally:
        shutil.rmtree(dumps)
    if not os.path.exists(path):
        print("FAILED: not written:", path)
        return 1
    rows = counts(path)
    print(rows)
    failures = ["no positive count for " + m for m in METHODS if not rows.get(m, 0) > 0]
    if not failures and not rows[METHODS[1]] > rows[METHODS[0]]:
        failures.append("the G-buffer frame counts no more instructions than plain VTK's")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
