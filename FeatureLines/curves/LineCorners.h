// SPDX-License-Identifier: LGPL-2.1-or-later
// The corners of one extracted line: where its direction breaks (the border of a flat face
// between fillets turns through a right angle at each of the face's corners), as against where
// it bends smoothly (an arc) or wobbles (noise, a slow excursion). The curve network cuts its
// lines there, so that a patch border is a few edges meeting at shared corners rather than one
// B-spline rounded over them. Design: docs/design/curves.md, "Corners".
#pragma once

#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines {

struct LineCornerOptions
{
    /// Each side of a candidate corner is the run of the line from `gap` to `window` spacings
    /// away from it (defaults 1 and 6): the lines round a corner off over about a spacing, and
    /// six spacings hold half a dozen vertices or more, enough for a side's direction.
    double gap = 1.0;
    double window = 6.0;
    /// The two sides' lines turn by at least this many degrees (default 30, the curve
    /// network's smoothAngle: a smaller turn runs on with one tangent), and so do those of the
    /// sides of twice the window (a slow excursion of a noisy line turns back within it).
    double angle = 30.0;
    /// The turn between the sides of twice the window grows by at most this share of what it
    /// grows on an arc (default 0.5): on an arc the sides' lines turn in proportion to their
    /// length, at a corner by its angle whatever their length.
    double growth = 0.5;
    /// And the one circle through both sides of twice the window misses their points by at
    /// least this many times the RMS distance of each side to its own line or arc (default 2):
    /// a gentle arc's turn is uncertain under noise, but its points lie on one circle.
    double arcRatio = 2.0;
};

struct LineCorner
{
    /// Row of the line's points nearest the corner.
    int vertex = -1;
    /// The corner: where both sides (from three gaps out) are straight, the point nearest both
    /// their fitted lines, when these pass within a spacing of each other and it lies within
    /// a spacing and a half of the line (which only rounds the corner off); else the vertex.
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    /// Turn between the two sides' directions, degrees.
    double turn = 0.0;
};

/// The corners of a polyline, in order along it, at least `window` spacings apart and (open
/// line) at least `window` spacings from either end:
/// P  #P by 3 vertices in order; a closed line does not repeat its first vertex.
/// spacing  the cloud's point spacing (> 0).
std::vector<LineCorner> findLineCorners(const PointMatrix& P, bool closed, double spacing,
                                        const LineCornerOptions& options = {});

} // namespace featurelines
