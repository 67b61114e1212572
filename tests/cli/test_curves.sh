#!/usr/bin/env bash
# featurelines extract's fitted network as a user reads it: a cube's JSON "network" has 12
# segments on 8 shared corners and 6 closed face borders of 4 edges; --curves writes them as
# OBJ polylines (12 l records on the 8 shared vertices) or PLY (vertex and edge elements); a
# closed cylinder gives its two rims as circles of its radius; a flat square sheet's boundary is
# one closed curve, or with --corner-angle its four sides; a bad --curves name or corner angle
# exits 2 or 1.
# Usage: test_curves.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_curves.sh FEATURELINES SCRATCH}
work=${2:?usage: test_curves.sh FEATURELINES SCRATCH}/curves
. "$(dirname "$0")/clouds.sh"
rm -rf "$work"
mkdir -p "$work/in" "$work/out" "$work/curves" || exit 1
py=/usr/bin/python3

cube 10 0.25 > "$work/in/cube.xyz"
"$bin" extract "$work/in/cube.xyz" -o "$work/cube.json" --curves "$work/cube.obj" \
    > "$work/cube.out" || fail "extract --curves on the cube exited $?"
grep -q "^curves: 12 (segment 12, arc 0, circle 0, bspline 0), vertices 8, patches closed 6 of 6$" \
    "$work/cube.out" || fail "cube curve summary: $(cat "$work/cube.out")"
$py - "$work/cube.json" "$work/cube.obj" <<'PY' || fail "cube network JSON or OBJ: see above"
import json, sys
n = json.load(open(sys.argv[1]))["network"]
corners = n["vertices"]
assert len(corners) == 8, "%d vertices" % len(corners)
for p in corners:  # every vertex is a cube corner (within half a spacing)
    assert all(min(abs(c), abs(c - 10)) < 0.15 for c in p), "vertex %s is no corner" % p
assert len(n["edges"]) == 12, "%d edges" % len(n["edges"])
degree = [0] * 8
for e in n["edges"]:
    assert e["kind"] == "segment" and e["type"] == "sharp", e
    assert abs(e["length"] - 10) < 0.3, "edge length %g" % e["length"]
    degree[e["start_vertex"]] += 1
    degree[e["end_vertex"]] += 1
assert degree == [3] * 8, "vertex degrees %s" % degree
borders = n["patch_borders"]
assert len(borders) == 6 and all(b["closed"] for b in borders), borders
for b in borders:
    assert len(b["loops"]) == 1 and len(b["loops"][0]) == 4 and b["open_edges"] == [], b
    loop = b["loops"][0]
    ends = []
    for le in loop:
        e = n["edges"][le["edge"]]
        s, t = e["start_vertex"], e["end_vertex"]
        ends.append((t, s) if le["reversed"] else (s, t))
    for k in range(4):  # each edge ends where the next one starts
        assert ends[k][1] == ends[(k + 1) % 4][0], "loop %s does not chain" % loop
# OBJ: the 8 shared vertices first, one l record per edge from corner to corner
v = [l.split()[1:] for l in open(sys.argv[2]) if l.startswith("v ")]
lines = [list(map(int, l.split()[1:])) for l in open(sys.argv[2]) if l.startswith("l ")]
assert len(lines) == 12, "%d l records" % len(lines)
for l in lines:
    assert 1 <= l[0] <= 8 and 1 <= l[-1] <= 8 and l[0] != l[-1], "l %s" % l
    assert all(1 <= i <= len(v) for i in l), "l %s indexes no vertex" % l
used = sorted(i for l in lines for i in (l[0], l[-1]))
assert used == sorted(list(range(1, 9)) * 3), "corners used %s" % used
PY

"$bin" extract "$work/in/cube.xyz" -o "$work/cube2.json" --curves "$work/cube.PLY" > /dev/null \
    || fail "extract --curves .PLY exited $?"
$py - "$work/cube.PLY" <<'PY' || fail "cube PLY: see above"
import sys
text = open(sys.argv[1]).read().split("end_header\n")
header, body = text[0].splitlines(), text[1].splitlines()
assert header[:2] == ["ply", "format ascii 1.0"], header[:2]
count = {l.split()[1]: int(l.split()[2]) for l in header if l.startswith("element")}
assert count == {"vertex": 8, "edge": 12}, count
assert len(body) == 20, "%d data lines" % len(body)
for l in body[8:]:
    a, b = map(int, l.split())
    assert 0 <= a < 8 and 0 <= b < 8 and a != b, l
PY

