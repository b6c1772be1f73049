"""ParaView-style use of vtkDeepGIPass: load a CT volume, extract an
iso-surface, switch global illumination on in one line, converge, save.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \\
        Examples/Python/deepgi_isosurface.py [--data Testing/Data] \\
        [--preset balanced] [--frames 20] [--size 400x300] [--output gi.png] \\
        [--plain plain.png]

--plain also writes the view as VTK renders it without the pass.
"""
import argparse
import os

from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkIOImage import vtkPNGWriter, vtkVolume16Reader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)

import vtkdeepgi


def save(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()  # the image just rendered, not one more frame
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", default=os.path.join(os.path.dirname(__file__), "..", "..",
                                                       "Testing", "Data"))
    parser.add_argument("--preset", default="balanced")
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--output", default="gi.png")
    parser.add_argument("--plain")
    args = parser.parse_args()

    # The volume: the headsq CT slices (64 x 64 x 93, 16-bit).
    reader = vtkVolume16Reader()
    reader.SetFilePrefix(os.path.join(args.data, "volumes", "headsq", "quarter"))
    reader.SetDataDimensions(64, 64)
    reader.SetImageRange(1, 93)
    reader.SetDataByteOrderToLittleEndian()
    reader.SetDataSpacing(3.2, 3.2, 1.5)
    # The iso-surface (the skin at 500), as a ParaView Contour would make it.
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(reader.GetOutputPort())
    contour.SetValue(0, 500.0)
    contour.ComputeNormalsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.92, 0.78, 0.68)
    actor.GetProperty().SetAmbient(0.25)  # the light AO darkens

    # X11 when a display answers, otherwise EGL (no X server needed).
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*(int(v) for v in args.size.split("x")))
    renderer = vtkRenderer()
    renderer.SetBackground(0.32, 0.34, 0.43)
    window.AddRenderer(renderer)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 1.0, 0.0)  # the face (the CT looks along -y)
    camera.SetViewUp(0.0, 0.0, -1.0)
    renderer.ResetCamera()
    camera.Azimuth(30.0)
    camera.Elevation(15.0)
    renderer.ResetCameraClippingRange()
    if args.plain:
        window.Render()
        save(window, args.plain)

    # Global illumination in one line, with a preset.
    gi = vtkdeepgi.vtkDeepGIPass()
    gi.SetPreset(args.preset)
    renderer.SetPass(gi)
    gi.Converge(renderer, args.frames)
    print("ran %s with %d layer(s)" % (gi.GetEffectsAsString(gi.GetLastFrameEffects()),
                                       gi.GetLastFrameNumberOfLayers()))
    save(window, args.output)
    gi.ReleaseGraphicsResources(window)  # while the window's context exists


if __name__ == "__main__":
    main()
