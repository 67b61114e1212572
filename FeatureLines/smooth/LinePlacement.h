// SPDX-License-Identifier: LGPL-2.1-or-later
// Placement of smooth lines on the surface's own curvature step (beyond the paper). Where a
// region's curvature had to be read at a coarser scale (CurvatureScale.h), its lines follow the
// coarse field, which places them up to a few of the cloud's spacings off the true fillet
// border. The border is where the surface's curvature across the line jumps while the surface
// stays tangent-continuous: across the line the height over the tangent plane is straight on
// one side (a face, or a cylinder along its axis) and a parabola on the other, joined with the
// same value and slope. Fitted by least squares to the region's points in a strip across the
// line, that profile gives the border to about a spacing: the fit uses the positions of
// hundreds of points, not a derivative of them.
#pragma once

#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/PointCloud.h"

namespace featurelines {

/// Lengths are multiples of the curvature's spacing (the region's spacing x its curvature
/// scale, the resolution the line was found at) unless stated otherwise.
struct LinePlacementOptions
{
    /// Half the width of the strip across the line whose points are fitted, at least. Three fit
    /// spacings reach past the line's uncertainty onto both surfaces.
    double halfWidth = 3.0;
    /// The strip is widened to this share of the radius of the fillet the line borders, when
    /// that is wider: the border is placed to about noise / (curvature step x width^1.5 x
    /// length^0.5), so the widest strip the profile's parabola holds is the most precise. The
    /// radius is that of a cylinder whose |H| = 1 / (2 r) lies twice above the threshold,
    /// r = 1 / (4 tau) (a threshold in the middle of its valley lies half-way between a face's
    /// curvature and the fillet's). Over 0.4 r a circle departs from its parabola by 4 %.
    double radiusShare = 0.4;
    /// Half the strip's length along the line, at least: it is made as long as the strip is
    /// wide (above), which costs no resolution across. Two fit spacings: a border curving
    /// with a radius of 20 fit spacings departs from its tangent by 0.1 of one at the ends.
    double halfLength = 2.0;
    /// The farthest a vertex moves across its line, x the strip's half width: the border
    /// then keeps at least half the strip on its far side. The coarse field can leave a line
    /// several fit spacings off (a shoulder of its level reaching into the face); a border
    /// found farther off lies outside what one strip can place (see recentres).
    double maxShift = 0.5;
    /// Where the best border lies on the edge of that range (the coarse field left the line
    /// farther off), the strip is centred on the edge and fitted again, at most this many
    /// times: a vertex can move up to (1 + recentres) x maxShift x the half width. A surface of
    /// one curvature across (a cylinder across, a sphere) keeps putting the border on the edge
    /// and its vertex stays where it was. 0: one strip only.
    int recentres = 2;
    /// x the region's own spacing: the step of the border positions tried.
    double step = 0.25;
    /// How much better the tangent-continuous pair of a straight side and a parabola must fit
    /// than the straight side alone: the drop in the residual sum of squares, in units of the
    /// residual variance (a chi-square with one degree of freedom; the best of the positions
    /// tried, so more than the 9 of a single 3-sigma test: 25, a 5-sigma step).
    double minEvidence = 25.0;
    /// Least number of points on each side of a border position.
    int minPointsPerSide = 12;
    /// x the strip's half length: the distance along the line between two vertices fitted;
    /// the vertices between move by the two's displacements, weighed by arc length. Strips of
    /// neighbouring vertices would hold nearly the same points.
    double fitStride = 0.5;
    /// Fitted vertices on each side whose shifts enter the median a vertex is moved by: a shift
    /// must agree with its neighbours' along the line.
    int medianHalfWindow = 2;
};

/// Moves the inner vertices of every line of `network` across the line onto the curvature
/// step found in the points under it (see above); vertices where no step is found with the
/// evidence asked, and the two end vertices of an open line (a junction or an anchor), stay.
///   P, N        #P by 3 region points and their unit normals (unoriented)
///   curvature   empty, or #P the points' mean curvature (the values the line was drawn on):
///               where given, a strip is narrowed to radiusShare of the radius of the fillet
///               the points on the line's high side show (1 / (2 |H|), |H| their lower
///               quartile) when that is smaller than the threshold's
///   spacing     the region's mean point spacing
///   fitSpacing  the spacing the line was found at (>= spacing)
///   threshold   the curvature threshold the line parts (|H|, 1 / length unit; 0: unknown,
///               the strip keeps its width in fit spacings)
/// Returns the number of vertices moved. Throws std::invalid_argument for sizes that disagree,
/// a spacing that is not positive, or options out of range.
int placeOnCurvatureSteps(LineNetwork& network, const PointMatrix& P, const NormalMatrix& N,
                          const Eigen::VectorXd& curvature, double spacing, double fitSpacing,
                          double threshold, const LinePlacementOptions& options = {});

} // namespace featurelines
