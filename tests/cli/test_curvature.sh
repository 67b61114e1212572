#!/usr/bin/env bash
# featurelines info and curvature on clouds with a known answer: a sphere of radius 2
# (|H| = 1/2 everywhere) and a plane (|H| = 0). Usage: test_curvature.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_curvature.sh FEATURELINES SCRATCH}
work=${2:?usage: test_curvature.sh FEATURELINES SCRATCH}/curvature
. "$(dirname "$0")/clouds.sh"
mkdir -p "$work" || exit 1

sphere 2 3000 0 0 0 > "$work/sphere.xyz"
plane 40 0.1 0 0 > "$work/grid.xyz"
plane 40 0.1 5 > "$work/plane.xyz"

# stats FILE: "count min max mean" of one number per line.
stats() {
    awk 'NR == 1 { lo = $1; hi = $1 } { s += $1; if ($1 < lo) lo = $1; if ($1 > hi) hi = $1 }
         END { printf "%d %.17g %.17g %.17g\n", NR, lo, hi, s / NR }' "$1"
}
# within VALUE LO HI: true when LO <= VALUE <= HI.
within() { awk -v v="$1" -v lo="$2" -v hi="$3" 'BEGIN { exit !(v >= lo && v <= hi) }'; }

# info: an exact 40 x 40 grid of spacing 0.1.
out=$("$bin" info "$work/grid.xyz") || fail "info exited $?"
echo "$out" | grep -qx "points: 1600" || fail "info point count: $out"
echo "$out" | grep -qx "bounding box min: 0 0 0" || fail "info box min: $out"
echo "$out" | grep -qx "bounding box max: 3.9 3.9 0" || fail "info box max: $out"
spacing=$(echo "$out" | sed -n 's/^mean spacing: //p')
within "$spacing" 0.0999999 0.1000001 || fail "info mean spacing $spacing, expected 0.1"

# A sphere of radius 2: every |H| close to 1/2 (quadric over 16 neighbours, no noise).
"$bin" curvature "$work/sphere.xyz" -o "$work/sphere.H" || fail "curvature exited $?"
read -r n lo hi mean < <(stats "$work/sphere.H")
[ "$n" = 3000 ] || fail "sphere: $n curvature lines, expected 3000 (one per point)"
within "$lo" 0.49 0.51 && within "$hi" 0.49 0.51 ||
    fail "sphere: |H| from $lo to $hi, expected 0.5 +- 2%"
# The quadric's truncation (z = x^2/2r + x^4/8r^3 + ...) biases |H| up by about (rho/r)^2/4 for
# a neighbourhood of radius rho (here about 0.3): 1% covers it.
within "$mean" 0.4975 0.505 || fail "sphere: mean |H| $mean, expected 0.5 -0.5% +1%"

# --signed: the same magnitude; the sign is that of the unoriented PCA normal.
"$bin" curvature "$work/sphere.xyz" --signed --k 24 -o "$work/sphere.signed" || fail "--signed exited $?"
awk '{ v = $1 < 0 ? -$1 : $1; if (v < 0.49 || v > 0.51) bad++ } END { exit bad > 0 }' \
    "$work/sphere.signed" || fail "sphere: signed |H| not 0.5 +- 2%"

# Taubin smoothing keeps the sphere's radius: |H| stays near 1/2.
"$bin" curvature "$work/sphere.xyz" --smooth 5 --output="$work/sphere.smooth" ||
    fail "--smooth exited $?"
read -r n lo hi mean < <(stats "$work/sphere.smooth")
within "$mean" 0.49 0.51 || fail "sphere after smoothing: mean |H| $mean, expected 0.5 +- 2%"

# A plane (jittered in-plane): |H| = 0 up to rounding.
"$bin" curvature "$work/plane.xyz" -o "$work/plane.H" || fail "curvature (plane) exited $?"
read -r n lo hi mean < <(stats "$work/plane.H")
[ "$n" = 1600 ] || fail "plane: $n curvature lines, expected 1600"
within "$hi" 0 1e-9 || fail "plane: largest |H| $hi, expected 0"

finish
