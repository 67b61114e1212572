// SPDX-License-Identifier: LGPL-2.1-or-later
// A smooth region's curvature at a coarser scale than the cloud's sampling, where noise hides
// its fillets (beyond the paper): the points averaged onto a grid and the values carried back.
// Design: docs/design/curvature.md, "Curvature scale".
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

struct CurvatureScaleOptions
{
    /// Coarsest scale tried, x spacing: the scales are 1, 2, 4, ... up to this; 1: the cloud's
    /// own sampling only, as the paper. Default 8.
    double maxScale = 8.0;
    /// A coarser scale is tried only while the region averages into at least this many cells.
    /// Default 2000.
    int minPoints = 2000;
    /// Width of a coarse region's rim whose curvature is taken from its interior, x the coarse
    /// spacing. Default 4.
    double rimWidth = 4.0;
    /// Standard deviation of the Gaussian carrying the coarse curvature back to the points, x
    /// the coarse spacing. Default 0.5.
    double carryWidth = 0.5;
    /// A region within this distance of one plane (all but a thousandth of its points; x the
    /// region's noise estimate, RegionGeometry::noise) is a face and tries no coarser scale;
    /// 0: faces try them too. Default 6.
    double planeTolerance = 6.0;
};

struct GridCentroids
{
    /// C  #C by 3 centroids of the points in each occupied cell, in the cells' Morton order
    /// (neighbouring cells mostly lie close in memory).
    PointMatrix points;
    /// #P: per point of the input, the row of its cell's centroid.
    std::vector<int> cellOf;
};

/// Each point of P as (Morton key of its cell in the grid of cubes `cell` wide whose corner is
/// `low`, point index), sorted by key and a cell's points by index. The caller checks that the
/// points lie at or above `low` and within 2^21 cells of it along every axis.
std::vector<std::pair<std::uint64_t, int>> gridCellKeys(const PointMatrix& P,
                                                        const Eigen::RowVector3d& low, double cell);

/// Averages the points of P onto a cubic grid of cells `cell` wide (length unit): one centroid
/// per occupied cell. Throws std::invalid_argument when cell is not positive or P is empty, or
/// when the cloud spans more than 2^21 cells along an axis.
GridCentroids gridCentroids(const PointMatrix& P, double cell);

/// How far the points of P lie from their least-squares plane: the distance that all but a
/// `share` of them (0 <= share < 1) stay within. Throws std::invalid_argument for fewer than 3
/// points or a share outside [0, 1).
double planeDeviation(const PointMatrix& P, double share);

/// Values given at the centroids carried back to the points they average: per point p of P,
/// the mean of the values at its cell's centroid and that centroid's neighbours in N (the
/// centroids' own neighbourhoods), weighted by a Gaussian of the distance from p with
/// standard deviation `width` (length unit).
Eigen::VectorXd valuesAtPoints(const PointMatrix& P, const GridCentroids& grid,
                               const Neighbourhoods& N, const Eigen::VectorXd& values,
                               double width);

} // namespace featurelines
