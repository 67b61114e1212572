#!/usr/bin/env bash
# featurelines threshold on a cloud of three patches of known mean curvature, far apart: a plane
# (|H| = 0, 1600 points), a sphere of radius 2 (|H| = 1/2, 3000 points) and one of radius 1
# (|H| = 1, 750 points), all at a spacing of about 0.13. The first threshold and one refinement
# (Sec. 2.3) must find both valleys. Usage: test_threshold.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_threshold.sh FEATURELINES SCRATCH}
work=${2:?usage: test_threshold.sh FEATURELINES SCRATCH}/threshold
. "$(dirname "$0")/clouds.sh"
mkdir -p "$work" || exit 1

cloud=$work/three.xyz
{ plane 40 0.13 -10; sphere 2 3000 0 0 0; sphere 1 750 10 0 0; } > "$cloud"
points=5350

# The low-point count tells which valley a threshold is in: 1600 (plane | spheres) or 4600.
"$bin" threshold "$cloud" > "$work/first.txt" || fail "threshold exited $?"
tau=$(sed -n 's/^threshold: //p' "$work/first.txt")
low=$(sed -n 's/^low points: //p' "$work/first.txt")
high=$(sed -n 's/^high points: //p' "$work/first.txt")
[ -n "$tau" ] && [ -n "$low" ] || fail "threshold output: $(cat "$work/first.txt")"
[ $((low + high)) -eq $points ] || fail "low $low + high $high points, expected $points"
case $low in
    1600) refine=--above; expect=4600 ;;
    4600) refine=--below; expect=1600 ;;
    *) fail "first threshold $tau puts $low points low, expected 1600 or 4600"; refine= ;;
esac
if [ -n "$refine" ]; then
    "$bin" threshold "$cloud" "$refine" "$tau" > "$work/second.txt" || fail "$refine exited $?"
    low2=$(sed -n 's/^low points: //p' "$work/second.txt")
    [ "$low2" = "$expect" ] ||
        fail "threshold $refine $tau puts ${low2:-?} points low, expected $expect"
fi

# --json: one object; the histogram adds up, its edges span [minimum, maximum].
check_json() { # FILE BINS EXPECTED_COUNT_SUM_MIN EXPECTED_COUNT_SUM_MAX
    python3 - "$@" <<'PY'
import json, math, sys
path, bins, lo, hi = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
with open(path) as f:
    d = json.load(f)
errors = []
for key in ("threshold", "ratio", "start_curv", "outlier_cut", "histogram", "bin_edges",
            "low_points", "high_points", "points"):
    if key not in d:
        errors.append("missing key " + key)
h = d["histogram"]
for key in ("minimum", "maximum", "bin_width", "counts"):
    if key not in h:
        errors.append("missing histogram key " + key)
counts, edges = h["counts"], d["bin_edges"]
if len(counts) != bins:
    errors.append("%d counts, expected %d" % (len(counts), bins))
if not lo <= sum(counts) <= hi:
    errors.append("counts sum to %d, expected %d..%d" % (sum(counts), lo, hi))
if len(edges) != bins + 1:
    errors.append("%d bin edges, expected %d" % (len(edges), bins + 1))
if edges[0] != h["minimum"] or edges[-1] != h["maximum"]:
    errors.append("edges span %r..%r, histogram %r..%r" % (edges[0], edges[-1], h["minimum"], h["maximum"]))
if any(b <= a for a, b in zip(edges, edges[1:])):
    errors.append("bin edges not increasing")
if not any(math.isclose(d["threshold"], e, rel_tol=1e-12, abs_tol=1e-15) for e in edges):
    errors.append("threshold %r is not a bin edge" % d["threshold"])
if d["low_points"] + d["high_points"] != d["points"]:
    errors.append("low + high != points")
if h["maximum"] > d["outlier_cut"]:
    errors.append("histogram maximum above the outlier cut")
if errors:
    print("\n".join(errors))
sys.exit(1 if errors else 0)
PY
}
"$bin" threshold "$cloud" --json > "$work/t.json" || fail "--json exited $?"
check_json "$work/t.json" 50 $points $points || fail "--json: see above"
low_json=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["low_points"])' "$work/t.json")
[ "$low_json" = "$low" ] || fail "--json low points $low_json, text output $low"

"$bin" threshold "$cloud" --json --bins 20 --single-run > "$work/single.json" ||
    fail "--single-run exited $?"
check_json "$work/single.json" 20 $points $points || fail "--single-run --json: see above"

# Sec. 2.4: 1% outliers: floor(53.5) = 53 of the highest values go (ties at the cut stay).
"$bin" threshold "$cloud" --json --outliers 1 --bins 1000 > "$work/outliers.json" ||
    fail "--outliers exited $?"
check_json "$work/outliers.json" 1000 $((points - 53)) $((points - 1)) || fail "--outliers: see above"

finish
