// SPDX-License-Identifier: LGPL-2.1-or-later
// Planes fitted to the points of one face, and where two of them meet.
#include "FeatureLines/sharp/PlaneFit.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

/// The positions' plane is kept where noise tilts it by less than this (degrees).
constexpr double agreeDegrees = 3.0;

/// fitPlane's plane, and the eigenvalues (increasing) of the covariance of the points it was
/// last fitted to.
struct TrimmedFit
{
    Plane plane;
    Eigen::Vector3d eigenvalues;
};

TrimmedFit trimmedFit(const std::vector<Eigen::Vector3d>& points, int minPoints)
{
    auto fit = [](const std::vector<const Eigen::Vector3d*>& use) {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (const auto* p : use) {
            mean += *p;
        }
        mean /= static_cast<double>(use.size());
        Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
        for (const auto* p : use) {
            const Eigen::Vector3d d = *p - mean;
            covariance += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(covariance);
        const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
        return TrimmedFit{Plane{normal, normal.dot(mean)}, solver.eigenvalues()};
    };
    std::vector<const Eigen::Vector3d*> use;
    for (const auto& p : points) {
        use.push_back(&p);
    }
    TrimmedFit result = fit(use);
    const Plane& plane = result.plane;
    double sum = 0.0;
    for (const auto* p : use) {
        sum += std::pow(plane.normal.dot(*p) - plane.offset, 2);
    }
    const double limit = 2.5 * std::sqrt(sum / static_cast<double>(use.size()));
    std::vector<const Eigen::Vector3d*> kept;
    for (const auto* p : use) {
        if (std::abs(plane.normal.dot(*p) - plane.offset) <= limit) {
            kept.push_back(p);
        }
    }
    if (static_cast<int>(kept.size()) >= minPoints && kept.size() < use.size()) {
        result = fit(kept);
    }
    return result;
}

} // namespace

Plane fitPlane(const std::vector<Eigen::Vector3d>& points, int minPoints)
{
    return trimmedFit(points, minPoints).plane;
}

namespace {

/// The normals' plane of fitPlaneByNormals.
Plane planeOfNormals(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<Eigen::Vector3d>& normals, int minPoints,
                     double maxTurnDegrees)
{
    // The dominant direction of the normals `use`, each n n^T divided by its entry of
    // `divisors` (1 when there is none).
    const auto dominant = [&](const std::vector<std::size_t>& use,
                              const std::vector<double>& divisors = {}) {
        Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
        for (std::size_t j = 0; j < use.size(); ++j) {
            const Eigen::Vector3d& n = normals[use[j]];
            sum += divisors.empty() ? Eigen::Matrix3d(n * n.transpose())
                                    : Eigen::Matrix3d(n * n.transpose() / divisors[j]);
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(sum);
        return Eigen::Vector3d(solver.eigenvectors().col(2).normalized());
    };
    std::vector<std::size_t> all(points.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = i;
    }
    const double cosine = std::cos(maxTurnDegrees * pi / 180.0);
    Eigen::Vector3d normal = dominant(all);
    std::vector<std::size_t> kept;
    for (int pass = 0; pass < 2; ++pass) {
        kept.clear();
        for (std::size_t i : all) {
            if (std::abs(normals[i].dot(normal)) >= cosine) {
                kept.push_back(i);
            }
        }
        if (static_cast<int>(kept.size()) < minPoints) {
            return fitPlane(points, minPoints);
        }
        normal = dominant(kept);
    }
    // Reweighted by the turn from the face's direction, in units of the median turn: the
    // normals near the edge, blended with the other face's over their neighbourhoods, all lean
    // one way, while noise scatters the others evenly.
    for (int pass = 0; pass < 6; ++pass) {
        std::vector<double> turns;
        for (std::size_t i : kept) {
            turns.push_back(std::acos(std::min(1.0, std::abs(normals[i].dot(normal)))));
        }
        std::vector<double> sorted = turns;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                         sorted.end());
        const double scale = 2.0 * sorted[sorted.size() / 2] + 1e-4;
        std::vector<double> divisors;
        for (double turn : turns) {
            const double u = turn / scale;
            divisors.push_back(1.0 + u * u);
        }
        normal = dominant(kept, divisors);
    }
    std::vector<double> offsets;
    offsets.reserve(kept.size());
    for (std::size_t i : kept) {
        offsets.push_back(normal.dot(points[i]));
    }
    std::nth_element(offsets.begin(), offsets.begin() + static_cast<long>(offsets.size() / 2),
                     offsets.end());
    return Plane{normal, offsets[offsets.size() / 2]};
}

} // namespace

Plane fitPlaneByNormals(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<Eigen::Vector3d>& normals, int minPoints,
                        double maxTurnDegrees)
{
    // Where the positions lie on their plane far closer than they spread across it, their own
    // plane is the better one (exact on a clean face, where the normals near the edge still
    // lean a little); noise across a narrow strip tilts it far beyond the normals' plane.
    // The tilt is the ratio of the points' RMS distance to their plane over their spread along
    // its smaller in-plane axis, over the points fitPlane keeps (not the points of another face
    // the segmentation gave to this one).
    const TrimmedFit positions = trimmedFit(points, minPoints);
    const Eigen::Vector3d values = positions.eigenvalues.cwiseMax(0.0);
    const double tilt = values(1) > 0.0 ? std::sqrt(values(0) / values(1)) : 1.0;
    if (points.empty() || normals.size() != points.size() ||
        tilt < std::tan(agreeDegrees * pi / 180.0)) {
        return positions.plane;
    }
    return planeOfNormals(points, normals, minPoints, maxTurnDegrees);
}

Eigen::Vector3d closestOnIntersection(const Plane& a, const Plane& b, const Eigen::Vector3d& c)
{
    Eigen::Matrix2d gram;
    gram << 1.0, a.normal.dot(b.normal), a.normal.dot(b.normal), 1.0;
    const Eigen::Vector2d rhs(a.offset - a.normal.dot(c), b.offset - b.normal.dot(c));
    const Eigen::Vector2d w = gram.inverse() * rhs;
    return c + w(0) * a.normal + w(1) * b.normal;
}

} // namespace featurelines
