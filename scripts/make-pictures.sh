#!/usr/bin/env bash
# Regenerates the pictures the README shows (docs/pictures/), all made by
# simcli itself: the Newton's cradle over a few steps and the default scene
# (--snapshot, SVG), 870 disks at 0.70 coloured by their local psi6
# (--colour-by psi6), and screenshots of the default scene's page and of the
# 870 disks' page (--animate, in headless Chromium). Installs what is
# missing, like the quick start.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/ensure-deps.sh chromium
cmake --preset release >/dev/null
cmake --build --preset release --target simcli simgen -j "$(nproc)" >/dev/null
simcli=build/apps/simcli
simgen=build/apps/simgen
out=docs/pictures
mkdir -p "$out"
for step in 4 5 6 7 8; do
  "$simcli" examples/newtons_cradle.in -o /dev/null --snapshot "$out/cradle-step-$step.svg" --snapshot-step "$step"
done
"$simcli" examples/default.in -o /dev/null --snapshot "$out/default-step-1000.svg"
page=$(mktemp --suffix=.html)
profile=$(mktemp -d)
hexatic=$(mktemp --suffix=.in)
trap 'rm -rf "$page" "$profile" "$hexatic"' EXIT
"$simgen" compressed -n 870 --fraction 0.70 --boundary periodic -s 200 --mode perf > "$hexatic"
"$simcli" "$hexatic" --engine exact --boundary periodic -o /dev/null --colour-by psi6 \
  --snapshot "$out/hexatic-870.svg" --animate "$page" --animate-every 2
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" --window-size=1180,1950 \
  --virtual-time-budget=4000 --screenshot="$out/animation-psi6.png" "file://$page#frame=100" 2>/dev/null
"$simcli" examples/default.in -o /dev/null --animate "$page"
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$profile" --window-size=1180,900 \
  --virtual-time-budget=4000 --screenshot="$out/animation.png" "file://$page#frame=500" 2>/dev/null
echo "wrote $out/cradle-step-{4..8}.svg, $out/default-step-1000.svg, $out/hexatic-870.svg, $out/animation.png and $out/animation-psi6.png"
