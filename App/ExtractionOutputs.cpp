// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ExtractionOutputs.h"

#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

#include <Mod/Points/App/Points.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "NetworkOutputs.h"

namespace FeatureLines {

using featurelines::ExtractionResult;
using featurelines::LineType;
using featurelines::PointMatrix;

namespace {

/// The line's vertices in world coordinates, without the ones closer than OCCT's confusion
/// tolerance to the previous (they would make degenerate edges); a closed line also drops the
/// last vertices that coincide with the first. `closed` says whether the wire closes.
std::vector<gp_Pnt> wireVertices(const featurelines::FeatureLine& line,
                                 const Base::Matrix4D& toWorld, bool& closed)
{
    std::vector<gp_Pnt> vertices;
    for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
        const Base::Vector3d p = worldPoint(toWorld, line.points, i);
        const gp_Pnt v(p.x, p.y, p.z);
        if (vertices.empty() || v.Distance(vertices.back()) > Precision::Confusion()) {
            vertices.push_back(v);
        }
    }
    closed = line.closed;
    while (closed && vertices.size() > 1 &&
           vertices.back().Distance(vertices.front()) <= Precision::Confusion()) {
        vertices.pop_back();
    }
    closed = closed && vertices.size() >= 3;
    return vertices;
}

void addWire(LineWires& out, const CleanedLine& cleaned, const TopoDS_Wire& wire)
{
    const featurelines::FeatureLine& line = cleaned.line;
    switch (line.type) {
    case LineType::Sharp:
        out.sharp.push_back(wire);
        out.sharpIds.push_back(cleaned.ids);
        out.sharpAngle.push_back(line.angle);
        break;
    case LineType::Smooth:
        out.smooth.push_back(wire);
        out.smoothIds.push_back(cleaned.ids);
        out.smoothRegion.push_back(line.region);
        out.smoothThreshold.push_back(line.threshold);
        out.smoothBlendRadius.push_back(line.blendRadius);
        break;
    case LineType::Boundary:
        out.boundary.push_back(wire);
        out.boundaryIds.push_back(cleaned.ids);
        break;
    }
}

/// The line's length in world coordinates (a closed line's closing segment included).
double worldLength(const featurelines::FeatureLine& line, const Base::Matrix4D& toWorld)
{
    double length = 0.0;
    const Eigen::Index n = line.points.rows();
    for (Eigen::Index i = 1; i < n; ++i) {
        length += Base::Distance(worldPoint(toWorld, line.points, i - 1),
                                 worldPoint(toWorld, line.points, i));
    }
    if (line.closed && n > 2) {
        length += Base::Distance(worldPoint(toWorld, line.points, n - 1),
                                 worldPoint(toWorld, line.points, 0));
    }
    return length;
}

/// The line run the other way.
void reverse(CleanedLine& c)
{
    c.line.points = c.line.points.colwise().reverse().eval();
    std::swap(c.line.startJunction, c.line.endJunction);
}

bool mergeable(const featurelines::FeatureLine& a, const featurelines::FeatureLine& b)
{
    // A blend's borders have no threshold (NaN): two pieces of them join like two of one level.
    const bool sameThreshold =
        a.threshold == b.threshold || (std::isnan(a.threshold) && std::isnan(b.threshold));
    return a.type == b.type && a.region == b.region &&
           (a.type != LineType::Smooth || sameThreshold);
}

/// The estimate of a line joined from pieces of lengths `la` and `lb` whose estimates are `a`
/// and `b`: their mean weighted by length over the pieces that have one (not NaN); NaN when
/// neither has.
double joinedEstimate(double a, double la, double b, double lb)
{
    if (std::isnan(a) || std::isnan(b)) {
        return std::isnan(a) ? b : a;
    }
    return la + lb > 0.0 ? (a * la + b * lb) / (la + lb) : 0.5 * (a + b);
}

/// `b` appended to `a`, both open and meeting at junction `j` (a's end, b's start after turning
/// them): a line from a's start to b's end, closed when those are one junction.
CleanedLine joined(CleanedLine a, CleanedLine b, int j)
{
    // Lengths in the cloud's coordinates: their ratio is that of the world's (a placement).
    const double la = worldLength(a.line, Base::Matrix4D());
    const double lb = worldLength(b.line, Base::Matrix4D());
    if (a.line.endJunction != j) {
        reverse(a);
    }
    if (b.line.startJunction != j) {
        reverse(b);
    }
    const Eigen::Index na = a.line.points.rows(), nb = b.line.points.rows();
    PointMatrix points(na + nb - 1, 3);
    points.topRows(na) = a.line.points;
    points.bottomRows(nb - 1) = b.line.points.bottomRows(nb - 1); // b's first is the junction
    CleanedLine out = a;
    out.line.points = points;
    out.line.endJunction = b.line.endJunction;
    out.line.angle = joinedEstimate(a.line.angle, la, b.line.angle, lb);
    out.line.blendRadius = joinedEstimate(a.line.blendRadius, la, b.line.blendRadius, lb);
    out.ids.insert(out.ids.end(), b.ids.begin(), b.ids.end());
    std::sort(out.ids.begin(), out.ids.end());
    if (out.line.startJunction >= 0 && out.line.startJunction == out.line.endJunction) {
        out.line.closed = true; // both ends on one junction: a loop (last vertex dropped)
        out.line.points.conservativeResize(out.line.points.rows() - 1, 3);
        out.line.startJunction = out.line.endJunction = -1;
    }
    return out;
}

/// One merge of two lines meeting end to end at a junction no other line ends on; false when
/// there is none.
bool mergeOnce(std::vector<CleanedLine>& lines)
{
    std::map<int, std::vector<size_t>> ends; // junction -> the lines ending there, once per end
    for (size_t i = 0; i < lines.size(); ++i) {
        const featurelines::FeatureLine& l = lines[i].line;
        if (l.closed || l.points.rows() < 2) {
            continue;
        }
        for (int j : {l.startJunction, l.endJunction}) {
            if (j >= 0) {
                ends[j].push_back(i);
            }
        }
    }
    for (const auto& [j, at] : ends) {
        if (at.size() != 2 || at[0] == at[1] || !mergeable(lines[at[0]].line, lines[at[1]].line)) {
            continue;
        }
        lines[at[0]] = joined(lines[at[0]], lines[at[1]], j);
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at[1]));
        return true;
    }
    return false;
}

