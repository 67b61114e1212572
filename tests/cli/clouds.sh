# Small point clouds with a known answer, written with awk (sourced by the test_*.sh scripts).
# Deterministic: the in-plane jitter comes from sin(), not from a random generator.

# sphere RADIUS N CX CY CZ: N points of a Fibonacci sphere (near-uniform), |H| = 1/RADIUS.
sphere() {
    awk -v r="$1" -v n="$2" -v cx="$3" -v cy="$4" -v cz="$5" 'BEGIN {
        pi = atan2(0, -1); golden = pi * (3 - sqrt(5));
        for (i = 0; i < n; i++) {
            z = 1 - (2 * i + 1) / n; rho = sqrt(1 - z * z); a = golden * i;
            printf "%.12f %.12f %.12f\n", cx + r * rho * cos(a), cy + r * rho * sin(a), cz + r * z;
        }
    }'
}

# plane SIDE_COUNT SPACING Z [JITTER]: a SIDE_COUNT x SIDE_COUNT grid of z = Z, |H| = 0; each
# point moved in the plane by up to JITTER spacings (default 0.2).
plane() {
    awk -v m="$1" -v h="$2" -v z0="$3" -v j="${4:-0.2}" 'BEGIN {
        for (i = 0; i < m; i++) for (k = 0; k < m; k++) {
            dx = j * h * sin(i * 12.9898 + k * 78.233); dy = j * h * sin(i * 39.3468 + k * 11.135);
            printf "%.12f %.12f %.12f\n", i * h + dx, k * h + dy, z0;
        }
    }'
}

# cube EDGE SPACING: the surface of the cube [0, EDGE]^3, a jittered grid of cell centres on each
# face (no point on an edge): 12 sharp edges meeting at 8 corners, flat faces.
cube() {
    awk -v e="$1" -v h="$2" 'BEGIN {
        m = int(e / h);
        for (f = 0; f < 6; f++) for (i = 0; i < m; i++) for (k = 0; k < m; k++) {
            u = (i + 0.5 + 0.2 * sin(i * 12.9898 + k * 78.233 + f)) * e / m;
            v = (k + 0.5 + 0.2 * sin(i * 39.3468 + k * 11.135 + f)) * e / m;
            w = (f % 2) * e; a = int(f / 2);
            if (a == 0) printf "%.12f %.12f %.12f\n", w, u, v;
            else if (a == 1) printf "%.12f %.12f %.12f\n", u, w, v;
            else printf "%.12f %.12f %.12f\n", u, v, w;
        }
    }'
}

# fail MESSAGE: report a failed check (the script goes on, and exits 1 at the end).
failures=0
fail() {
    echo "FAILED: $*" >&2
    failures=$((failures + 1))
}

# expect CODE TEXT ARGS...: featurelines ($bin) ARGS exits CODE with one line on stderr that
# contains TEXT (the scripts set $bin and $work).
expect() {
    local code=$1 text=$2; shift 2
    "$bin" "$@" > /dev/null 2> "$work/err.txt"
    local got=$?
    [ "$got" -eq "$code" ] || fail "featurelines $* exited $got, expected $code"
    grep -q -- "$text" "$work/err.txt" || fail "featurelines $*: message '$(cat "$work/err.txt")' lacks '$text'"
    [ "$(wc -l < "$work/err.txt")" -eq 1 ] || fail "featurelines $*: more than one line on stderr"
}

finish() {
    if [ "$failures" -ne 0 ]; then
        echo "$failures check(s) failed" >&2
        exit 1
    fi
    echo "all checks passed"
}
