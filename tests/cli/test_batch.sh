#!/usr/bin/env bash
# featurelines extract for batches and pipes: several inputs or a folder give one lines file per
# input and one summary line each, and exit 1 when any input failed (the others are still
# written); "-" reads standard input and writes standard output; --version; progress on standard
# error with --progress, none with --quiet; -1 marks "no region" in the labels file.
# Usage: test_batch.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_batch.sh FEATURELINES SCRATCH}
work=${2:?usage: test_batch.sh FEATURELINES SCRATCH}/batch
. "$(dirname "$0")/clouds.sh"
rm -rf "$work"
mkdir -p "$work/in" "$work/out" "$work/labels" "$work/tmp" || exit 1
py=/usr/bin/python3

cube 10 0.25 > "$work/in/cube.xyz"
sphere 3 4000 0 0 0 > "$work/in/sphere.xyz"
echo "not a cloud" > "$work/in/readme.md"

# --version: the project's version, exit 0
version=$("$bin" --version) || fail "--version exited $?"
[[ "$version" =~ ^featurelines\ [0-9]+\.[0-9]+\.[0-9]+$ ]] || fail "--version printed '$version'"

# a folder: its two clouds (not readme.md), one lines and one labels file each, exit 0
"$bin" extract "$work/in" -o "$work/out" --labels "$work/labels" --quiet \
    > "$work/folder.out" 2> "$work/folder.err" || fail "extract on a folder exited $?"
[ -s "$work/folder.err" ] && fail "--quiet, yet stderr: $(cat "$work/folder.err")"
[ "$(ls "$work/out")" = "$(printf 'cube.json\nsphere.json')" ] \
    || fail "folder outputs: $(ls "$work/out")"
[ "$(ls "$work/labels")" = "$(printf 'cube.labels.txt\nsphere.labels.txt')" ] \
    || fail "folder labels: $(ls "$work/labels")"
grep -q "^$work/in/cube.xyz: lines: 12 (sharp 12" "$work/folder.out" \
    || fail "cube summary: $(cat "$work/folder.out")"
grep -q "^$work/in/sphere.xyz: lines: 0 " "$work/folder.out" \
    || fail "sphere summary: $(cat "$work/folder.out")"
grep -q "^2 inputs: 2 done, 0 failed$" "$work/folder.out" \
    || fail "folder total: $(cat "$work/folder.out")"
$py - "$work/out/cube.json" <<'PY' || fail "cube lines file of the batch: see above"
import json, sys
d = json.load(open(sys.argv[1]))
assert sum(1 for l in d["lines"] if l["type"] == "sharp") == 12
PY

# labels: -1 is "no region / patch / label" (the cube's edge bands), never 255; every face
# point has a region 0..5
$py - "$work/labels/cube.labels.txt" "$work/in/cube.xyz" <<'PY' || fail "cube labels: see above"
import sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
assert len(rows) == sum(1 for _ in open(sys.argv[2])), "one row per input point"
regions = {int(r[0]) for r in rows}
labels = {int(r[2]) for r in rows}
assert regions == {-1, 0, 1, 2, 3, 4, 5}, regions
assert -1 in labels and 255 not in labels, labels
for r in rows:
    assert (int(r[0]) == -1) == (int(r[2]) == -1), "region and label disagree on %s" % r
PY

