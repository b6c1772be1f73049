"""Capture the two layers of the deep G-buffer and save them as a VTK image.

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
        Examples/Python/deepgi_capture_layers.py [--size 400x300] [--output layers.vti]

A sphere floats above a plane: layer 0 is what the camera sees, layer 1 the
next surface behind it (the plane behind the sphere, the sphere's back).
vtkDeepGBufferPass.CaptureLayers copies both into one vtkImageData, one
point-data array per quantity and layer ("Depth_0", "Depth_1", "Normal_0",
..., named in Core/vtkDeepGICaptureNames.h), which vtkXMLImageDataWriter
saves; open the .vti in ParaView to look at them.
"""
import argparse

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import vtkdeepgi


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--output", default="layers.vti")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    renderer = vtkRenderer()
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(32)
    plane = vtkPlaneSource()  # 4 x 4, below the sphere, its normal up
    plane.SetOrigin(-2, -1, 2)
    plane.SetPoint1(2, -1, 2)
    plane.SetPoint2(-2, -1, -2)
    for source in (sphere, plane):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    renderer.GetActiveCamera().SetPosition(0, 3, 3)  # looking down at 45 degrees
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.4)

    # X11 when a display answers, otherwise EGL (no X server needed).
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    window.AddRenderer(renderer)

    # The G-buffer alone: it draws what VTK draws and keeps two layers.
    gbuffer = vtkdeepgi.vtkDeepGBufferPass()
    gbuffer.SetNumberOfLayers(2)
    renderer.SetPass(gbuffer)
    window.Render()

    layers = vtkImageData()
    if not gbuffer.CaptureLayers(layers, renderer):  # right after Render()
        raise SystemExit("CaptureLayers failed")
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(layers)
    writer.SetFileName(args.output)
    writer.Write()
    print("wrote %s: %d x %d pixels, %d layers, dz %.4g" % (
        args.output, width, height, gbuffer.GetEffectiveNumberOfLayers(),
        gbuffer.GetEffectiveMinimumSeparation()))
    # Its OpenGL objects, while the window's context exists (Python may
    # delete the window first at exit).
    gbuffer.ReleaseGraphicsResources(window)


if __name__ == "__main__":
    main()
