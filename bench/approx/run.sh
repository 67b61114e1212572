#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# FeatureLines' patch surfaces against FreeCAD's approxSurface (issue 21), from a built tree:
#   bench/approx/run.sh [BUILD [OUTPUT.md]]    BUILD: default <repo>/build; OUTPUT: default
#                                              ./approx-results.md
# 1. copies what it uses out of BUILD first (the FreeCAD module BUILD/Mod, featurelines_accuracy),
#    so that BUILD may be rebuilt while it runs;
# 2. writes the nine built-in parts' clouds, clean and noisy, with their true B-reps
#    (featurelines_accuracy --write, seed 1, 50000 points, noise 0.3 spacing);
# 3. runs compare_approx_surface.py in freecadcmd on them and on samples/boss_blend.xyz.
# APPROX_WORK: the scratch folder (default: a new one under /tmp, kept for inspection). The
# APPROX_* settings of compare_approx_surface.py (APPROX_ONLY, APPROX_POLES, ...) pass through.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
output=$(realpath -m "${2:-$PWD/approx-results.md}")
work=${APPROX_WORK:-$(mktemp -d /tmp/approx-XXXXXX)}
mkdir -p "$work"
echo "scratch folder: $work"

# 1. Copies: the module as FreeCAD finds it (FREECAD_USER_DATA holds Mod/), the tool.
rm -rf "$work/mod" && mkdir -p "$work/mod"
cp -r "$build/Mod" "$work/mod/"
cp "$build/bench/cad/featurelines_accuracy" "$work/"

# 2. The clouds and their truth (cloud.xyz, truth.json, truth.brep per case); the demo cloud's
#    truth is the boss_blend part's.
if [ ! -d "$work/cases" ]; then
    "$work/featurelines_accuracy" --write "$work/cases" --no-baselines --seed 1 \
        > "$work/accuracy.log" 2>&1
fi
mkdir -p "$work/truth"
cp "$work/cases/boss_blend-clean/truth.brep" "$work/truth/boss_blend.brep"

# 3. The comparison, in a FreeCAD profile of its own (settings kept out of the user's).
mkdir -p "$work/home/config" "$work/home/data" "$work/home/cache"
env FREECAD_USER_DATA="$work/mod" FREECAD_USER_HOME="$work/home" \
    XDG_CONFIG_HOME="$work/home/config" XDG_DATA_HOME="$work/home/data" \
    XDG_CACHE_HOME="$work/home/cache" \
    APPROX_CASES="$work/cases" APPROX_TRUTH="$work/truth" \
    APPROX_DEMO_CLOUD="$repo/samples/boss_blend.xyz" APPROX_OUTPUT="$output" \
    freecadcmd "$here/compare_approx_surface.py" > "$work/freecadcmd.log"
echo "results: $output"
