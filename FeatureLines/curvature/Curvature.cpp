// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/support/IdleThreads.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <omp.h>

namespace featurelines {

namespace {

/// The quadric has six coefficients: at least five neighbours and the point itself.
constexpr int minimumNeighbours = 5;

/// The fit is degenerate (neighbours collinear, or all in too few directions to fix a
/// quadric) when a pivot of the normal equations' Cholesky factor is this small relative to
/// their largest diagonal entry. The coordinates are scaled to the unit disc, so this is a pure
/// rounding level.
constexpr double degeneratePivot = 1e-12;

/// Solves the normal equations M c = r of the quadric fit, M symmetric positive definite with
/// its upper triangle packed row by row in m (21 entries), by a Cholesky factorisation without
/// pivoting, unrolled for the fixed size (Eigen's LLT of a 6 x 6 matrix goes through two calls
/// and loops of run-time length: over a quarter of the fit's time in a profile of the 1M-point
/// cube). Returns false when the fit is degenerate: a squared pivot not above degeneratePivot
/// times the largest diagonal entry.
bool solveNormalEquations(const double (&m)[21], const double (&r)[6], double (&c)[6])
{
    double M[6][6]; // lower triangle
    double largest = 0.0;
    for (int a = 0, entry = 0; a < 6; ++a) {
        for (int b = a; b < 6; ++b) {
            M[b][a] = m[entry++];
        }
        largest = std::max(largest, M[a][a]);
    }
    const double smallest = degeneratePivot * largest;
    double L[6][6];
    double inverse[6]; // 1 / L[j][j]
    for (int j = 0; j < 6; ++j) {
        double pivot = M[j][j];
        for (int p = 0; p < j; ++p) {
            pivot -= L[j][p] * L[j][p];
        }
        if (!(pivot > smallest)) {
            return false;
        }
        L[j][j] = std::sqrt(pivot);
        inverse[j] = 1.0 / L[j][j];
        for (int i = j + 1; i < 6; ++i) {
            double sum = M[i][j];
            for (int p = 0; p < j; ++p) {
                sum -= L[i][p] * L[j][p];
            }
            L[i][j] = sum * inverse[j];
        }
    }
    double y[6];
    for (int i = 0; i < 6; ++i) {
        double sum = r[i];
        for (int p = 0; p < i; ++p) {
            sum -= L[i][p] * y[p];
        }
        y[i] = sum * inverse[i];
    }
    for (int i = 5; i >= 0; --i) {
        double sum = y[i];
        for (int p = i + 1; p < 6; ++p) {
            sum -= L[p][i] * c[p];
        }
        c[i] = sum * inverse[i];
    }
    return true;
}

/// A point's frame for the fit: the axes (u, v, n) of its tangent plane, each divided by the
/// neighbourhood's radius so that the coordinates come out in units of it (the normal
/// equations then mix terms of one magnitude, x^4 next to 1, whatever the unit of the cloud).
struct Frame
{
    bool valid = false;
    double scale = 0.0;
    double u[3], v[3], w[3];
};

Frame frameOf(const NormalMatrix& normals, const Neighbourhoods& N, Eigen::Index i, int k)
{
    Frame f;
    const Eigen::Vector3d normal = normals.row(i).transpose();
    const double length = normal.norm();
    const double radius = std::sqrt(N.squaredDistances(i, k - 1));
    if (!(length > 0.0) || !(radius > 0.0) || !std::isfinite(length)) {
        return f;
    }
    f.valid = true;
    f.scale = 1.0 / radius;
    const Eigen::Vector3d w = normal / length;
    const Eigen::Vector3d u0 = w.unitOrthogonal();
    const Eigen::Vector3d u = u0 * f.scale;
    const Eigen::Vector3d v = w.cross(u0) * f.scale;
    const Eigen::Vector3d ws = w * f.scale;
    for (int d = 0; d < 3; ++d) {
        f.u[d] = u(d);
        f.v[d] = v(d);
        f.w[d] = ws(d);
    }
    return f;
}

/// The sums of the normal equations A^T A c = A^T z of the rows (x^2, xy, y^2, x, y, 1); the
/// point itself is the row (0, 0, 0, 0, 0, 1) with z = 0. The 21 entries of the symmetric
/// A^T A are sums of the 15 monomials x^i y^j, i + j <= 4 (x^2 y^2 stands at two places),
/// summed by hand: s[0..4] degree 4 (x^4 .. y^4), s[5..8] degree 3, s[9..11] degree 2,
/// s[12..13] degree 1; r the right-hand side. T is a double, or a pair of them for two points
/// at once (the same operations, lane by lane).
template <class T> struct Sums
{
    T s[14] = {};
    T r[6] = {};

    void add(T dx, T dy, T dz, const T (&u)[3], const T (&v)[3], const T (&w)[3])
    {
        const T x = dx * u[0] + dy * u[1] + dz * u[2];
        const T y = dx * v[0] + dy * v[1] + dz * v[2];
        const T z = dx * w[0] + dy * w[1] + dz * w[2];
        const T xx = x * x, xy = x * y, yy = y * y;
        const T monomial[14] = {xx * xx, xx * xy, xx * yy, xy * yy, yy * yy, xx * x, xx * y,
                                x * yy,  yy * y,  xx,      xy,      yy,      x,      y};
        for (int t = 0; t < 14; ++t) {
            s[t] += monomial[t];
        }
        r[0] += z * xx;
        r[1] += z * xy;
        r[2] += z * yy;
        r[3] += z * x;
        r[4] += z * y;
        r[5] += z;
    }
};

/// The sums of point i's fit over its first k neighbours, in frame f.
Sums<double> sumsOf(const PointMatrix& P, const Neighbourhoods& N, Eigen::Index i, int k,
                    const Frame& f)
{
    Sums<double> sums;
    const double* o = P.row(i).data();
    const int* neighbours = N.indices.row(i).data();
    for (int j = 0; j < k; ++j) {
        const double* p = P.row(neighbours[j]).data();
        sums.add(p[0] - o[0], p[1] - o[1], p[2] - o[2], f.u, f.v, f.w);
    }
    return sums;
}

/// Two doubles in one SSE register where the processor has one (GCC and Clang vectors).
typedef double DoublePair __attribute__((vector_size(16)));

/// Solves the fit whose sums are s and r, over `rows` rows (the count is A^T A's last
/// diagonal entry, the sum of 1 * 1): the coefficients (a, b, c, d, e, f) of
/// z = a x^2 + b xy + c y^2 + d x + e y + f in the frame's units. False when degenerate.
bool solveQuadric(const double (&s)[14], const double (&r)[6], double rows, double (&c)[6])
{
    // Upper triangle of A^T A row by row, rows and columns (x^2, xy, y^2, x, y, 1).
    const double m[21] = {s[0],  s[1],  s[2],  s[5],  s[6],  s[9], //
                          s[2],  s[3],  s[6],  s[7],  s[10],       //
                          s[4],  s[7],  s[8],  s[11],              //
                          s[9],  s[10], s[12],                     //
                          s[11], s[13],                            //
                          rows};
    return solveNormalEquations(m, r, c);
}

/// The mean curvature from the sums of one point and its k neighbours (0 when the fit is
/// degenerate or not finite).
double curvatureFromSums(const double (&s)[14], const double (&r)[6], int k, double scale,
                         bool signedCurvature)
{
    double c[6];
    if (!solveQuadric(s, r, k + 1.0, c)) {
        return 0.0;
    }
    const double a = c[0], b = c[1], cc = c[2], d = c[3], e = c[4];
    // Mean curvature of the graph z(x, y) at the origin, gradient (d, e) included:
    // H = ((1 + e^2) z_xx - 2 d e z_xy + (1 + d^2) z_yy) / (2 (1 + d^2 + e^2)^(3/2)).
    const double g = 1.0 + d * d + e * e;
    const double graphH = ((1.0 + e * e) * 2.0 * a - 2.0 * d * e * b + (1.0 + d * d) * 2.0 * cc) /
                          (2.0 * g * std::sqrt(g));
    // Back to the cloud's unit (second derivatives scale with 1/radius). The graph bends
    // towards +n where graphH > 0; the signed convention is positive where the surface bends
    // away from the normal (an outward-oriented sphere has +1/r).
    const double signedH = -graphH * scale;
    const double value = signedCurvature ? signedH : std::abs(signedH);
    return std::isfinite(value) ? value : 0.0;
}

/// The neighbours in the fit: options.k, or all N.k() of them for 0.
int neighboursInFit(const CurvatureOptions& options, const Neighbourhoods& N)
{
    return options.k == 0 ? N.k() : options.k;
}

/// What each point's fit reads.
struct CurvatureFit
{
    const PointMatrix& P;
    const NormalMatrix& normals;
    const Neighbourhoods& N;
    /// Neighbours in the fit.
    int k;
    bool signedCurvature;
};

/// The mean curvature of point i in frame f (0 where the frame is not valid).
double curvatureOfOne(const CurvatureFit& fit, Eigen::Index i, const Frame& f)
{
    if (!f.valid) {
        return 0.0;
    }
    const Sums<double> sums = sumsOf(fit.P, fit.N, i, fit.k, f);
    return curvatureFromSums(sums.s, sums.r, fit.k, f.scale, fit.signedCurvature);
}

/// The mean curvature of points i and i + 1 in their valid frames f0 and f1, into H[0], H[1]:
/// the sums of both in the two lanes of a pair of doubles.
void curvatureOfPair(const CurvatureFit& fit, Eigen::Index i, const Frame& f0, const Frame& f1,
                     double* H)
{
    DoublePair u[3], v[3], w[3];
    for (int d = 0; d < 3; ++d) {
        u[d] = DoublePair{f0.u[d], f1.u[d]};
        v[d] = DoublePair{f0.v[d], f1.v[d]};
        w[d] = DoublePair{f0.w[d], f1.w[d]};
    }
    const PointMatrix& P = fit.P;
    Sums<DoublePair> sums;
    const double* o0 = P.row(i).data();
    const double* o1 = P.row(i + 1).data();
    const int* n0 = fit.N.indices.row(i).data();
    const int* n1 = fit.N.indices.row(i + 1).data();
    for (int j = 0; j < fit.k; ++j) {
        const double* p0 = P.row(n0[j]).data();
        const double* p1 = P.row(n1[j]).data();
        sums.add(DoublePair{p0[0] - o0[0], p1[0] - o1[0]}, DoublePair{p0[1] - o0[1], p1[1] - o1[1]},
                 DoublePair{p0[2] - o0[2], p1[2] - o1[2]}, u, v, w);
    }
    for (int lane = 0; lane < 2; ++lane) {
        double s[14], r[6];
        for (int t = 0; t < 14; ++t) {
            s[t] = sums.s[t][lane];
        }
        for (int t = 0; t < 6; ++t) {
            r[t] = sums.r[t][lane];
        }
        H[lane] =
            curvatureFromSums(s, r, fit.k, lane == 0 ? f0.scale : f1.scale, fit.signedCurvature);
    }
}

/// The quadric of point i over all N.k() neighbours in i's frame f, its coefficients into c:
/// with the point itself as a row of the fit (`withPoint`, as meanCurvature() fits) or without.
/// False when the normal, the neighbourhood or the fit is degenerate.
bool quadricOf(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
               Eigen::Index i, bool withPoint, Frame& f, double (&c)[6])
{
    const int k = N.k();
    f = frameOf(normals, N, i, k);
    if (!f.valid || k < minimumNeighbours) {
        return false;
    }
    const Sums<double> sums = sumsOf(P, N, i, k, f);
    return solveQuadric(sums.s, sums.r, withPoint ? k + 1.0 : k, c);
}

} // namespace

Eigen::VectorXd meanCurvature(const PointMatrix& P, const NormalMatrix& normals,
                              const Neighbourhoods& N, const CurvatureOptions& options,
                              const ProgressSpan& progress)
{
    if (N.size() != P.rows() || normals.rows() != P.rows()) {
        throw std::invalid_argument("mean curvature: points (" + std::to_string(P.rows()) +
                                    "), normals (" + std::to_string(normals.rows()) +
                                    ") and neighbourhoods (" + std::to_string(N.size()) +
                                    ") must describe the same cloud");
    }
    const int k = neighboursInFit(options, N);
    if (k < minimumNeighbours || k > N.k()) {
        throw std::invalid_argument(
            "mean curvature: the quadric fit needs between " + std::to_string(minimumNeighbours) +
            " and the " + std::to_string(N.k()) + " neighbours computed, not " + std::to_string(k));
    }

    const Eigen::Index n = P.rows();
    Eigen::VectorXd H(n);
    // Sec. 2.1: curv(p) from a quadric through the k nearest neighbours of p, here the height
    // function over p's tangent plane, origin at p, axes (u, v, n). Two points at a time.
    const CurvatureFit fit{P, normals, N, k, options.signedCurvature};
    const Eigen::Index pairs = n / 2;
    LoopProgress loop(progress, pairs);
#pragma omp parallel for schedule(static, 2048) num_threads(threadCount(options.threads))
    for (Eigen::Index pair = 0; pair < pairs; ++pair) {
        if (!loop.next(pair)) {
            continue;
        }
        const Eigen::Index i = 2 * pair;
        const Frame f0 = frameOf(normals, N, i, k), f1 = frameOf(normals, N, i + 1, k);
        if (!f0.valid || !f1.valid) {
            H(i) = curvatureOfOne(fit, i, f0);
            H(i + 1) = curvatureOfOne(fit, i + 1, f1);
            continue;
        }
        curvatureOfPair(fit, i, f0, f1, H.data() + i);
    }
    loop.finish();
    if (n % 2 == 1) {
        H(n - 1) = curvatureOfOne(fit, n - 1, frameOf(normals, N, n - 1, k));
    }
    return H;
}

double largestCurvature(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                        Eigen::Index i)
{
    Frame f;
    double c[6];
    if (!quadricOf(P, normals, N, i, true, f, c)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    // The shape operator of the graph z(x, y) at the origin: the first fundamental form I of
    // the gradient (d, e), the second II = Hessian / sqrt(1 + d^2 + e^2); its eigenvalues, those
    // of I^-1 II, are the principal curvatures.
    const double a = c[0], b = c[1], cc = c[2], d = c[3], e = c[4];
    const double g = 1.0 + d * d + e * e;
    Eigen::Matrix2d first, second;
    first << 1.0 + d * d, d * e, d * e, 1.0 + e * e;
    second << 2.0 * a, b, b, 2.0 * cc;
    second /= std::sqrt(g);
    const Eigen::Matrix2d shape = first.inverse() * second;
    // Real eigenvalues (I is positive definite, II symmetric): from the trace and determinant.
    const double mean = 0.5 * shape.trace();
    const double spread = std::sqrt(std::max(0.0, mean * mean - shape.determinant()));
    const double largest = (std::abs(mean) + spread) * f.scale;
    return std::isfinite(largest) ? largest : std::numeric_limits<double>::quiet_NaN();
}

double quadricHeight(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     Eigen::Index i)
{
    Frame f;
    double c[6];
    if (!quadricOf(P, normals, N, i, false, f, c)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return c[5] / f.scale;
}

} // namespace featurelines
