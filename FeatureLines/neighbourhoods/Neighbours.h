// SPDX-License-Identifier: LGPL-2.1-or-later
// k nearest neighbours of every point, and the cloud's point spacing (Sec. 2.1).
// Design: docs/design/neighbourhoods.md.
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines {

struct NeighbourOptions
{
    /// Neighbours per point, the point itself not counted; at least 3, below #P (default 16).
    int k = 16;
    /// Worker threads for the queries, 0 for OpenMP's default (default 0).
    int threads = 0;
};

struct Neighbourhoods
{
    /// I  #P by k indices of the k nearest other points of each point, nearest first.
    IndexMatrix indices;
    /// D  #P by k squared Euclidean distances, matching `indices`.
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> squaredDistances;

    int k() const { return static_cast<int>(indices.cols()); }
    /// Sizes both arrays for `rows` points of k neighbours each, uninitialised, on huge pages
    /// where the system gives them (HugePages.h).
    void allocate(Eigen::Index rows, int k);
    Eigen::Index size() const { return indices.rows(); }
};

/// The k nearest other points of every point of P: an exact search over the cells of the
/// points' Morton order (MortonOrder.h), on P itself when it comes in that order (as
/// analyseCloud's points do), else on a sorted copy.
/// Throws std::invalid_argument when P has no more than k points or options.k < 3.
Neighbourhoods nearestNeighbours(const PointMatrix& P, const NeighbourOptions& options = {});

/// Mean distance from each point to its nearest neighbour at a distance above zero (exact
/// duplicates are not spacing). Every default length of the library is a multiple of it.
/// Throws std::invalid_argument when every point coincides with its neighbours.
double meanSpacing(const Neighbourhoods& neighbourhoods);

/// The sampling's spacing: the mean nearest spacing, raised where the cloud is sparser than
/// its nearest spacings say. An even (Poisson disk) sampling has its points about 0.8 of the
/// square root of the area per point apart; a random one, or scan lines finer along a row than
/// across, has nearest neighbours much closer than that (0.5-0.6), although its gaps are as
/// wide. The area per point is measured by the median radius r of the k-neighbourhoods
/// (k points in pi r^2), so the result is max(meanSpacing, 0.8 sqrt(pi r^2 / k)).
/// Throws std::invalid_argument when every point coincides with its neighbours.
double samplingSpacing(const Neighbourhoods& neighbourhoods);

} // namespace featurelines
