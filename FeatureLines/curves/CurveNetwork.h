// SPDX-License-Identifier: LGPL-2.1-or-later
// The lines as CAD geometry: every line piece between two junctions (or a closed loop) fitted
// by a straight segment, a circular arc, a circle or a cubic B-spline; one vertex per junction,
// shared by every edge that meets there; and the closed border loops of each surface patch.
// Plain data: no OpenCASCADE types (App/ builds the TopoDS shapes from it).
// Design: docs/design/curves.md.
#pragma once

#include <cstdint>
#include <vector>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/PointCloud.h"

namespace featurelines {

enum class CurveKind : std::uint8_t
{
    Segment,
    Arc,
    Circle,
    BSpline,
};

/// "segment", "arc", "circle", "bspline".
const char* curveKindName(CurveKind kind);

/// One fitted curve. Its ends are exactly its edge's vertices (for a closed edge, start ==
/// end == the one vertex).
struct FittedCurve
{
    CurveKind kind = CurveKind::BSpline;
    /// Every kind: the first and last point of the curve.
    Eigen::Vector3d start = Eigen::Vector3d::Zero();
    Eigen::Vector3d end = Eigen::Vector3d::Zero();
    /// Arc and Circle: centre, unit axis and radius; an arc runs counter-clockwise about
    /// `axis` from `start` to `end`; a circle starts and ends at `start`.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    double radius = 0.0;
    /// BSpline, in OpenCASCADE's convention: degree, poles  #P by 3, the distinct knots and
    /// their multiplicities; clamped (first and last pole are `start` and `end`) unless
    /// `periodic` (a closed loop without vertex of degree other than 2).
    int degree = 3;
    PointMatrix poles;
    std::vector<double> knots;
    std::vector<int> multiplicities;
    bool periodic = false;
    /// Distance from the polyline's vertices to the curve, in model units.
    double rmsDeviation = 0.0;
    double maxDeviation = 0.0;
};

/// One edge of the network: a fitted piece of one extracted line.
struct NetworkEdge
{
    LineType type = LineType::Sharp;
    /// Row of ExtractionResult::lines the piece comes from.
    int line = -1;
    /// The stretch of that line between junctions (or free ends) the piece belongs to: edges
    /// with the same `run` are one stretch cut at its corners (CurveFitOptions::cornerAngle),
    /// in order along the line; numbered from 0 over the network.
    int run = -1;
    /// Rows of CurveNetwork::vertices; equal for a closed edge.
    int startVertex = -1;
    int endVertex = -1;
    FittedCurve curve;
    /// V  #V by 3 the polyline vertices the curve was fitted to (the line's, from start to
    /// end vertex).
    PointMatrix points;
};

struct CurveNetwork
{
    /// N  #N by 3 vertex positions: the junctions, the free ends of open lines, and one vertex
    /// on each closed loop.
    PointMatrix vertices;
    std::vector<NetworkEdge> edges;
};

/// An edge of a border loop, walked forwards (start to end vertex) or reversed.
struct LoopEdge
{
    int edge = -1;
    bool reversed = false;
};

/// The border of one surface patch (ExtractionResult::patch ids).
struct PatchBorder
{
    int patch = -1;
    /// Closed loops of edges, each running end to start; the first is the outer loop (the
    /// longest), the others holes.
    std::vector<std::vector<LoopEdge>> loops;
    /// Edges that touch the patch but close no loop (where the lines found leave the patch
    /// open). Empty when the patch's border is closed.
    std::vector<int> openEdges;
    bool closed() const { return !loops.empty() && openEdges.empty(); }
};

struct CurveFitOptions
{
    /// The fitting tolerance in point spacings (ExtractionResult::spacing): every polyline
    /// vertex within it of its curve. Raised to noiseFactor times the noise where that is
    /// larger: the cloud's (the median of RegionReport::noise) or the polyline's own scatter
    /// (polylineScatter in CurveFit.h).
    double tolerance = 0.25;
    /// Multiple of the noise the tolerance is raised to (default 6).
    double noiseFactor = 6.0;
    /// A free line end within this many spacings of a vertex or of another line is joined to
    /// it there (default 2).
    double joinDistance = 2.0;
    /// Junctions closer than this many spacings are one vertex (default 1).
    double mergeDistance = 1.0;
    /// Polyline vertices within this many spacings of an edge's end vertex are left out of its
    /// fit: the lines bend on their last spacing or two into a junction (default 2).
    double vertexGap = 2.0;
    /// Two edges meeting alone at a vertex whose direction turns there by less than this many
    /// degrees run on with one tangent (default 30).
    double smoothAngle = 30.0;
    /// Below 180: a line is also cut where its direction breaks by this many degrees or more
    /// between straight or evenly curved sides of `cornerWindow` spacings (findLineCorners in
    /// LineCorners.h), such as the corners of a flat face's border between fillets; a corner
    /// within `joinDistance` of a junction or of another line's corner shares its vertex.
    /// Default 180, cuts at junctions only: on the accuracy benchmark's random parts nine in
    /// ten of the corners that 30 degrees finds lie on no corner of the part, but where the
    /// lines stray (docs/design/curves.md, "Corners"). Window default 6.
    double cornerAngle = 180.0;
    double cornerWindow = 6.0;
};

/// The cloud's noise in spacings: the median of its regions' estimates (RegionReport::noise),
/// 0 without regions. The curves' and the surfaces' noise-aware tolerances start from it.
double cloudNoise(const ExtractionResult& result);

/// The network of fitted curves of `result`'s lines.
CurveNetwork fitCurveNetwork(const ExtractionResult& result, const CurveFitOptions& options = {});

struct PatchBorderOptions
{
    /// An edge borders a patch when, at `share` or more of its samples (one per spacing, those
    /// within `reach` or a quarter of its length of its vertices left out), the patch's nearest
    /// point is within `reach` spacings and within `margin` spacings of the nearest point of any
    /// patch (a sharp edge's band of patch -1 is about 3 spacings wide on either side; a patch
    /// across a narrow chamfer is farther). Defaults 8, 1.5 and 0.5.
    double reach = 8.0;
    double margin = 1.5;
    double share = 0.5;
    /// Patches of fewer points are specks between two thresholds, not surfaces: no border is
    /// returned for them (default 20).
    int minPoints = 20;
};

/// Every patch's border in `network`, one per patch id of result.patch (of minPoints or more
/// points) in increasing order:
/// P  #P by 3 the cloud the result came from (result.patch holds one id per row of P).
std::vector<PatchBorder> patchBorders(const CurveNetwork& network, const ExtractionResult& result,
                                      const PointMatrix& points,
                                      const PatchBorderOptions& options = {});

} // namespace featurelines
