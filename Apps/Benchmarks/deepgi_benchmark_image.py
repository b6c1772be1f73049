"""The final image against the ray-traced truth: plain VTK, vtkSSAOPass and
vtkDeepGIPass side by side, on built-in scenes and on the user's own files.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
        Apps/Benchmarks/deepgi_benchmark_image.py [options]

(scripts/benchmark-image.sh installs, builds and runs it.) For every scene,
at one still camera:

- plain VTK; vtkSSAOPass with kernel 16 and 64 (radius = the obscurance
  pass's automatic radius, 0.05 x the scene's diagonal, blur on); and
  vtkDeepGIPass with each preset, converged with Converge(renderer, 16,
  0.07 / 255) as the main job does, BALANCED with UseSecondLayer off
  (one G-buffer layer: what the second layer is worth), and BALANCED
  without Converge after INTERACTIVE_FRAMES frames at the camera (the
  image a user sees while interacting, once the temporal filters settled);
- the reference: vtkDeepGIReferenceImage (the pass's lighting model,
  Documentation/lighting-model.md) on the G-buffer capture of the same
  camera, with the same obscurance radius and the same rule for what
  ambient visibility scales;
- per method: milliseconds per frame (median of --frames frames after
  three warm-up frames, methods interleaved in --rounds rounds, ratio to
  plain VTK), and RMSE, MAE and bias (mean signed error) of the 8-bit image
  (RGB / 255) against the reference over every valid surface pixel, over
  the pixels where the G-buffer has a second layer, and over the pixels
  where the second layer changes the image (BALANCED with two layers and
  with one differ by more than CHANGE_THRESHOLD in a channel: the light it
  carries through hidden surfaces also reaches pixels that have no second
  layer themselves). The reference is
  clipped to [0, 1] like the images (white walls with albedo 1 and four
  undamped bounces exceed 1).

Scenes: --scenes takes the built-in demo, cornell-lucy, dragon and headsq;
--mesh FILE (repeatable: .ply .stl .vtk .vtp .obj; --scene FILE is the
same) and --volume FILE --iso V add the user's own, and
--camera PX,PY,PZ,FX,FY,FZ,UX,UY,UZ[,A] after one gives it a camera
(vtkDeepGICameraText; the scene table shows every scene's camera so).
--default-actors gives every actor VTK's default
property (white, Ambient 0, Diffuse 1, Specular 0), i.e. what a VTK user
gets without choosing materials; otherwise the scene loader's materials.

Writes OUTDIR/benchmark-image.md (the tables), OUTDIR/benchmark-image-plot.png
(RMSE against time per frame, both means over the scenes, one point per
method and the reference's own: its computing time and mean standard
error; the trade a user chooses from) and, per scene, OUTDIR/SCENE.png:
plain | vtkSSAOPass K16 | vtkDeepGIPass BALANCED | reference |
|BALANCED - reference| x 4.
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData, vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkCamera, vtkRenderer, vtkWindowToImageFilter
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401 (the charts' OpenGL device)

import vtkdeepgi

PRESETS = ("HIGH_PERFORMANCE", "BALANCED", "HIGH_QUALITY")
# A pixel where BALANCED with one layer and with two differ by more than
# this (RGB, any channel; about 5 of 255 levels) is one the second layer
# changes. Converge renders both with the same fixed taps, so what differs
# is the second layer's contribution, not sampling noise.
CHANGE_THRESHOLD = 0.02
# Frames of the interactive image: the radiosity's temporal filter (alpha
# 0.85) then keeps 0.85^40 = 0.2 % of the first frame.
INTERACTIVE_FRAMES = 40


class UserSceneAction(argparse.Action):
    """--mesh FILE (or --scene FILE), --volume FILE, --iso V and --camera
    TEXT in the order given: each --mesh and each --volume is a scene of
    the user's (args.user_scenes), the k-th --iso the iso-value of the k-th
    --volume, and --camera the camera of the scene given just before it (a
    volume's after its --iso)."""

    def __call__(self, parser, namespace, value, option_string=None):
        scenes = list(getattr(namespace, "user_scenes", None) or [])
        if option_string in ("--mesh", "--scene"):
            scenes.append({"kind": "mesh", "path": value, "camera": None})
        elif option_string == "--volume":
            scenes.append({"kind": "volume", "path": value, "iso": None, "camera": None})
        elif option_string == "--iso":
            volume = next((s for s in scenes if s["kind"] == "volume" and s["iso"] is None), None)
            if volume is None:
                parser.error("--iso needs a --volume before it")
            volume["iso"] = value
        else:
            if not scenes or (scenes[-1]["kind"] == "volume" and scenes[-1]["iso"] is None):
                parser.error("--camera needs a --mesh, or a --volume and its --iso, before it")
            if scenes[-1]["camera"] is not None:
                parser.error("a second --camera for the same scene")
            camera = vtkCamera()
            error = vtkdeepgi.vtkDeepGICameraText.Apply(value, camera)
            if error:
                parser.error("--camera '%s': %s" % (value, error))
            scenes[-1]["camera"] = vtkdeepgi.vtkDeepGICameraText.Write(camera)
        namespace.user_scenes = scenes


def add_user_scene_options(parser):
    """The options of the user's own scenes, shared by the Python benchmarks."""
    parser.set_defaults(user_scenes=[])
    parser.add_argument("--mesh", "--scene", action=UserSceneAction,
                        help="a mesh or OBJ scene (--scene is the same)")
    parser.add_argument("--volume", action=UserSceneAction, help="a volume (with --iso)")
    parser.add_argument("--iso", action=UserSceneAction, type=float, help="iso-value")
    parser.add_argument("--camera", action=UserSceneAction,
                        help="PX,PY,PZ,FX,FY,FZ,UX,UY,UZ[,A]: the camera of the scene just "
                        "before (position, focal point, view-up, view angle in degrees)")


def user_scene_list(parser, args):
    """The user's scenes as ("mesh", path, camera) and ("volume", path, iso,
    camera), camera None for the loader's; their files checked."""
    scenes = []
    for s in args.user_scenes:
        if s["kind"] == "volume" and s["iso"] is None:
            parser.error("--volume %s needs --iso V after it" % s["path"])
        if not os.path.isfile(s["path"]):
            parser.error("no such file: " + s["path"])
        scenes.append(("mesh", s["path"], s["camera"]) if s["kind"] == "mesh"
                      else ("volume", s["path"], s["iso"], s["camera"]))
    return scenes


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", default="320x240", help="WxH (default 320x240)")
    parser.add_argument("--samples", type=int, default=128, help="reference rays per pixel")
    parser.add_argument("--bounces", type=int, default=4, help="reference bounces (1..16)")
    parser.add_argument("--frames", type=int, default=5, help="timed frames per method and round")
    parser.add_argument("--rounds", type=int, default=2, help="rounds over the methods")
    parser.add_argument("--scenes", default="demo,cornell-lucy,dragon,headsq")
    add_user_scene_options(parser)
    parser.add_argument("--default-actors", action="store_true")
    parser.add_argument("--data", required=True, help="the project's Testing/Data folder")
    parser.add_argument("--output", default="output")
    args = parser.parse_args()
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        parser.error("--size needs WxH")
    if not (16 <= width <= 8192 and 16 <= height <= 8192):
        parser.error("--size needs 16..8192 pixels per side")
    args.width, args.height = width, height
    if not (1 <= args.samples <= 1048576 and 1 <= args.bounces <= 16):
        parser.error("--samples 1..1048576, --bounces 1..16")
    if not (1 <= args.frames <= 1000 and 1 <= args.rounds <= 100):
        parser.error("--frames 1..1000, --rounds 1..100")
    args.scene_list = [s for s in args.scenes.split(",") if s]
    for name in args.scene_list:
        if name not in ("demo", "cornell-lucy", "dragon", "headsq"):
            parser.error("unknown scene " + name)
    args.scene_list += user_scene_list(parser, args)
    return args


def load_shared_scene(loader, scene, data):
    """The scenes every benchmark has: the CT head's skin ("headsq"), a
    ("mesh", path, camera) and a ("volume", path, iso, camera). Returns
    (loaded, name); a scene with a camera is named by its position too."""
    if scene == "headsq":
        loader.SetViewDirection(0.0, -1.0, 0.0)
        loader.SetViewUp(0.0, 0.0, -1.0)
        return loader.LoadVolume(data + "/volumes/headsq/quarter", 500.0), scene
    if scene[0] == "mesh":
        ok, name = loader.Load(scene[1]), os.path.basename(scene[1])
    else:
        ok, name = (loader.LoadVolume(scene[1], scene[2]),
                    "%s iso %g" % (os.path.basename(scene[1]), scene[2]))
    camera = scene[-1]
    return ok, name + (" from " + ",".join(camera.split(",")[:3]) if camera else "")


def apply_user_camera(renderer, scene):
    """A user's scene with --camera: its camera replaces the loader's."""
    if isinstance(scene, tuple) and scene[-1]:
        vtkdeepgi.vtkDeepGICameraText.Apply(scene[-1], renderer.GetActiveCamera())
        renderer.ResetCameraClippingRange()


def populate(renderer, scene, data):
    """Fills the renderer; returns the scene's display name, and an object to keep."""
    if scene == "demo":
        demo = vtkdeepgi.vtkDeepGIDemoScene()
        demo.SetTargetNumberOfTriangles(20000)
        demo.Populate(renderer)
        demo.SetCameraToDefaultView(renderer.GetActiveCamera())
        return "demo", demo
    loader = vtkdeepgi.vtkDeepGISceneLoader()
    if scene == "cornell-lucy":
        ok, name = loader.Load(data + "/scenes/cornell-lucy/CornellBox-Lucy.obj"), scene
    elif scene == "dragon":
        ok, name = loader.Load(data + "/meshes/dragon.ply"), scene
    else:
        ok, name = load_shared_scene(loader, scene, data)
    if not ok:
        sys.exit("deepgi_benchmark_image.py: cannot load %s" % (name if ok is not None else scene))
    loader.Populate(renderer)
    loader.ResetCamera(renderer)
    apply_user_camera(renderer, scene)
    return name, loader


def use_default_properties(renderer):
    actors = renderer.GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        prop = actors.GetNextActor().GetProperty()
        prop.SetColor(1.0, 1.0, 1.0)
        prop.SetAmbient(0.0)
        prop.SetDiffuse(1.0)
        prop.SetSpecular(0.0)


def grab(window):
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.ShouldRerenderOff()
    image.SetInputBufferTypeToRGB()
    image.Update()
    return vtk_to_numpy(image.GetOutput().GetPointData().GetScalars()).astype(float) / 255.0


def timed_frames(window, count):
    times = []
    for _ in range(count):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
    return times


class Method:
    def __init__(self, name, make_pass, interactive=False):
        self.name = name
        self.make_pass = make_pass
        self.interactive = interactive
        self.times = []
        self.image = None
        self.pass_ = None


def make_ssao(kernel, radius):
    def make():
        ssao = vtkSSAOPass()
        ssao.SetDelegatePass(vtkRenderStepsPass())
        ssao.SetKernelSize(kernel)
        ssao.SetRadius(radius)
        ssao.SetBias(0.02 * radius)
        ssao.SetBlur(True)
        return ssao

    return make


def make_gi(preset, second_layer=True):
    def make():
        gi = vtkdeepgi.vtkDeepGIPass()
        gi.SetPreset(preset)
        gi.SetUseSecondLayer(second_layer)
        return gi

    return make


def method_named(methods, name):
    return next(m for m in methods if m.name == name)


def errors(image, truth, mask):
    if not mask.any():
        return (float("nan"),) * 3
    d = image[mask] - truth[mask]
    return float(np.sqrt(np.mean(d * d))), float(np.mean(np.abs(d))), float(np.mean(d))


def save_strip(path, images, width, height):
    strip = np.concatenate([np.clip(i, 0, 1).reshape(height, width, 3) for i in images], axis=1)
    data = vtkImageData()
    data.SetDimensions(strip.shape[1], height, 1)
    scalars = numpy_to_vtk((255.0 * strip).round().astype(np.uint8).reshape(-1, 3), deep=True)
    data.GetPointData().SetScalars(scalars)
    writer = vtkPNGWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    writer.Write()


def method_family(method):
    """The curve of the error-against-time plot a method belongs to."""
    if method.startswith("vtkSSAOPass"):
        return "vtkSSAOPass (K16, K64)"
    if method.endswith("1 layer"):
        return "vtkDeepGIPass BALANCED, 1 layer"
    if method.endswith("interactive"):
        return "vtkDeepGIPass BALANCED, interactive"
    if method.startswith("vtkDeepGIPass"):
        return "vtkDeepGIPass (HIGH_PERFORMANCE, BALANCED, HIGH_QUALITY)"
    return method


def save_plot(path, infos, rows):
    """RMSE against log10 of the ms per frame, means over the scenes: one
    curve per family of methods, and the reference (its computing time, its
    mean standard error). (The time axis is log10 of the values rather than
    vtkAxis's log scale, with which VTK 9.1's vtkChartXY draws no plot.)"""
    points = {}
    for row in rows:
        points.setdefault(row[1], []).append((row[2], row[4]))
    curves = {}
    for method, values in points.items():
        mean = (float(np.log10(np.mean([v[0] for v in values]))),
                float(np.mean([v[1] for v in values])))
        curves.setdefault(method_family(method), []).append(mean)
    curves["vtkDeepGIReferenceImage"] = [(float(np.log10(1000.0 * np.mean([i[5] for i in infos]))),
                                          float(np.mean([i[4] for i in infos])))]
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    view = vtkContextView()
    view.SetRenderWindow(window)
    view.GetRenderer().SetBackground(1.0, 1.0, 1.0)
    window.SetSize(900, 600)
    chart = vtkChartXY()
    view.GetScene().AddItem(chart)
    chart.SetTitle("Final image: RMSE against the reference vs time per frame (mean over scenes)")
    chart.SetShowLegend(True)
    chart.GetAxis(vtkAxis.BOTTOM).SetTitle("log10 of ms per frame (reference: of ms to compute)")
    chart.GetAxis(vtkAxis.LEFT).SetTitle("RMSE (reference: its mean standard error)")
    colors = ((60, 60, 60), (40, 90, 200), (200, 40, 40), (230, 140, 20), (150, 60, 170),
              (30, 150, 60))
    tables = []
    for k, (family, values) in enumerate(curves.items()):
        table = vtkTable()
        for name, column in (("log10 ms", 0), (family, 1)):
            array = vtkFloatArray()
            array.SetName(name)
            for value in sorted(values):
                array.InsertNextValue(value[column])
            table.AddColumn(array)
        tables.append(table)
        plot = chart.AddPlot(vtkChart.LINE if len(values) > 1 else vtkChart.POINTS)
        plot.SetInputData(table, 0, 1)
        plot.SetColor(*colors[k % len(colors)], 255)
        plot.SetWidth(2.5)
    window.Render()
    save_strip(path, [grab(window)], *window.GetSize())


def measure_scene(args, scene):
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(args.width, args.height)
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    name, keep = populate(renderer, scene, args.data)
    if args.default_actors:
        use_default_properties(renderer)
    renderer.ResetCameraClippingRange()
    window.Render()
    bounds = renderer.ComputeVisiblePropBounds()
    diagonal = np.linalg.norm(np.array(bounds[1::2]) - np.array(bounds[0::2]))
    radius = 0.05 * diagonal

    methods = [Method("plain VTK", None)]
    methods += [Method("vtkSSAOPass K%d" % k, make_ssao(k, radius)) for k in (16, 64)]
    methods.append(Method("vtkDeepGIPass BALANCED 1 layer", make_gi("BALANCED", False)))
    methods += [Method("vtkDeepGIPass " + p, make_gi(p)) for p in PRESETS]
    methods.append(Method("vtkDeepGIPass BALANCED interactive", make_gi("BALANCED"), True))
    for m in methods:
        m.pass_ = m.make_pass() if m.make_pass else None

    # Accuracy: each method's still image, GI converged as the main job does
    # or, for the interactive method, rendered frame after frame.
    for m in methods:
        renderer.SetPass(m.pass_)
        if m.interactive:
            for _ in range(INTERACTIVE_FRAMES):
                window.Render()
        elif isinstance(m.pass_, vtkdeepgi.vtkDeepGIPass):
            m.pass_.Converge(renderer, 16, 0.07 / 255.0)
        else:
            window.Render()
        m.image = grab(window)
    balanced = method_named(methods, "vtkDeepGIPass BALANCED")
    one_layer = method_named(methods, "vtkDeepGIPass BALANCED 1 layer")
    renderer.SetPass(balanced.pass_)
    window.Render()
    capture = vtkImageData()
    balanced.pass_.GetGBufferPass().CaptureLayers(capture, renderer)
    obscurance = balanced.pass_.GetAmbientObscurancePass()
    reference = vtkdeepgi.vtkDeepGIReferenceImage()
    scene_polydata = vtkPolyData()
    vtkdeepgi.vtkDeepGIReferenceImage.SceneFromRenderer(renderer, scene_polydata)
    reference.SetScene(scene_polydata)
    reference.SetLightsFromRenderer(renderer)
    reference.SetObscuranceRadius(obscurance.GetEffectiveRadius())
    multiply = obscurance.ResolveComposition(renderer) == obscurance.COMPOSITE_MULTIPLY
    reference.SetVisibility(reference.AV_SCALES_RADIANCE if multiply else reference.AV_SCALES_AMBIENT)
    reference.SetSamplesPerPixel(args.samples)
    reference.SetNumberOfBounces(args.bounces)
    start = time.perf_counter()
    if not reference.Compute(capture):
        sys.exit("deepgi_benchmark_image.py: no reference for " + name)
    reference_seconds = time.perf_counter() - start
    out = reference.GetOutput().GetPointData()
    # What a display shows: the 8-bit images clip at 1, so does the truth.
    truth = np.clip(vtk_to_numpy(out.GetArray("Radiance")).astype(float), 0.0, 1.0)
    valid = vtk_to_numpy(out.GetArray("Valid")) > 0
    layer1 = capture.GetPointData().GetArray("Valid_1")
    second = valid & (vtk_to_numpy(layer1) > 0) if layer1 else np.zeros_like(valid)
    changed = valid & (np.abs(balanced.image - one_layer.image).max(axis=1) > CHANGE_THRESHOLD)

    # Time: methods interleaved, rounds, after warm-up.
    for _ in range(args.rounds):
        for m in methods:
            renderer.SetPass(m.pass_)
            timed_frames(window, 3)
            m.times += timed_frames(window, args.frames)
    for m in methods:
        if m.pass_:
            m.pass_.ReleaseGraphicsResources(window)

    plain_ms = statistics.median(methods[0].times)
    rows = []
    for m in methods:
        ms = statistics.median(m.times)
        rows.append((name, m.name, ms, ms / plain_ms) + errors(m.image, truth, valid)
                    + errors(m.image, truth, second)[:1] + errors(m.image, truth, changed)[:1])
    difference = np.abs(balanced.image - truth) * 4.0
    save_strip(os.path.join(args.output, "".join(c if c.isalnum() else "-" for c in name) + ".png"),
               [methods[0].image, methods[1].image, balanced.image, truth, difference],
               args.width, args.height)
    info = (name, int(valid.sum()), int(second.sum()), int(changed.sum()), reference.GetMeanStandardError(),
            reference_seconds, "AV x RADIANCE" if multiply else "AV x AMBIENT",
            vtkdeepgi.vtkDeepGICameraText.Write(renderer.GetActiveCamera()))
    del keep
    return info, rows


def main():
    args = parse_arguments()
    os.makedirs(args.output, exist_ok=True)
    infos, rows = [], []
    for scene in args.scene_list:
        info, scene_rows = measure_scene(args, scene)
        infos.append(info)
        rows += scene_rows
        print("scene %s done" % info[0], file=sys.stderr)
    lines = [
        "Final image against vtkDeepGIReferenceImage (%d rays per pixel and estimate, %d bounces), "
        "%dx%d, %s; time: median of %d frames x %d rounds per method, interleaved." % (
            args.samples, args.bounces, args.width, args.height,
            "every actor with VTK's default property" if args.default_actors
            else "the scene loader's materials", args.frames, args.rounds),
        "",
        "| scene | surface px | 2-layer px | px the 2nd layer changes | reference std. error | reference [s] | AV scales | camera (--camera) |",
        "|---|---|---|---|---|---|---|---|",
    ]
    lines += ["| %s | %d | %d | %d | %.4f | %.1f | %s | %s |" % i for i in infos]
    lines += ["", "| scene | method | ms per frame | x plain | RMSE | MAE | bias | RMSE 2-layer px | RMSE changed px |",
              "|---|---|---|---|---|---|---|---|---|"]
    lines += ["| %s | %s | %.1f | %.2f | %.4f | %.4f | %+.4f | %.4f | %.4f |" % r for r in rows]
    text = "\n".join(lines) + "\n"
    print(text)
    path = os.path.join(args.output, "benchmark-image.md")
    with open(path + ".partial", "w") as f:
        f.write(text)
    os.replace(path + ".partial", path)
    save_plot(os.path.join(args.output, "benchmark-image-plot.png"), infos, rows)


if __name__ == "__main__":
    main()
