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

# fail MESSAGE: report a failed check (the script goes on, and exits 1 at the end).
failures=0
fail() {
    echo "FAILED: $*" >&2
    failures=$((failures + 1))
}

finish() {
    if [ "$failures" -ne 0 ]; then
        echo "$failures check(s) failed" >&2
        exit 1
    fi
    echo "all checks passed"
}
