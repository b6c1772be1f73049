"""The frame time of plain VTK, vtkSSAOPass and every deep G-buffer pass.

Each deep pass's frame is also split into its stages.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
        Apps/Benchmarks/deepgi_benchmark_frame.py --data Testing/Data [options]

(scripts/benchmark-frame.sh installs, builds and runs it;
Documentation/performance.md explains the results.)

Scenes (--scenes, comma list; every actor gets VTK's default property:
white, Ambient 0, Diffuse 1, Specular 0, i.e. what a VTK user gets without
choosing materials):

- bunny-floor: Testing/Data/meshes/bunny.ply (vtkDeepGISceneLoader:
  its camera and camera light) above a square floor three times the
  bunny's width;
- bunny-floor-1m: the same with the bunny subdivided twice
  (vtkLoopSubdivisionFilter, about 1.1 million triangles); same camera and
  floor, so nearly the same pixels are shaded;
- headsq: the iso-surface 500 of Testing/Data/volumes/headsq/quarter;
- --mesh FILE (repeatable) and --volume FILE --iso V: the user's own;
  --camera PX,PY,PZ,FX,FY,FZ,UX,UY,UZ[,A] after one gives it its start
  camera (vtkDeepGICameraText; each scene's heading shows its start
  camera so).

Each scene has its own window; for each size of --sizes the methods run
side by side in that window: plain VTK; vtkSSAOPass with kernel 16 and 64
(radius 0.05 x the diagonal of the visible props' bounding box, blur on);
vtkDeepGBufferPass with 1 layer, 2 layers (the default oracle, AUTOMATIC:
DEPTH_PEEL on a CPU renderer, REPROJECT on a GPU), and 2 layers with each
of those two oracles; vtkDeepAmbientObscurancePass with 1 layer (UseSecondLayer off
and a one-layer G-buffer) and 2 layers; vtkDeepRadiosityPass;
vtkDeepGIPass with each preset (the "deep methods": vtkDeepGBufferPass
on). The
camera orbits (Azimuth 0.5 degree before every frame) from the same start
for every method, as in interaction, so the temporal filters and the
reprojecting oracle work as they do for a user.

Output (stdout, OUTDIR/benchmark-frame.md and OUTDIR/benchmark-frame.csv,
each written to a temporary file and then renamed), per scene and size:

- frame table: "ms per frame", the median of --frames frames x --rounds
  rounds (the methods interleaved round by round, 3 warm-up frames each
  time a method becomes current), each frame timed as window.Render() and
  window.WaitForCompletion(); "x plain", that median over plain VTK's;
  "textures [MiB]", the pass's GetTextureBytes() (the deep methods only);
- stage table: a separate run of --frames frames per deep method with a
  vtkDeepGIStageTimer attached (glFinish around each stage, so not the
  timed frames): milliseconds per frame of each stage (exclusive of the
  stages nested in it), in the order the stages first ran; "outside the
  stages" is the profiled frame's mean time ("profiled frame") minus the
  stages' sum (VTK's camera, lights, translucent and overlay steps,
  Python);
- converging a still image (vtkDeepGIPass presets): Converge(renderer, 16,
  0.07 / 255) after 3 orbit frames, once where the orbit stopped (a user
  who stops moving the camera) and once at the start camera after orbit
  frames a quarter turn away (a view set by a script, the temporal
  filter's history from another view), each
  after one untimed Converge (llvmpipe compiles the programs and state
  variants that only Converge's frames use the first time): the frames it
  rendered, its seconds and those seconds in the preset's median frames
  ("GI frames").

When both bunny scenes ran, "Flat in triangle count" compares, per size
and deep method, the shading cost (profiled frame minus the stage
"G-buffer: layers") of bunny-floor and bunny-floor-1m.
"""
import argparse
import csv
import datetime
import io
import os
import shlex
import statistics
import sys
import time

import numpy as np
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer

import vtkdeepgi
# The image benchmark's scenes, default actors and vtkSSAOPass, shared.
import deepgi_benchmark_image
from deepgi_benchmark_image import (add_user_scene_options, apply_user_camera, load_shared_scene,
                                    use_default_properties, user_scene_list)

