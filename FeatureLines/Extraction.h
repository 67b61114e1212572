// SPDX-License-Identifier: LGPL-2.1-or-later
// The whole method (Sec. 1.2 of the 2008 paper): from a raw cloud to a network of closed,
// typed feature lines, in three steps a caller may keep and recompute from.
// Design: docs/design/pipeline.md.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/sharp/SharpEdges.h"
#include "FeatureLines/smooth/AutomaticThresholds.h"
#include "FeatureLines/smooth/RegionGeometry.h"
#include "FeatureLines/smooth/SmoothEdgeOptions.h"
#include "FeatureLines/smooth/SmoothRegions.h"
#include "FeatureLines/support/Progress.h"

namespace featurelines {

enum class LineType : std::uint8_t
{
    Sharp,
    Smooth,
    Boundary,
};

/// "sharp", "smooth", "boundary".
const char* lineTypeName(LineType type);

struct FeatureLine
{
    LineType type = LineType::Sharp;
    bool closed = false;
    /// V  #V by 3 vertices; a closed line does not repeat its first vertex.
    PointMatrix points;
    /// Smooth lines: the smooth region, the index of their threshold in that region's list,
    /// and the threshold. -1 / NaN for sharp and boundary lines.
    int region = -1;
    int level = -1;
    double threshold = std::numeric_limits<double>::quiet_NaN();
    /// Sharp lines: the angle between the two faces that meet on the line, in degrees, measured
    /// inside the wedge they form (0-180: 90 for every edge of a box, convex or concave; near
    /// 180 for a shallow crease); the median along the line of the faces' fitted planes. NaN
    /// where no two faces were fitted, and for smooth and boundary lines.
    double angle = std::numeric_limits<double>::quiet_NaN();
    /// Smooth lines: the estimated radius of the blend the line borders (length unit), from the
    /// profile fitted across it (the lines of a blend typed by its profile) or from the
    /// largest principal curvature beside it (blendRadii()); NaN where none was estimated, and
    /// for sharp and boundary lines.
    double blendRadius = std::numeric_limits<double>::quiet_NaN();
    /// Rows of ExtractionResult::junctions the ends sit on, -1 for none.
    int startJunction = -1;
    int endJunction = -1;
};

enum class ThresholdMode
{
    /// Per region, as many thresholds as have a significant valley (AutomaticThresholdOptions).
    Automatic,
    /// Per region, the first threshold of its histogram only (Sec. 2.3: "Typically ... one
    /// threshold immediately after the first peak is sufficient").
    First,
    /// The thresholds given: ExtractionOptions::regionThresholds for a region listed there,
    /// ExtractionOptions::thresholds for every other region.
    Explicit,
};

struct ExtractionOptions
{
    /// The k nearest neighbours of the cloud (Sec. 2.1).
    NeighbourOptions neighbours;
    /// Sharp edges are extracted (default true).
    bool sharpEdges = true;
    /// Sharp edges, and the boundary of an open cloud (sharp.includeBoundary).
    SharpEdgeOptions sharp;
    /// Smooth edges are extracted (default true).
    bool smoothEdges = true;
    /// The division of the cloud into smooth regions.
    SmoothRegionOptions regions;
    /// Each region's smoothing, curvature, thresholds and smooth edges.
    SmoothEdgeOptions smooth;
    /// How each region's thresholds are chosen (default Automatic).
    ThresholdMode thresholdMode = ThresholdMode::Automatic;
    /// Explicit mode: the curvature thresholds (1/length) of every region not listed below.
    std::vector<double> thresholds;
    /// Explicit mode: the curvature thresholds of the listed regions, by region number.
    std::map<int, std::vector<double>> regionThresholds;
    /// Called with the share of the work done (0..1) and the stage's name at each stage and,
    /// within the long ones, as their loops go (support/Progress.h); returning false cancels
    /// the extraction (ExtractionCancelled is thrown). Called on the caller's thread only.
    /// Default none.
    ProgressCallback progress;
    /// Within a stage, the least time between two calls of `progress`, seconds. Default 0.2.
    double progressInterval = 0.2;
};

/// The geometry every extraction of one cloud shares, whatever its thresholds: computed once
/// and kept by a caller that recomputes with other options (the FreeCAD document object).
struct CloudGeometry
{
    /// The distinct points (exact duplicates merged) in a canonical spatial order (Morton order
    /// of their positions: no result depends on the input's order) and, per input point, its
    /// row here.
    PointMatrix points;
    std::vector<int> inputToPoint;
    Neighbourhoods neighbours;
    NormalEstimate normals;
    /// The sampling spacing (samplingSpacing()): every default length is a multiple of it.
    double spacing = 0.0;
};

/// Throws std::invalid_argument naming the problem when P is no cloud feature lines can be
/// found on: a coordinate that is not finite, k or fewer distinct points (exact duplicates
/// merged), or all points on one line. analyseCloud's own check, for the tools that compute
/// other stages (the curvature) of the same cloud.
void requireSurfaceCloud(const PointMatrix& P, int k);

/// Validates the cloud (requireSurfaceCloud) and computes neighbours, normals and spacing.
/// Throws std::invalid_argument naming the problem.
CloudGeometry analyseCloud(const PointMatrix& P, const NeighbourOptions& options = {},
                           const ProgressCallback& progress = {}, double progressInterval = 0.2);

struct RegionReport
{
    int region = -1;
    int points = 0;
    double noise = 0.0;
    bool smoothed = false;
    /// The scale the curvature was computed at, x spacing (RegionGeometry::curvatureScale).
    double curvatureScale = 1.0;
    /// Every scale weighed (RegionGeometry::scaleTrials); empty when only the cloud's own
    /// sampling was looked at.
    std::vector<RegionGeometry::ScaleTrial> scaleTrials;
    /// The thresholds applied, high to low, and the curvature histogram the first search ran
    /// on (what a user interface draws).
    std::vector<double> thresholds;
    Histogram histogram;
    /// Automatic mode: every threshold weighed and why it was accepted or not.
    std::vector<ThresholdDecision> decisions;
};

struct ExtractionResult
{
    std::vector<FeatureLine> lines;
    /// J  #J by 3 points where three or more line ends meet.
    PointMatrix junctions;
    double spacing = 0.0;
    /// Per input point: its smooth region (-1 on the band of a sharp edge), its patch (points
    /// of one region between the same two thresholds, connected; -1 off every region), its
    /// Sec. 3 label at the region's first threshold (Low where the region has none;
    /// Outside off every region), and its curvature in the region (NaN off every region).
    std::vector<int> region;
    std::vector<int> patch;
    std::vector<PointLabel> label;
    Eigen::VectorXd curvature;
    std::vector<RegionReport> regions;
    int countLines(LineType type) const;
};

/// The second shared step: sharp edges and boundary, the smooth regions they enclose, and each
/// region's own geometry (smoothing, normals, 1-rings, curvature). It depends on the options
/// of those stages only, so a change of thresholds reuses it.
struct RegionAnalysis
{
    SharpEdges sharp;
    SmoothRegions regions;
    std::vector<RegionGeometry> geometry;
};

RegionAnalysis analyseRegions(const CloudGeometry& geometry, const ExtractionOptions& options = {});

/// The last step: thresholds per region, labels, clusters and smooth-edge lines, merged with
/// the sharp and boundary lines into one result.
ExtractionResult extractFeatureLines(const CloudGeometry& geometry, const RegionAnalysis& regions,
                                     const ExtractionOptions& options = {});

/// All three steps on a cloud. Throws std::invalid_argument for bad input or options and
/// ExtractionCancelled when the progress callback asks to stop.
ExtractionResult extractFeatureLines(const PointMatrix& P, const ExtractionOptions& options = {});

/// Per point of region g its patch: the connected pieces (over the 1-rings, a ring member
/// either way) of the points that lie between the same two of `thresholds`, numbered from
/// `firstId` on in the order of their first points (patchOfRegionPoint, #g.points). Returns
/// the next free number.
int labelPatches(const RegionGeometry& g, const std::vector<double>& thresholds, int firstId,
                 std::vector<int>& patchOfRegionPoint);

} // namespace featurelines
