// SPDX-License-Identifier: LGPL-2.1-or-later
// First-order segmentation (Demarsin et al. 2007): region growing on the normals. Flat and
// smoothly curved areas become large clusters; where the estimated normals turn quickly, near a
// sharp edge, the growing stops and the points left over form small clusters: the candidate
// feature points.
#pragma once

#include <vector>

#include "FeatureLines/Neighbours.h"

namespace featurelines {

/// The paper states region growing on normal variation; the criterion, its thresholds and
/// the meaning of "small" are designed here (see each option).
struct FirstOrderSegmentationOptions
{
    /// Degrees. A point grows its cluster only when the normals of all its k neighbours lie
    /// within this angle of its own normal (its "normal spread"); other points can join a
    /// cluster but not extend it, as PCL's region growing gates growth by curvature.
    /// Why 30: PCA normals over k = 16 neighbours (a ball of radius R ~ 2.7 spacings) blur a
    /// crease over about 2R, so across a crease turning the normal by a the spread reaches
    /// ~0.6 a: ~55 degrees at a 90 degree edge, ~30 at a 45 degree one. On a fillet of radius
    /// r the normal turns by R / r radians across the ball: 25 degrees at r = 6 spacings, 18 at
    /// r = 9; noise of 0.3 spacing along the normal adds ~10. 30 keeps fillets of radius >= 6
    /// spacings and noisy planes growing and stops at creases turning by about 60 degrees or
    /// more (edges between faces meeting at 120 degrees or less).
    double growAngle = 30.0;
    /// Degrees. A neighbour joins the cluster of a growing point when their normals differ by
    /// less than this. Half the spread limit: the points on a crease, whose normals lie half
    /// way between those of the two faces, join neither face.
    double joinAngle = 15.0;
    /// A cluster is large (a surface patch) when at least this many of its points have all
    /// their k neighbours inside it; otherwise it is small and its points are candidates.
    /// Counting whole neighbourhoods rather than points is the design's reading of "small":
    /// a thin chain of points with similar normals running along a crease can hold many
    /// points, yet none of them is surrounded by its own cluster.
    int minInteriorPoints = 1;
    /// Worker threads (0: OpenMP's default).
    int threads = 0;
};

struct FirstOrderSegmentation
{
    /// #P cluster id of every point, 0 .. #C-1, numbered in the order of their first point.
    std::vector<int> cluster;
    /// #C points per cluster.
    std::vector<int> clusterSize;
    /// #C nonzero for small clusters, whose points are the candidate feature points.
    std::vector<char> smallCluster;
    /// #P normal spread of every point in degrees: the largest angle between its normal and
    /// those of its k neighbours (normals are unoriented, so at most 90).
    Eigen::VectorXd spread;

    int clusterCount() const { return static_cast<int>(clusterSize.size()); }
    bool isCandidate(Eigen::Index i) const { return smallCluster[cluster[i]] != 0; }
};

/// Segments a cloud by region growing on its (unoriented) normals.
///   normals  #P by 3 unit normals, e.g. from pcaNormals()
///   N        the k nearest neighbours the normals were estimated on
/// Every point ends in exactly one cluster; the result does not depend on the point order
/// beyond cluster numbering. Throws std::invalid_argument when the sizes disagree, a normal
/// is not finite or the angles are not in (0, 90].
FirstOrderSegmentation segmentByNormals(const NormalMatrix& normals, const Neighbourhoods& N,
                                        const FirstOrderSegmentationOptions& options = {});

} // namespace featurelines
