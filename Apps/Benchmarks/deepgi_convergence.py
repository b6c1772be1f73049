"""How many frames vtkDeepGIPass needs to converge a still image.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
        Apps/Benchmarks/deepgi_convergence.py

Renders the demo scene (20,000 triangles, 320 x 240, default view) for 40
frames per preset at a fixed camera and prints, as Markdown table rows, the
mean absolute difference (0..255, RGB) between frame k and the mean of
frames 36-40 at k = 1, 5, 10, 20, the first frame from which every later
frame stays below 1/255, and the mean change per frame over the last five
frames. The presets run with the radiosity pass's default estimator, then
BALANCED once more with the paper's eq. 4 (ACCEPTED_TAPS). Needs an X
display (e.g. scripts/with-display.sh) or EGL.
"""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter

import vtkdeepgi

FRAMES = 40
SETTLED = slice(35, 40)


def grab(window):
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.ShouldRerenderOff()
    image.Update()
    return vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)


def measure(preset, estimator=None):
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(320, 240)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    scene.SetTargetNumberOfTriangles(20000)
    scene.Populate(renderer)
    scene.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    gi = vtkdeepgi.vtkDeepGIPass()
    gi.SetPreset(preset)
    if estimator is not None:
        gi.GetRadiosityPass().SetEstimator(estimator)
    renderer.SetPass(gi)
    frames = []
    for _ in range(FRAMES):
        window.Render()
        frames.append(grab(window))
    gi.ReleaseGraphicsResources(window)
    final = np.mean(frames[SETTLED], axis=0)
    difference = [np.abs(f - final).mean() for f in frames]
    change = [np.abs(frames[k] - frames[k - 1]).mean() for k in range(1, FRAMES)]
    settled = next(k + 1 for k in range(FRAMES) if max(difference[k:SETTLED.start]) < 1.0)
    return difference, settled, np.mean(change[-5:])


def main():
    Pass = vtkdeepgi.vtkDeepGIPass
    runs = [(name, preset, None) for name, preset in (
        ("HIGH_PERFORMANCE", Pass.HIGH_PERFORMANCE), ("BALANCED", Pass.BALANCED),
        ("HIGH_QUALITY", Pass.HIGH_QUALITY))]
    runs.append(("BALANCED, eq. 4", Pass.BALANCED, vtkdeepgi.vtkDeepRadiosityPass.ACCEPTED_TAPS))
    print("| preset | frame 1 | frame 5 | frame 10 | frame 20 | below 1/255 from frame | "
          "change per frame at the end |")
    print("|---|---|---|---|---|---|---|")
    for name, preset, estimator in runs:
        difference, settled, change = measure(preset, estimator)
        print("| `%s` | %.2f | %.2f | %.2f | %.2f | %d | %.2f |" % (
            name, difference[0], difference[4], difference[9], difference[19], settled, change))


if __name__ == "__main__":
    main()