SCENES = ("bunny-floor", "bunny-floor-1m", "headsq")
PRESETS = ("HIGH_PERFORMANCE", "BALANCED", "HIGH_QUALITY")
WARM_UP_FRAMES = 3
ORBIT_DEGREES = 0.5
# Converge's arguments: deepgi-render's tolerance, 0.07 of a colour level.
CONVERGE_FRAMES = 16
CONVERGE_TOLERANCE = 0.07 / 255.0
# Where Converge starts: where the orbit stopped, or at the start camera
# after orbit frames a quarter turn away (a script setting another view: the
# history is of a view that mostly does not reproject onto it).
STOP_SCENARIO = "after the camera stops"
JUMP_SCENARIO = "after a jump from another view"
JUMP_DEGREES = 90.0
CONVERGE_SCENARIOS = (STOP_SCENARIO, JUMP_SCENARIO)
LAYERS_STAGE = "G-buffer: layers"
OUTSIDE_ROW = "outside the stages (VTK's camera, lights, translucent and overlay steps, Python)"


def parse_sizes(parser, text):
    sizes = []
    for item in (s for s in text.split(",") if s):
        try:
            width, height = (int(v) for v in item.lower().split("x"))
        except ValueError:
            parser.error("--sizes needs WxH[,WxH...], not " + item)
        if not (16 <= width <= 8192 and 16 <= height <= 8192):
            parser.error("--sizes needs 16..8192 pixels per side")
        sizes.append((width, height))
    if not sizes:
        parser.error("--sizes needs at least one WxH")
    return sizes


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", default="640x480,1920x1080",
                        help="WxH[,WxH...] (default 640x480,1920x1080)")
    parser.add_argument("--frames", type=int, default=7, help="timed frames per method and round")
    parser.add_argument("--rounds", type=int, default=2, help="rounds over the methods")
    parser.add_argument("--scenes", default=",".join(SCENES),
                        help="comma list of " + ", ".join(SCENES))
    add_user_scene_options(parser)
    parser.add_argument("--data", required=True, help="the project's Testing/Data folder")
    parser.add_argument("--output", default="output", help="folder of the files (default output)")
    parser.add_argument("--methods", default="",
                        help="comma list of words; only the methods whose name contains one of "
                        "them run, besides plain VTK (default: every method)")
    args = parser.parse_args()
    args.sizes = parse_sizes(parser, args.sizes)
    if not (1 <= args.frames <= 1000 and 1 <= args.rounds <= 100):
        parser.error("--frames 1..1000, --rounds 1..100")
    args.method_words = [w for w in args.methods.split(",") if w]
    args.scene_list = [s for s in args.scenes.split(",") if s]
    for name in args.scene_list:
        if name not in SCENES:
            parser.error("unknown scene %s (known: %s)" % (name, ", ".join(SCENES)))
    needed = []
    if any(s.startswith("bunny") for s in args.scene_list):
        needed.append(os.path.join(args.data, "meshes", "bunny.ply"))
    if "headsq" in args.scene_list:
        needed.append(os.path.join(args.data, "volumes", "headsq", "quarter.1"))
    for path in needed:
        if not os.path.isfile(path):
            parser.error("no such file: " + path)
    args.scene_list += user_scene_list(parser, args)
    if not args.scene_list:
        parser.error("no scene: give --scenes, --mesh or --volume")
    return args


def add_floor(renderer, bounds):
    """A square floor three times the bunny's width, centred under it."""
    half = 1.5 * (bounds[1] - bounds[0])
    x, z = 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[4] + bounds[5])
    plane = vtkPlaneSource()
    # Origin, then +z, then +x: the plane's normal (point1 x point2) is +y.
    plane.SetOrigin(x - half, bounds[2], z - half)
    plane.SetPoint1(x - half, bounds[2], z + half)
    plane.SetPoint2(x + half, bounds[2], z - half)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(plane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)


def subdivide(actor):
    """Gives the actor its mesh subdivided twice (16 x the triangles)."""
    loop = vtkLoopSubdivisionFilter()
    loop.SetInputData(actor.GetMapper().GetInput())
    loop.SetNumberOfSubdivisions(2)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(loop.GetOutputPort())
    # Smooth shading like the loader's mesh; subdivision keeps the
    # orientation, so the consistency walk (slow on a million triangles) is
    # not needed.
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.Update()
    actor.GetMapper().SetInputData(normals.GetOutput())


