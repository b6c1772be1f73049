"""vtkDeepRadiosityPass::SkipStillCameraReprojection gives the same pixels
as reprojecting at a still camera.

A sphere on a floor before a wall (which layer 1 holds behind the sphere),
actors with VTK's default properties, rendered by each
GI preset and by the radiosity pass with the skip on and off. The camera
turns for the first frames (the reprojecting variants run), then stays
(frames rendered again with the temporal filter on: the bounce input and
the temporal filter read each texel's own history), then `Converge`
renders its still image (temporal filter off). HIGH_PERFORMANCE's reduced
grid keeps the reprojecting bounce input and skips only in the temporal
filter. A variant that read another texel, another layer or compared
another distance would change the image or a capture.

For each method the images after the still frames and after `Converge`,
and every array of the irradiance captures, must be equal, bit for bit.
Exits non-zero on failure.
"""
import sys

import numpy as np
from vtkmodules.vtkFiltersSources import vtkPlaneSource

import vtkdeepgi
from deepgi_testing import (
    add_actor, add_sphere_on_floor, capture_arrays, compare_bitwise, gi_preset, grab, look_at,
    new_window)

WIDTH, HEIGHT = 160, 120
MOVING_FRAMES = 3
DEGREES_PER_FRAME = 5.0
STILL_FRAMES = 3
CONVERGE_FRAMES = 4


def scene():
    window, renderer = new_window(WIDTH, HEIGHT)
    add_sphere_on_floor(renderer)
    wall = vtkPlaneSource()
    wall.SetOrigin(-1.5, -0.5, -1.5)
    wall.SetPoint1(1.5, -0.5, -1.5)
    wall.SetPoint2(-1.5, 2.0, -1.5)
    add_actor(renderer, wall)
    look_at(renderer, (0.0, 0.4, 3.0), (0.0, 0.0, 0.0))
    return window, renderer


def render(make, skip):
    """The images and irradiance captures after the still frames and after Converge."""
    window, renderer = scene()
    effect = make()
    gi = effect if isinstance(effect, vtkdeepgi.vtkDeepGIPass) else None
    radiosity = gi.GetRadiosityPass() if gi else effect
    radiosity.SetSkipStillCameraReprojection(skip)
    renderer.SetPass(effect)
    camera = renderer.GetActiveCamera()
    for _ in range(MOVING_FRAMES):
        camera.Azimuth(DEGREES_PER_FRAME)
        renderer.ResetCameraClippingRange()
        window.Render()
    for _ in range(STILL_FRAMES):
        window.Render()
    out = {"still image": grab(window)}
    capture_arrays(radiosity.CaptureIrradiance, renderer, "still irradiance ", out)
    if gi:
        gi.Converge(renderer, CONVERGE_FRAMES)
        out["converged image"] = grab(window)
        capture_arrays(radiosity.CaptureIrradiance, renderer, "converged irradiance ", out)
    renderer.SetPass(None)
    effect.ReleaseGraphicsResources(window)
    return out


METHODS = {
    "HIGH_PERFORMANCE": gi_preset("HIGH_PERFORMANCE"),
    "BALANCED": gi_preset("BALANCED"),
    "HIGH_QUALITY": gi_preset("HIGH_QUALITY"),
    "vtkDeepRadiosityPass": vtkdeepgi.vtkDeepRadiosityPass,
}


def main():
    failures = []
    for name, make in METHODS.items():
        skipped = render(make, True)
        reprojected = render(make, False)
        print("%s: %d arrays compared" % (name, len(reprojected)))
        compare_bitwise(name, skipped, reprojected, "with the skip on", failures)
        failures.extend("%s: %s is all zero" % (name, key) for key, value in reprojected.items()
                        if value is not None and not np.any(value) and key.endswith("_0"))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
