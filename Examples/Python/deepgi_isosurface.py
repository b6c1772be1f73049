"""ParaView-style use of vtkDeepGIPass: load a CT volume, extract an
iso-surface, switch global illumination on in one line, converge, save.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/deepgi_isosurface.py [--data DIR] [--iso 500] \
        [--preset balanced] [--frames 20] [--size 400x300] [--output gi.png] \
        [--plain plain.png]

--data is the folder holding volumes/headsq (default: the repository's
Testing/Data); --plain also writes the same view
rendered by VTK without the pass, for comparison.
"""
import argparse
import os
import sys

from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkIOImage import vtkPNGWriter, vtkVolume16Reader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL implementations)

import vtkdeepgi

HERE = os.path.dirname(os.path.abspath(__file__))


def save(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    print("wrote", path)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "Testing", "Data"))
    parser.add_argument("--iso", type=float, default=500.0)
    parser.add_argument("--preset", default="balanced",
                        choices=["high_performance", "balanced", "high_quality"])
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--output", default="gi.png")
    parser.add_argument("--plain", default=None)
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.split("x"))

    # The volume: the headsq CT slices (64 x 64 x 93, 16-bit).
    reader = vtkVolume16Reader()
    reader.SetFilePrefix(os.path.join(args.data, "volumes", "headsq", "quarter"))
    reader.SetDataDimensions(64, 64)
    reader.SetImageRange(1, 93)
    reader.SetDataByteOrderToLittleEndian()
    reader.SetDataSpacing(3.2, 3.2, 1.5)
    reader.Update()
    if reader.GetOutput().GetNumberOfPoints() == 0:
        print("cannot read", reader.GetFilePrefix(), file=sys.stderr)
        return 1

    # The iso-surface (the skin at 500), as a ParaView Contour would make it.
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(reader.GetOutputPort())
    contour.SetValue(0, args.iso)
    contour.ComputeNormalsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.92, 0.78, 0.68)
    actor.GetProperty().SetAmbient(0.25)  # the light AO darkens

    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    renderer = vtkRenderer()
    renderer.SetBackground(0.32, 0.34, 0.43)
    window.AddRenderer(renderer)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 1.0, 0.0)  # the face (the CT looks along -y)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
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
    gi.SetPreset(gi.GetPresetFromString(args.preset))
    renderer.SetPass(gi)

    gi.Converge(renderer, args.frames)
    print("ran %s with %d layer(s)" % (gi.GetEffectsAsString(gi.GetLastFrameEffects()),
                                       gi.GetLastFrameNumberOfLayers()))
    save(window, args.output)
    gi.ReleaseGraphicsResources(window)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
