// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/Normals.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>
#include <omp.h>

#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

/// The PCA normal, surface variation and spread of point i over its first k neighbours
/// (variation and spread when given).
void fitNormal(const PointMatrix& P, const Neighbourhoods& N, Eigen::Index i, int k,
               NormalMatrix& normals, Eigen::VectorXd* variation, Eigen::VectorXd* spread)
{
    // Moments relative to the point itself: the covariance of a small neighbourhood far
    // from the origin would otherwise lose its digits to cancellation. The six products
    // are summed by hand: Eigen's rankUpdate is not inlined and took a third of the time.
    const double ox = P(i, 0), oy = P(i, 1), oz = P(i, 2);
    double sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
    const int* neighbours = N.indices.row(i).data();
    for (int j = 0; j < k; ++j) {
        const double* q = P.row(neighbours[j]).data();
        const double x = q[0] - ox, y = q[1] - oy, z = q[2] - oz;
        sx += x;
        sy += y;
        sz += z;
        sxx += x * x;
        sxy += x * y;
        sxz += x * z;
        syy += y * y;
        syz += y * z;
        szz += z * z;
    }
    // The point itself adds a zero row to the sums but counts in the mean.
    const double count = k + 1;
    const double mx = sx / count, my = sy / count, mz = sz / count;
    Eigen::Matrix3d covariance;
    covariance(0, 0) = sxx / count - mx * mx;
    covariance(1, 0) = sxy / count - mx * my;
    covariance(2, 0) = sxz / count - mx * mz;
    covariance(1, 1) = syy / count - my * my;
    covariance(2, 1) = syz / count - my * mz;
    covariance(2, 2) = szz / count - mz * mz;

    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance, Eigen::ComputeEigenvectors);
    const Eigen::Vector3d lambda = solver.eigenvalues().cwiseMax(0.0); // ascending
    const double total = lambda.sum();
    Eigen::Vector3d normal = solver.eigenvectors().col(0);
    if (!(total > 0.0) || !normal.allFinite()) {
        // Every neighbour coincides with the point: no plane to speak of.
        normals.row(i) = Eigen::RowVector3d::UnitZ();
        if (variation) {
            (*variation)(i) = 0.0;
            (*spread)(i) = 0.0;
        }
        return;
    }
    // A deterministic sign (orientation is not needed downstream): the component of
    // largest magnitude is made positive.
    Eigen::Index largest = 0;
    normal.cwiseAbs().maxCoeff(&largest);
    if (normal(largest) < 0.0) {
        normal = -normal;
    }
    normals.row(i) = normal.normalized().transpose();
    if (variation) {
        (*variation)(i) = lambda(0) / total;
        (*spread)(i) = lambda(1) / lambda(2);
    }
}

int neighbourCount(const PointMatrix& P, const Neighbourhoods& N, const NormalOptions& options)
{
    if (N.size() != P.rows()) {
        throw std::invalid_argument(
            "normals: the neighbourhoods were computed for another cloud (" +
            std::to_string(N.size()) + " rows for " + std::to_string(P.rows()) + " points)");
    }
    const int k = options.k == 0 ? N.k() : options.k;
    if (k < 2 || k > N.k()) {
        throw std::invalid_argument("normals: the neighbour count must be between 2 and the " +
                                    std::to_string(N.k()) + " neighbours computed, not " +
                                    std::to_string(k));
    }
    return k;
}

} // namespace

NormalEstimate pcaNormals(const PointMatrix& P, const Neighbourhoods& N,
                          const NormalOptions& options, const ProgressSpan& progress)
{
    const int k = neighbourCount(P, N, options);
    const Eigen::Index n = P.rows();
    NormalEstimate result;
    result.normals.resize(n, 3);
    result.variation.resize(n);
    result.spread.resize(n);
    adviseHugePagesOf(result.normals);
    LoopProgress loop(progress, n);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        if (loop.next(i)) {
            fitNormal(P, N, i, k, result.normals, &result.variation, &result.spread);
        }
    }
    loop.finish();
    return result;
}

void pcaNormalsOfRows(const PointMatrix& P, const Neighbourhoods& N, const std::vector<int>& rows,
                      NormalMatrix& normals, const NormalOptions& options)
{
    const int k = neighbourCount(P, N, options);
    if (normals.rows() != P.rows()) {
        throw std::invalid_argument("normals: " + std::to_string(normals.rows()) +
                                    " normals given for " + std::to_string(P.rows()) + " points");
    }
    for (int i : rows) {
        if (i < 0 || i >= P.rows()) {
            throw std::invalid_argument("normals: point index " + std::to_string(i) +
                                        " is outside the cloud");
        }
    }
#pragma omp parallel for schedule(static, 1024) num_threads(threadCount(options.threads))
    for (long r = 0; r < static_cast<long>(rows.size()); ++r) {
        fitNormal(P, N, rows[static_cast<size_t>(r)], k, normals, nullptr, nullptr);
    }
}

Moments momentsOf(const PointMatrix& P, Eigen::Index stride)
{
    if (P.rows() == 0 || stride < 1) {
        throw std::invalid_argument("moments of a cloud: need a point and a stride of at least 1");
    }
    const Eigen::Index samples = (P.rows() + stride - 1) / stride;
    constexpr Eigen::Index block = 16384;
    const Eigen::Index blocks = (samples + block - 1) / block;
    const Eigen::RowVector3d origin = P.row(0);
    std::vector<Eigen::Matrix<double, 3, 4>> sums(static_cast<size_t>(blocks));
#pragma omp parallel for schedule(static, 1)
    for (Eigen::Index b = 0; b < blocks; ++b) {
        Eigen::Matrix<double, 3, 4> s = Eigen::Matrix<double, 3, 4>::Zero();
        for (Eigen::Index j = b * block; j < std::min(samples, (b + 1) * block); ++j) {
            const Eigen::Vector3d d = (P.row(j * stride) - origin).transpose();
            s.leftCols<3>() += d * d.transpose();
            s.col(3) += d;
        }
        sums[static_cast<size_t>(b)] = s;
    }
    Eigen::Matrix<double, 3, 4> total = Eigen::Matrix<double, 3, 4>::Zero();
    for (const auto& s : sums) {
        total += s;
    }
    const Eigen::Vector3d shift = total.col(3) / static_cast<double>(samples);
    return {origin + shift.transpose(),
            total.leftCols<3>() / static_cast<double>(samples) - shift * shift.transpose()};
}

Eigen::Matrix3d covarianceOf(const PointMatrix& P, Eigen::Index stride)
{
    return momentsOf(P, stride).covariance;
}

} // namespace featurelines
