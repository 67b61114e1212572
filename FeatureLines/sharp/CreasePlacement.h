// SPDX-License-Identifier: LGPL-2.1-or-later
// Crease placement: the last step of the sharp stage, moving every sharp line onto the crease.
#pragma once

#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/sharp/SharpEdges.h"

namespace featurelines {

/// Design note: docs/design/sharp-edges.md, "Crease placement" (beyond the papers).

/// What the placement reads.
struct CreasePlacementInput
{
    /// #P by 3 points.
    const PointMatrix& P;
    /// k nearest neighbours of every point.
    const Neighbourhoods& N;
    /// The sharp stage's graph, its lines neither smoothed nor resampled.
    const ClusterGraph& graph;
    /// The sharp stage's segmentation (its large clusters are the faces fitted) and boundary
    /// points (fitted to no face); its network is not read.
    const SharpEdges& sharp;
    /// The cloud's sampling spacing (samplingSpacing()).
    double spacing;
    /// #P by 3 unit normals over N; when given, each face's plane is read from its points'
    /// normals (fitPlaneByNormals), else from their positions (fitPlane).
    const NormalMatrix* normals = nullptr;
};

/// The graph's lines and junctions, the sharp lines (sharpLineLabel) placed on the crease:
/// every node moves onto the line where the planes fitted to two faces around it meet (a
/// junction onto the corner of three, or to the rim where a sharp line ends on the boundary),
/// then the line is resampled at resampleSpacing with every new vertex put back on its crease.
/// Lines of other labels keep their nodes (placed at junctions), smoothed and resampled as
/// options.graph says. The options read: fitRadius, minFitPoints, minCreaseAngle,
/// maxCreaseShift, resampleSpacing and graph.
LineNetwork placeOnCreases(const CreasePlacementInput& in, const SharpEdgeOptions& options);

} // namespace featurelines
