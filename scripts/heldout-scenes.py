"""Writes the benchmarks' held-out scenes into a folder (argument 1).

Scenes that no estimator or default of this project was chosen on, for the
accuracy benchmarks (Documentation/benchmark-ao.md, lighting-model.md):

- wuson-on-floor.vtp: the "Wuson" figure of Debian's assimp-testmodels
  package (/usr/share/assimp/models/PLY/Wuson.ply, BSD-3-Clause, the assimp
  project's test model) standing on a floor: an object on a floor.
- stairs-room.vtp: a room (floor, three walls, a ceiling strip) with a
  staircase of ten steps along one wall and a column: an interior.
- wavelet.nhdr + wavelet.raw: VTK's analytic "wavelet" field
  (vtkRTAnalyticSource, 64^3 floats), an iso-surface scene read with
  --volume wavelet.nhdr --iso 160.

Run with VTK's Python: /usr/bin/python3 scripts/heldout-scenes.py OUTDIR
(scripts/heldout-scenes.sh installs assimp-testmodels first; the
benchmark scripts' --heldout runs it).
"""

import os
import sys

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkPolyDataNormals, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkCylinderSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

WUSON = "/usr/share/assimp/models/PLY/Wuson.ply"


def box(x0, x1, y0, y1, z0, z1):
    cube = vtkCubeSource()
    cube.SetBounds(x0, x1, y0, y1, z0, z1)
    cube.Update()
    return cube.GetOutput()


def write(parts, path):
    append = vtkAppendPolyData()
    for part in parts:
        triangles = vtkTriangleFilter()
        triangles.SetInputData(part)
        triangles.Update()
        clean = vtkPolyData()
        clean.SetPoints(triangles.GetOutput().GetPoints())
        clean.SetPolys(triangles.GetOutput().GetPolys())
        append.AddInputData(clean)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(append.GetOutputPort())
    normals.SplittingOn()
    normals.SetFeatureAngle(45.0)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(normals.GetOutputPort())
    writer.SetFileName(path)
    if not writer.Write():
        sys.exit("heldout-scenes.py: cannot write " + path)


def wuson_on_floor(path):
    if not os.path.isfile(WUSON):
        sys.exit("heldout-scenes.py: %s is missing (apt-get install assimp-testmodels)" % WUSON)
    reader = vtkPLYReader()
    reader.SetFileName(WUSON)
    reader.Update()
    figure = reader.GetOutput()
    x0, x1, y0, y1, z0, z1 = figure.GetBounds()
    # The figure stands along +y; the floor touches its lowest point. The
    # scene is tilted by 30 degrees about x so that the loader's default
    # front view sees the floor from above.
    size = 0.6 * (y1 - y0)
    cx, cz = 0.5 * (x0 + x1), 0.5 * (z0 + z1)
    floor = box(cx - size, cx + size, y0 - 0.02 * size, y0, cz - size, cz + size)
    tilt = vtkTransform()
    tilt.RotateX(30.0)
    tilted = []
    for part in (figure, floor):
        move = vtkTransformPolyDataFilter()
        move.SetInputData(part)
        move.SetTransform(tilt)
        move.Update()
        tilted.append(move.GetOutput())
    write(tilted, path)


def stairs_room(path):
    parts = [
        box(0, 10, -0.2, 0, 0, 8),  # floor
        box(0, 10, 0, 5, -0.2, 0),  # back wall
        box(-0.2, 0, 0, 5, 0, 8),  # left wall
        box(10, 10.2, 0, 5, 0, 8),  # right wall
        box(0, 10, 5, 5.2, 0, 3),  # ceiling strip over the stairs
    ]
    for step in range(10):  # along the back wall, rising to the right
        parts.append(box(1 + 0.6 * step, 1.6 + 0.6 * step, 0, 0.4 * (step + 1), 0, 1.5))
    column = vtkCylinderSource()
    column.SetCenter(6.5, 2.25, 5)
    column.SetRadius(0.4)
    column.SetHeight(4.5)
    column.SetResolution(48)
    column.Update()
    parts.append(column.GetOutput())
    write(parts, path)


def wavelet(folder):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(0, 63, 0, 63, 0, 63)
    source.Update()
    values = source.GetOutput().GetPointData().GetScalars()
    from array import array

    data = array("f", (values.GetValue(i) for i in range(values.GetNumberOfTuples())))
    if sys.byteorder != "little":
        data.byteswap()
    with open(os.path.join(folder, "wavelet.raw"), "wb") as raw:
        data.tofile(raw)
    with open(os.path.join(folder, "wavelet.nhdr"), "w") as header:
        header.write(
            "NRRD0004\ntype: float\ndimension: 3\nsizes: 64 64 64\n"
            "spacings: 1 1 1\nendian: little\nencoding: raw\ndata file: wavelet.raw\n"
        )


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: heldout-scenes.py OUTDIR")
    folder = sys.argv[1]
    os.makedirs(folder, exist_ok=True)
    wuson_on_floor(os.path.join(folder, "wuson-on-floor.vtp"))
    stairs_room(os.path.join(folder, "stairs-room.vtp"))
    wavelet(folder)


if __name__ == "__main__":
    main()
