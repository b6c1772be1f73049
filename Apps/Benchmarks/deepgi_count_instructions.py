"""Instructions per frame of plain VTK and the deep G-buffer passes on llvmpipe.

On Mesa's llvmpipe every stage of a frame runs on the CPU, so the
instructions it executes measure its cost without the noise of a shared
machine's clock: the same build, scene and camera give the same count to
within a fraction of a percent. scripts/count-instructions.sh runs this
script under Valgrind's callgrind with llvmpipe rasterising in the calling
thread (LP_NUM_THREADS=0); Documentation/performance.md explains the
results.

    scripts/count-instructions.sh --scenes bunny-floor --methods "plain VTK,2 layers"

The scenes, methods (--methods: substrings of the frame benchmark's method
names) and the camera orbit are deepgi_benchmark_frame.py's. For each scene
and method: the method becomes the renderer's pass, the camera goes to the
start, 3 warm-up frames (shader compilation) are rendered uncounted, then
--frames frames are counted (callgrind's instrumentation on), and the count
is dumped. Printed and written to OUTDIR/count-instructions.md: per scene,
millions of instructions per frame and the ratio to plain VTK's.
"""

import argparse
import glob
import os
import subprocess
import sys
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
    parser.add_argument("--callgrind-output", required=True,
                        help="the --callgrind-out-file prefix callgrind writes its dumps to")
    parser.add_argument("--output", default="output", help="directory of count-instructions.md")
    args = parser.parse_args()
    args.size = frame.parse_sizes(parser, args.size)[0]
    if args.frames < 1:
        parser.error("--frames must be at least 1")
    args.method_words = [w for w in args.methods.split(",") if w]
    return args


def callgrind(*words):
    subprocess.run(["callgrind_control"] + list(words) + [str(os.getpid())],
                   stdout=subprocess.DEVNULL, check=True)


def dumped_instructions(prefix, index):
    """The total of callgrind's dump number `index` (written by callgrind_control -d)."""
    path = "%s.%d" % (prefix, index)
    for _ in range(100):
        if os.path.exists(path):
            with open(path) as dump:
                for line in dump:
                    if line.startswith("totals:"):
                        return int(line.split()[1])
        time.sleep(0.1)
    sys.exit("deepgi_count_instructions.py: no callgrind dump %s" % path)


def count_scene(args, scene, dumps):
    """Returns (display name, triangles, [(method, instructions per frame)])."""
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
    orbit, rows = frame.Orbit(window, renderer), []
    for m in frame.make_methods(radius, args.method_words):
        renderer.SetPass(m.pass_)
        orbit.restart()
        orbit.frames(WARM_UP_FRAMES)
        callgrind("-i", "on")
        orbit.frames(args.frames)
        callgrind("-i", "off")
        callgrind("-d")
        dumps[0] += 1
        rows.append((m.name, dumped_instructions(args.callgrind_output, dumps[0]) / args.frames))
        renderer.SetPass(None)
        if m.pass_:
            m.pass_.ReleaseGraphicsResources(window)
    triangles = frame.count_triangles(renderer)
    del keep
    return name, triangles, rows


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
    for name, triangles, rows in results:
        lines += ["#### %s, %d triangles, %dx%d" % ((name, triangles) + args.size), "",
                  "| method | millions of instructions per frame | x plain |", "|---|---|---|"]
        plain = dict(rows).get("plain VTK")
        for method, count in rows:
            ratio = "%.2f" % (count / plain) if plain else "—"
            lines.append("| %s | %.0f | %s |" % (method, count / 1e6, ratio))
        lines.append("")
    return "\n".join(lines)


def main():
    args = parse_arguments()
    dumps = [0]
    results = [count_scene(args, scene, dumps) for scene in args.scenes.split(",") if scene]
    text = markdown(args, results)
    print(text)
    os.makedirs(args.output, exist_ok=True)
    frame.write_atomically(os.path.join(args.output, "count-instructions.md"), text)
    for path in glob.glob(args.callgrind_output + "*"):
        os.remove(path)


if __name__ == "__main__":
    main()
