"""Test of the --camera option of the Python benchmarks
(deepgi_benchmark_frame.py, deepgi_benchmark_image.py): a malformed or
misplaced --camera stops either one before anything renders, with exit
status 2 and the reason; a good one is the start camera of its scene (the
frame benchmark on the dragon at 64x48, one frame of vtkDeepGIPass
BALANCED; the second file given with --scene, which is --mesh's other
name): the scene is named by the camera's position, and the heading
shows exactly the camera given, where the same file without --camera has
the loader's. Exits non-zero on failure.

    CheckDeepGIBenchmarkCamera.py DATA_DIR OUTPUT_DIR
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CAMERA = "0,0.12,0.3,0,0.12,0,0,1,0,25"


def run(script, arguments):
    result = subprocess.run([sys.executable, os.path.join(HERE, script)] + arguments,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return result.returncode, result.stdout, result.stderr


def check_rejections(data, out):
    mesh = os.path.join(data, "meshes", "dragon.ply")
    volume = os.path.join(data, "volumes", "headsq", "quarter.nhdr")
    cases = [
        (["--camera", CAMERA], "--camera needs a --mesh"),
        (["--mesh", mesh, "--camera", "0,0,1,0,0,0,0,0,1"], "parallel to the direction of view"),
        (["--mesh", mesh, "--camera", "0,0,x,0,0,0,0,1,0"], "value 3 ('x') is not a finite number"),
        (["--mesh", mesh, "--camera", "0,0,1,0,0,0"], "9 or 10 numbers"),
        (["--mesh", mesh, "--camera", CAMERA, "--camera", CAMERA], "a second --camera"),
        (["--volume", volume, "--camera", CAMERA, "--iso", "500"], "--camera needs a --mesh"),
    ]
    failures = []
    for script in ("deepgi_benchmark_frame.py", "deepgi_benchmark_image.py"):
        for arguments, reason in cases:
            code, _, err = run(script, ["--data", data, "--output", out] + arguments)
            if code != 2 or reason not in err:
                failures.append("%s %s: exit %d, %r" % (script, " ".join(arguments), code, err))
    return failures


def check_camera(data, out):
    mesh = os.path.join(data, "meshes", "dragon.ply")
    code, text, err = run("deepgi_benchmark_frame.py", [
        "--data", data, "--scenes", "", "--mesh", mesh, "--scene", mesh, "--camera", CAMERA,
        "--sizes", "64x48", "--frames", "1", "--rounds", "1", "--methods", "BALANCED",
        "--output", out])
    if code != 0:
        return ["deepgi_benchmark_frame.py with --camera: exit %d\n%s" % (code, err)]
    failures = []
    headings = [line for line in text.splitlines() if line.startswith("### dragon.ply")]
    if [h.split(",")[0] for h in headings] != ["### dragon.ply", "### dragon.ply from 0"]:
        failures.append("the scenes are %s" % headings)
    cameras = [line for line in text.splitlines() if line.startswith("Start camera")]
    if len(cameras) != 2 or cameras[1] != "Start camera (`--camera`): `%s`" % CAMERA:
        failures.append("the start cameras are %s" % cameras)
    elif cameras[0] == cameras[1]:
        failures.append("the loader's camera is the one given")
    return failures


def main(argv):
    data, out = argv[0], argv[1]
    failures = check_rejections(data, out) + check_camera(data, out)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