# A closed cylinder (radius 5, height 6, spacing 0.2): two circles about z of radius 5
awk 'BEGIN {
    srand(3); r = 5; h = 6; s = 0.2; pi = atan2(0, -1);
    n = int(2 * pi * r / s);
    for (i = 0; i < n; i++) for (z = -h / 2 + s / 2; z < h / 2; z += s) {
        a = 2 * pi * (i + 0.4 * (rand() - 0.5)) / n;
        printf "%.6f %.6f %.6f\n", r * cos(a), r * sin(a), z + 0.08 * (rand() - 0.5) }
    for (x = -r + s / 2; x < r; x += s) for (y = -r + s / 2; y < r; y += s) {
        px = x + 0.08 * (rand() - 0.5); py = y + 0.08 * (rand() - 0.5);
        if (px * px + py * py < (r - s / 4) ^ 2) printf "%.6f %.6f %.6f\n%.6f %.6f %.6f\n", px, py, h / 2, px, py, -h / 2 }
}' > "$work/in/cylinder.xyz"
"$bin" extract "$work/in/cylinder.xyz" -o "$work/cylinder.json" > "$work/cylinder.out" \
    || fail "extract on the cylinder exited $?"
$py - "$work/cylinder.json" <<'PY' || fail "cylinder network: see above"
import json, sys
n = json.load(open(sys.argv[1]))["network"]
circles = [e for e in n["edges"] if e["kind"] == "circle"]
assert len(n["edges"]) == 2 and len(circles) == 2, [e["kind"] for e in n["edges"]]
for c in circles:
    assert abs(c["radius"] - 5) < 0.1, "radius %g" % c["radius"]
    assert abs(abs(c["axis"][2]) - 1) < 1e-3, "axis %s" % c["axis"]
    assert abs(abs(c["centre"][2]) - 3) < 0.1, "centre %s" % c["centre"]
    assert c["start_vertex"] == c["end_vertex"]
assert sum(len(b["loops"]) for b in n["patch_borders"]) == 4, n["patch_borders"]
PY

# A flat square sheet (side 20, spacing 0.25): its one boundary loop is one closed curve, and
# with --corner-angle 30 four segments of its side meeting at its four corners
mkdir -p "$work/sheet"
awk 'BEGIN { srand(5); s = 0.25;
    for (x = 0; x <= 20.0001; x += s) for (y = 0; y <= 20.0001; y += s)
        printf "%.6f %.6f 0\n", x + 0.05 * (rand() - 0.5), y + 0.05 * (rand() - 0.5) }' \
    > "$work/sheet/square.xyz"
"$bin" extract "$work/sheet/square.xyz" -o "$work/square.json" > "$work/square.out" \
    || fail "extract on the square sheet exited $?"
grep -q "^curves: 1 (segment 0, arc 0, circle 0, bspline 1), vertices 1, patches closed 1 of 1$" \
    "$work/square.out" || fail "square sheet curve summary: $(cat "$work/square.out")"
"$bin" extract "$work/sheet/square.xyz" -o "$work/square30.json" --corner-angle 30 \
    > "$work/square30.out" || fail "extract --corner-angle 30 on the square sheet exited $?"
$py - "$work/square30.json" <<'PY' || fail "square sheet cut at its corners: see above"
import json, sys
n = json.load(open(sys.argv[1]))["network"]
assert len(n["vertices"]) == 4, "%d vertices" % len(n["vertices"])
for p in n["vertices"]:  # each a corner of the square, within a fifth of a spacing
    assert all(min(abs(c), abs(c - 20)) < 0.05 for c in p), "vertex %s is no corner" % p
assert len(n["edges"]) == 4, "%d edges" % len(n["edges"])
for e in n["edges"]:
    assert e["kind"] == "segment" and e["type"] == "boundary", e
    assert abs(e["length"] - 20) < 0.1, "edge length %g" % e["length"]
b = n["patch_borders"]
assert len(b) == 1 and b[0]["closed"] and len(b[0]["loops"][0]) == 4, b
PY
expect 2 "--corner-angle must be at least 0 and at most 180" \
    extract "$work/sheet/square.xyz" -o "$work/x.json" --corner-angle 200

# A folder: NAME.obj per input beside the lines files
"$bin" extract "$work/in" -o "$work/out" --curves "$work/curves" --quiet > /dev/null \
    || fail "extract on a folder with --curves exited $?"
[ "$(ls "$work/curves")" = "$(printf 'cube.obj\ncylinder.obj')" ] \
    || fail "folder curves: $(ls "$work/curves")"

expect 2 "must end in .obj or .ply" extract "$work/in/cube.xyz" -o "$work/x.json" --curves "$work/x.stl"
expect 2 "standard output" extract "$work/in/cube.xyz" -o - --curves -
expect 1 "no-such-folder" extract "$work/in/cube.xyz" -o "$work/x.json" --curves "$work/no-such-folder/x.obj"
expect 1 "is not a folder" extract "$work/in" -o "$work/out" --curves "$work/cube.obj"
finish
