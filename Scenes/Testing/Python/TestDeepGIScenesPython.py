"""The scenes from VTK's Python: the readers in a pipeline, the demo scene
as a source, and the former class names (deprecated subclasses) still
constructed and behaving as the new ones."""
import os
import sys

import vtkdeepgi
from vtkmodules.vtkFiltersCore import vtkTriangleFilter

DATA = sys.argv[1]
failures = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def test_readers():
    obj = vtkdeepgi.vtkDeepGIOBJReader()
    obj.SetFileName(os.path.join(DATA, "scenes/cornell-original/CornellBox-Original.obj"))
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(obj.GetOutputPort())
    triangles.Update()
    names = obj.GetOutput().GetFieldData().GetAbstractArray("MaterialName")
    check(obj.GetOutput().GetNumberOfCells() == 18 and names.GetNumberOfValues() == 8,
          "OBJ reader: the Cornell box's 18 faces and 8 materials")
    check(triangles.GetOutput().GetNumberOfCells() >= 18, "OBJ reader feeds vtkTriangleFilter")
    nrrd = vtkdeepgi.vtkDeepGINrrdReader()
    nrrd.SetFileName(os.path.join(DATA, "volumes/headsq/quarter.nhdr"))
    nrrd.Update()
    check(nrrd.GetOutput().GetDimensions() == (64, 64, 93), "NRRD reader: headsq is 64 x 64 x 93")


def test_demo_scene_source():
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(scene.GetOutputPort())
    triangles.Update()
    check(triangles.GetOutput().GetNumberOfCells() == scene.GetNumberOfTriangles(),
          "the demo scene is a source of its %d triangles" % scene.GetNumberOfTriangles())


def test_deprecated_names():
    scene = vtkdeepgi.vtkDeepGBufferDemoScene()
    check(scene.IsA("vtkDeepGIDemoScene") and
          scene.GetNumberOfTriangles() == vtkdeepgi.vtkDeepGIDemoScene().GetNumberOfTriangles(),
          "vtkDeepGBufferDemoScene() is a vtkDeepGIDemoScene building the same room")
    loader = vtkdeepgi.vtkDeepGBufferSceneLoader()
    path = os.path.join(DATA, "scenes/cornell-original/CornellBox-Original.obj")
    check(loader.IsA("vtkDeepGISceneLoader") and loader.Load(path) and
          loader.GetNumberOfParts() == 8,
          "vtkDeepGBufferSceneLoader() is a vtkDeepGISceneLoader loading the Cornell box")


test_readers()
test_demo_scene_source()
test_deprecated_names()
print("%d check(s) failed" % len(failures))
sys.exit(1 if failures else 0)
