"""vtkDeepGIPass from Debian's VTK Python, in one line: renderer.SetPass(gi).

On the demo scene (ambient term, diffuse colours, a light) with the
BALANCED preset:
- gi.Converge(renderer, 6) renders 6 frames and fires 6 ProgressEvents,
  the last with progress 1;
- GetLastFrameEffects() names ambient obscurance and radiosity (the demo
  scene has no specular prop: no reflections) and two layers;
- the G-buffer has the default guard band (0.1 of the height, 16 pixels);
- the image differs from the plain vtkDeepGBufferPass image (GI adds and
  removes light) but keeps the same background, and the G-buffer shared
  by the sub-passes is the GI pass's;
- the composite equals RADIANCE - (1 - AV) AMBIENT + L_ind of layer 0
  within 2 8-bit levels where unsaturated (numpy, from the captures).
Exits non-zero on failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData

import deepgi_testing
import vtkdeepgi
from deepgi_testing import new_window

WIDTH, HEIGHT = 200, 150


def scene():
    window, renderer = new_window(WIDTH, HEIGHT)
    demo = vtkdeepgi.vtkDeepGIDemoScene()
    demo.SetTargetNumberOfTriangles(10000)
    demo.Populate(renderer)
    demo.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    return window, renderer


def grab(window):
    return deepgi_testing.grab(window).astype(float)


def main():
    failures = []
    window, renderer = scene()
    gi = vtkdeepgi.vtkDeepGIPass()
    gi.SetPresetToBalanced()
    renderer.SetPass(gi)
    progress = []

    @calldata_type(VTK_DOUBLE)
    def on_progress(caller, event, data):
        progress.append(data)

    gi.AddObserver(vtkCommand.ProgressEvent, on_progress)
    frames = gi.Converge(renderer, 6)
    image = grab(window)
    effects = gi.GetLastFrameEffects()
    print("Converge: %d frames, %d ProgressEvents; effects %s, %d layers" % (
        frames, len(progress), gi.GetEffectsAsString(effects), gi.GetLastFrameNumberOfLayers()))
    print("progress:", progress)
    if frames != 6 or len(progress) != 6 or abs(progress[-1] - 1.0) > 1e-12:
        failures.append("Converge did not render 6 frames with 6 ProgressEvents ending at 1")
    wanted = gi.AMBIENT_OBSCURANCE | gi.RADIOSITY | gi.SECOND_LAYER
    if effects != wanted:
        failures.append("expected %s" % gi.GetEffectsAsString(wanted))
    if gi.GetRadiosityPass().GetGBufferPass() is not gi.GetGBufferPass():
        failures.append("the radiosity pass does not share the G-buffer")
    # The G-buffer's guard band: 0.1 of the height, rounded up to 8 pixels.
    band = gi.GetGBufferPass().GetEffectiveGuardBand()
    print("guard band %.2f: %d pixels" % (gi.GetGBufferPass().GetGuardBand(), band))
    if gi.GetGBufferPass().GetGuardBand() != 0.1 or band != 16:
        failures.append("expected the default guard band of 0.1 (16 pixels at 150)")

    layers, av, radiosity = vtkImageData(), vtkImageData(), vtkImageData()
    ok = (gi.GetGBufferPass().CaptureLayers(layers, renderer)
          and gi.GetAmbientObscurancePass().CaptureAmbientVisibility(av, renderer)
          and gi.GetRadiosityPass().CaptureIrradiance(radiosity, renderer))
    gi.ReleaseGraphicsResources(window)
    if not ok:
        print("FAILED: captures")
        return 1

    def array(data, name):
        return vtk_to_numpy(data.GetPointData().GetArray(name)).astype(float)

    valid = array(layers, "Valid_0") > 0
    expected = 255.0 * (array(layers, "Radiance_0")[:, :3]
                        - (1.0 - array(av, "AmbientVisibility"))[:, None] * array(layers, "Ambient_0")
                        + array(radiosity, "IndirectRadiance_0"))
    unsaturated = valid & (expected.max(axis=1) < 250.0) & (expected.min(axis=1) > 0.0)
    error = np.abs(image - expected)[unsaturated].max()
    print("composite: %d unsaturated px, max |image - formula| %.2f levels" % (
        unsaturated.sum(), error))
    if unsaturated.sum() < WIDTH * HEIGHT // 4 or error > 2:
        failures.append("the image is not RADIANCE - (1 - AV) AMBIENT + L_ind")

    plain_window, plain_renderer = scene()
    plain = vtkdeepgi.vtkDeepGBufferPass()
    plain_renderer.SetPass(plain)
    plain_window.Render()
    plain_image = grab(plain_window)
    plain.ReleaseGraphicsResources(plain_window)
    changed = (np.abs(image - plain_image).max(axis=1) > 4)
    print("vs the plain G-buffer image: %d surface px differ by more than 4 levels, %d "
          "background px differ" % ((changed & valid).sum(), (changed & ~valid).sum()))
    if (changed & valid).sum() < valid.sum() // 10:
        failures.append("GI changes too few pixels")
    if (changed & ~valid).any():
        failures.append("GI changed the background")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