def populate(renderer, scene, data):
    """Fills the renderer; returns the scene's display name, and an object to keep."""
    loader = vtkdeepgi.vtkDeepGISceneLoader()
    if scene in ("bunny-floor", "bunny-floor-1m"):
        ok, name = loader.Load(data + "/meshes/bunny.ply"), scene
    else:
        ok, name = load_shared_scene(loader, scene, data)
    if not ok:
        sys.exit("deepgi_benchmark_frame.py: cannot load %s" % name)
    loader.Populate(renderer)
    # The camera frames the loaded parts only, so both bunny scenes have the
    # camera of the original mesh and the floor does not move it.
    loader.ResetCamera(renderer)
    apply_user_camera(renderer, scene)
    if name == "bunny-floor-1m":
        subdivide(renderer.GetActors().GetLastActor())
    if name.startswith("bunny-floor"):
        bounds = [0.0] * 6
        loader.GetBounds(bounds)
        add_floor(renderer, bounds)
    return name, loader


def actors(renderer):
    collection = renderer.GetActors()
    collection.InitTraversal()
    return [collection.GetNextActor() for _ in range(collection.GetNumberOfItems())]


def count_triangles(renderer):
    """Triangles the scene's polygons make (n - 2 per n-gon); after a Render."""
    total = 0
    for actor in actors(renderer):
        polys = actor.GetMapper().GetInput().GetPolys()
        total += polys.GetNumberOfConnectivityIds() - 2 * polys.GetNumberOfCells()
    return total


def opengl_renderer(window):
    for line in window.ReportCapabilities().splitlines():
        if "OpenGL renderer string" in line:
            return line.split(":", 1)[1].strip()
    return "unknown"


class Method:
    """One column: a pass (None: plain VTK) and what was measured with it."""

    def __init__(self, name, pass_=None, gbuffer=None):
        self.name = name
        self.pass_ = pass_
        # The vtkDeepGBufferPass a stage timer attaches to; None: not a deep method.
        self.gbuffer = gbuffer
        self.times = []
        self.stages = {}  # stage name -> ms per frame, in the order the stages first ran
        self.profiled_ms = None
        self.texture_mib = None
        self.converge = {}  # CONVERGE_SCENARIOS name -> (frames, seconds)


def make_ssao(kernel, radius):
    # The image benchmark's vtkSSAOPass settings.
    return Method("vtkSSAOPass K%d" % kernel, deepgi_benchmark_image.make_ssao(kernel, radius)())


def make_gbuffer(name, layers, oracle=None):
    gbuffer = vtkdeepgi.vtkDeepGBufferPass()
    gbuffer.SetNumberOfLayers(layers)
    if oracle is not None:
        gbuffer.SetOracle(oracle)
    return Method(name, gbuffer, gbuffer)


def make_effect(name, effect):
    return Method(name, effect, effect.GetGBufferPass())


def make_methods(radius, wanted):
    one_layer_ao = vtkdeepgi.vtkDeepAmbientObscurancePass()
    one_layer_ao.SetUseSecondLayer(False)
    # A second layer nobody reads would be built and timed otherwise.
    one_layer_ao.GetGBufferPass().SetNumberOfLayers(1)
    methods = [Method("plain VTK"), make_ssao(16, radius), make_ssao(64, radius),
               make_gbuffer("vtkDeepGBufferPass 1 layer", 1),
               make_gbuffer("vtkDeepGBufferPass 2 layers", 2),
               make_gbuffer("vtkDeepGBufferPass 2 layers DEPTH_PEEL", 2,
                            vtkdeepgi.vtkDeepGBufferPass.DEPTH_PEEL),
               make_gbuffer("vtkDeepGBufferPass 2 layers REPROJECT", 2,
                            vtkdeepgi.vtkDeepGBufferPass.REPROJECT),
               make_effect("vtkDeepAmbientObscurancePass 1 layer", one_layer_ao),
               make_effect("vtkDeepAmbientObscurancePass 2 layers",
                           vtkdeepgi.vtkDeepAmbientObscurancePass()),
               make_effect("vtkDeepRadiosityPass", vtkdeepgi.vtkDeepRadiosityPass())]
    for preset in PRESETS:
        gi = vtkdeepgi.vtkDeepGIPass()
        gi.SetPreset(preset)
        methods.append(make_effect("vtkDeepGIPass " + preset, gi))
    return [m for m in methods if m.pass_ is None or not wanted or any(w in m.name for w in wanted)]


