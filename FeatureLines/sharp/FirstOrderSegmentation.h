// SPDX-License-Identifier: LGPL-2.1-or-later
// First-order segmentation (Demarsin 2007): region growing on the normals; the points of the
// small clusters are the candidate feature points.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

/// Design note: docs/design/sharp-edges.md, "First-order segmentation" (Demarsin 2007).
struct FirstOrderSegmentationOptions
{
    /// Degrees: the largest spread limit; beyond the limit a point may stop the growing (20).
    double growAngle = 20.0;
    /// The spread limit: this many times the cloud's median spread, in [joinAngle, growAngle] (2).
    double noiseSpreadFactor = 2.0;
    /// Spreads beyond this many times the median spread are not noise's (1.6).
    double noiseSpreadTail = 1.6;
    /// Degrees: a neighbour joins a growing point's cluster when their normals differ less (10).
    double joinAngle = 10.0;
    /// Spacings: blends of this radius or more are too flat to stop the growing (6).
    double minFilletRadius = 6.0;
    /// Noise deviations of surface variation a point's planarity excess must also exceed (1).
    double noiseMargin = 1.0;
    /// Neighbours of the planarity excess's fine scale; 0: the k neighbours only (8).
    int fineNeighbours = 8;
    /// Degrees: faces meeting at less than this keep the points between them as candidates;
    /// 0: off (60).
    double shallowCreaseAngle = 60.0;
    /// Flat points a face's plane is fitted to for shallowCreaseAngle, at least 3 (3).
    int minFacePoints = 3;
    /// Spacings: for shallowCreaseAngle the point lies this close to one of the two planes (1).
    double creasePlaneTolerance = 1.0;
    /// Spacings: ... and this close to the line where the two planes meet (2.5).
    double creaseLineReach = 2.5;
    /// A cluster with fewer points whose k neighbours all lie inside it is small (1).
    int minInteriorPoints = 1;
    /// Worker threads; 0: OpenMP's default (0).
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
    /// #P face of every flat point (spread within noiseSpreadTail, shallowCreaseAngle): the
    /// groups of flat points joined within joinAngle, of more than k points, each numbered by
    /// its lowest point; -1 for the other points and when the rule is off.
    std::vector<int> face;
    /// #P normal spread of every point in degrees: the largest angle between its normal and
    /// those of its k neighbours (normals are unoriented, so at most 90).
    Eigen::VectorXd spread;
    /// #P surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the point and its
    /// neighbours, read along the given normal, less the cloud's median.
    Eigen::VectorXd planarityExcess;
    /// The excess above which a point may stop the growing (minFilletRadius, noiseMargin).
    double minExcess = 0.0;
    /// The neighbours (nearest first) the planarity excess was measured over (k or
    /// fineNeighbours).
    int excessNeighbours = 0;
    /// Degrees: the spread limit used (growAngle, noiseSpreadFactor).
    double growAngle = 0.0;
    /// Degrees: noiseSpreadTail times the cloud's median spread, beyond which a spread is not
    /// noise's.
    double noiseSpreadLimit = 0.0;

    int clusterCount() const { return static_cast<int>(clusterSize.size()); }
    bool isCandidate(Eigen::Index i) const { return smallCluster[cluster[i]] != 0; }
};

/// Segments a cloud by region growing on its (unoriented) normals.
///   P        #P by 3 points
///   normals  #P by 3 unit normals, e.g. from pcaNormals()
///   N        the k nearest neighbours the normals were estimated on
///   spacing  the cloud's sampling spacing (samplingSpacing())
/// A point grows its cluster unless both its normal spread and its planarity excess are high;
/// one that does not grow joins the cluster of its growing neighbour of closest normal (within
/// joinAngle), unless it lies between two faces (the design note). Every point ends in exactly
/// one cluster; the result does not depend on the point order beyond cluster and face
/// numbering. Throws std::invalid_argument when the sizes disagree, a normal is not finite, the
/// spacing is not positive, an angle is not in (0, 90] (shallowCreaseAngle in [0, 90]), a
/// crease length is not positive or minFacePoints is below 3.
FirstOrderSegmentation segmentByNormals(const PointMatrix& P, const NormalMatrix& normals,
                                        const Neighbourhoods& N, double spacing,
                                        const FirstOrderSegmentationOptions& options = {});

} // namespace featurelines
