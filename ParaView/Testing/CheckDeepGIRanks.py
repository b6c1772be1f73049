"""The DeepGI view under `mpiexec -n N pvbatch`: every rank holds part of
the data, the view renders with the GI and IceT's compositing, and the run
ends (RunRanks.cmake bounds its time).

    mpiexec -n N pvbatch CheckDeepGIRanks.py PLUGIN OUTPUT_DIR N

What it checks: N ranks run; the sphere is split across them (its
ProcessId array spans 0..N-1); the composited still shows the scene with the
GI's effects on. Each rank computes the effects on its own part of the data
before IceT composites the colours, so the image is not yet the one-rank
image (Documentation/paraview.md, "Several ranks"). A failed check aborts
the run (MPI_Abort, a non-zero exit status).
"""
import os
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import (Connect, CreateView, Disconnect, LoadPlugin, Plane,
                             ProcessIdScalars, Render, SaveScreenshot, Show, Sphere)

PLUGIN, OUTPUT, RANKS = sys.argv[1], sys.argv[2], int(sys.argv[3])
SERVER = sys.argv[4] if len(sys.argv) > 4 else None
failures = []


def check(condition, what):
    print("%s: %s" % ("ok" if condition else "FAILED", what))
    if not condition:
        failures.append(what)


os.makedirs(OUTPUT, exist_ok=True)
if SERVER:
    host, port = SERVER.rsplit(":", 1)
    Connect(host, int(port))
    LoadPlugin(PLUGIN, remote=True, ns=globals())
LoadPlugin(PLUGIN, remote=False, ns=globals())
processes = servermanager.ActiveConnection.GetNumberOfDataPartitions()
check(processes == RANKS, "%d ranks run %s" % (processes, "pvserver" if SERVER else "pvbatch"))

sphere = ProcessIdScalars(Input=Sphere(Center=[0.0, 0.0, 5.0], Radius=5.0,
                                       ThetaResolution=48, PhiResolution=48))
plane = Plane(Origin=[-20.0, -20.0, 0.0], Point1=[20.0, -20.0, 0.0], Point2=[-20.0, 20.0, 0.0],
              XResolution=16, YResolution=16)
sphere.UpdatePipeline()
owners = sphere.GetPointDataInformation().GetArray("ProcessId").GetRange()
check(owners == (0.0, RANKS - 1.0), "the sphere is split over ranks %g..%g" % owners)

view = CreateView("DeepGIRenderView")
view.ViewSize = [200, 150]
view.OrientationAxesVisibility = 0
view.CameraPosition = [30.0, -40.0, 30.0]
view.CameraFocalPoint = [0.0, 0.0, 3.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.RemoteRenderThreshold = 0.0  # a client has the server ranks render
# The same still on every rank count: a fixed number of frames.
view.DeepGIConvergeMaximumFrames = 4
view.DeepGIConvergeTolerance = 0.0
Show(sphere, view).ColorArrayName = ["POINTS", ""]
Show(plane, view)
path = os.path.join(OUTPUT, ("client-server-%d.png" if SERVER else "ranks-%d.png") % RANKS)
SaveScreenshot(path, view, ImageResolution=[200, 150], TransparentBackground=0)
view.UpdatePropertyInformation()
effects = view.GetProperty("DeepGILastFrameEffects").GetElement(0)
if not SERVER:
    check("RADIOSITY" in effects, "the frame ran %s" % effects)
check(os.path.getsize(path) > 1000, "the composited still was written (%s)" % path)

# The cost: single frames (no converging), the median of 5, and the bytes
# rank 0 sent per frame to composite the layers.
view.DeepGIConvergeStills = 0
Render(view)
times = []
for _ in range(5):
    start = time.perf_counter()
    Render(view)
    times.append(1000.0 * (time.perf_counter() - start))
view.UpdatePropertyInformation()
sent = view.GetProperty("DeepGILayerExchangeBytes").GetElement(0)
if SERVER:
    print("cost: %d rank(s) of pvserver, %.0f ms per frame (median of 5), as the client sees it"
          % (RANKS, statistics.median(times)))
else:
    print("cost: %d rank(s), %.0f ms per frame (median of 5), %d bytes sent by rank 0 per frame "
          "(%.2f MB per layer)" % (RANKS, statistics.median(times), sent, sent / 2.0 / 1e6))
# A client's information properties are its own process's (it renders no
# layers): the exchange is checked where the ranks run the script.
if not SERVER:
    check(RANKS == 1 and sent == 0 or RANKS > 1 and sent > 0,
          "the layers were exchanged exactly when there are several ranks")
print("%d failure(s)" % len(failures))
if SERVER:
    Disconnect()  # the server ends with its client
    sys.exit(1 if failures else 0)
# pvbatch ends its MPI ranks itself after the script: sys.exit would leave
# them unfinalized, and an exception on rank 0 would leave the others
# waiting. A failure aborts every rank.
if failures:
    from mpi4py import MPI
    MPI.COMM_WORLD.Abort(1)
