"""The scene of Documentation/images/paraview-gui.png, run by ParaView's GUI
(scripts/paraview-gui-screenshot.sh): the bunny on a floor in a Render View
(Deep GI) that replaces the GUI's first view. The plugin's path comes from
DEEPGI_PARAVIEW_PLUGIN and the mesh's from DEEPGI_MESH (the GUI passes no
script arguments).
"""
import os

from paraview.simple import (AssignViewToLayout, CreateView, Delete, GetActiveView, GetLayout,
                             LoadPlugin, Plane, PLYReader, Render, SetActiveSource,
                             SetActiveView, Show)

LoadPlugin(os.environ["DEEPGI_PARAVIEW_PLUGIN"], remote=False, ns=globals())
bunny = PLYReader(registrationName="bunny.ply", FileNames=[os.environ["DEEPGI_MESH"]])
bunny.UpdatePipeline()
xmin, xmax, ymin, ymax, zmin, zmax = bunny.GetDataInformation().GetBounds()
size = max(xmax - xmin, zmax - zmin)
floor = Plane(registrationName="floor", Origin=[xmin - size, ymin, zmin - size],
              Point1=[xmax + size, ymin, zmin - size], Point2=[xmin - size, ymin, zmax + size])

default_view = GetActiveView()
layout = GetLayout(default_view)
Delete(default_view)
view = CreateView("DeepGIRenderView")
AssignViewToLayout(view=view, layout=layout, hint=0)
SetActiveView(view)
Show(floor, view)
Show(bunny, view)
SetActiveSource(bunny)
view.CameraPosition = [xmax + 1.4 * size, ymax + 1.0 * size, zmax + 2.0 * size]
view.CameraFocalPoint = [0.5 * (xmin + xmax), ymin + 0.3 * (ymax - ymin), 0.5 * (zmin + zmax)]
view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)
