#!/usr/bin/env bash
# fuzz.sh: build the fuzz targets of Testing/Fuzz (libFuzzer, AddressSanitizer,
# UndefinedBehaviorSanitizer) and run them.
#
#   bash scripts/fuzz.sh [TARGET|all] [SECONDS]
#
# TARGET: obj, mtl (vtkDeepGIOBJReader, then vtkDeepGISceneLoader), nhdr,
# nrrd (vtkDeepGINrrdReader, then the loader), ply, stl, vtk (the loader) on
# a file of that format, or exr (vtkDeepGIEXRReader); default all, one after
# the other. SECONDS: how long each target runs (default 60).
#
# - clang and its libFuzzer runtime are installed with apt-get when missing
#   (as root, or through sudo), like scripts/setup.sh does; VTK and OpenEXR
#   are what setup.sh installs.
# - Builds into build-fuzz/ (override with DEEPGI_FUZZ_DIR), Ninja, clang.
# - Corpus: build-fuzz/corpus/TARGET (kept between runs), seeded from the
#   files of Testing/Data with the target's extension (up to 1 MB each).
# - Findings (crash-*, leak-*, timeout-*, oom-*) land in
#   build-fuzz/artifacts/TARGET/; the script exits 1 when a target finds one.
#   Reproduce one with: build-fuzz/fuzz-TARGET FILE
# - Limits per input: 10 s (-timeout), 2 GB of memory (-rss_limit_mb,
#   -malloc_limit_mb), inputs up to 1 MB (-max_len).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DEEPGI_FUZZ_DIR:-$repo/build-fuzz}"
target="${1:-all}"
seconds="${2:-60}"
targets=(obj mtl nhdr nrrd ply stl vtk exr)

log() { echo "fuzz.sh: $*" >&2; }

if [[ "$target" != all && ! " ${targets[*]} " =~ " $target " ]]; then
  log "unknown target '$target' (known: ${targets[*]} all)"
  exit 2
fi
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || ((seconds < 1)); then
  log "SECONDS must be a positive integer, got '$seconds'"
  exit 2
fi

apt_install() {
  local sudo=()
  if ((EUID != 0)); then
    if ! command -v sudo >/dev/null 2>&1; then
      log "missing: $*; install them (not root, no sudo)"
      exit 1
    fi
    sudo=(sudo)
  fi
  log "installing: $*"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q >&2
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "$@" >&2
}

# clang, then libFuzzer's runtime of that clang (libclang-rt-N-dev).
if ! command -v clang++ >/dev/null 2>&1; then
  apt_install clang
fi
major="$(clang++ -dumpversion | cut -d. -f1)"
if [[ ! -f "$(clang++ -print-resource-dir)/lib/linux/libclang_rt.fuzzer-$(uname -m).a" ]]; then
  apt_install "libclang-rt-${major}-dev"
fi
for tool in cmake ninja; do
  command -v "$tool" >/dev/null 2>&1 || apt_install cmake ninja-build
done

if [[ ! -f "$build/build.ninja" ]]; then
  log "configuring $build"
  CC=clang CXX=clang++ cmake -S "$repo/Testing/Fuzz" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo >&2
fi
ninja -C "$build" >&2

extensions() {
  case "$1" in
    obj) echo obj ;;
    mtl) echo mtl ;;
    nhdr) echo nhdr ;;
    nrrd) echo nrrd nhdr ;;
    ply) echo ply ;;
    stl) echo stl ;;
    vtk) echo vtk ;;
    exr) echo exr ;;
  esac
}

status=0
run_target() {
  local t="$1" corpus="$build/corpus/$1" artifacts="$build/artifacts/$1" ext f
  if [[ ! -x "$build/fuzz-$t" ]]; then
    log "fuzz-$t was not built (OpenEXR missing?); skipped"
    return
  fi
  mkdir -p "$corpus" "$artifacts"
  for ext in $(extensions "$t"); do
    while IFS= read -r -d '' f; do
      cp -n "$f" "$corpus/seed-$(basename "$f")" 2>/dev/null || true
    done < <(find "$repo/Testing/Data" -name "*.$ext" -size -1000k -print0)
  done
  log "fuzz-$t: $seconds s, corpus $corpus ($(ls "$corpus" | wc -l) files)"
  local start end
  start=$(date +%s)
  if ! (cd "$artifacts" && "$build/fuzz-$t" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=1048576 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$corpus"); then
    log "fuzz-$t found a problem: see $artifacts"
    status=1
  fi
  end=$(date +%s)
  log "fuzz-$t ran $((end - start)) s"
}

if [[ "$target" == all ]]; then
  for t in "${targets[@]}"; do
    run_target "$t"
  done
else
  run_target "$target"
fi
exit "$status"
