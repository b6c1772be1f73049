"""Instructions per frame of plain VTK and the deep G-buffer passes on llvmpipe.

On Mesa's llvmpipe every stage of a frame runs on the CPU, so the
instructions it executes measure its cost without the noise of a shared
machine's clock: the same build, scene and camera give the same count to
within a fraction of a percent. The script runs itself again under
Valgrind's callgrind, with llvmpipe rasterising in the calling thread
(LP_NUM_THREADS=0, so the count does not depend on how threads
interleave); scripts/count-instructions.sh builds what it needs and runs
it. Documentation/performance.md explains the results.

    scripts/count-instructions.sh --scenes bunny-floor --methods "plain VTK,2 layers"

The scenes, methods (--methods: substrings of the frame benchmark's method
names) and the camera orbit are deepgi_benchmark_frame.py's. For each scene
and method: the method becomes the renderer's pass, the camera goes to the
start, 3 warm-up frames (shader compilation) are rendered uncounted, then
--frames frames are counted (callgrind's instrumentation on), and the count
is dumped. Printed and written to OUTDIR/count-instructions.md: per scene,
millions of instructions per frame and the ratio to plain VTK's.

With --stages each deep method's frames are counted a second time with a
vtkDeepGIStageTimer attached (glFinish around every stage) whose stage
boundaries dump callgrind's counts (DumpCallgrindCounts), and a second
table gives the millions of instructions per frame of each stage
(exclusive of the stages nested in it), in the order the stages first ran,
and of the whole profiled frame.

With --converge each vtkDeepGIPass preset's Converge is counted in the
frame benchmark's two scenarios (after the camera stops, after a jump from
another view; each after one uncounted Converge): the frames it
rendered, its instructions and those in the preset's counted frames ("GI
frames").
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402
import vtkdeepgi  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderer  # noqa: E402

import deepgi_benchmark_frame as frame  # noqa: E402
from deepgi_benchmark_image import use_default_properties  # noqa: E402

WARM_UP_FRAMES = 3


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--data", required=True, help="the project's Testing/Data")
    parser.add_argument("--scenes", default="bunny-floor,headsq",
                        help="built-in scenes of deepgi_benchmark_frame.py (comma list)")
    parser.add_argument("--size", default="640x480", help="window size, WIDTHxHEIGHT")
    parser.add_argument("--frames", type=int, default=2, help="counted frames per method")
    parser.add_argument("--methods", default="",
                        help="comma list of substrings of the frame benchmark's method "
                             "names (default: every method)")
    parser.add_argument("--stages", action="store_true",
                        help="also count each deep method's stages (a second run per method)")
    parser.add_argument("--converge", action="store_true",
                        help="also count the vtkDeepGIPass presets' Converge in the frame "
                             "benchmark's two scenarios")
    parser.add_argument("--callgrind-output", help=argparse.SUPPRESS)  # set under callgrind
    parser.add_argument("--output", default="output", help="directory of count-instructions.md")
    args = parser.parse_args()
    args.size = frame.parse_sizes(parser, args.size)[0]
    if args.frames < 1:
        parser.error("--frames must be at least 1")
    args.method_words = [w for w in args.methods.split(",") if w]
    return args


def run_under_callgrind():
    """Runs this script with these arguments under callgrind; its exit status."""
    if not shutil.which("valgrind"):
        sys.exit("deepgi_count_instructions.py: needs Valgrind (Debian: apt-get install valgrind; "
                 "scripts/count-instructions.sh installs it)")
    dumps = tempfile.mkdtemp()
    try:
        prefix = os.path.join(dumps, "callgrind.out")
        log = os.path.join(dumps, "valgrind.log")
        status = subprocess.call(
            ["valgrind", "--tool=callgrind", "--instr-atstart=no", "--log-file=" + log,
             "--callgrind-out-file=" + prefix, sys.executable, os.path.abspath(__file__)] +
            sys.argv[1:] + ["--callgrind-output", prefix],
            env=dict(os.environ, LP_NUM_THREADS="0"))
        if status != 0 and os.path.exists(log):
            with open(log) as f:
                sys.stderr.write(f.read())
        return status
    finally:
        shutil.rmtree(dumps)


def callgrind(*words):
    subprocess.run(["callgrind_control"] + list(words) + [str(os.getpid())],
                   stdout=subprocess.DEVNULL, check=True)


def dump_number(path):
    return int(path.rsplit(".", 1)[1])


def take_dumps(prefix, expected_label):
    """[(label, instructions)] of callgrind's dumps so far, in order, removed.

    A stage boundary's dump (vtkDeepGIStageTimer::DumpCallgrindCounts) is
    labelled with its stage; the one callgrind_control -d writes last gets
    `expected_label`. Waits for that last dump, written asynchronously.
    """
    for _ in range(100):
        paths = sorted(glob.glob(prefix + ".*"), key=dump_number)
        dumps = [read_dump(path) for path in paths]
        if dumps and None not in dumps and dumps[-1][0] is None:
            for path in paths:
                os.remove(path)
            return [(label or expected_label, count) for label, count in dumps]
        time.sleep(0.1)
    sys.exit("deepgi_count_instructions.py: no complete callgrind dump %s.*" % prefix)


CLIENT_REQUEST = re.compile(r"^desc: Trigger: Client Request: (.*)$")


def read_dump(path):
    """(the stage label or None, total instructions), or None while incomplete."""
    label, total = None, None
    with open(path) as dump:
        for line in dump:
            match = CLIENT_REQUEST.match(line.rstrip("\n"))
            if match:
                label = match.group(1)
            elif line.startswith("totals:"):
                total = int(line.split()[1])
    return None if total is None else (label, total)


def count_call(args, call, label):
    """(call()'s result, [(label, count)] of the instructions it executed):
    callgrind's instrumentation is on for the call only."""
    for path in glob.glob(args.callgrind_output + ".*"):
        os.remove(path)  # stage boundaries passed while counting was off
    callgrind("-i", "on")
    result = call()
    callgrind("-i", "off")
    callgrind("-d")
    return result, take_dumps(args.callgrind_output, label)


def count_frames(args, orbit):
    """Instructions of --frames frames of the current pass: [(label, count)]."""
    orbit.restart()
    orbit.frames(WARM_UP_FRAMES)
    _, dumps = count_call(args, lambda: orbit.frames(args.frames),
                          vtkdeepgi.vtkDeepGIStageTimer.GetOutsideStagesLabel())
    return dumps


def count_converge(args, orbit, m):
    """[(scenario, frames, instructions)] of the frame benchmark's Converge
    scenarios, each counted after one uncounted Converge."""
    def counted(scenario, run):
        frames, dumps = count_call(args, run, scenario)
        return frames, sum(count for _, count in dumps)

    return [(scenario, frames, count) for scenario, (frames, count)
            in frame.converge_scenarios(orbit, m.pass_, counted)]


def count_stages(args, orbit, m):
    """{stage: instructions per frame} of a deep method, in the order they first ran."""
    timer = vtkdeepgi.vtkDeepGIStageTimer()
    timer.DumpCallgrindCountsOn()
    m.gbuffer.SetStageTimer(timer)
    stages = {}
    for label, count in count_frames(args, orbit):
        stages[label] = stages.get(label, 0) + count / args.frames
    m.gbuffer.SetStageTimer(None)
    return stages


def count_scene(args, scene):
    """Returns (display name, triangles, [(method, instructions per frame)],
    [(method, {stage: instructions per frame})], [(method, instructions per
    frame, count_converge's list)])."""
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(*args.size)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    name, keep = frame.populate(renderer, scene, args.data)
    use_default_properties(renderer)
    renderer.ResetCameraClippingRange()
    window.Render()
    bounds = renderer.ComputeVisiblePropBounds()
    radius = 0.05 * np.linalg.norm(np.array(bounds[1::2]) - np.array(bounds[0::2]))
    orbit, rows, stage_rows, converge_rows = frame.Orbit(window, renderer), [], [], []
    for m in frame.make_methods(radius, args.method_words):
        renderer.SetPass(m.pass_)
        counts = count_frames(args, orbit)
        rows.append((m.name, sum(count for _, count in counts) / args.frames))
        if args.stages and m.gbuffer:
            stage_rows.append((m.name, count_stages(args, orbit, m)))
        if args.converge and isinstance(m.pass_, vtkdeepgi.vtkDeepGIPass):
            converge_rows.append((m.name, rows[-1][1], count_converge(args, orbit, m)))
        renderer.SetPass(None)
        if m.pass_:
            m.pass_.ReleaseGraphicsResources(window)
    triangles = frame.count_triangles(renderer)
    del keep
    return name, triangles, rows, stage_rows, converge_rows


def user_arguments():
    """The command line without the options the wrapper adds."""
    words, skip = [], False
    for word in sys.argv[1:]:
        if skip:
            skip = False
        elif word in ("--data", "--callgrind-output"):
            skip = True
        else:
            words.append(word if word and " " not in word else '"%s"' % word)
    return words


def markdown(args, results):
    lines = ["Command: `scripts/count-instructions.sh %s`; %s." % (
        " ".join(user_arguments()), time.strftime("%Y-%m-%d %H:%M:%S")), ""]
    for name, triangles, rows, stage_rows, converge_rows in results:
        lines += ["#### %s, %d triangles, %dx%d" % ((name, triangles) + args.size), "",
                  "| method | millions of instructions per frame | x plain |", "|---|---|---|"]
        plain = dict(rows).get("plain VTK")
        for method, count in rows:
            ratio = "%.2f" % (count / plain) if plain else "—"
            lines.append("| %s | %.0f | %s |" % (method, count / 1e6, ratio))
        lines.append("")
        if stage_rows:
            lines += stage_table(stage_rows) + [""]
        if converge_rows:
            lines += converge_table(converge_rows) + [""]
    return "\n".join(lines)


def converge_table(converge_rows):
    """Converge's frames and instructions, also in frames of the method."""
    lines = ["Converging a still image: Converge(renderer, %d, %.2f / 255) after %d orbit "
             "frames, where the orbit stopped, and at the start camera after orbit frames %g "
             "degrees away, each after one uncounted Converge:"
             % (frame.CONVERGE_FRAMES, frame.CONVERGE_TOLERANCE * 255.0, frame.WARM_UP_FRAMES,
                frame.JUMP_DEGREES), "",
             "| method | scenario | frames | millions of instructions | GI frames |",
             "|---|---|---|---|---|"]
    for method, per_frame, scenarios in converge_rows:
        for scenario, frames, count in scenarios:
            lines.append("| %s | %s | %d | %.0f | %.2f |" % (
                method, scenario, frames, count / 1e6, count / per_frame))
    return lines


def stage_table(stage_rows):
    """Millions of instructions per frame of each stage (rows) and method."""
    outside = vtkdeepgi.vtkDeepGIStageTimer.GetOutsideStagesLabel()
    names = list(dict.fromkeys(stage for _, stages in stage_rows for stage in stages
                               if stage != outside)) + [outside]
    lines = ["Stages, millions of instructions per frame (glFinish around every stage):", "",
             "| stage | " + " | ".join(method for method, _ in stage_rows) + " |",
             "|---|" + "---|" * len(stage_rows)]
    for stage in names:
        cells = [stages.get(stage) for _, stages in stage_rows]
        lines.append("| %s | %s |" % (stage, " | ".join(
            "—" if c is None else "%.1f" % (c / 1e6) for c in cells)))
    lines.append("| profiled frame | %s |" % " | ".join(
        "%.0f" % (sum(stages.values()) / 1e6) for _, stages in stage_rows))
    return lines


def main():
    args = parse_arguments()
    if not args.callgrind_output:
        return run_under_callgrind()
    if args.stages and not vtkdeepgi.vtkDeepGIStageTimer.CanDumpCallgrindCounts():
        sys.exit("deepgi_count_instructions.py: --stages needs a library built with "
                 "Valgrind's valgrind/callgrind.h")
    results = [count_scene(args, scene) for scene in args.scenes.split(",") if scene]
    text = markdown(args, results)
    print(text)
    os.makedirs(args.output, exist_ok=True)
    frame.write_atomically(os.path.join(args.output, "count-instructions.md"), text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
