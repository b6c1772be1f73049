"""Deep ambient obscurance from Debian's VTK Python.

Imports the `vtkdeepgi` package, puts vtkDeepAmbientObscurancePass on a
renderer with the demo scene, renders through vtkDeepGIRenderWindowFactory,
captures the ambient visibility AV and checks it with numpy:
- every value finite and in [0, 1], exactly 1 on empty pixels;
- creases are darker than open surfaces: the mean of the darkest 5 % of the
  surface pixels lies at least 0.2 below the median (the demo room's
  floor-wall corners, column feet and banners; the median, 0.90 when
  written, is an open surface: at least 0.8; the darkest 5 % averaged 0.43);
- with COMPOSITE_MULTIPLY the image differs from the plain G-buffer image
  (vtkDeepGBufferPass alone, same scene) only by darkening: never brighter
  by more than one 8-bit level (rounding), and equal to plain x AV within 2
  levels;
- with the default COMPOSITE_AUTOMATIC the demo scene (Ambient 0.1) gets the
  ambient composition: only VTK's ambient term is darkened, so no pixel is
  brighter than plain (1 level) or darker than 0.1 x 255 + 1 levels, and
  some pixels are darker by more than 2 levels.
Exits non-zero on failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

import vtkdeepgi
from deepgi_testing import new_window

WIDTH, HEIGHT = 256, 192


def render(make_pass):
    window, renderer = new_window(WIDTH, HEIGHT)
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    scene.SetTargetNumberOfTriangles(10000)
    scene.Populate(renderer)
    scene.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    render_pass = make_pass()
    renderer.SetPass(render_pass)
    for _ in range(3):
        window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)
    capture = None
    if isinstance(render_pass, vtkdeepgi.vtkDeepAmbientObscurancePass):
        capture = vtkImageData()
        if not render_pass.CaptureAmbientVisibility(capture, renderer):
            raise RuntimeError("CaptureAmbientVisibility failed")
    render_pass.ReleaseGraphicsResources(window)
    return image, capture, render_pass


def multiply_pass():
    render_pass = vtkdeepgi.vtkDeepAmbientObscurancePass()
    render_pass.SetCompositionToMultiply()
    return render_pass


def main():
    failures = []
    ao_image, capture, ao = render(multiply_pass)
    plain_image, _, _ = render(vtkdeepgi.vtkDeepGBufferPass)
    ambient_image, _, automatic = render(vtkdeepgi.vtkDeepAmbientObscurancePass)

    data = capture.GetPointData()
    av = vtk_to_numpy(data.GetArray("AmbientVisibility")).astype(float)
    raw = vtk_to_numpy(data.GetArray("RawAmbientVisibility")).astype(float)
    valid = vtk_to_numpy(data.GetArray("Valid")) > 0
    if av.size != WIDTH * HEIGHT:
        failures.append("capture has %d pixels, not %d" % (av.size, WIDTH * HEIGHT))
    if not (np.isfinite(av).all() and np.isfinite(raw).all()):
        failures.append("non-finite AV")
    if (av < 0).any() or (av > 1).any() or (raw < 0).any() or (raw > 1).any():
        failures.append("AV outside [0, 1]")
    if (av[~valid] != 1).any():
        failures.append("AV not 1 on empty pixels")

    surface = np.sort(av[valid])
    darkest = surface[: max(1, surface.size // 20)].mean()
    median = np.median(surface)
    print("radius %.4g, %d surface px, median AV %.4f, mean of the darkest 5%% %.4f" % (
        ao.GetEffectiveRadius(), surface.size, median, darkest))
    if surface.size < WIDTH * HEIGHT // 4:
        failures.append("too few surface pixels")
    if median < 0.8 or darkest > median - 0.2:
        failures.append("creases are not darker than open surfaces")

    # Only darkening: the AO image is the plain image times AV (alpha kept).
    brighter = (ao_image - plain_image).max()
    expected = plain_image * av[:, None]
    error = np.abs(ao_image - expected).max()
    print("AO image vs plain: brightest increase %.0f levels, max |AO - plain x AV| %.2f levels, "
          "%d px darker" % (brighter, error, (ao_image < plain_image - 1).any(axis=1).sum()))
    if brighter > 1:
        failures.append("the AO image is brighter than the plain image somewhere")
    if error > 2:
        failures.append("the AO image is not the plain image times AV")

    # The default composition darkens only the ambient term (Ambient 0.1).
    Pass = vtkdeepgi.vtkDeepAmbientObscurancePass
    effective = Pass.GetCompositionAsString(automatic.GetEffectiveComposition())
    darkening = (plain_image - ambient_image).max()
    print("default composition %s -> %s: brightest increase %.0f levels, largest darkening "
          "%.0f levels" % (Pass.GetCompositionAsString(automatic.GetComposition()), effective,
                           (ambient_image - plain_image).max(), darkening))
    if automatic.GetComposition() != Pass.COMPOSITE_AUTOMATIC:
        failures.append("the default composition is not COMPOSITE_AUTOMATIC")
    if automatic.GetEffectiveComposition() != Pass.COMPOSITE_AMBIENT:
        failures.append("an ambient scene did not get the ambient composition")
    if (ambient_image - plain_image).max() > 1 or darkening > 0.1 * 255 + 1 or darkening <= 2:
        failures.append("the ambient composition darkens more than the ambient term, or nothing")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
