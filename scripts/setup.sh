#!/usr/bin/env bash
# setup.sh: install what the project needs (Debian bookworm, apt) and build it.
#
# - Packages are checked with one dpkg-query call; apt-get update and
#   apt-get install --no-install-recommends run only when something is
#   missing (as root, or through sudo).
# - The build directory is build/ in the repository (override with
#   DEEPGI_BUILD_DIR). It is configured once (Ninja, Release, plus the options
#   in DEEPGI_CMAKE_ARGS); later runs just call ninja, which re-runs CMake
#   itself when a CMakeLists.txt changed.
#
# - With --paraview (scripts/test.sh passes it), also what the ParaView
#   plugin and its tests need: Debian's ParaView 5.11 (paraview-dev, without
#   its recommended packages, which would remove libvtk9-dev) and MPI's
#   mpiexec; python3-paraview, which conflicts with python3-vtk9 (both ship
#   `vtkmodules`), is not installed but unpacked into
#   <build>/python3-paraview, the Python that pvbatch is given there
#   (PYTHONPATH=<build>/python3-paraview/usr/lib/python3/dist-packages).
#
# Everything this script prints goes to stderr, so that the stdout of
# scripts/run.sh is the main job's alone.
set -euo pipefail
exec 1>&2

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_BUILD_DIR:-$repo/build}"
with_paraview=0
if [[ "${1:-}" == "--paraview" ]]; then
  with_paraview=1
elif [[ $# -gt 0 ]]; then
  echo "usage: $0 [--paraview]"
  exit 2
fi

# libvtk9-dev pulls in what Debian's VTK CMake package needs to configure
# (MPI, GLEW, X11, Qt, Java, ... are Depends of libvtk9-dev), so they are not
# listed here.
packages=(
  build-essential cmake ninja-build   # toolchain
  clang-format                        # the style check (test deepgi-format)
  libvtk9-dev vtk9 python3-vtk9       # VTK 9.1: headers/CMake package, wrapping tools, Python
  python3-numpy                       # numeric checks in the Python tests
  libglm-dev libopenexr-dev libembree-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri  # EGL backend: headers, Mesa's EGL, llvmpipe
  xvfb xauth                          # X11 backend without a display (scripts/with-display.sh)
  valgrind                            # instructions per frame (scripts/count-instructions.sh)
)
if ((with_paraview)); then
  packages+=(paraview-dev openmpi-bin)  # the ParaView plugin (ParaView/), pvbatch under mpiexec
fi

log() { echo "setup.sh: $*"; }

missing_packages() {
  # Prints the packages that are not installed, one per line.
  local installed
  installed="$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${packages[@]}" 2>/dev/null |
    awk '$2 == "installed" { print $1 }')" || true
  local p
  for p in "${packages[@]}"; do
    if ! grep -qx -- "$p" <<<"$installed"; then
      echo "$p"
    fi
  done
}

if command -v dpkg-query >/dev/null 2>&1 && command -v apt-get >/dev/null 2>&1; then
  mapfile -t missing < <(missing_packages)
  if ((${#missing[@]} > 0)); then
    log "installing: ${missing[*]}"
    sudo=()
    if ((EUID != 0)); then
      if command -v sudo >/dev/null 2>&1; then
        sudo=(sudo)
      else
        log "these packages are missing and this is not root (no sudo either): ${missing[*]}"
        exit 1
      fi
    fi
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
      apt-get install -y -q --no-install-recommends "${missing[@]}"
    mapfile -t still_missing < <(missing_packages)
    if ((${#still_missing[@]} > 0)); then
      log "still missing after apt-get install: ${still_missing[*]}"
      exit 1
    fi
  fi
else
  log "no dpkg/apt here: make sure the equivalents of these are installed: ${packages[*]}"
fi

# unpack_paraview_python DIR: python3-paraview's files under DIR, once.
unpack_paraview_python() {
  local dir="$1"
  if [[ -f "$dir/usr/lib/python3/dist-packages/paraview/simple.py" ]]; then
    return
  fi
  log "unpacking python3-paraview into $dir"
  local download
  download="$(mktemp -d)"
  chmod 755 "$download" # apt-get download runs as the _apt user when it can
  (cd "$download" && apt-get download -q python3-paraview)
  rm -rf "$dir.partial"
  dpkg-deb -x "$download"/python3-paraview_*.deb "$dir.partial"
  rm -rf "$download" "$dir"
  mv "$dir.partial" "$dir"
}

if ((with_paraview)); then
  mkdir -p "$build"
  unpack_paraview_python "$build/python3-paraview"
fi

# Configure once; ninja re-runs CMake when needed.
if [[ ! -f "$build/build.ninja" ]]; then
  log "configuring $build"
  # DEEPGI_CMAKE_ARGS: extra configure options, e.g.
  # "-DDEEPGI_ENABLE_REFERENCE=OFF -DDEEPGI_ENABLE_OPENEXR=OFF".
  # shellcheck disable=SC2086
  cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release ${DEEPGI_CMAKE_ARGS:-}
fi
ninja -C "$build"
