#!/usr/bin/env bash
# The sha256 of every PNG frame a scantrace binary draws for four replays that together use every
# kind of frame, so that a change to the drawing can be shown to leave them byte for byte:
#   triangle  explain of the course's example triangle (47 steps: cards, edge table, scanlines, insets)
#   painter   explain of the built-in demo scene (painter's algorithm, batches)
#   zbuffer   explain of an OBJ model with interpenetrating faces (z-buffer, rejected pixels)
#   why       why --explain of a pixel of the course scene (when /work/shared/data has it)
# Usage: scripts/frame_hashes.sh [BINARY] [WORKDIR] > hashes.txt   (one "case/frame  sha256" a line)
# Compare two binaries: diff <(scripts/frame_hashes.sh old) <(scripts/frame_hashes.sh new).
set -euo pipefail
bin=$(realpath "${1:-build/cli/scantrace}")
work=$(realpath -m "${2:-$(mktemp -d)}")
here=$(cd "$(dirname "$0")/.." && pwd)
course=${COURSE_SCENE:-/work/shared/data/hw1_2024.json}
mkdir -p "$work"
# Title cards name their input: the inputs are named relative to the work directory, so that any
# two work directories draw the same frames.
cd "$work"
cp "$here/examples/models/interpenetrating.obj" model.obj
log=$work/log.txt
: >"$log"
# The demo scene is generated content; every binary writes the same file (it is hashed too).
# `demo` also writes a video and a page: done once per work directory.
[[ -f demo/demo_scene.json ]] || "$bin" demo -o demo >>"$log" 2>&1
run() {  # case, then the command's arguments; the frames go to $work/$case/
  local case=$1
  shift
  rm -rf "${work:?}/$case"
  "$bin" "$@" -o "$case/" >>"$log" 2>&1 || { cat "$log" >&2; exit 1; }
}
run triangle explain --triangle "20,20 250,80 300,400"
run painter explain demo/demo_scene.json
run zbuffer explain model.obj
if [[ -f $course ]]; then
  rm -rf "${work:?}/why"
  "$bin" why "$course" 200 150 --explain why/ >>"$log" 2>&1 || { cat "$log" >&2; exit 1; }
fi
sha256sum demo/demo_scene.json | awk '{print $2 "  " $1}'
find triangle painter zbuffer why -name '*.png' 2>/dev/null | LC_ALL=C sort | xargs sha256sum |
  awk '{print $2 "  " $1}'
