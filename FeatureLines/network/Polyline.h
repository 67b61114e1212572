// SPDX-License-Identifier: LGPL-2.1-or-later
// The network stage's output: polylines meeting at junctions, and the smoothing and resampling
// along a polyline's length that every line stage uses (docs/design/network.md).
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines {

/// One polyline of a LineNetwork.
struct Polyline
{
    /// V  #V by 3 vertices in order. A closed line does not repeat its first vertex at the end.
    PointMatrix points;
    bool closed = false;
    /// Row of LineNetwork::junctions the first / last vertex sits on, -1 when that end is free
    /// (a dangling end) or the line is closed without junction.
    int startJunction = -1;
    int endJunction = -1;
    /// The caller's label of the candidate clusters the line runs through (the majority along
    /// it), 0 when the caller gave no labels. SharpEdges.h names its labels.
    int label = 0;
};

/// Lines meeting at junctions: every junction is a point where three or more line ends meet.
struct LineNetwork
{
    std::vector<Polyline> lines;
    /// J  #J by 3 junction positions.
    PointMatrix junctions;
};

/// The polyline smoothed along its length over `length` (the standard deviation of the
/// equivalent Gaussian): resampled at half of `length`, then eight passes of (1/4, 1/2, 1/4)
/// weights, which is what makes a smoothing by vertex count one by length. The ends of an open
/// line stay put; the result has the fine vertices (resample it after).
PointMatrix smoothPolyline(const PointMatrix& points, bool closed, double length);

/// The polyline `points` resampled at equal arc-length steps as close to `step` as the length
/// allows; an open line keeps its two end points exactly, a closed line gets at least three
/// vertices. Lines shorter than a step keep their ends only.
PointMatrix resamplePolyline(const PointMatrix& points, bool closed, double step);

} // namespace featurelines
