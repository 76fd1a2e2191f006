#!/usr/bin/env bash
# Installs missing dependencies, then configures and builds scantrace (Release) in build/.
#   scripts/build.sh           everything: libraries, command, tests, examples, benchmarks
#   scripts/build.sh --demo    only the `scantrace` command with the subcommands the demo runs
#                              (not stress, bench, why, diff) and its libraries, with only the
#                              packages they need (scripts/demo.sh: the quick first run)
#   scripts/build.sh --web     only the WebAssembly build (docs/web.md) into build/web/: the ES
#                              module, its .wasm, the JavaScript API, the explorer page, and the
#                              trace page's own module and template
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

demo=0
if [ "${1:-}" = "--demo" ]; then
  demo=1
elif [ "${1:-}" = "--web" ]; then
  demo=web
elif [ $# -gt 0 ]; then
  echo "usage: scripts/build.sh [--demo | --web]" >&2
  exit 2
fi

if [ "$demo" = 1 ]; then bash scripts/deps.sh --demo; else bash scripts/deps.sh; fi
# ccache, when present, makes a rebuild in another clone of the same sources cheap (CI's fresh
# clone, worktrees): paths below the clone are hashed relative to it.
if command -v ccache >/dev/null 2>&1 && [ -z "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
fi
if [ "$demo" = web ]; then
  # The compiler launcher comes from the environment (above). Debian's emscripten runs its tools
  # with node and Debian's node-acorn, which NodeSource's node does not look for (web/native.cmake).
  export NODE_PATH=/usr/share/nodejs
  # The explorer's build, then the trace page's (-Oz), which writes into build/web/ too
  # (web/CMakeLists.txt says why there are two).
  cmake --preset web
  cmake --build build/web -j"$(nproc)"
  cmake --preset web-player
  cmake --build --preset web-player -j"$(nproc)"
  exit 0
fi
# The options are always given: build/ is shared by both forms, and a demo build must not leave
# the tests switched off in the cache for the next full build (nor the reverse).
if [ "$demo" = 1 ]; then
  # Only the `scantrace` command, which runs `render` and `demo` without OpenCV (cli/main_render.cpp);
  # none of OpenCV, matio, Catch2, Google Benchmark or pybind11 is installed for it. The full build
  # adds scantrace-tools and reuses every object of this one (same flags, same compiler launcher).
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSCANTRACE_BUILD_TESTS=OFF \
    -DSCANTRACE_BUILD_BENCH=OFF -DSCANTRACE_BUILD_PYTHON=OFF -DSCANTRACE_TOOLS=OFF \
    -DSCANTRACE_BUILD_WEB=OFF
  cmake --build build -j"$(nproc)" --target scantrace
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSCANTRACE_BUILD_TESTS=ON \
    -DSCANTRACE_BUILD_BENCH=ON -DSCANTRACE_BUILD_PYTHON=ON -DSCANTRACE_TOOLS=ON \
    -DSCANTRACE_BUILD_WEB=ON
  cmake --build build -j"$(nproc)"
fi
