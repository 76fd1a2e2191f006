#!/usr/bin/env bash
# Installs the Debian packages scantrace needs to build and test, but only those that are missing:
# when everything is installed this neither calls apt-get nor asks for sudo.
#   scripts/deps.sh           everything: the test command (scripts/test.sh) and CI (.ci/run)
#   scripts/deps.sh --demo    only what the scantrace command and its libraries need to build
#                             (scripts/demo.sh): the quick first run
set -euo pipefail

# The demo's packages: the compiler, CMake, and the libraries the `scantrace` command links, which
# runs the demo without OpenCV (cli/demo_explain.hpp): about 100 Debian packages, where OpenCV's
# development packages alone are 316 more (docs/performance.md, "Building").
# (pkg-config finds libdeflate-dev, the compressor of the PNG writer of `scantrace render`,
# io/png_writer.hpp, which has no CMake package.) (libhwy-dev: Google Highway, the core's SIMD
# Gouraud spans, src/fast/shade_bytes.hpp.) (libsimdjson-dev: the scene file's fast path,
# io/scene_json_fast.hpp.)
# (ccache: scripts/build.sh compiles through it when it is installed; the demo installs it too, so
# that the demo's build and the full one use the same compiler launcher and the full build reuses
# the demo's objects instead of compiling everything again.)
demo_packages=(cmake g++ make pkg-config libspdlog-dev nlohmann-json3-dev libsimdjson-dev libdeflate-dev
               libcli11-dev libtinyobjloader-dev libhwy-dev ccache)

# THE FULL LIST (the test command, CI): every package, the demo's included; append new ones here.
# ffmpeg provides ffprobe, with which the tests check the codec of the videos `replay` writes;
# clang-14 and libfuzzer-14-dev build the fuzz targets (scripts/fuzz.sh, run by .ci/run).
packages=(cmake g++ make libspdlog-dev nlohmann-json3-dev libopencv-dev catch2 libcli11-dev
          libbenchmark-dev python3-jsonschema ffmpeg libtinyobjloader-dev clang-14 libfuzzer-14-dev
          ccache
          pybind11-dev python3-dev python3-numpy python3-pytest)
# (libmatio-dev: the MATLAB .mat reader, found by pkg-config. libxcb1-dev: `scantrace step` makes
# the X connection itself before HighGUI's Qt would abort on a refused one, cli/x_display.hpp.)
packages+=(pkg-config libmatio-dev libxcb1-dev libhwy-dev libdeflate-dev libsimdjson-dev)
# libjpeg's header read (grade/jpeg_header.hpp) and zlib for the .mat layout check
# (io/mat5_layout.hpp): both come with libopencv-dev and libmatio-dev, named here as used.
packages+=(libjpeg-dev zlib1g-dev)
# libpng: `scantrace-diff` decodes a submitted PNG with it, loading no OpenCV (grade/png_decoder.hpp).
packages+=(libpng-dev)
# Stepping through replays: Qt's headers for the window's focus fix (cli/highgui_focus.hpp), and
# for the tests a virtual display, xdotool and headless chromium.
packages+=(qtbase5-dev xvfb xdotool chromium)
# The display list's backends (viz/): xmllint validates the SVG frames in the tests; the Hershey
# glyphs (viz/hershey/glyphs.inc) are generated from hershey-fonts-data by viz/hershey/generate.py.
packages+=(libxml2-utils hershey-fonts-data)
# The Python package's build (pip install ., python3 -m build) and its benchmark's alternatives
# (python/bench/bench_alternatives.py: OpenCV's, scikit-image's and PIL's polygon fills).
packages+=(python3-setuptools python3-wheel python3-build python3-venv python3-opencv python3-pil
           python3-skimage)
# The Python package's tests: property tests (hypothesis), examples/python/course.ipynb executed
# (nbclient, ipykernel) and its static HTML export (nbconvert), opened in chromium.
packages+=(python3-hypothesis python3-nbclient python3-ipykernel python3-nbconvert)
# The WebAssembly build and its tests (web/, docs/web.md): emscripten compiles, Node runs the
# module's tests (node-acorn: emscripten's JavaScript optimizer); libdeflate-gzip compresses the
# pages' .wasm (level 12: 5 % smaller than zlib's best, which the trace page's 400 KB goal needs).
packages+=(emscripten nodejs node-acorn libdeflate-tools)
# The grader (python -m scantrace.grade) runs each student's code in a bubblewrap sandbox.
packages+=(bubblewrap)

if [ "${1:-}" = "--demo" ]; then
  packages=("${demo_packages[@]}")
elif [ $# -gt 0 ]; then
  echo "usage: scripts/deps.sh [--demo]" >&2
  exit 2
fi

if ! command -v dpkg >/dev/null 2>&1; then
  echo "deps.sh: dpkg not found (not Debian/Ubuntu?); install these yourself: ${packages[*]}" >&2
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  # dpkg -s also succeeds for removed packages whose configuration is kept: check the status.
  if ! dpkg -s "$p" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "deps.sh: installing ${missing[*]}" >&2
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo >/dev/null 2>&1; then
    echo "deps.sh: not root and sudo is not available; install as root: ${missing[*]}" >&2
    exit 1
  fi
  sudo=(sudo)
fi
"${sudo[@]}" apt-get update
# --force-unsafe-io: dpkg does not fsync every file it unpacks, as Debian's own Docker images set
# it. Unpacking is most of the wait (the demo's 90 MB download took 4 s, unpacking 75 s on a fresh
# Debian 12, 2 cores): this cut it to 52-60 s from 92-94 s, measured side by side. The cost is
# only that a power cut during the install could leave a package to reinstall.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends -o Dpkg::Options::=--force-unsafe-io "${missing[@]}"
