#!/usr/bin/env bash
# Nothing lost (issue 23): what a careless call does to the files. Each case checks the exit
# code, the one-line message and that the input file is unchanged (checksum before and after);
# docs/RELIABILITY.md lists the same cases. Usage: test_reliability.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_reliability.sh FEATURELINES SCRATCH}
work=${2:?usage: test_reliability.sh FEATURELINES SCRATCH}/reliability
. "$(dirname "$0")/clouds.sh"
rm -rf "$work"
mkdir -p "$work" || exit 1

cloud=$work/cube.xyz
cube 10 0.5 > "$cloud"
head -n 50 "$cloud" > "$work/small.xyz"

# expect CODE TEXT FILE ARGS...: featurelines ARGS exits CODE, says one line containing TEXT,
# and leaves FILE (the input, or an output that must survive) as it was.
expect() {
    local code=$1 text=$2 keep=$3
    shift 3
    local before
    before=$(cksum < "$keep")
    timeout 60 "$bin" "$@" > /dev/null 2> "$work/err"
    local got=$?
    [ "$got" -eq "$code" ] || fail "featurelines $*: exit $got, expected $code ($(cat "$work/err"))"
    grep -q -F -- "$text" "$work/err" || fail "featurelines $*: '$(cat "$work/err")' lacks '$text'"
    [ "$(wc -l < "$work/err")" -eq 1 ] || fail "featurelines $*: not one line on stderr"
    [ "$(cksum < "$keep")" = "$before" ] || fail "featurelines $*: $keep was changed"
}

# ---- outputs ----
expect 2 "--output $cloud is the input file" "$cloud" extract "$cloud" -o "$cloud"
expect 2 "is the input file" "$cloud" curvature "$cloud" -o "$cloud"
ln -s "$cloud" "$work/link.xyz"
expect 2 "--output $work/link.xyz is the input file" "$cloud" \
    curvature "$cloud" -o "$work/link.xyz"
expect 2 "is the input file" "$cloud" curvature "$cloud" -o "$work/./../reliability/cube.xyz"
expect 2 "--labels $cloud is the input file" "$cloud" \
    extract "$cloud" -o "$work/lines.json" --labels "$cloud"
expect 2 "--labels $work/lines.json is also the file of --output" "$cloud" \
    extract "$cloud" -o "$work/lines.json" --labels "$work/lines.json"
expect 2 "--output: the output file name is empty" "$cloud" extract "$cloud" -o ""
# Outputs are checked before the input is even read: the missing folder is reported, not the
# missing input.
expect 1 "the folder $work/no-such-folder does not exist" "$cloud" \
    extract "$work/missing.xyz" -o "$work/no-such-folder/lines.json"
mkdir -p "$work/folder"
expect 1 "$work/folder: is a folder" "$cloud" curvature "$cloud" -o "$work/folder"
[ -e "$work/lines.json" ] && fail "a refused call wrote lines.json"

if [ -w /dev/full ]; then
    expect 1 "/dev/full: writing the file failed" "$cloud" \
        extract "$cloud" -o /dev/full --no-sharp --no-smooth --no-boundary
fi

# A write cut short (a file size limit of 4 KiB) exits 1 and leaves the previous result whole,
# with no temporary file beside it.
"$bin" curvature "$cloud" -o "$work/good.H" || fail "curvature exited $?"
(
    trap '' XFSZ
    ulimit -f 4
    expect 1 "$work/good.H: writing the file failed" "$work/good.H" \
        curvature "$cloud" -o "$work/good.H" --k 20
    exit "$failures"
) || failures=$((failures + 1))
[ "$(find "$work" -name '*.tmp' | wc -l)" -eq 0 ] || fail "a temporary file was left behind"

# A good run replaces an existing output whole.
echo "old" > "$work/lines.json"
"$bin" extract "$cloud" -o "$work/lines.json" > /dev/null || fail "extract exited $?"
grep -q '"lines"' "$work/lines.json" || fail "extract did not replace the old lines.json"

# An output that is a link to another file: the file is replaced, the link kept.
echo "old" > "$work/real.json"
ln -s real.json "$work/link.json"
"$bin" extract "$cloud" -o "$work/link.json" > /dev/null || fail "extract through a link exited $?"
[ -L "$work/link.json" ] || fail "the output link was replaced by a file"
grep -q '"lines"' "$work/real.json" || fail "the file behind the output link was not written"

# A device is written directly: /dev/stdout gives one curvature line per point.
lines=$("$bin" curvature "$cloud" -o /dev/stdout | wc -l)
[ "$lines" -eq "$(wc -l < "$cloud")" ] || fail "curvature -o /dev/stdout wrote $lines lines"

# ---- inputs ----
printf '0 0 0\n1,5 2,25 3,125\n' > "$work/comma.xyz"
expect 1 "decimal commas are not supported, line 2" "$work/comma.xyz" info "$work/comma.xyz"
printf '1,2,3\n4, 5, 6\n7.5,8.5,9.5\n' > "$work/rows.csv"
"$bin" info "$work/rows.csv" | grep -qx "points: 3" || fail "x,y,z CSV rows are not read"

