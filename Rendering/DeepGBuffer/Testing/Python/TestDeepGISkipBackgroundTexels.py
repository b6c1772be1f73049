"""vtkDeepGBufferPass::SkipBackgroundTexels gives the same pixels as
shading every texel.

A sphere on a floor, actors with VTK's default properties, with a third of
the frame background, rendered by each GI preset, the radiosity and the
obscurance passes with the skip on and off. The camera turns 12 degrees
per frame, so that texels change between surface and background and the
temporal filters reproject history across silhouettes: a stage that left
stale values in skipped texels, or wrote other values there than its
shader writes for the background, would change the image or a capture.
The window is resized before the last frames.

For each method the final image and every array of the irradiance and
ambient visibility captures must be equal, bit for bit. Exits non-zero on
failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData

import vtkdeepgi
from deepgi_testing import (
    add_sphere_on_floor, capture_arrays, compare_bitwise, gi_preset, grab, look_at, new_window)

WIDTH, HEIGHT = 160, 120
RESIZED = 200, 150  # the last frames' size: the coverage follows a resize
FRAMES = 4
DEGREES_PER_FRAME = 12.0
MINIMUM_BACKGROUND = 0.2  # of the layers' texels, so that skipping matters


def scene():
    window, renderer = new_window(WIDTH, HEIGHT)
    add_sphere_on_floor(renderer)
    look_at(renderer, (0.0, 1.2, 3.5), (0.0, -0.2, 0.0))
    return window, renderer


def background_fraction(gbuffer, renderer):
    layers = vtkImageData()
    if not gbuffer.CaptureLayers(layers, renderer):
        return 0.0
    return float(np.mean(vtk_to_numpy(layers.GetPointData().GetArray("Depth_0")) <= 0.0))


def render(make, skip):
    """The image and captures after FRAMES frames; the layers' background fraction."""
    window, renderer = scene()
    effect = make()
    effect.GetGBufferPass().SetSkipBackgroundTexels(skip)
    renderer.SetPass(effect)
    camera = renderer.GetActiveCamera()
    for frame in range(FRAMES):
        if frame == FRAMES - 2:
            window.SetSize(*RESIZED)
        camera.Azimuth(DEGREES_PER_FRAME)
        renderer.ResetCameraClippingRange()
        window.Render()
    out = {"image": grab(window)}
    radiosity = obscurance = None
    if isinstance(effect, vtkdeepgi.vtkDeepGIPass):
        radiosity, obscurance = effect.GetRadiosityPass(), effect.GetAmbientObscurancePass()
    elif isinstance(effect, vtkdeepgi.vtkDeepRadiosityPass):
        radiosity = effect
    else:
        obscurance = effect
    if radiosity:
        capture_arrays(radiosity.CaptureIrradiance, renderer, "irradiance ", out)
    if obscurance:
        capture_arrays(obscurance.CaptureAmbientVisibility, renderer, "visibility ", out)
    fraction = background_fraction(effect.GetGBufferPass(), renderer)
    renderer.SetPass(None)
    effect.ReleaseGraphicsResources(window)
    return out, fraction


METHODS = {
    "HIGH_PERFORMANCE": gi_preset("HIGH_PERFORMANCE"),
    "BALANCED": gi_preset("BALANCED"),
    "HIGH_QUALITY": gi_preset("HIGH_QUALITY"),
    "vtkDeepRadiosityPass": vtkdeepgi.vtkDeepRadiosityPass,
    "vtkDeepAmbientObscurancePass": vtkdeepgi.vtkDeepAmbientObscurancePass,
}


def main():
    failures = []
    for name, make in METHODS.items():
        skipped, fraction = render(make, True)
        shaded, _ = render(make, False)
        print("%s: %d arrays compared, %.2f of the layers background"
              % (name, len(shaded), fraction))
        if fraction < MINIMUM_BACKGROUND:
            failures.append("%s: only %.2f of the layers is background" % (name, fraction))
        compare_bitwise(name, skipped, shaded, "with the skip on", failures)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
