// SPDX-License-Identifier: LGPL-2.1-or-later
// k nearest neighbours of every point, and the cloud's point spacing (Sec. 2.1).
// Design: docs/design/neighbourhoods.md.
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

/// How the neighbourhoods are kept to one sheet of a thin wall (SheetNeighbourhoods.h).
struct SheetOptions
{
    /// Keep each neighbourhood to its point's own sheet (default true).
    bool separate = true;
    /// Points of the local plane fit: the point and its nearest this many, at most 31 (default 8).
    int fitPoints = 8;
    /// The least gap along the normal between two sheets, x the sampling spacing (1; merged
    /// views misregistered by up to half a spacing each are one sheet).
    double minGap = 1.0;
    /// The gap is at least this many times the local fit's RMS residual, so that noise across
    /// one sheet is not read as a second one (3).
    double noiseGap = 3.0;
    /// The offsets along a sheet's direction of a point and its neighbours fall in two groups
    /// (two sheets) only when the groups' means lie at least this far apart, x the sampling
    /// spacing (1.25: a wall of 1.5 spacings is split, misregistered merged views of up to a
    /// spacing are not).
    double minWall = 1.25;
    /// Two sheets' planes turn by at most this, degrees (25).
    double maxTurnDegrees = 25.0;
    /// A neighbourhood reaches another sheet when at least this many of its points lie across
    /// the gap, all on one side (1).
    int minAcross = 1;
};

struct NeighbourOptions
{
    /// Neighbours per point, the point itself not counted; at least 3, below #P (default 16).
    int k = 16;
    /// Worker threads for the queries, 0 for OpenMP's default (default 0).
    int threads = 0;
    /// Neighbours across a thin wall are exchanged for points of the own sheet
    /// (analyseCloud; nearestNeighbours itself ignores it).
    SheetOptions sheets;
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
/// `progress` is told as the queries go. Throws std::invalid_argument when P has no more than k
/// points or options.k < 3.
Neighbourhoods nearestNeighbours(const PointMatrix& P, const NeighbourOptions& options = {},
                                 const ProgressSpan& progress = {});

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
