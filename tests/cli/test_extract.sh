#!/usr/bin/env bash
# featurelines extract as a user runs it: a cube gives its 12 sharp edges meeting at 8 corners
# in the JSON lines file (each with its right angle, or null where not estimated), the labels
# file has one line per input point, the demo part's smooth lines carry their fillets' radii, a
# sphere gives no line and says so, and bad calls exit 2 (usage) or 1 (input) with a reason.
# Usage: test_extract.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_extract.sh FEATURELINES SCRATCH}
work=${2:?usage: test_extract.sh FEATURELINES SCRATCH}/extract
. "$(dirname "$0")/clouds.sh"
mkdir -p "$work" || exit 1
py=/usr/bin/python3

cube 10 0.25 > "$work/cube.xyz"
points=$(wc -l < "$work/cube.xyz")
"$bin" extract "$work/cube.xyz" -o "$work/cube.json" --labels "$work/cube-labels.txt" \
    > "$work/cube.out" || fail "extract on the cube exited $?"
grep -q "sharp 12" "$work/cube.out" || fail "cube summary: $(cat "$work/cube.out")"
$py - "$work/cube.json" <<'PY' || fail "cube JSON: see above"
import json, sys
d = json.load(open(sys.argv[1]))
sharp = [l for l in d["lines"] if l["type"] == "sharp"]
assert len(sharp) == 12, "%d sharp lines" % len(sharp)
assert len(d["junctions"]) == 8, "%d junctions" % len(d["junctions"])
for l in sharp:
    assert l["start_junction"] >= 0 and l["end_junction"] >= 0, "a sharp line with a free end"
    # every vertex lies on a cube edge: two of its coordinates are 0 or 10 (within 0.5)
    for p in l["points"]:
        near = sum(1 for c in p if min(abs(c), abs(c - 10)) < 0.5)
        assert near >= 2, "vertex %s is on no cube edge" % p
assert len(d["regions"]) == 6, "%d smooth regions, expected the 6 faces" % len(d["regions"])
for l in d["lines"]:
    # Every line carries both estimates, null where none was made: an angle on sharp lines only
    # (where estimated, the cube's right angle), a blend radius on smooth lines only.
    assert "angle" in l and "blend_radius" in l, "a line without angle / blend_radius: %s" % l
    if l["type"] == "sharp":
        assert l["angle"] is None or 75 < l["angle"] < 105, "a cube edge at %r deg" % l["angle"]
    else:
        assert l["angle"] is None, "a %s line with an angle: %r" % (l["type"], l["angle"])
    if l["type"] != "smooth":
        assert l["blend_radius"] is None, "a %s line with a blend radius" % l["type"]
PY
labels=$(grep -vc '^#' "$work/cube-labels.txt")
[ "$labels" -eq "$points" ] || fail "labels file has $labels lines for $points points"

sphere 3 4000 0 0 0 > "$work/sphere.xyz"
"$bin" extract "$work/sphere.xyz" -o "$work/sphere.json" > "$work/sphere.out" \
    || fail "extract on the sphere exited $?"
grep -q "no feature lines" "$work/sphere.out" || fail "sphere summary: $(cat "$work/sphere.out")"
$py -c "import json,sys; assert json.load(open(sys.argv[1]))['lines'] == []" "$work/sphere.json" \
    || fail "sphere JSON has lines"

# The shipped demo part (bench/cad/CadShapes.cpp, boss_blend): its smooth lines border the 6 mm
# fillet round the boss and the 12 mm fillets of the plate's vertical corners; each carries the
# radius of its blend within 10 %.
demo="$(dirname "$0")/../../samples/boss_blend.xyz"
"$bin" extract "$demo" -o "$work/demo.json" > "$work/demo.out" || fail "extract on the demo exited $?"
$py - "$work/demo.json" <<'PY' || fail "demo JSON: see above"
import json, sys
d = json.load(open(sys.argv[1]))
smooth = [l for l in d["lines"] if l["type"] == "smooth"]
assert len(smooth) >= 6, "%d smooth lines" % len(smooth)
radii = sorted(l["blend_radius"] for l in smooth)
assert all(r is not None for r in radii), "a smooth line without its blend radius: %s" % radii
near = [r for r in radii if abs(r - 6) < 0.6 or abs(r - 12) < 1.2]
assert near == radii, "blend radii not 6 or 12 mm within 10 %%: %s" % radii
assert any(abs(r - 6) < 0.6 for r in radii) and any(abs(r - 12) < 1.2 for r in radii), radii
PY

expect 2 "no output file" extract "$work/cube.xyz"
expect 2 "no INPUT" extract -o "$work/x.json"
expect 2 "--thresholds" extract "$work/cube.xyz" -o "$work/x.json" --thresholds 0.1,abc
expect 2 "--thresholds" extract "$work/cube.xyz" -o "$work/x.json" --thresholds -0.1
expect 2 "explicit needs --thresholds" extract "$work/cube.xyz" -o "$work/x.json" --threshold-mode explicit
expect 2 "--smoothing must be one of" extract "$work/cube.xyz" -o "$work/x.json" --smoothing sometimes
expect 2 "--k" extract "$work/cube.xyz" -o "$work/x.json" --k 2
expect 1 "missing.xyz" extract "$work/missing.xyz" -o "$work/x.json"
head -n 10 "$work/cube.xyz" > "$work/tiny.xyz"
expect 1 "at least 17" extract "$work/tiny.xyz" -o "$work/x.json"
expect 1 "x.json" extract "$work/cube.xyz" -o "$work/no-such-folder/x.json"
finish