class Orbit:
    """The camera path every method follows: back to the start, then a
    small azimuth step before each frame."""

    def __init__(self, window, renderer):
        self.window, self.renderer = window, renderer
        self.start = vtkCamera()
        self.start.DeepCopy(renderer.GetActiveCamera())

    def restart(self):
        self.renderer.GetActiveCamera().DeepCopy(self.start)
        self.renderer.ResetCameraClippingRange()

    def turn(self, degrees):
        """Turns the camera about the view up vector, without a frame, and
        resets the clipping range, as an interactor style does."""
        self.renderer.GetActiveCamera().Azimuth(degrees)
        self.renderer.ResetCameraClippingRange()

    def frames(self, count):
        """Renders `count` frames; returns the milliseconds of each."""
        times = []
        for _ in range(count):
            self.turn(ORBIT_DEGREES)
            start = time.perf_counter()
            self.window.Render()
            self.window.WaitForCompletion()
            times.append(1000.0 * (time.perf_counter() - start))
        return times


def run_rounds(args, renderer, orbit, methods):
    """The timed frames: the methods interleaved round by round."""
    for _ in range(args.rounds):
        for m in methods:
            renderer.SetPass(m.pass_)
            orbit.restart()
            orbit.frames(WARM_UP_FRAMES)
            m.times += orbit.frames(args.frames)


def profile(args, renderer, orbit, m):
    """A deep method's stages over --frames frames, and its textures."""
    timer = vtkdeepgi.vtkDeepGIStageTimer()
    renderer.SetPass(m.pass_)
    m.gbuffer.SetStageTimer(timer)
    orbit.restart()
    orbit.frames(WARM_UP_FRAMES)
    timer.Reset()
    m.profiled_ms = statistics.mean(orbit.frames(args.frames))
    m.gbuffer.SetStageTimer(None)
    for i in range(timer.GetNumberOfStages()):
        m.stages[timer.GetStageName(i)] = timer.GetStageMilliseconds(i) / args.frames
    m.texture_mib = m.pass_.GetTextureBytes() / 2.0 ** 20


def prepare_still(orbit, scenario):
    """The camera Converge starts from in a CONVERGE_SCENARIOS scenario."""
    orbit.restart()
    if scenario == JUMP_SCENARIO:
        orbit.turn(JUMP_DEGREES)
    orbit.frames(WARM_UP_FRAMES)
    if scenario == JUMP_SCENARIO:
        orbit.restart()


def converge_still(orbit, gi):
    """Converge(renderer, CONVERGE_FRAMES, CONVERGE_TOLERANCE); its frames."""
    return gi.Converge(orbit.renderer, CONVERGE_FRAMES, CONVERGE_TOLERANCE)


def converge_scenarios(orbit, gi, measure):
    """[(scenario, measure(scenario, run))] for each CONVERGE_SCENARIOS
    scenario, where run() converges from its start camera and returns the
    frames; after one unmeasured Converge (llvmpipe compiles the programs
    and state variants that only Converge's frames use the first time)."""
    prepare_still(orbit, JUMP_SCENARIO)
    converge_still(orbit, gi)
    results = []
    for scenario in CONVERGE_SCENARIOS:
        prepare_still(orbit, scenario)
        results.append((scenario, measure(scenario, lambda: converge_still(orbit, gi))))
    return results


def converge(renderer, orbit, m):
    def timed(scenario, run):
        start = time.perf_counter()
        frames = run()
        renderer.GetRenderWindow().WaitForCompletion()
        return frames, time.perf_counter() - start

    renderer.SetPass(m.pass_)
    m.converge = dict(converge_scenarios(orbit, m.pass_, timed))


