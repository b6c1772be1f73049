"""The final image's error against the reference as the radiosity's gather
radius and damping change (Documentation/lighting-model.md).

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
        Apps/Benchmarks/deepgi_radiosity_radius_sweep.py DATA HELDOUT \\
        [--default-actors] [FRACTION:DAMPING[:OUTER] ...]

DATA is the project's Testing/Data, HELDOUT the folder of
scripts/heldout-scenes.sh. For the image benchmark's seven scenes (the
demo scene, the Cornell box with Lucy, the dragon, the CT head, and the
object on a floor, the stairs room and the wavelet of HELDOUT; the scene
loader's materials, or with --default-actors VTK's default property on
every actor; 320 x 240), each setting (default 0.1:0.5 0.3:1.0 0.5:1.0
0.75:1.0 1.0:1.0) sets the radiosity pass's AutomaticRadiusFraction,
Damping and OuterSamples (OUTER; without it the pass's own) of a BALANCED
vtkDeepGIPass,
converges it as the image benchmark does (Converge(renderer,
16, 0.07 / 255)) and prints the RMSE and bias of the 8-bit image against
vtkDeepGIReferenceImage (128 rays per pixel, 4 bounces, clipped at 1),
computed once per scene on the first setting's capture.
Needs an X display (scripts/with-display.sh) or EGL.
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkRenderer

import vtkdeepgi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deepgi_benchmark_image as bench  # noqa: E402 (the scenes and the grab)


def reference_of(gi, renderer):
    capture = vtkImageData()
    gi.GetGBufferPass().CaptureLayers(capture, renderer)
    reference = vtkdeepgi.vtkDeepGIReferenceImage()
    scene = vtkPolyData()
    reference.SceneFromRenderer(renderer, scene)
    reference.SetScene(scene)
    reference.SetLightsFromRenderer(renderer)
    obscurance = gi.GetAmbientObscurancePass()
    reference.SetObscuranceRadius(obscurance.GetEffectiveRadius())
    multiply = obscurance.ResolveComposition(renderer) == obscurance.COMPOSITE_MULTIPLY
    reference.SetVisibility(reference.AV_SCALES_RADIANCE if multiply else reference.AV_SCALES_AMBIENT)
    reference.SetSamplesPerPixel(128)
    if not reference.Compute(capture):
        sys.exit("deepgi_radiosity_radius_sweep.py: no reference")
    out = reference.GetOutput().GetPointData()
    truth = np.clip(vtk_to_numpy(out.GetArray("Radiance")).astype(float), 0.0, 1.0)
    return truth, vtk_to_numpy(out.GetArray("Valid")) > 0


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    data, heldout = sys.argv[1], sys.argv[2]
    default_actors = "--default-actors" in sys.argv[3:]
    settings = [tuple(float(v) for v in s.split(":")) for s in sys.argv[3:]
                if s != "--default-actors"] or [(0.1, 0.5), (0.3, 1.0), (0.5, 1.0),
                                                (0.75, 1.0), (1.0, 1.0)]
    # Without OUTER the pass's own OuterSamples.
    settings = [s if len(s) == 3 else s + (None,) for s in settings]
    scenes = ["demo", "cornell-lucy", "dragon", "headsq",
              ("mesh", os.path.join(heldout, "wuson-on-floor.vtp")),
              ("mesh", os.path.join(heldout, "stairs-room.vtp")),
              ("volume", os.path.join(heldout, "wavelet.nhdr"), 160.0)]
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    for scene in scenes:
        window = factory.NewRenderWindow(factory.BACKEND_AUTO)
        window.SetMultiSamples(0)
        window.SetSize(320, 240)
        renderer = vtkRenderer()
        window.AddRenderer(renderer)
        name, keep = bench.populate(renderer, scene, data)
        if default_actors:
            bench.use_default_properties(renderer)
        renderer.ResetCameraClippingRange()
        truth, valid, cells = None, None, []
        for fraction, damping, outer in settings:
            gi = vtkdeepgi.vtkDeepGIPass()
            gi.GetRadiosityPass().SetAutomaticRadiusFraction(fraction)
            gi.GetRadiosityPass().SetDamping(damping)
            if outer is not None:
                gi.GetRadiosityPass().SetOuterSamples(int(outer))
            renderer.SetPass(gi)
            gi.Converge(renderer, 16, 0.07 / 255.0)
            image = bench.grab(window)
            if truth is None:
                truth, valid = reference_of(gi, renderer)
            d = image[valid] - truth[valid]
            cells.append("r %.2f damping %.1f outer taps %d: RMSE %.4f bias %+.4f" % (
                fraction, damping, gi.GetRadiosityPass().GetOuterSamples(),
                np.sqrt(np.mean(d * d)), np.mean(d)))
            gi.ReleaseGraphicsResources(window)
        renderer.SetPass(None)
        print(name + " | " + " | ".join(cells), flush=True)
        del keep


if __name__ == "__main__":
    main()
