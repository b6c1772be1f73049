"""Deep screen-space radiosity from Debian's VTK Python.

Puts vtkDeepRadiosityPass (Damping 0.5, TemporalAlpha 0: the bounces
converge at a still camera) on a renderer with the demo scene, renders 12
frames through vtkDeepGIRenderWindowFactory, captures the radiosity and
the G-buffer layers and checks them with numpy:
- every array finite; E, L_ind and the confidence non-negative, the
  confidence at most 1, all of them exactly 0 on empty pixels;
- L_ind = rho E / pi (eq. 6, boost 1, no fallback) within 1e-5 (1 + |L|)
  from the captured irradiance and albedo;
- the framebuffer is RADIANCE + L_ind of layer 0 within 2 8-bit levels
  where that sum is below 1 (8-bit rounding), and never darker than the
  plain G-buffer image by more than one level.
Exits non-zero on failure.
"""
import math
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

import vtkdeepgi
from deepgi_testing import new_window

WIDTH, HEIGHT = 200, 150


def render(make_pass, frames):
    window, renderer = new_window(WIDTH, HEIGHT)
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    scene.SetTargetNumberOfTriangles(10000)
    scene.Populate(renderer)
    scene.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    render_pass = make_pass()
    renderer.SetPass(render_pass)
    for _ in range(frames):
        window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)
    radiosity, layers = None, None
    if isinstance(render_pass, vtkdeepgi.vtkDeepRadiosityPass):
        radiosity, layers = vtkImageData(), vtkImageData()
        if not render_pass.CaptureIrradiance(radiosity, renderer):
            raise RuntimeError("CaptureIrradiance failed")
        if not render_pass.GetGBufferPass().CaptureLayers(layers, renderer):
            raise RuntimeError("CaptureLayers failed")
    render_pass.ReleaseGraphicsResources(window)
    return image, radiosity, layers


def radiosity_pass():
    p = vtkdeepgi.vtkDeepRadiosityPass()
    p.SetDamping(0.5)
    p.SetTemporalAlpha(0.0)
    return p


def main():
    failures = []
    image, radiosity, layers = render(radiosity_pass, 12)
    plain, _, _ = render(vtkdeepgi.vtkDeepGBufferPass, 3)

    def array(data, name):
        return vtk_to_numpy(data.GetPointData().GetArray(name)).astype(float)

    for j in (0, 1):
        valid = array(radiosity, "Valid_%d" % j) > 0
        for name in ("Irradiance", "IndirectRadiance", "Confidence", "RawIrradiance"):
            a = array(radiosity, "%s_%d" % (name, j))
            if not np.isfinite(a).all():
                failures.append("%s_%d not finite" % (name, j))
            if (a < 0).any():
                failures.append("%s_%d negative" % (name, j))
            if (a[~valid] != 0).any():
                failures.append("%s_%d not 0 on empty pixels" % (name, j))
        if (array(radiosity, "Confidence_%d" % j) > 1).any():
            failures.append("confidence above 1")
        e = array(radiosity, "Irradiance_%d" % j)
        l_ind = array(radiosity, "IndirectRadiance_%d" % j)
        rho = array(layers, "Albedo_%d" % j)[:, :3]
        error = np.abs(l_ind - rho * e / math.pi)[valid]
        worst = (error / (1 + np.abs(l_ind[valid]))).max() if valid.any() else 0.0
        print("layer %d: %d px, mean L_ind %.4f, mean confidence %.3f, max |L - rho E / pi| %.2e" % (
            j, valid.sum(), l_ind[valid].mean() if valid.any() else 0.0,
            array(radiosity, "Confidence_%d" % j)[valid].mean() if valid.any() else 0.0, worst))
        # L_ind is stored in an RGBA16F target: rounded by at most 2^-11
        # (4.9e-4) of its value.
        if worst > 1e-3:
            failures.append("L_ind is not rho E / pi on layer %d" % j)

    valid = array(radiosity, "Valid_0") > 0
    expected = 255.0 * (array(layers, "Radiance_0")[:, :3] + array(radiosity, "IndirectRadiance_0"))
    unsaturated = valid & (expected.max(axis=1) < 250.0)
    error = np.abs(image - expected)[unsaturated].max()
    darker = (plain - image).max()
    print("composite: %d unsaturated px, max |image - (RADIANCE + L_ind)| %.2f levels; largest "
          "darkening vs the plain image %.0f levels" % (unsaturated.sum(), error, darker))
    if unsaturated.sum() < WIDTH * HEIGHT // 4:
        failures.append("too few unsaturated surface pixels")
    if error > 2:
        failures.append("the image is not RADIANCE + L_ind")
    if darker > 1:
        failures.append("the image is darker than the plain image somewhere")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
