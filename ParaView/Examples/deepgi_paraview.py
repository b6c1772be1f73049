"""Deep GI in ParaView from Python: the Stanford bunny on a floor in a
"Render View (Deep GI)", saved with the GI off and on.

    PYTHONPATH=build/python3-paraview/usr/lib/python3/dist-packages \
      pvbatch ParaView/Examples/deepgi_paraview.py PLUGIN MESH OUTPUT_DIR

PLUGIN: the plugin library (build/paraview-plugin/install/lib/
paraview-5.11/plugins/DeepGI/DeepGI.so after `bash scripts/test.sh`); MESH: a
mesh ParaView reads (Testing/Data/meshes/bunny.ply). Writes plain.png and
deep-gi.png into OUTPUT_DIR.
"""
import os
import sys

from paraview.simple import (CreateView, LoadPlugin, OpenDataFile, Plane, SaveScreenshot, Show)

plugin, mesh, output = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())

bunny = OpenDataFile(mesh)
bunny.UpdatePipeline()
xmin, xmax, ymin, ymax, zmin, zmax = bunny.GetDataInformation().GetBounds()
size = max(xmax - xmin, zmax - zmin)
# The floor under the bunny (its y axis points up).
floor = Plane(Origin=[xmin - size, ymin, zmin - size], Point1=[xmax + size, ymin, zmin - size],
              Point2=[xmin - size, ymin, zmax + size])

view = CreateView("DeepGIRenderView")   # "Render View (Deep GI)" in the GUI
view.ViewSize = [640, 480]
view.OrientationAxesVisibility = 0
Show(bunny, view)
Show(floor, view)
view.CameraPosition = [xmax + 1.4 * size, ymax + 1.0 * size, zmax + 2.0 * size]
view.CameraFocalPoint = [0.5 * (xmin + xmax), ymin + 0.3 * (ymax - ymin), 0.5 * (zmin + zmax)]
view.CameraViewUp = [0.0, 1.0, 0.0]

view.UseDeepGI = 0
SaveScreenshot(os.path.join(output, "plain.png"), view, ImageResolution=[640, 480])
view.UseDeepGI = 1                      # the default of this view
view.DeepGIPreset = "Balanced"          # or "High Performance", "High Quality"
SaveScreenshot(os.path.join(output, "deep-gi.png"), view, ImageResolution=[640, 480])
view.UpdatePropertyInformation()
print("effects:", view.GetProperty("DeepGILastFrameEffects").GetElement(0))
