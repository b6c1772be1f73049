"""The deep G-buffer from Debian's VTK Python.

Imports the `vtkdeepgi` package, puts vtkDeepGBufferPass on a renderer with
the demo scene, renders, and checks the captured layers with numpy: layer 1
exists, lies at least dz behind layer 0, all values are finite, and the
resolved image equals what VTK draws without the pass. Exits non-zero on
failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter

import vtkdeepgi


def render(use_pass):
    # X11 when a display answers (one shared connection), else EGL.
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(256, 192)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    scene.SetTargetNumberOfTriangles(10000)
    scene.Populate(renderer)
    scene.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    gbuffer = None
    if use_pass:
        gbuffer = vtkdeepgi.vtkDeepGBufferPass()
        gbuffer.SetOracleToReproject()
        renderer.SetPass(gbuffer)
    for _ in range(3):
        window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)
    capture = None
    if gbuffer is not None:
        capture = vtkImageData()
        if not gbuffer.CaptureLayers(capture, renderer):
            raise RuntimeError("CaptureLayers failed")
        gbuffer.ReleaseGraphicsResources(window)
    return image, capture, gbuffer


def main():
    failures = []
    with_pass, capture, gbuffer = render(True)
    plain, _, _ = render(False)

    data = capture.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}
    if not all(np.isfinite(a).all() for a in arrays.values()):
        failures.append("non-finite values in the capture")
    dz = gbuffer.GetEffectiveMinimumSeparation()
    valid1 = arrays["Valid_1"] > 0
    excess = arrays["Depth_1"][valid1] - arrays["Depth_0"][valid1] - dz
    print("dz %.4f, layer 1 pixels %d, min excess over dz %.3g, geometry passes %d" % (
        dz, valid1.sum(), excess.min() if excess.size else float("nan"), gbuffer.GetLastGeometryPassCount()))
    if valid1.sum() < 1000 or (excess < -1e-6 * arrays["Depth_1"][valid1]).any():
        failures.append("layer 1 missing or closer than dz to layer 0")
    if gbuffer.GetEffectiveOracle() != vtkdeepgi.vtkDeepGBufferPass.REPROJECT:
        failures.append("REPROJECT was not used after the first frame")
    difference = np.abs(with_pass - plain).max()
    print("max difference to plain VTK: %d of 255" % difference)
    if difference > 1:
        failures.append("layer 0 differs from VTK's own image")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