def measure_size(args, orbit, radius, size):
    """Every method at one window size; returns the methods with their results."""
    window, renderer = orbit.window, orbit.renderer
    window.SetSize(*size)
    methods = make_methods(radius, args.method_words)
    run_rounds(args, renderer, orbit, methods)
    for m in methods:
        if m.gbuffer:
            profile(args, renderer, orbit, m)
        if isinstance(m.pass_, vtkdeepgi.vtkDeepGIPass):
            converge(renderer, orbit, m)
    renderer.SetPass(None)
    # The passes' OpenGL objects belong to this window: free them while it exists.
    for m in methods:
        if m.pass_:
            m.pass_.ReleaseGraphicsResources(window)
    return methods


def measure_scene(args, scene):
    """Returns (OpenGL renderer, [(scene, triangles, size, methods)], the
    start camera's text)."""
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(*args.sizes[0])
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    name, keep = populate(renderer, scene, args.data)
    use_default_properties(renderer)
    renderer.ResetCameraClippingRange()
    window.Render()
    bounds = renderer.ComputeVisiblePropBounds()
    radius = 0.05 * np.linalg.norm(np.array(bounds[1::2]) - np.array(bounds[0::2]))
    triangles = count_triangles(renderer)
    camera = vtkdeepgi.vtkDeepGICameraText.Write(renderer.GetActiveCamera())
    orbit, results = Orbit(window, renderer), []
    for size in args.sizes:
        results.append((name, triangles, size, measure_size(args, orbit, radius, size)))
        print("%s %dx%d done" % ((name,) + size), file=sys.stderr)
    device = opengl_renderer(window)
    del keep
    return device, results, camera


def cell(value, form):
    return "—" if value is None else form % value


def frame_table(methods):
    plain = statistics.median(methods[0].times)
    lines = ["| method | ms per frame | x plain | textures [MiB] |", "|---|---|---|---|"]
    for m in methods:
        ms = statistics.median(m.times)
        lines.append("| %s | %.1f | %.2f | %s |" % (m.name, ms, ms / plain,
                                                  cell(m.texture_mib, "%.1f")))
    return lines


def stage_names(methods):
    """Every stage of the methods, in the order they first ran."""
    return list(dict.fromkeys(name for m in methods for name in m.stages))


def outside_ms(m):
    return m.profiled_ms - sum(m.stages.values())


def stage_table(methods, frames):
    deep = [m for m in methods if m.gbuffer]
    lines = ["Stages, ms per frame (%d profiled frames per method, glFinish around "
             "every stage):" % frames, "",
             "| stage | " + " | ".join(m.name for m in deep) + " |",
             "|---|" + "---|" * len(deep)]
    rows = [(name, [m.stages.get(name) for m in deep]) for name in stage_names(deep)]
    rows.append((OUTSIDE_ROW, [outside_ms(m) for m in deep]))
    rows.append(("profiled frame", [m.profiled_ms for m in deep]))
    for name, values in rows:
        lines.append("| %s | %s |" % (name, " | ".join(cell(v, "%.2f") for v in values)))
    return lines


def converge_table(methods):
    lines = ["Converging a still image: Converge(renderer, %d, %.2f / 255) after %d orbit frames, "
             "where the orbit stopped, and at the start camera after orbit frames %g degrees "
             "away, each after one untimed Converge."
             % (CONVERGE_FRAMES, CONVERGE_TOLERANCE * 255.0, WARM_UP_FRAMES, JUMP_DEGREES), "",
             "| method | scenario | frames | seconds | GI frames |", "|---|---|---|---|---|"]
    for m in (m for m in methods if m.converge):
        for scenario, (frames, seconds) in m.converge.items():
            gi_frames = 1000.0 * seconds / statistics.median(m.times)
            lines.append("| %s | %s | %d | %.2f | %.1f |" % (
                m.name, scenario, frames, seconds, gi_frames))
    return lines


