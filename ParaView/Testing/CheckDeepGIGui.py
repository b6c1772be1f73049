"""The DeepGI plugin in ParaView's GUI: loaded by the client, its view
placed in the main window's layout (a Qt widget), rendered with the GI on
and off. Run by the GUI, which has no script arguments:

    DEEPGI_PARAVIEW_PLUGIN=PLUGIN paraview --dr --script=CheckDeepGIGui.py --exit

The GUI's exit status does not report a script's errors, so the last line
printed, "DeepGI GUI: all checks passed", is the verdict (the test passes on
it).
"""
import os

from paraview.simple import (AssignViewToLayout, CreateView, Delete, GetActiveView, GetLayout,
                             LoadPlugin, Plane, Render, Show, Sphere)

LoadPlugin(os.environ["DEEPGI_PARAVIEW_PLUGIN"], remote=False, ns=globals())
failures = []


def check(condition, what):
    print("%s: %s" % ("ok" if condition else "FAILED", what))
    if not condition:
        failures.append(what)


def effects(view):
    view.UpdatePropertyInformation()
    return view.GetProperty("DeepGILastFrameEffects").GetElement(0)


# The GUI's own render view makes way for a Deep GI view in the same layout.
default_view = GetActiveView()
layout = GetLayout(default_view)
Delete(default_view)
view = CreateView("DeepGIRenderView")
AssignViewToLayout(view=view, layout=layout, hint=0)
check(GetLayout(view) is not None, "the view sits in the main window's layout")

Show(Sphere(Center=[0.0, 0.0, 5.0], Radius=5.0, ThetaResolution=48, PhiResolution=48), view)
Show(Plane(Origin=[-20.0, -20.0, 0.0], Point1=[20.0, -20.0, 0.0], Point2=[-20.0, 20.0, 0.0]), view)
view.CameraPosition = [30.0, -40.0, 30.0]
view.CameraFocalPoint = [0.0, 0.0, 3.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
Render(view)
check("RADIOSITY" in effects(view), "rendered in the GUI with %s" % effects(view))
view.UseDeepGI = 0
Render(view)
check(effects(view) == "NONE", "Use Deep GI off: %s" % effects(view))
view.UseDeepGI = 1
Render(view)
check("RADIOSITY" in effects(view), "Use Deep GI on again: %s" % effects(view))

print("DeepGI GUI: %s" % ("all checks passed" if not failures else "%d failure(s)" % len(failures)))
