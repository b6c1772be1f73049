"""What the Python tests of the rendering passes share: a window from the
project's factory (EGL or X, whichever works here), its pixels, actors with
VTK's default properties, the passes' captures as arrays, and their
comparison bit for bit."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor, vtkPolyDataMapper, vtkRenderer, vtkWindowToImageFilter)

import vtkdeepgi


def new_window(width, height):
    """A render window without multisampling, of width x height, holding one
    renderer; returns (window, renderer)."""
    factory = vtkdeepgi.vtkDeepGIRenderWindowFactory
    window = factory.NewRenderWindow(factory.BACKEND_AUTO)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    return window, renderer


def grab(window):
    """The window's back buffer as a numpy array (a copy), one row per pixel."""
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.Update()
    return vtk_to_numpy(image.GetOutput().GetPointData().GetScalars()).copy()


def add_actor(renderer, source):
    """An actor with VTK's default properties showing `source`'s output."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)


def add_sphere_on_floor(renderer):
    """A unit-diameter sphere resting on a 3 x 3 floor (y = -0.5), both with
    VTK's default properties."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    add_actor(renderer, sphere)
    floor = vtkPlaneSource()
    floor.SetOrigin(-1.5, -0.5, 1.5)
    floor.SetPoint1(1.5, -0.5, 1.5)
    floor.SetPoint2(-1.5, -0.5, -1.5)
    add_actor(renderer, floor)


def look_at(renderer, position, focal_point):
    """Points the renderer's camera from `position` at `focal_point` and fits
    the clipping range to its props."""
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal_point)
    renderer.ResetCameraClippingRange()


def capture_arrays(capture, renderer, prefix, out):
    """Every array of a pass's capture (e.g. CaptureIrradiance) into `out`,
    keyed prefix + array name; out[prefix] = None when it fails."""
    image = vtkImageData()
    if not capture(image, renderer):
        out[prefix] = None
        return
    data = image.GetPointData()
    for i in range(data.GetNumberOfArrays()):
        out[prefix + data.GetArrayName(i)] = vtk_to_numpy(data.GetArray(i)).copy()


def gi_preset(name):
    """A factory of vtkDeepGIPass set to the preset `name`."""
    def make():
        gi = vtkdeepgi.vtkDeepGIPass()
        gi.SetPreset(getattr(vtkdeepgi.vtkDeepGIPass, name))
        return gi
    return make


def compare_bitwise(name, tested, reference, what, failures):
    """Appends to `failures` each image or array of `tested` (a dict, as
    capture_arrays fills) that is missing or differs, bit for bit, from
    `reference`'s; `what` names the tested setting in the messages."""
    if set(tested) != set(reference):
        failures.append("%s: the captures differ in their arrays: %s"
                        % (name, sorted(set(tested) ^ set(reference))))
        return
    for key in sorted(reference):
        a, b = tested[key], reference[key]
        if a is None or b is None:
            failures.append("%s: %s could not be captured" % (name, key))
        elif a.shape != b.shape or not np.array_equal(a, b):
            differing = np.count_nonzero(a != b) if a.shape == b.shape else "all"
            failures.append("%s: %s differs %s (%s values)" % (name, key, what, differing))