def flat_section(results):
    """Shading cost (profiled frame minus the layers) of both bunny scenes."""
    by_key = {(scene, size): (triangles, methods) for scene, triangles, size, methods in results}
    lines = []
    for size in dict.fromkeys(size for _, _, size, _ in results):
        small, large = by_key.get(("bunny-floor", size)), by_key.get(("bunny-floor-1m", size))
        if not (small and large):
            continue
        if not lines:
            lines = ["## Flat in triangle count", "",
                     "Shading cost = profiled frame minus the stage \"%s\" [ms]." % LAYERS_STAGE]
        lines += ["", "%dx%d, bunny-floor %d triangles, bunny-floor-1m %d triangles:" % (
                      size + (small[0], large[0])), "",
                  "| method | layers | layers 1m | shading | shading 1m | shading 1m / shading |",
                  "|---|---|---|---|---|---|"]
        for a, b in zip(small[1], large[1]):
            if not a.gbuffer:
                continue
            layers = (a.stages.get(LAYERS_STAGE, 0.0), b.stages.get(LAYERS_STAGE, 0.0))
            shading = (a.profiled_ms - layers[0], b.profiled_ms - layers[1])
            lines.append("| %s | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
                (a.name,) + layers + shading + (shading[1] / shading[0],)))
    return lines


def markdown(args, device, results, cameras):
    lines = ["OpenGL renderer: %s; %d CPUs; command: `%s`; %s." % (
                 device, os.cpu_count(), shlex.join(sys.argv),
                 datetime.datetime.now().isoformat(sep=" ", timespec="seconds")),
             "",
             "Time: median of %d frames x %d rounds per method, methods interleaved, %d warm-up "
             "frames each time a method becomes current, camera orbiting %g degree per frame "
             "from the same start; every actor with VTK's default property." % (
                 args.frames, args.rounds, WARM_UP_FRAMES, ORBIT_DEGREES)]
    for scene, triangles, size, methods in results:
        lines += ["", "### %s, %d triangles, %dx%d" % ((scene, triangles) + size), "",
                  "Start camera (`--camera`): `%s`" % cameras[scene], ""]
        lines += frame_table(methods) + [""] + stage_table(methods, args.frames)
        lines += [""] + converge_table(methods)
    flat = flat_section(results)
    return "\n".join(lines + ([""] + flat if flat else [])) + "\n"


def csv_text(results):
    """One row per scene, size and method; one column per stage (ms per frame)."""
    stages = stage_names([m for _, _, _, methods in results for m in methods])
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["scene", "triangles", "width", "height", "method", "frame_ms", "x_plain",
                     "texture_mib", "profiled_frame_ms", "outside_stages_ms"] +
                    [prefix + column for prefix in ("converge_stop_", "converge_jump_")
                     for column in ("frames", "s", "gi_frames")] + [s + " [ms]" for s in stages])
    for scene, triangles, size, methods in results:
        plain = statistics.median(methods[0].times)
        for m in methods:
            ms = statistics.median(m.times)
            row = [scene, triangles, size[0], size[1], m.name, ms, ms / plain, m.texture_mib,
                   m.profiled_ms, outside_ms(m) if m.gbuffer else None]
            for scenario in CONVERGE_SCENARIOS:
                frames, seconds = m.converge.get(scenario, (None, None))
                row += [frames, seconds, 1000.0 * seconds / ms if seconds else None]
            row += [m.stages.get(s) for s in stages]
            writer.writerow(["" if v is None else round(v, 4) if isinstance(v, float) else v
                             for v in row])
    return out.getvalue()


def write_atomically(path, text):
    """A reader sees the old file or the whole new one, never a partial one."""
    with open(path + ".partial", "w") as f:
        f.write(text)
    os.replace(path + ".partial", path)


def main():
    args = parse_arguments()
    os.makedirs(args.output, exist_ok=True)
    device, results, cameras = None, [], {}
    for scene in args.scene_list:
        scene_device, scene_results, camera = measure_scene(args, scene)
        device = device or scene_device
        results += scene_results
        cameras[scene_results[0][0]] = camera
    text = markdown(args, device, results, cameras)
    print(text)
    write_atomically(os.path.join(args.output, "benchmark-frame.md"), text)
    write_atomically(os.path.join(args.output, "benchmark-frame.csv"), csv_text(results))


if __name__ == "__main__":
    main()