std::vector<Base::Vector3d> worldJunctions(const ExtractionResult& r, const Base::Matrix4D& toWorld)
{
    std::vector<Base::Vector3d> junctions;
    for (Eigen::Index j = 0; j < r.junctions.rows(); ++j) {
        junctions.push_back(worldPoint(toWorld, r.junctions, j));
    }
    return junctions;
}

void setThresholds(ExtractionOutputs& out, const ExtractionResult& r)
{
    for (const featurelines::RegionReport& report : r.regions) {
        out.thresholdsByRegion.emplace_back(report.region, report.thresholds);
        for (double t : report.thresholds) {
            out.usedThresholds.push_back(t);
            out.usedThresholdRegions.push_back(report.region);
        }
    }
}

/// The largest number + 1, 0 for none.
long countOf(const std::vector<long>& numbers)
{
    return numbers.empty() ? 0 : *std::max_element(numbers.begin(), numbers.end()) + 1;
}

void setPerPoint(ExtractionOutputs& out, const ExtractionResult& r)
{
    out.region.assign(r.region.begin(), r.region.end());
    out.patch.assign(r.patch.begin(), r.patch.end());
    out.label = labelValues<long>(r.label);
    out.curvature.assign(r.curvature.data(), r.curvature.data() + r.curvature.size());
    out.regionCount = countOf(out.region);
    out.patchCount = countOf(out.patch);
}

} // namespace

PointMatrix kernelPoints(const Points::PointKernel& kernel)
{
    const auto& stored = kernel.getBasicPoints();
    PointMatrix P(static_cast<Eigen::Index>(stored.size()), 3);
    for (size_t i = 0; i < stored.size(); ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        P(row, 0) = stored[i].x;
        P(row, 1) = stored[i].y;
        P(row, 2) = stored[i].z;
    }
    return P;
}

