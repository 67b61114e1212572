#!/usr/bin/env bash
# featurelines extract's progress on standard error: with --progress a line per stage and, within
# a long stage, lines as its loops go (--progress-every 0: at every report of the core), the
# shares rising; nothing with --quiet; the lines file the same either way.
# Usage: test_progress.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_progress.sh FEATURELINES SCRATCH}
work=${2:?usage: test_progress.sh FEATURELINES SCRATCH}/progress
. "$(dirname "$0")/clouds.sh"
rm -rf "$work"
mkdir -p "$work" || exit 1

cube 10 0.1 > "$work/cube.xyz"
name="featurelines: $work/cube.xyz"

# --quiet: nothing on standard error, the summary on standard output
"$bin" extract "$work/cube.xyz" -o "$work/quiet.json" --quiet > "$work/quiet.out" \
    2> "$work/quiet.err" || fail "extract --quiet exited $?"
[ -s "$work/quiet.err" ] && fail "--quiet, yet stderr: $(cat "$work/quiet.err")"
grep -q "^lines: 12 (sharp 12" "$work/quiet.out" || fail "--quiet summary: $(cat "$work/quiet.out")"

# --progress --progress-every 0: several lines within the neighbours and the normals stages
"$bin" extract "$work/cube.xyz" -o "$work/progress.json" --progress --progress-every 0 \
    > "$work/progress.out" 2> "$work/progress.err" || fail "extract --progress exited $?"
for stage in neighbours normals; do
    lines=$(grep -c "^$name: [0-9]*% $stage" "$work/progress.err")
    [ "$lines" -ge 5 ] || fail "$lines progress lines for '$stage': $(cat "$work/progress.err")"
done
sed -n 's/^featurelines: .*: \([0-9]*\)% .*/\1/p' "$work/progress.err" | sort -c -n \
    || fail "progress shares do not rise: $(cat "$work/progress.err")"
tail -n 1 "$work/progress.err" | grep -q "^$name: done in [0-9.]* s$" \
    || fail "last progress line: $(tail -n 1 "$work/progress.err")"
grep -q "%" "$work/progress.out" && fail "progress on stdout"

# the reports change nothing of the result
cmp -s "$work/quiet.json" "$work/progress.json" || fail "the lines differ with --progress"

# --progress-every: a number of seconds, and only with --progress
expect 2 "needs --progress" extract "$work/cube.xyz" -o "$work/x.json" --progress-every 1
expect 2 "progress-every" extract "$work/cube.xyz" -o "$work/x.json" --progress --progress-every -1
finish
