#!/usr/bin/env bash
# Every way of calling featurelines wrongly: exit code 2 for a usage error, 1 for bad input,
# and one line "featurelines: <reason>" on stderr. Usage: test_errors.sh FEATURELINES SCRATCH
set -u
bin=${1:?usage: test_errors.sh FEATURELINES SCRATCH}
work=${2:?usage: test_errors.sh FEATURELINES SCRATCH}/errors
. "$(dirname "$0")/clouds.sh"
mkdir -p "$work" || exit 1

good=$work/sphere.xyz
sphere 1 400 0 0 0 > "$good"
printf '0 0 0\n1 0 0\n0 1 0\n' > "$work/three.xyz"
printf '0 0 0\n1 zero 0\n' > "$work/text.xyz"
: > "$work/empty.xyz"

# expect CODE PATTERN ARGS...: featurelines ARGS exits CODE and says one line matching PATTERN.
expect() {
    local code=$1 pattern=$2
    shift 2
    "$bin" "$@" > "$work/out" 2> "$work/err"
    local got=$?
    local lines
    lines=$(wc -l < "$work/err")
    if [ "$got" -ne "$code" ]; then
        fail "featurelines $*: exit $got, expected $code (stderr: $(cat "$work/err"))"
    elif [ "$lines" -ne 1 ]; then
        fail "featurelines $*: $lines lines on stderr, expected 1: $(cat "$work/err")"
    elif ! grep -q "^featurelines: .*$pattern" "$work/err"; then
        fail "featurelines $*: stderr '$(cat "$work/err")' does not match '$pattern'"
    fi
}

# usage errors: 2
expect 2 "no command"
expect 2 "unknown command 'frobnicate'" frobnicate "$good"
expect 2 "unknown option '--frobnicate'" threshold "$good" --frobnicate
expect 2 "unknown option '-x'" info "$good" -x
expect 2 "no INPUT" threshold
expect 2 "unexpected argument" info "$good" "$good"
expect 2 "'--k' needs a value" threshold "$good" --k
expect 2 "--k needs a whole number, got 'many'" threshold "$good" --k many
expect 2 "--k needs a whole number, got '16.5'" curvature "$good" -o "$work/h" --k 16.5
expect 2 "--k must be at least 3" threshold "$good" --k 2
expect 2 "--bins must be at least 2" threshold "$good" --bins 1
expect 2 "--bins needs a whole number" threshold "$good" --bins=
expect 2 "--bins must be at least 2 and at most 1000000" threshold "$good" --bins 2000000
expect 2 "--outliers must be at least 0 and below 100" threshold "$good" --outliers 100
expect 2 "--outliers must be at least 0 and below 100" threshold "$good" --outliers -1
expect 2 "--outliers needs a finite number, got 'nan'" threshold "$good" --outliers nan
expect 2 "--outliers needs a finite number, got '5%'" threshold "$good" --outliers 5%
expect 2 "--below and --above exclude each other" threshold "$good" --below 0.1 --above 0.2
expect 2 "--below needs a finite number, got 'inf'" threshold "$good" --below inf
expect 2 "--smooth must be at least 0" curvature "$good" -o "$work/h" --smooth -3
expect 2 "--max-scale must be at least 1" extract "$good" -o "$work/l.json" --max-scale 0.5
expect 2 "--threads needs a whole number" curvature "$good" -o "$work/h" --threads all
expect 2 "needs an output file" curvature "$good"
expect 2 "'--json' takes no value" threshold "$good" --json=yes
expect 2 "given twice" threshold "$good" --bins 10 --bins 20

# bad input: 1
expect 1 "$work/missing.xyz" info "$work/missing.xyz"
expect 1 "$work/missing.xyz" threshold "$work/missing.xyz"
expect 1 "text.xyz" curvature "$work/text.xyz" -o "$work/h"
expect 1 "empty.xyz" info "$work/empty.xyz"
expect 1 "point" curvature "$work/three.xyz" -o "$work/h"
expect 1 "" curvature "$good" -o "$work/no/such/folder/h"
expect 1 "no values at or below" threshold "$good" --below -1

# help goes to stdout with exit 0
for args in "--help" "-h" "info --help" "curvature --help" "threshold -h"; do
    # shellcheck disable=SC2086
    "$bin" $args > "$work/out" 2> "$work/err" || fail "featurelines $args exited $?"
    grep -q "^usage: featurelines" "$work/out" || fail "featurelines $args: no usage on stdout"
    [ -s "$work/err" ] && fail "featurelines $args wrote to stderr: $(cat "$work/err")"
done
"$bin" --help | grep -q "^  threshold" || fail "--help does not list the threshold command"

finish