Base::Vector3d worldPoint(const Base::Matrix4D& toWorld, const PointMatrix& points,
                          Eigen::Index row)
{
    return toWorld * Base::Vector3d(points(row, 0), points(row, 1), points(row, 2));
}

int labelValue(featurelines::PointLabel label)
{
    return label == featurelines::PointLabel::Outside ? -1 : int(label);
}

std::vector<CleanedLine> cleanLines(const std::vector<featurelines::FeatureLine>& lines,
                                    const LineCleaning& cleaning, const Base::Matrix4D& toWorld)
{
    const std::set<long> removed(cleaning.removed.begin(), cleaning.removed.end());
    std::vector<CleanedLine> out;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (!removed.count(static_cast<long>(i))) {
            out.push_back({lines[i], {static_cast<long>(i)}});
        }
    }
    if (cleaning.mergeEndToEnd) {
        while (mergeOnce(out)) {
        }
    }
    if (cleaning.minLength > 0.0) {
        out.erase(std::remove_if(out.begin(), out.end(),
                                 [&](const CleanedLine& c) {
                                     return worldLength(c.line, toWorld) < cleaning.minLength;
                                 }),
                  out.end());
    }
    return out;
}

std::vector<std::string> wireLineIds(const LineWires& w)
{
    std::vector<std::string> out;
    for (const auto* ids : {&w.sharpIds, &w.smoothIds, &w.boundaryIds}) {
        for (const std::vector<long>& wire : *ids) {
            std::string s;
            for (long id : wire) {
                s += (s.empty() ? "" : " ") + std::to_string(id);
            }
            out.push_back(s);
        }
    }
    return out;
}

bool polylineWire(const CleanedLine& cleaned, const Base::Matrix4D& toWorld, TopoDS_Wire& wire)
{
    bool closed = false;
    const std::vector<gp_Pnt> vertices = wireVertices(cleaned.line, toWorld, closed);
    if (vertices.size() < 2) {
        return false; // all vertices coincide: no wire
    }
    BRepBuilderAPI_MakePolygon polygon;
    for (const gp_Pnt& v : vertices) {
        polygon.Add(v);
    }
    if (closed) {
        polygon.Close();
    }
    if (!polygon.IsDone()) {
        return false;
    }
    wire = polygon.Wire();
    return true;
}

LineWires makeWires(const std::vector<CleanedLine>& lines, const WireOfLine& wireOf)
{
    LineWires out;
    for (const CleanedLine& cleaned : lines) {
        TopoDS_Wire wire;
        if (wireOf(cleaned, wire)) {
            out.closed += BRep_Tool::IsClosed(wire) ? 1 : 0;
            addWire(out, cleaned, wire);
        }
    }
    return out;
}

LineWires makePolylineWires(const std::vector<CleanedLine>& lines, const Base::Matrix4D& toWorld)
{
    return makeWires(lines, [&](const CleanedLine& line, TopoDS_Wire& wire) {
        return polylineWire(line, toWorld, wire);
    });
}

TopoDS_Shape makeCompound(const std::vector<TopoDS_Wire>& wires)
{
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (const TopoDS_Wire& wire : wires) {
        builder.Add(compound, wire);
    }
    return compound;
}

TopoDS_Shape makeCompoundOfAll(const LineWires& w)
{
    std::vector<TopoDS_Wire> all = w.sharp;
    all.insert(all.end(), w.smooth.begin(), w.smooth.end());
    all.insert(all.end(), w.boundary.begin(), w.boundary.end());
    return makeCompound(all);
}

ExtractionOutputs toOutputs(const ExtractionResult& result, const PointMatrix& P,
                            const Base::Matrix4D& toWorld, const LineCleaning& cleaning)
{
    ExtractionOutputs out;
    const std::vector<CleanedLine> lines = cleanLines(result.lines, cleaning, toWorld);
    out.polylines = makePolylineWires(lines, toWorld);
    out.network = makeNetworkOutputs(result, P, lines, toWorld, cleaning.cornerAngle);
    out.junctions = worldJunctions(result, toWorld);
    out.spacing = result.spacing;
    setThresholds(out, result);
    setPerPoint(out, result);
    return out;
}

} // namespace FeatureLines
