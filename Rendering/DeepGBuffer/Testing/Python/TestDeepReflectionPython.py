"""Deep mirror reflections from Debian's VTK Python.

Imports the `vtkdeepgi` package, puts vtkDeepReflectionPass on a renderer
with the demo room whose floor is made a 50 % Phong mirror (Specular 0.5,
white SpecularColor), renders through vtkDeepGIRenderWindowFactory,
captures the reflections and the G-buffer layers and checks with numpy:
- every captured value finite; rays are traced exactly on the floor pixels
  (reflectivity 0.5 there, 128/255 in RGBA8, 0 elsewhere);
- hit layers are -1, 0 or 1, and most floor rays hit the room (the walls,
  columns and furniture: at least half);
- the image equals RADIANCE + REFLECTIVITY x reflected radiance within one
  8-bit level where traced, and the plain G-buffer image (vtkDeepGBufferPass
  alone, same scene) exactly elsewhere;
- with the floor's Specular back to 0 nothing is traced.
Exits non-zero on failure.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

import vtkdeepgi
from deepgi_testing import new_window

WIDTH, HEIGHT = 256, 192


def array(image, name):
    return vtk_to_numpy(image.GetPointData().GetArray(name)).astype(float)


def render(make_pass, mirror):
    window, renderer = new_window(WIDTH, HEIGHT)
    scene = vtkdeepgi.vtkDeepGIDemoScene()
    scene.SetTargetNumberOfTriangles(10000)
    scene.Populate(renderer)
    scene.SetCameraToDefaultView(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    actors = renderer.GetActors()
    actors.InitTraversal()
    floor = actors.GetNextActor()  # one actor per material, the floor first
    if mirror:
        floor.GetProperty().SetSpecular(0.5)
        floor.GetProperty().SetSpecularColor(1.0, 1.0, 1.0)
    render_pass = make_pass()
    renderer.SetPass(render_pass)
    for _ in range(2):
        window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)
    result = {"image": image}
    if isinstance(render_pass, vtkdeepgi.vtkDeepReflectionPass):
        result["traced"] = render_pass.GetLastFrameTraced()
        if mirror:
            result["reflections"] = vtkImageData()
            result["layers"] = vtkImageData()
            if not render_pass.CaptureReflections(result["reflections"], renderer):
                raise RuntimeError("CaptureReflections failed")
            render_pass.GetGBufferPass().CaptureLayers(result["layers"], renderer)
            result["floor"] = array(result["layers"], "Depth_0") > 0
        floor.GetProperty().SetSpecular(0.0)
        window.Render()
        result["traced_after"] = render_pass.GetLastFrameTraced()
    render_pass.ReleaseGraphicsResources(window)
    return result


def main():
    failures = []
    mirror = render(vtkdeepgi.vtkDeepReflectionPass, True)
    plain = render(vtkdeepgi.vtkDeepGBufferPass, True)

    refl = mirror["reflections"]
    layers = mirror["layers"]
    valid = array(refl, "Valid") > 0
    hit = array(refl, "HitLayer")
    radiance = array(refl, "ReflectedRadiance")
    reflectivity = array(refl, "Reflectivity")
    finite = all(np.isfinite(array(refl, name)).all() for name in
                 ("ReflectedRadiance", "HitLayer", "HitDistance", "Reflectivity"))
    if not (mirror["traced"] and finite):
        failures.append("no rays traced or non-finite values")
    on_floor = np.abs(reflectivity[:, 0] - 128.0 / 255.0) < 1e-6
    print("%d traced pixels, %d with reflectivity 128/255, %d hit layer 0, %d layer 1, "
          "%d environment" % (valid.sum(), on_floor.sum(), (hit[valid] == 0).sum(),
                              (hit[valid] == 1).sum(), (hit[valid] == -1).sum()))
    if valid.sum() < WIDTH * HEIGHT // 10 or (valid != on_floor).any():
        failures.append("rays are not traced exactly on the floor (reflectivity 0.5)")
    if not np.isin(hit, (-1.0, 0.0, 1.0)).all() or (hit[~valid] != -1).any():
        failures.append("hit layers outside {-1, 0, 1}")
    if (hit[valid] >= 0).sum() < 0.5 * valid.sum():
        failures.append("fewer than half of the floor's rays hit the room")

    rad0 = array(layers, "Radiance_0")[:, :3]
    expected = np.minimum(rad0 + reflectivity * radiance, 1.0) * 255.0
    image = mirror["image"]
    composite_error = np.abs(image[valid] - expected[valid]).max()
    untraced_difference = np.abs(image[~valid] - plain["image"][~valid]).max()
    print("traced pixels: max |image - (RADIANCE + REFLECTIVITY x L_r)| %.2f levels; "
          "other pixels: max difference to the plain G-buffer image %.0f" % (
              composite_error, untraced_difference))
    if composite_error > 1.01:
        failures.append("the image is not RADIANCE + REFLECTIVITY x L_r")
    if untraced_difference != 0:
        failures.append("pixels without rays differ from the plain G-buffer image")
    if mirror["traced_after"]:
        failures.append("rays traced although nothing reflects")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
