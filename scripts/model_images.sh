#!/usr/bin/env bash
# Regenerates the model images of docs/ with the scantrace command (docs/models.md):
#   docs/head_lit.png           ../shared/data/african_head.obj, lit, Gouraud, culled, gamma 2.2
#   docs/zbuffer_vs_painter.png examples/models/interpenetrating.obj, painter's order (left) and
#                               z-buffer (right), side by side (ffmpeg's hstack)
#   bash scripts/model_images.sh [path/to/scantrace]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scantrace="${1:-$root/build/cli/scantrace}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

head="$root/../shared/data/african_head.obj"
if [[ -f "$head" ]]; then
  "$scantrace" render "$head" --light -1,-0.6,-0.8 --ambient 0.05 --shading gouraud --cull back \
    --gamma 2.2 --depth zbuffer --background 0.12,0.14,0.18 -o "$work/head.png"
  mv "$work/head.png" "$root/docs/head_lit.png"
else
  echo "model_images.sh: $head not found; docs/head_lit.png left as it is" >&2
fi

model="$root/examples/models/interpenetrating.obj"
for depth in painter zbuffer; do
  "$scantrace" render "$model" --unlit --depth "$depth" --size 384x384 -o "$work/$depth.png"
done
# A 4-pixel grey gutter between the two halves.
ffmpeg -loglevel error -y -i "$work/painter.png" -i "$work/zbuffer.png" -filter_complex \
  "[0]pad=iw+4:ih:0:0:color=gray[a];[a][1]hstack" "$work/side.png"
mv "$work/side.png" "$root/docs/zbuffer_vs_painter.png"
echo "wrote docs/head_lit.png and docs/zbuffer_vs_painter.png" >&2
