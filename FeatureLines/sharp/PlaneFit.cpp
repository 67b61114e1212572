// SPDX-License-Identifier: LGPL-2.1-or-later
// Planes fitted to the points of one face, and where two of them meet.
#include "FeatureLines/sharp/PlaneFit.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace featurelines {

Plane fitPlane(const std::vector<Eigen::Vector3d>& points, int minPoints)
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
        return Plane{normal, normal.dot(mean)};
    };
    std::vector<const Eigen::Vector3d*> use;
    for (const auto& p : points) {
        use.push_back(&p);
    }
    Plane plane = fit(use);
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
        plane = fit(kept);
    }
    return plane;
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
