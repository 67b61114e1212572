// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ExtractionOutputs.h"

#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pnt.hxx>

#include <Mod/Points/App/Points.h>

#include <algorithm>

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

void addWire(LineWires& out, const featurelines::FeatureLine& line, const TopoDS_Wire& wire)
{
    switch (line.type) {
    case LineType::Sharp:
        out.sharp.push_back(wire);
        break;
    case LineType::Smooth:
        out.smooth.push_back(wire);
        out.smoothRegion.push_back(line.region);
        out.smoothThreshold.push_back(line.threshold);
        break;
    case LineType::Boundary:
        out.boundary.push_back(wire);
        break;
    }
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

LineWires makeWires(const ExtractionResult& result, const Base::Matrix4D& toWorld)
{
    LineWires out;
    for (const featurelines::FeatureLine& line : result.lines) {
        bool closed = false;
        const std::vector<gp_Pnt> vertices = wireVertices(line, toWorld, closed);
        if (vertices.size() < 2) {
            continue; // all vertices coincide: no wire
        }
        BRepBuilderAPI_MakePolygon polygon;
        for (const gp_Pnt& v : vertices) {
            polygon.Add(v);
        }
        if (closed) {
            polygon.Close();
        }
        if (!polygon.IsDone()) {
            continue;
        }
        out.closed += closed ? 1 : 0;
        addWire(out, line, polygon.Wire());
    }
    return out;
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

ExtractionOutputs toOutputs(const ExtractionResult& result, const Base::Matrix4D& toWorld)
{
    ExtractionOutputs out;
    out.wires = makeWires(result, toWorld);
    out.junctions = worldJunctions(result, toWorld);
    out.spacing = result.spacing;
    setThresholds(out, result);
    setPerPoint(out, result);
    return out;
}

} // namespace FeatureLines
