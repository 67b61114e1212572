// SPDX-License-Identifier: LGPL-2.1-or-later
// One curve through an ordered run of points: a straight segment, a circular arc, a full circle
// or a cubic B-spline (Eigen least squares), the curve's ends on given vertices; and the
// evaluation of a fitted curve. Design: docs/design/curves.md.
#pragma once

#include <optional>

#include "FeatureLines/curves/CurveNetwork.h"

namespace featurelines {

/// The points one curve is fitted to.
struct CurveFitInput
{
    /// V  #V by 3 points in order along the curve. Open: the first and last rows are the
    /// curve's end vertices, met exactly. Closed: a loop (first row not repeated at the end)
    /// that starts and ends at its first row.
    PointMatrix points;
    bool closed = false;
    /// Closed only: the loop's vertex may slide onto the curve (no other edge meets it), so
    /// the fit may be a full circle or a periodic B-spline; start and end are then the
    /// curve's point nearest the first row.
    bool freeVertex = false;
    /// Unit tangents (direction of travel) the B-spline must have at its start / end, where
    /// it runs on smoothly into another edge. Segments and arcs ignore them.
    std::optional<Eigen::Vector3d> startTangent;
    std::optional<Eigen::Vector3d> endTangent;
    /// Every point within this distance of the curve (model units, > 0).
    double tolerance = 0.0;
};

/// The estimated standard deviation of the points' scatter across their run: the RMS of each
/// interior point's offset from the midpoint of its two neighbours, across the chord between
/// them, divided by sqrt(1.5) (the offset of independent scatter sigma has variance
/// 1.5 sigma^2). 0 for fewer than 3 points.
double polylineScatter(const PointMatrix& points, bool closed);

/// A circle in space: its centre, the unit normal of its plane, its radius.
struct BestCircle
{
    Eigen::Vector3d centre;
    Eigen::Vector3d normal;
    double radius = 0.0;
};

/// The circle that fits points best: the plane in which they spread least, Kasa's algebraic
/// circle in it, then Gauss-Newton on the geometric distances in the plane. nullopt for fewer
/// than 3 points or where no circle is found (collinear points).
/// P  #P by 3 points.
std::optional<BestCircle> bestFitCircle(const PointMatrix& P);

/// The simplest curve that holds the tolerance: a segment, else an arc (open) or a circle
/// (closed with a free vertex), else a B-spline with as few poles as keep every point within
/// it (at most one per two points; the last fit is kept where even that does not). rmsDeviation
/// and maxDeviation are set.
FittedCurve fitCurve(const CurveFitInput& input);

/// The segment from the first to the last point when it holds the tolerance: the points' RMS
/// distance within half of it and none beyond 1.5 times it (the same for arcs and circles).
std::optional<FittedCurve> fitSegment(const CurveFitInput& input);
/// The circular arc from the first to the last point (open input), or the full circle (closed
/// input with a free vertex), when it holds the tolerance.
std::optional<FittedCurve> fitArc(const CurveFitInput& input);
std::optional<FittedCurve> fitCircle(const CurveFitInput& input);
/// The cubic B-spline: clamped on the first and last point (open, or closed on a fixed
/// vertex), periodic for a closed input with a free vertex. Knots are inserted where the
/// deviation is largest until the tolerance holds or the pole count reaches its limit.
FittedCurve fitBSpline(const CurveFitInput& input);

/// The curve's point at `s` in [0, 1], the fraction of its parameter range (arc and circle:
/// of the angle; B-spline: of the knot range). curvePoint(c, 0) is c.start.
Eigen::Vector3d curvePoint(const FittedCurve& curve, double s);

/// Unit tangent (direction of travel) at `s` in [0, 1].
Eigen::Vector3d curveTangent(const FittedCurve& curve, double s);

/// S  #S by 3 points along the curve from start to end, at most `step` apart (model units,
/// > 0), the first and last exactly start and end (a closed curve repeats its start at the
/// end). A segment gives its two ends.
PointMatrix sampleCurve(const FittedCurve& curve, double step);

/// The curve's length (from a sampling fine enough for a tenth of a percent).
double curveLength(const FittedCurve& curve);

/// The distance of each point to the curve (the nearest point of a sampling at `step`).
Eigen::VectorXd distancesToCurve(const FittedCurve& curve, const PointMatrix& points, double step);

} // namespace featurelines
