"""What the Python tests of the rendering passes share: a window from the
project's factory (EGL or X, whichever works here) and its pixels."""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter

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
