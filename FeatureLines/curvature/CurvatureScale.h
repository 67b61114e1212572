// SPDX-License-Identifier: LGPL-2.1-or-later
// A smooth region's curvature at a coarser scale than the cloud's sampling (beyond the 2008
// paper). The quadric fit of Sec. 2.1 over k neighbours turns noise of n spacings into a
// curvature spread proportional to n / spacing, while a fillet of radius r has |H| = 1 / (2 r):
// the denser a noisy scan, the more fillet radii lie below the noise (a 6 mm fillet scanned at
// 0.16 mm with noise of 0.05 mm shows 3 noise floors above a flat face, too few to part the
// levels). Averaged onto a grid of cells s spacings wide, the same points carry 1 / s of the
// noise at s times the spacing, so the spread falls as 1 / s^3 while the fillet keeps its
// curvature, as long as it spans a few cells.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

struct CurvatureScaleOptions
{
    /// Coarsest scale tried (x spacing): the scales are 1, 2, 4, ... up to this. 1 computes
    /// the curvature at the cloud's own sampling only, as the paper does.
    double maxScale = 8.0;
    /// A coarser scale is tried only while the region averages into at least this many cells:
    /// its histogram and its patches (SmoothEdgeOptions::automatic) need a few thousand values.
    int minPoints = 2000;
    /// x the coarse spacing: how far from the rim of a coarse region its curvature is taken
    /// from the region's interior instead of the one-sided fits there (the bias of the fit
    /// and of the smoothing at a rim reaches about three spacings in).
    double rimWidth = 4.0;
    /// Width of the Gaussian that carries the coarse curvature back to the points, x the
    /// coarse sampling's spacing: wide enough that the values vary smoothly from cell to cell
    /// (a threshold then crosses between points, not on the grid), narrow against the fit.
    double carryWidth = 0.5;
    /// x the region's noise estimate (RegionGeometry::noise, spacings): a region whose points,
    /// all but a thousandth, lie this close to one plane (planeDeviation) is a face; it has
    /// no curvature level above noise to find at any scale, and no coarser scale is tried.
    /// 0 tries them on faces too.
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
