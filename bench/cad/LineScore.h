// SPDX-License-Identifier: LGPL-2.1-or-later
// Scoring typed feature lines (or flagged points) against the typed edges of a CAD model.
//
// The metric of the accuracy benchmark (docs/ACCURACY.md): per edge type T, precision is the
// share of the detector's T samples that lie within a tolerance of a true T edge, recall the
// share of the true T edge samples that lie within the tolerance of a detector T sample, F1
// their harmonic mean. Closedness is the share of detected lines that are closed or whose both
// ends lie on another line (Demarsin et al. 2008, Sec. 1.2: the lines must form a closed
// network bounding the surface patches).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "FeatureLines/PointCloud.h"

namespace featurelines::bench {

/// The three kinds of line the extraction returns (Demarsin 2008, Fig. 1): a sharp edge
/// (tangent discontinuity), a smooth edge (curvature discontinuity, e.g. a fillet border) and
/// the external boundary of an open surface.
enum class LineType
{
    Sharp = 0,
    Smooth = 1,
    Boundary = 2
};
constexpr int lineTypeCount = 3;

/// The core's name of the type (featurelines::lineTypeName), the spelling of the lines JSON
/// format.
std::string lineTypeName(LineType type);
/// The inverse of lineTypeName; throws std::invalid_argument for any other word.
LineType lineTypeFromName(const std::string& name);

/// One polyline. When `closed`, the last point joins the first (the first point is not
/// repeated at the end).
struct TypedPolyline
{
    LineType type = LineType::Sharp;
    bool closed = false;
    /// P  #P by 3 vertices in order along the line.
    PointMatrix points;
    /// Sharp lines: the angle between the two faces inside their wedge (degrees); smooth lines:
    /// the radius of the blend they border (model units). Of the true edge, or the detector's
    /// estimate; NaN where none.
    double angle = std::numeric_limits<double>::quiet_NaN();
    double radius = std::numeric_limits<double>::quiet_NaN();
};

struct LineScoreOptions
{
    /// Mean point spacing of the cloud the lines were extracted from (model units, > 0).
    /// Every length below is a multiple of it.
    double spacing = 1.0;
    /// A sample matches when it lies within toleranceFactor x spacing of the other side.
    /// 3 x spacing: a line placed anywhere inside the k = 16 neighbourhood of the true edge
    /// still counts, one displaced onto the next patch does not.
    double toleranceFactor = 3.0;
    /// Lines are resampled at this multiple of the spacing before counting, so that precision
    /// and recall weigh length, not vertex count.
    double resampleFactor = 0.5;
};

/// Precision, recall and F1 of one edge type. A value is NaN where it is undefined: precision
/// when the detector gave no sample of the type, recall and F1 when the model has no edge of
/// the type. F1 is 0 (not NaN) when the model has edges of the type and the detector none.
struct TypeScore
{
    double precision = 0.0;
    double recall = 0.0;
    double f1 = 0.0;
    /// Samples counted in the precision's denominator and the recall's.
    long detectedSamples = 0;
    long truthSamples = 0;
};

struct LineScore
{
    /// Indexed by static_cast<int>(LineType).
    std::array<TypeScore, lineTypeCount> types;
    /// Share of detected lines that are closed or have both ends within the tolerance of a
    /// sample of another line or of a part of the same line farther than twice the tolerance
    /// along it (a junction). NaN when there is no line.
    double closedness = 0.0;
    /// The same share over the sharp lines only (their ends may lie on a line of any type: a
    /// sharp edge ends on the boundary or where a fillet border begins). NaN when there is no
    /// sharp line.
    double sharpClosedness = 0.0;
    int lineCount = 0;
};

/// Resamples a polyline at arc-length steps of `step` (> 0), keeping both ends (and the
/// closing segment of a closed line). Returns #S by 3 samples.
PointMatrix resamplePolyline(const TypedPolyline& line, double step);

/// Scores the detector's `detected` lines against the true edges `truth` (both typed
/// polylines). Throws std::invalid_argument when options.spacing or a factor is not a
/// positive finite number, or a polyline has a NaN coordinate.
LineScore scoreLines(const std::vector<TypedPolyline>& detected,
                     const std::vector<TypedPolyline>& truth, const LineScoreOptions& options);

/// Scores a per-point detector, which flags points but gives them no type: the flagged
/// points F (#F by 3) are the samples of every type. For type T, a flagged point within the
/// tolerance of a true edge of another type but not of a true T edge is left out of T's
/// precision denominator (it is no false T detection, just another edge); recall is the share
/// of true T edge samples within the tolerance of a flagged point. closedness is NaN and
/// lineCount 0.
LineScore scoreFlaggedPoints(const PointMatrix& flagged, const std::vector<TypedPolyline>& truth,
                             const LineScoreOptions& options);

/// How well the detected lines sit on the true edges, beyond matching within the tolerance:
/// the distance of the lines to the edges, which type they give each edge, and how many
/// pieces they come in. Lengths in point spacings.
struct LineQuality
{
    /// Distance from each detected line sample (any type) to the nearest true edge (any
    /// type; the exact distance to the true polyline's segments), over the samples within the
    /// tolerance of an edge: median and 95th percentile, in spacings. NaN without such samples.
    double medianDistance = 0.0;
    double p95Distance = 0.0;
    /// Share of the detected samples within the tolerance of a true edge of any type.
    double matchedShare = 0.0;
    /// confusion[t][u]: true samples of type t whose nearest detected sample within the
    /// tolerance lies on a line of type u; missed[t]: true samples of type t with none.
    std::array<std::array<long, lineTypeCount>, lineTypeCount> confusion{};
    std::array<long, lineTypeCount> missed{};
    /// Total length of the detected boundary lines, in spacings (0 on a closed part).
    double boundaryLength = 0.0;
    /// Detected lines per true edge (one true edge per B-rep edge of the truth), and the ends
    /// of open lines that neither join another line nor come back to their own (as in
    /// LineScore::closedness).
    double linesPerTrueEdge = 0.0;
    int freeEnds = 0;
    /// The lines' estimates against the true edges': over the samples of detected sharp lines
    /// that carry an angle, and whose nearest true sample within the tolerance lies on a true
    /// sharp edge (which always has one), |angle - true angle| in degrees; over the samples of
    /// smooth lines that carry a radius, nearest a true smooth edge, |radius / true radius - 1|.
    /// Medians; NaN without such samples. estimatedShare: of the detected sharp (smooth)
    /// samples nearest a true edge of their own type, the share whose line carries an estimate.
    double medianAngleError = 0.0;
    double medianRadiusError = 0.0;
    double angleEstimatedShare = 0.0;
    double radiusEstimatedShare = 0.0;

    /// Share of the true samples of type `truth` found as type `found` (NaN without true
    /// samples of that type).
    double confusionShare(LineType truth, LineType found) const;
};

/// Measures LineQuality of `detected` against `truth` with the tolerance and resampling of
/// `options` (the true edges are resampled at the same step; distances are to their
/// segments). Throws std::invalid_argument as scoreLines does.
LineQuality measureLineQuality(const std::vector<TypedPolyline>& detected,
                               const std::vector<TypedPolyline>& truth,
                               const LineScoreOptions& options);

} // namespace featurelines::bench
