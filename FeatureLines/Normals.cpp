// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/Normals.h"

#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <omp.h>

namespace featurelines {

namespace {

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

} // namespace

NormalEstimate pcaNormals(const PointMatrix& P, const Neighbourhoods& N,
                          const NormalOptions& options)
{
    if (N.size() != P.rows()) {
        throw std::invalid_argument("normals: the neighbourhoods were computed for another cloud (" +
                                    std::to_string(N.size()) + " rows for " +
                                    std::to_string(P.rows()) + " points)");
    }
    const int k = options.k == 0 ? N.k() : options.k;
    if (k < 2 || k > N.k()) {
        throw std::invalid_argument("normals: the neighbour count must be between 2 and the " +
                                    std::to_string(N.k()) + " neighbours computed, not " +
                                    std::to_string(k));
    }

    const Eigen::Index n = P.rows();
    NormalEstimate result;
    result.normals.resize(n, 3);
    result.variation.resize(n);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        // Moments relative to the point itself: the covariance of a small neighbourhood far
        // from the origin would otherwise lose its digits to cancellation.
        const Eigen::RowVector3d origin = P.row(i);
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d products = Eigen::Matrix3d::Zero();
        for (int j = 0; j < k; ++j) {
            const Eigen::Vector3d q = (P.row(N.indices(i, j)) - origin).transpose();
            sum += q;
            products.selfadjointView<Eigen::Lower>().rankUpdate(q);
        }
        // The point itself adds a zero row to both sums but counts in the mean.
        const double count = k + 1;
        const Eigen::Vector3d mean = sum / count;
        Eigen::Matrix3d covariance = products / count;
        covariance.selfadjointView<Eigen::Lower>().rankUpdate(mean, -1.0);

        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
        solver.computeDirect(covariance, Eigen::ComputeEigenvectors);
        const Eigen::Vector3d lambda = solver.eigenvalues().cwiseMax(0.0); // ascending
        const double total = lambda.sum();
        Eigen::Vector3d normal = solver.eigenvectors().col(0);
        if (!(total > 0.0) || !normal.allFinite()) {
            // Every neighbour coincides with the point: no plane to speak of.
            result.normals.row(i) = Eigen::RowVector3d::UnitZ();
            result.variation(i) = 0.0;
            continue;
        }
        // A deterministic sign (orientation is not needed downstream): the component of
        // largest magnitude is made positive.
        Eigen::Index largest = 0;
        normal.cwiseAbs().maxCoeff(&largest);
        if (normal(largest) < 0.0) {
            normal = -normal;
        }
        result.normals.row(i) = normal.normalized().transpose();
        result.variation(i) = lambda(0) / total;
    }
    return result;
}

} // namespace featurelines
