// SPDX-License-Identifier: LGPL-2.1-or-later
// The joins that close lines at their free ends: reconnection, facing ends, converging ends,
// extension. One cone search from each free end, with a policy per join. Internal to the
// network stage (docs/design/network.md).
#pragma once

#include <memory>
#include <vector>

#include "FeatureLines/PointCloud.h"
#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/network/NodeGraph.h"

namespace featurelines::clustergraph {

/// Where a line may run: along candidates, or where the caller marks points as supporting.
class Support
{
public:
    /// The points i of P for which supports(i) holds, each covering `radius` around it.
    template <class Supports>
    Support(const PointMatrix& P, Supports supports, double radius) : radius_(radius)
    {
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            if (supports(i)) {
                points_.emplace_back(P.row(i).transpose());
            }
        }
        grid_ = std::make_unique<NodeGrid>(points_, radius);
    }

    /// Share of the steps (one spacing apart) along the cubic (Hermite) curve from a, leaving
    /// in direction da, to b, arriving against db (unit directions, or zero for the straight
    /// segment), that have a supporting point within the radius.
    double along(const Eigen::Vector3d& a, const Eigen::Vector3d& da, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& db, double spacing) const;

private:
    double radius_;
    std::vector<Eigen::Vector3d> points_;
    std::unique_ptr<NodeGrid> grid_;
};

/// Reconnection: every free end joined to the nearest node ahead within reconnectRadius (two
/// free ends meeting at an angle through the corner between them). Adds a label per new node.
int reconnectEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                  const Support* support);

/// Free ends facing each other within facingEndsRadius joined end to end.
int joinFacingEnds(Graph& g, const ClusterGraphOptions& options, const Support* support);

/// Free ends whose lines meet straight ahead joined through a new corner node, which further
/// ends heading for it join too. Adds a label per new node.
int joinConvergingEnds(Graph& g, const ClusterGraphOptions& options, std::vector<int>& labels,
                       const Support* support);

/// Free ends extended straight ahead, up to extendReach, to the first node of a line they
/// point at (with support: else to the nearest node whose way there is supported).
int extendFreeEnds(Graph& g, const ClusterGraphOptions& options, const Support* support);

} // namespace featurelines::clustergraph
