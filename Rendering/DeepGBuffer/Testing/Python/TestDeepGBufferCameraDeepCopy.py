"""A camera restored with vtkCamera::DeepCopy, which in VTK 9.1 does not
call Modified(), renders its own view in the deep G-buffer.

VTK's mappers take the camera's matrices from a cache that vtkOpenGLCamera
refreshes when the camera's modification time passes it; vtkDeepGBufferPass
refreshes it when the cached view or projection is not the camera's.
A sphere on a floor is rendered at a saved camera, after turning the
camera by 3 degrees, and after restoring the saved camera with DeepCopy
(and ResetCameraClippingRange, which leaves the camera unmodified here):

- vtkDeepGBufferPass: layer 0's distance and the recorded view equal those
  of the first frame, bit for bit;
- vtkDeepRadiosityPass with its temporal filter off (each frame one more
  bounce): the restore, a turn back, keeps as much of the bounces as the
  turn did (the mean irradiance within 2 % of the turned frame's), where
  layers rasterised with the last frame's view and reprojected with this
  one's lose more of them (6 % here).

Exits non-zero on failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkCamera, vtkLight

import vtkdeepgi
from deepgi_testing import add_sphere_on_floor, look_at, new_window

WIDTH, HEIGHT = 160, 120
DEGREES = 3.0
SETTLE_FRAMES = 6
KEPT_BOUNCES = 0.98  # of the mean irradiance after the turn


def scene():
    window, renderer = new_window(WIDTH, HEIGHT)
    add_sphere_on_floor(renderer)
    # A light of the scene's own: VTK's automatic headlight, created at
    # the first frame, would refresh the camera's cached matrices itself.
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(-1.0, 3.0, 2.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(light)
    look_at(renderer, (0.0, 1.2, 3.5), (0.0, -0.2, 0.0))
    return window, renderer


def layers(gbuffer, renderer):
    """Layer 0's distance and the recorded view matrix."""
    image = vtkImageData()
    if not gbuffer.CaptureLayers(image, renderer):
        return None, None
    view = image.GetFieldData().GetArray("ViewMatrix")
    return (vtk_to_numpy(image.GetPointData().GetArray("Depth_0")).copy(),
            vtk_to_numpy(view).copy() if view else None)


def turn_and_restore(window, renderer, measure):
    """measure() at the saved camera, after the turn and after the restore."""
    camera = renderer.GetActiveCamera()
    saved = vtkCamera()
    saved.DeepCopy(camera)
    window.Render()
    before = measure()
    camera.Azimuth(DEGREES)
    renderer.ResetCameraClippingRange()
    window.Render()
    turned = measure()
    modified = camera.GetMTime()
    camera.DeepCopy(saved)
    renderer.ResetCameraClippingRange()
    unmodified = camera.GetMTime() == modified
    window.Render()
    return before, turned, measure(), unmodified


def check_layers(failures):
    window, renderer = scene()
    gbuffer = vtkdeepgi.vtkDeepGBufferPass()
    renderer.SetPass(gbuffer)
    window.Render()
    (d0, v0), (d1, _), (d2, v2), unmodified = turn_and_restore(
        window, renderer, lambda: layers(gbuffer, renderer))
    renderer.SetPass(None)
    gbuffer.ReleaseGraphicsResources(window)
    print("G-buffer: camera unmodified by the restore: %s; distance moved by the turn: %.3g, "
          "after the restore: %.3g" % (unmodified, np.abs(d1 - d0).max(), np.abs(d2 - d0).max()))
    if not unmodified:
        failures.append("the restore modified the camera: the case is not tested")
    if not np.any(d1 != d0):
        failures.append("the turn did not change the layers")
    if not np.array_equal(d2, d0) or v0 is None or not np.array_equal(v2, v0):
        failures.append("after the restore the layers are not those of the saved camera")


def mean_irradiance(radiosity, renderer):
    """The mean of layer 0's captured irradiance (RGB)."""
    image = vtkImageData()
    radiosity.CaptureIrradiance(image, renderer)
    return float(vtk_to_numpy(image.GetPointData().GetArray("Irradiance_0"))[..., :3].mean())


def check_radiosity(failures):
    window, renderer = scene()
    radiosity = vtkdeepgi.vtkDeepRadiosityPass()
    radiosity.SetTemporalAlpha(0.0)
    renderer.SetPass(radiosity)
    for _ in range(SETTLE_FRAMES):
        window.Render()
    before, turned, restored, _ = turn_and_restore(
        window, renderer, lambda: mean_irradiance(radiosity, renderer))
    renderer.SetPass(None)
    radiosity.ReleaseGraphicsResources(window)
    # The single bounce: the first frame of a new pass.
    fresh_window, fresh_renderer = scene()
    fresh = vtkdeepgi.vtkDeepRadiosityPass()
    fresh_renderer.SetPass(fresh)
    fresh_window.Render()
    single = mean_irradiance(fresh, fresh_renderer)
    fresh_renderer.SetPass(None)
    fresh.ReleaseGraphicsResources(fresh_window)
    print("radiosity: mean E before %.4f, turned %.4f, restored %.4f; single bounce %.4f"
          % (before, turned, restored, single))
    if not (single < 0.8 * turned):
        failures.append("the bounces add too little light to tell a lost history")
    if not (restored >= KEPT_BOUNCES * turned):
        failures.append("after the restore the radiosity lost bounces (%.4f against %.4f)"
                        % (restored, turned))


def main():
    failures = []
    check_layers(failures)
    check_radiosity(failures)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
