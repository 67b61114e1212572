// SPDX-License-Identifier: LGPL-2.1-or-later
// The one conversion of the core's result (featurelines::ExtractionResult) into FreeCAD data:
// Part wires by line type, the thresholds used, per-point arrays and junctions, in world
// coordinates. The document object (Extraction::setOutputs), the Python API (extract()) and the
// task panel all read the result through it, so a line, a label or a junction means the same
// thing in each.
#pragma once

#include <Base/Matrix.h>
#include <Base/Vector3D.h>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "FeatureLines/Extraction.h"

namespace Points {
class PointKernel;
}

namespace FeatureLines {

/// The source cloud's points in its own coordinates (the kernel's stored points); the matrix to
/// world coordinates is the kernel's transform (its placement).
featurelines::PointMatrix kernelPoints(const Points::PointKernel& kernel);

/// Row `row` of `points` (x, y, z in the cloud's coordinates) in world coordinates.
Base::Vector3d worldPoint(const Base::Matrix4D& toWorld, const featurelines::PointMatrix& points,
                          Eigen::Index row);

/// A point's Sec. 3 label as FreeCAD shows it: 0 low, 1 inner, 2 border, 3 noisy, -1 outside
/// every region.
int labelValue(featurelines::PointLabel label);
/// labelValue of every label, in order.
template <class Int>
std::vector<Int> labelValues(const std::vector<featurelines::PointLabel>& labels)
{
    std::vector<Int> values(labels.size());
    for (size_t i = 0; i < labels.size(); ++i) {
        values[i] = Int(labelValue(labels[i]));
    }
    return values;
}

/// What the user cleaned of the lines after the extraction (the Extraction's "Cleaning"
/// properties). A line's id is its place in the core's result (ExtractionResult::lines), the same
/// for the same cloud and parameters.
struct LineCleaning
{
    /// Lines (after merging) shorter than this, in world units, are dropped; 0 keeps all.
    double minLength = 0.0;
    /// Ids of lines removed (before merging).
    std::vector<long> removed;
    /// Two lines whose ends sit on one junction where no other remaining line ends become one.
    bool mergeEndToEnd = false;
    /// Below 180: the fitted curves are also cut where a line's direction breaks by this many
    /// degrees (featurelines::CurveFitOptions::cornerAngle).
    double cornerAngle = 180.0;
};

/// A line of the result after cleaning, with the ids of the result's lines it is made of.
struct CleanedLine
{
    featurelines::FeatureLine line;
    std::vector<long> ids;
};

/// The result's lines cleaned: the removed ones left out, then lines meeting end to end merged
/// (when asked; a merge of lines of one type, and for smooth lines of one region and threshold;
/// its angle and blend radius are those of the pieces weighted by their lengths, of the
/// estimated pieces only, NaN when none was), then the ones shorter than minLength (measured in
/// world coordinates) dropped. Ids out of range are ignored.
std::vector<CleanedLine> cleanLines(const std::vector<featurelines::FeatureLine>& lines,
                                    const LineCleaning& cleaning, const Base::Matrix4D& toWorld);

/// The lines as wires by type, in world coordinates.
struct LineWires
{
    std::vector<TopoDS_Wire> sharp, smooth, boundary;
    /// Per wire of each type: the ids of the result's lines it is made of.
    std::vector<std::vector<long>> sharpIds, smoothIds, boundaryIds;
    /// Per smooth wire: the region and threshold of its line.
    std::vector<long> smoothRegion;
    std::vector<double> smoothThreshold;
    /// Per sharp wire: its line's angle (FeatureLine::angle, degrees); per smooth wire: its
    /// line's blend radius (FeatureLine::blendRadius, the cloud's units). NaN where not
    /// estimated.
    std::vector<double> sharpAngle;
    std::vector<double> smoothBlendRadius;
    int closed = 0;
};
/// How one line becomes a wire: false when it makes none.
using WireOfLine = std::function<bool(const CleanedLine& line, TopoDS_Wire& wire)>;
/// The lines as wires by type, each made by `wireOf`; the lines it makes no wire of are skipped.
LineWires makeWires(const std::vector<CleanedLine>& lines, const WireOfLine& wireOf);
/// The line's polyline as a wire of straight edges, in world coordinates; false when its
/// vertices all coincide.
bool polylineWire(const CleanedLine& line, const Base::Matrix4D& toWorld, TopoDS_Wire& wire);
/// The lines as their polylines (makeWires with polylineWire).
LineWires makePolylineWires(const std::vector<CleanedLine>& lines, const Base::Matrix4D& toWorld);
/// The ids of every wire in the order of makeCompoundOfAll, one "3" or "3 7" string per wire.
std::vector<std::string> wireLineIds(const LineWires& wires);
/// A compound of the wires, in order.
TopoDS_Shape makeCompound(const std::vector<TopoDS_Wire>& wires);
/// A compound of every wire: the sharp ones, then the smooth ones, then the boundary.
TopoDS_Shape makeCompoundOfAll(const LineWires& wires);

/// The fitted line network as FreeCAD shows it (NetworkOutputs.h builds it): the lines on the
/// network's edges, the patches' closed borders, and what could not be fitted or closed.
struct NetworkOutputs
{
    /// One wire per cleaned line (as LineWires orders them), on the fitted edges, which share
    /// one vertex per junction; a line whose edges make no wire is its polyline.
    LineWires wires;
    /// Per edge of makeCompoundOfAll(wires), in TopExp's order: "segment", "arc", "circle",
    /// "bspline", or "polyline" where the fitted curve made no edge.
    std::vector<std::string> curveKinds;
    /// The closed border wires of every patch whose border the lines close (its outer wire
    /// first, then its holes) and the patch of each.
    std::vector<TopoDS_Wire> borderWires;
    std::vector<long> borderPatches;
    /// Per border wire, its edges' names in makeCompoundOfAll(wires), "Edge3 Edge7 ..." (what
    /// a Surface::Filling's BoundaryEdges links).
    std::vector<std::string> borderEdgeNames;
    /// The patches whose border is not closed, and why ("patch 4: ..."), in parallel.
    std::vector<long> openPatches;
    std::vector<std::string> openPatchReasons;
    /// One line per edge drawn as its polyline or left out, and per line without fitted wire.
    std::vector<std::string> curveProblems;
};

/// Everything FreeCAD shows of a result.
struct ExtractionOutputs
{
    /// The lines on the fitted network's edges, the patches' borders (Shape, PatchBorders).
    NetworkOutputs network;
    /// The lines as the polylines the curves were fitted to, wire for wire (Polylines).
    LineWires polylines;
    /// Points where three or more lines meet, in world coordinates.
    std::vector<Base::Vector3d> junctions;
    /// Mean point spacing of the cloud.
    double spacing = 0.0;
    /// Per region of the result, in its order: the region and the thresholds applied, high to
    /// low.
    std::vector<std::pair<long, std::vector<double>>> thresholdsByRegion;
    /// The same thresholds as parallel lists: every threshold and its region.
    std::vector<double> usedThresholds;
    std::vector<long> usedThresholdRegions;
    /// Per input point: its smooth region (-1 on the band of a sharp edge), patch (-1 outside
    /// every region), label (labelValue) and mean curvature (NaN outside every region).
    std::vector<long> region, patch, label;
    std::vector<double> curvature;
    /// The largest region and patch number + 1 (0 when there are none).
    long regionCount = 0;
    long patchCount = 0;
};

/// The result in world coordinates (`toWorld`: the source cloud's placement), its lines cleaned.
/// P  #P by 3 the cloud the result came from, in its own coordinates.
ExtractionOutputs toOutputs(const featurelines::ExtractionResult& result,
                            const featurelines::PointMatrix& P, const Base::Matrix4D& toWorld,
                            const LineCleaning& cleaning = {});

} // namespace FeatureLines