# several files, one of them bad: the good ones are written, the bad one named, exit 1
head -n 5 "$work/in/cube.xyz" > "$work/tiny.xyz"
rm -f "$work/out"/*
"$bin" extract "$work/in/cube.xyz" "$work/tiny.xyz" "$work/missing.xyz" "$work/in/sphere.xyz" \
    -o "$work/out" > "$work/mixed.out" 2> "$work/mixed.err"
code=$?
[ "$code" -eq 1 ] || fail "a batch with bad inputs exited $code, expected 1"
[ -s "$work/out/cube.json" ] && [ -s "$work/out/sphere.json" ] \
    || fail "the good inputs of a failing batch were not written: $(ls "$work/out")"
[ -e "$work/out/tiny.json" ] && fail "a failed input left a lines file"
grep -q "^$work/tiny.xyz: failed$" "$work/mixed.out" || fail "tiny summary: $(cat "$work/mixed.out")"
grep -q "^$work/missing.xyz: failed$" "$work/mixed.out" || fail "missing summary"
grep -q "^4 inputs: 2 done, 2 failed$" "$work/mixed.out" || fail "mixed total: $(cat "$work/mixed.out")"
grep -q "^featurelines: $work/tiny.xyz: .*at least 17" "$work/mixed.err" \
    || fail "tiny's reason: $(cat "$work/mixed.err")"
grep -q "^featurelines: .*missing.xyz" "$work/mixed.err" || fail "missing's reason"
[ "$(wc -l < "$work/mixed.err")" -eq 2 ] || fail "stderr of the batch: $(cat "$work/mixed.err")"

# batch usage: -o must be a folder, names must not collide, - is for one input only
mkdir -p "$work/b"
cp "$work/in/cube.xyz" "$work/b/cube.xyz"
expect 1 "is not a folder" extract "$work/in" -o "$work/out/x.json"
expect 2 "would both write" extract "$work/in/cube.xyz" "$work/b/cube.xyz" -o "$work/out"
expect 2 "only be the one INPUT" extract - "$work/in/cube.xyz" -o "$work/out"
expect 2 "exclude each other" extract "$work/in/cube.xyz" -o "$work/x.json" --quiet --progress
expect 2 "standard output" extract "$work/in/cube.xyz" -o - --labels -
expect 2 "standard input (-) only" info "$work/in/cube.xyz" --format ply
expect 2 "--format must be one of" info - --format obj
: | TMPDIR="$work/tmp" "$bin" info - > /dev/null 2> "$work/err.txt"
[ $? -eq 1 ] && grep -q "^featurelines: standard input: " "$work/err.txt" \
    || fail "empty standard input: $(cat "$work/err.txt")"
TMPDIR="$work/tmp" "$bin" info - < "$work/in/sphere.xyz" > /dev/null || fail "info - exited $?"
[ -z "$(ls -A "$work/tmp")" ] || fail "temporary copies of stdin were left: $(ls -A "$work/tmp")"

# pipes: the cloud from standard input, the lines to standard output, the summary to stderr
"$bin" extract - -o - --quiet < "$work/in/cube.xyz" > "$work/piped.json" 2> "$work/piped.err" \
    || fail "extract - -o - exited $?"
cmp -s <(tail -n +2 "$work/piped.json") <(tail -n +2 "$work/out/cube.json") \
    || fail "the piped lines differ from the lines of the file"
grep -q "^lines: 12 (sharp 12" "$work/piped.err" || fail "piped summary: $(cat "$work/piped.err")"
"$bin" extract - -o "$work/ply.json" --format ply --quiet < "$work/in/cube.xyz" 2> "$work/err.txt"
[ $? -eq 1 ] && grep -q "^featurelines: standard input: .*PLY" "$work/err.txt" \
    || fail "xyz text read as PLY: $(cat "$work/err.txt")"
"$bin" curvature - -o - < "$work/in/sphere.xyz" > "$work/h.txt" || fail "curvature - -o - exited $?"
[ "$(wc -l < "$work/h.txt")" -eq 4000 ] || fail "curvature to stdout: $(wc -l < "$work/h.txt") lines"
awk '{ if ($1 < 0.3 || $1 > 0.37) bad++ } END { exit bad > 0 }' "$work/h.txt" \
    || fail "sphere curvature to stdout is not 1/3"

# progress: forced with --progress, on stderr only, rising shares, a last "done in" line
"$bin" extract "$work/in/cube.xyz" -o "$work/p.json" --progress > "$work/p.out" 2> "$work/p.err" \
    || fail "extract --progress exited $?"
grep -q "^featurelines: $work/in/cube.xyz: 0% " "$work/p.err" || fail "no 0% line: $(cat "$work/p.err")"
tail -n 1 "$work/p.err" | grep -q "^featurelines: $work/in/cube.xyz: done in [0-9.]* s$" \
    || fail "last progress line: $(tail -n 1 "$work/p.err")"
sed -n 's/^featurelines: .*: \([0-9]*\)% .*/\1/p' "$work/p.err" | sort -c -n \
    || fail "progress shares do not rise: $(cat "$work/p.err")"
grep -q "%" "$work/p.out" && fail "progress on stdout"
# without a terminal and without --progress: nothing on stderr
"$bin" extract "$work/in/cube.xyz" -o "$work/p.json" > /dev/null 2> "$work/np.err"
[ -s "$work/np.err" ] && fail "progress without a terminal: $(cat "$work/np.err")"
finish
