// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/Curvature.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <omp.h>

namespace featurelines {

namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// The quadric has six coefficients: at least five neighbours and the point itself.
constexpr int minimumNeighbours = 5;

/// The fit is degenerate (neighbours collinear, or all in too few directions to fix a
/// quadric) when a pivot of the normal equations' Cholesky factor is this small relative to
/// their largest diagonal entry. The coordinates are scaled to the unit disc, so this is a pure
/// rounding level.
constexpr double degeneratePivot = 1e-12;

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

} // namespace

Eigen::VectorXd meanCurvature(const PointMatrix& P, const NormalMatrix& normals,
                              const Neighbourhoods& N, const CurvatureOptions& options)
{
    if (N.size() != P.rows() || normals.rows() != P.rows()) {
        throw std::invalid_argument("mean curvature: points (" + std::to_string(P.rows()) +
                                    "), normals (" + std::to_string(normals.rows()) +
                                    ") and neighbourhoods (" + std::to_string(N.size()) +
                                    ") must describe the same cloud");
    }
    const int k = options.k == 0 ? N.k() : options.k;
    if (k < minimumNeighbours || k > N.k()) {
        throw std::invalid_argument(
            "mean curvature: the quadric fit needs between " + std::to_string(minimumNeighbours) +
            " and the " + std::to_string(N.k()) + " neighbours computed, not " + std::to_string(k));
    }

    const Eigen::Index n = P.rows();
    Eigen::VectorXd H(n);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        // Sec. 2.1: curv(p) from a quadric through the k nearest neighbours of p, here the
        // height function over p's tangent plane, origin at p, axes (u, v, n).
        const Eigen::Vector3d normal = normals.row(i).transpose();
        const double length = normal.norm();
        // Coordinates are divided by the neighbourhood radius so that the normal equations mix
        // terms of one magnitude (x^4 next to 1) whatever the unit of the cloud.
        const double radius = std::sqrt(N.squaredDistances(i, k - 1));
        if (!(length > 0.0) || !(radius > 0.0) || !std::isfinite(length)) {
            H(i) = 0.0;
            continue;
        }
        const Eigen::Vector3d w = normal / length;
        const Eigen::Vector3d u = w.unitOrthogonal();
        const Eigen::Vector3d v = w.cross(u);
        const double scale = 1.0 / radius;

        // Normal equations A^T A c = A^T z of the rows (x^2, xy, y^2, x, y, 1); the point
        // itself is the row (0, 0, 0, 0, 0, 1) with z = 0. The 21 distinct products of the
        // symmetric A^T A are summed by hand (Eigen's rankUpdate is not inlined).
        double m[21] = {};
        double r[6] = {};
        m[20] = 1.0;
        const double* o = P.row(i).data();
        const int* neighbours = N.indices.row(i).data();
        for (int j = 0; j < k; ++j) {
            const double* p = P.row(neighbours[j]).data();
            const double dx = (p[0] - o[0]) * scale, dy = (p[1] - o[1]) * scale,
                         dz = (p[2] - o[2]) * scale;
            const double x = dx * u(0) + dy * u(1) + dz * u(2);
            const double y = dx * v(0) + dy * v(1) + dz * v(2);
            const double z = dx * w(0) + dy * w(1) + dz * w(2);
            const double row[6] = {x * x, x * y, y * y, x, y, 1.0};
            int entry = 0;
            for (int a = 0; a < 6; ++a) {
                r[a] += z * row[a];
                for (int b = a; b < 6; ++b) {
                    m[entry++] += row[a] * row[b];
                }
            }
        }
        Matrix6d AtA;
        Vector6d Atz;
        for (int a = 0, entry = 0; a < 6; ++a) {
            Atz(a) = r[a];
            for (int b = a; b < 6; ++b) {
                AtA(b, a) = m[entry++]; // lower triangle, all the solver reads
            }
        }
        // Cholesky without pivoting: A^T A is positive definite unless the fit is degenerate,
        // which shows as a vanishing pivot.
        const Eigen::LLT<Matrix6d, Eigen::Lower> llt(AtA);
        const Vector6d pivots = llt.matrixLLT().diagonal().cwiseAbs2();
        if (llt.info() != Eigen::Success ||
            !(pivots.minCoeff() > degeneratePivot * AtA.diagonal().maxCoeff())) {
            H(i) = 0.0;
            continue;
        }
        const Vector6d c = llt.solve(Atz);
        const double a = c(0), b = c(1), cc = c(2), d = c(3), e = c(4);
        // Mean curvature of the graph z(x, y) at the origin, gradient (d, e) included:
        // H = ((1 + e^2) z_xx - 2 d e z_xy + (1 + d^2) z_yy) / (2 (1 + d^2 + e^2)^(3/2)).
        const double g = 1.0 + d * d + e * e;
        const double graphH =
            ((1.0 + e * e) * 2.0 * a - 2.0 * d * e * b + (1.0 + d * d) * 2.0 * cc) /
            (2.0 * g * std::sqrt(g));
        // Back to the cloud's unit (second derivatives scale with 1/radius). The graph bends
        // towards +n where graphH > 0; the signed convention is positive where the surface
        // bends away from the normal (an outward-oriented sphere has +1/r).
        const double signedH = -graphH * scale;
        const double value = options.signedCurvature ? signedH : std::abs(signedH);
        H(i) = std::isfinite(value) ? value : 0.0;
    }
    return H;
}

} // namespace featurelines