ply() { # ply COUNT: an ascii PLY header for COUNT vertices
    printf 'ply\nformat ascii 1.0\nelement vertex %s\nproperty float x\n' "$1"
    printf 'property float y\nproperty float z\nend_header\n'
}
{ ply 40; head -n 50 "$cloud"; } > "$work/more.ply"
expect 1 "the header says 'element vertex 40' (40 data rows), the file holds 50" \
    "$work/more.ply" info "$work/more.ply"
{ ply 60; head -n 50 "$cloud"; } > "$work/fewer.ply"
expect 1 "'element vertex 60'" "$work/fewer.ply" info "$work/fewer.ply"
{
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 60\n'
    printf 'HEIGHT 1\nPOINTS 60\nDATA ascii\n'
    head -n 50 "$cloud"
} > "$work/fewer.pcd"
expect 1 "the header says 'POINTS 60', the file holds 50 data rows" "$work/fewer.pcd" \
    info "$work/fewer.pcd"

mkfifo "$work/pipe.xyz"
expect 1 "$work/pipe.xyz: is not a regular file" "$cloud" info "$work/pipe.xyz"
expect 1 "is not a regular file" "$cloud" info /dev/zero

printf '\033[2J\033]0;title\007 0 0\n' > "$work/binary.xyz"
expect 1 "'\\x1B[2J\\x1B]0;title\\x07' is not a number" "$work/binary.xyz" info "$work/binary.xyz"
LC_ALL=C grep -q "$(printf '\033')" "$work/err" && fail "an escape byte reached the terminal"

printf '0 0 0\n1e39 0 0\n' > "$work/huge.xyz"
expect 1 "line 2: coordinate '1e39' is beyond the float range" "$work/huge.xyz" \
    info "$work/huge.xyz"

for i in $(seq 40); do echo "1 2 3"; done > "$work/duplicates.xyz"
expect 1 "1 distinct points (39 duplicates merged)" "$work/duplicates.xyz" \
    curvature "$work/duplicates.xyz" -o "$work/duplicates.H"
for i in $(seq 40); do echo "$i 0 0"; done > "$work/line.xyz"
expect 1 "the points lie on a line" "$work/line.xyz" curvature "$work/line.xyz" -o "$work/line.H"
expect 1 "the points lie on a line" "$work/line.xyz" threshold "$work/line.xyz"
[ -e "$work/duplicates.H" ] || [ -e "$work/line.H" ] && fail "a refused curvature wrote a file"

# ---- hostile input (issue 22): refused at once with one line, never a hang or a crash ----
awk '{ printf "%se-310 %se-310 %se-310\n", $1, $2, $3 }' "$cloud" > "$work/denormal.xyz"
for command in info curvature threshold; do
    expect 1 "below the smallest supported, 1e-100" "$work/denormal.xyz" \
        $command "$work/denormal.xyz" $([ $command = curvature ] && echo "-o $work/d.H")
done
awk '{ printf "%.17g %.17g %.17g\n", $1 + 1e15, $2 + 1e15, $3 + 1e15 }' "$cloud" > "$work/far.xyz"
for command in info curvature threshold; do
    expect 1 "more than 1e8 times its size" "$work/far.xyz" \
        $command "$work/far.xyz" $([ $command = curvature ] && echo "-o $work/f.H")
done
# info computes the spacing before it prints it: a refused cloud leaves no half-written line.
"$bin" info "$work/far.xyz" > "$work/out" 2> /dev/null
grep -q "mean spacing" "$work/out" && fail "info on a refused cloud printed a 'mean spacing' line"
{ cat "$cloud"; echo "1e8 0 0"; } > "$work/outlier.xyz"
expect 1 "more than 1024 points lie in one cell" "$work/outlier.xyz" info "$work/outlier.xyz"
expect 1 "more than 1024 points lie in one cell" "$work/outlier.xyz" \
    extract "$work/outlier.xyz" -o "$work/o.json"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4294967296\n' > "$work/claims.ply"
printf 'property float x\nproperty float y\nproperty float z\nend_header\n' >> "$work/claims.ply"
head -c 120 /dev/zero >> "$work/claims.ply"
expect 1 "the header says 'element vertex 4294967296', the file ends in row 11" \
    "$work/claims.ply" info "$work/claims.ply"
{
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 4000000000\n'
    printf 'WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n'
    head -c 12 /dev/zero
} > "$work/count.pcd"
expect 1 "field 'z' has COUNT '4000000000'" "$work/count.pcd" extract "$work/count.pcd" \
    -o "$work/c.json"
{ ply 50 | sed 's/^format ascii 1.0$/format ascii 1.0\nobj_info scanner 1/'; head -n 50 "$cloud"; } \
    > "$work/info.ply"
"$bin" info "$work/info.ply" | grep -qx "points: 50" || fail "a PLY with obj_info is not read"
head -c 3000 "$bin" > "$work/junk.xyz"
expect 1 "$work/junk.xyz, line 1: '\x7FELF" "$work/junk.xyz" info "$work/junk.xyz"
printf '\377\3761\000 \0002\000 \0003\000\n\000' > "$work/utf16.xyz"
expect 1 "$work/utf16.xyz: is UTF-16 text" "$work/utf16.xyz" extract "$work/utf16.xyz" \
    -o "$work/u.json"

# ---- options ----
expect 2 "--k must be at least 3 and at most 256, got 10000" "$cloud" \
    curvature "$cloud" -o "$work/k.H" --k 10000
expect 1 "--k 100 must be below the point count of $work/small.xyz (50)" "$work/small.xyz" \
    curvature "$work/small.xyz" -o "$work/k.H" --k 100
expect 1 "--bins 1000000 must be below the point count" "$cloud" threshold "$cloud" --bins 1000000
expect 1 "--bins 5000 must be below the point count" "$cloud" \
    extract "$cloud" -o "$work/bins.json" --bins 5000
expect 2 "--threads must be at most" "$cloud" extract "$cloud" -o "$work/t.json" --threads 4096

finish
