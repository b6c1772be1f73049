"""The DeepGI plugin in pvbatch: the view loads, its properties have their
documented defaults, and each property set from Python changes the image the
way it should. Run with pvbatch (ParaView's Python), one rank:

    pvbatch CheckDeepGIRenderView.py PLUGIN OUTPUT_DIR

Scene: a sphere resting on a plane, ParaView's default display properties
(Ambient 0, Diffuse 1), 200 x 150 pixels; later a volume and a slice beside
them. Each check prints its measured
values; the run fails (a Python exception) when a check fails.
"""
import os
import sys

import numpy
from paraview import servermanager
from paraview.simple import (CreateView, Delete, LoadPlugin, Plane, SaveScreenshot, Show,
                             Slice, Sphere, Wavelet)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

PLUGIN, OUTPUT = sys.argv[1], sys.argv[2]
SIZE = [200, 150]
LEVEL = 1.0 / 255.0
failures = []


def check(condition, what):
    print("%s: %s" % ("ok" if condition else "FAILED", what))
    if not condition:
        failures.append(what)


def make_view(kind):
    view = CreateView(kind)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [30.0, -40.0, 30.0]
    view.CameraFocalPoint = [0.0, 0.0, 3.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    return view


def show_scene(view):
    sphere = Sphere(Center=[0.0, 0.0, 5.0], Radius=5.0, ThetaResolution=48, PhiResolution=48)
    plane = Plane(Origin=[-20.0, -20.0, 0.0], Point1=[20.0, -20.0, 0.0],
                  Point2=[-20.0, 20.0, 0.0], XResolution=16, YResolution=16)
    return [Show(sphere, view), Show(plane, view)]


def capture(view, name):
    """The view's image as floats in [0, 1], shape (rows, columns, 3)."""
    path = os.path.join(OUTPUT, name + ".png")
    SaveScreenshot(path, view, ImageResolution=SIZE, TransparentBackground=0)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    columns, rows, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(rows, columns, -1)
    return pixels[:, :, :3].astype(numpy.float64) / 255.0


def effects(view):
    view.UpdatePropertyInformation()
    return view.GetProperty("DeepGILastFrameEffects").GetElement(0)


def mean_change(a, b):
    return float(numpy.abs(a - b).mean())


def changed_fraction(a, b):
    return float((numpy.abs(a - b).max(axis=2) > 2.0 * LEVEL).mean())


os.makedirs(OUTPUT, exist_ok=True)
LoadPlugin(PLUGIN, remote=False, ns=globals())

# ParaView's own render view: the image the plugin must leave alone when off.
standard = make_view("RenderView")
show_scene(standard)
plain = capture(standard, "standard")
standard.UseAmbientOcclusion = 1
plain_ssao = capture(standard, "standard-ssao")
check(mean_change(plain_ssao, plain) > 2.0 * LEVEL, "ParaView's SSAO changes its image")
Delete(standard)

view = make_view("DeepGIRenderView")
displays = show_scene(view)
defaults = {"UseDeepGI": 1, "DeepGIPreset": "Balanced", "DeepGIAmbientObscurance": 1,
            "DeepGIRadiosity": 1, "DeepGIReflections": 1, "DeepGIObscuranceRadius": 0.05,
            "DeepGIRadiosityRadius": 0.5, "DeepGIConvergeStills": 1,
            "DeepGIConvergeMaximumFrames": 16}
for name, expected in defaults.items():
    value = getattr(view, name)
    close = abs(value - expected) < 1e-9 if isinstance(expected, float) else value == expected
    check(close, "default %s = %r (expected %r)" % (name, value, expected))

gi = capture(view, "gi")
check("RADIOSITY" in effects(view), "GI on: the frame ran %s" % effects(view))
background = numpy.all(numpy.abs(plain - plain[0, 0]) < 0.5 * LEVEL, axis=2)
check(float(numpy.abs(gi - plain)[background].max()) < 0.5 * LEVEL,
      "GI on: the background is untouched")
check(changed_fraction(gi, plain) > 0.05,
      "GI on: %.1f %% of the pixels changed against ParaView's view"
      % (100 * changed_fraction(gi, plain)))

view.UseDeepGI = 0
off = capture(view, "off")
check(effects(view) == "NONE", "GI off: nothing ran (%s)" % effects(view))
check(float(numpy.abs(off - plain).max()) < 0.5 * LEVEL,
      "GI off: the image equals ParaView's own view (max change %.4f)"
      % float(numpy.abs(off - plain).max()))

# ParaView's SSAO still works with the GI off, and is off while the GI is on.
view.UseAmbientOcclusion = 1
check(mean_change(capture(view, "off-ssao"), plain_ssao) < 0.5 * LEVEL,
      "GI off, UseAmbientOcclusion on: ParaView's SSAO image")
view.UseDeepGI = 1
check(mean_change(capture(view, "gi-ssao"), gi) < 0.5 * LEVEL,
      "GI on, UseAmbientOcclusion on: ParaView's SSAO is off (mean change %.5f)"
      % mean_change(capture(view, "gi-ssao"), gi))
view.UseAmbientOcclusion = 0

view.DeepGIPreset = "High Performance"
fast = capture(view, "high-performance")
check(0.0 < mean_change(fast, gi) < 2.0 * LEVEL,
      "High Performance: a different, close image (mean change %.5f)" % mean_change(fast, gi))
view.DeepGIPreset = "Balanced"

view.DeepGIConvergeStills = 0
single = capture(view, "single-frame")
check(float((gi - single).mean()) > 0.0,
      "ConvergeStills off: one bounce only, a darker image (mean %.5f lower)"
      % float((gi - single).mean()))
view.DeepGIConvergeStills = 1

view.DeepGIRadiosity = 0
no_radiosity = capture(view, "no-radiosity")
check("RADIOSITY" not in effects(view), "Radiosity off: %s" % effects(view))
check(mean_change(no_radiosity, plain) < mean_change(gi, plain),
      "Radiosity off: closer to ParaView's image (%.5f against %.5f)"
      % (mean_change(no_radiosity, plain), mean_change(gi, plain)))
view.DeepGIRadiosity = 1

# Obscurance needs an ambient term; a larger radius occludes more.
for display in displays:
    display.Ambient = 0.3
    display.Diffuse = 0.7
ambient = capture(view, "ambient")
check("AMBIENT_OBSCURANCE" in effects(view), "Ambient 0.3: %s" % effects(view))
view.DeepGIObscuranceRadius = 0.2
wide = capture(view, "ambient-wide-radius")
check(float((ambient - wide).mean()) > 0.0,
      "ObscuranceRadius 0.2: darker than 0.05 (mean %.5f lower)" % float((ambient - wide).mean()))
view.DeepGIObscuranceRadius = 0.05
for display in displays:
    display.Ambient = 0.0
    display.Diffuse = 1.0

# ParaView's other view features around the GI.
view.UseFXAA = 1
fxaa = capture(view, "fxaa")
check(0.0 < mean_change(fxaa, gi) < 2.0 * LEVEL,
      "UseFXAA: edges smoothed (mean change %.5f)" % mean_change(fxaa, gi))
view.UseFXAA = 0
view.UseToneMapping = 1
view.Exposure = 2.0
toned = capture(view, "tone-mapping")
check(mean_change(toned, gi) > 2.0 * LEVEL, "UseToneMapping: a different image")
view.UseToneMapping = 0
view.OrientationAxesVisibility = 1
axes = capture(view, "orientation-axes")
check(0.0 < changed_fraction(axes, gi) < 0.05 and "RADIOSITY" in effects(view),
      "OrientationAxesVisibility: the axes drawn over the GI image (%.2f %% of the pixels)"
      % (100 * changed_fraction(axes, gi)))
view.OrientationAxesVisibility = 0

# A volume and a slice beside the surfaces.
wavelet = Wavelet(WholeExtent=[8, 16, -4, 4, 0, 8])
volume = Show(wavelet, view)
volume.SetRepresentationType("Volume")
slice_display = Show(Slice(Input=wavelet), view)
mixed = capture(view, "volume-slice")
check("RADIOSITY" in effects(view) and mean_change(mixed, gi) > 2.0 * LEVEL,
      "a volume and a slice: drawn with the GI (%s)" % effects(view))

Delete(view)
print("%d failure(s)" % len(failures))
# pvbatch finalizes MPI itself after the script: an exception, not
# sys.exit, fails it.
if failures:
    raise RuntimeError("%d check(s) failed" % len(failures))
