// SPDX-License-Identifier: LGPL-2.1-or-later
// Neighbourhoods that reach across scan rows: where a point's k nearest neighbours all lie on
// its own scan line, the neighbourhood is rebuilt from a wider search so that it spans the
// surface. Design: docs/design/neighbourhoods.md ("Scan rows").
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

struct BalanceOptions
{
    /// A neighbourhood is collinear when its spread (the middle eigenvalue of its covariance
    /// over the largest) is below this (a row of points with 0.2 spacing of scatter: about 0.001;
    /// one point of another row 4 spacings away lifts it to 0.05) (0.02).
    double collinearShare = 0.02;
    /// The wider search, in multiples of k (3).
    int widerFactor = 3;
    /// Below this share of collinear neighbourhoods nothing is rebuilt: a few points on thin
    /// spikes or along a wire do not pay for the wider search (0.005).
    double minCollinearShare = 0.005;
    /// Worker threads; 0: OpenMP's default (0).
    int threads = 0;
};

/// The rows of the neighbourhoods of N that were rebuilt, in ascending order (none when fewer
/// than minCollinearShare were collinear); their normals are to be estimated again
/// (pcaNormalsOfRows). A neighbourhood is collinear when its spread (NormalEstimate::spread,
/// over N) is below collinearShare. A collinear neighbourhood of point i keeps its k/2 nearest
/// neighbours and takes the k - k/2 nearest of the wider search that lie off the line of its row
/// (farther from it than twice the cloud's mean spacing), so that the neighbourhood reaches the
/// rows on either side; the list stays sorted by distance.
///   P       #P by 3 points; N their k nearest neighbours, changed in place
///   spread  #P NormalEstimate::spread over N
std::vector<int> balanceCollinearNeighbourhoods(const PointMatrix& P, Neighbourhoods& N,
                                                const Eigen::VectorXd& spread,
                                                const BalanceOptions& options = {});

} // namespace featurelines
