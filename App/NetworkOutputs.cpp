// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "NetworkOutputs.h"

#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>

#include <map>
#include <set>
#include <stdexcept>

#include "CurveShapes.h"

namespace FeatureLines {

using featurelines::CurveNetwork;
using featurelines::ExtractionResult;
using featurelines::PointMatrix;

namespace {

/// "line 3" or "lines 3 7".
std::string linesName(const std::vector<long>& ids)
{
    std::string s = ids.size() == 1 ? "line" : "lines";
    for (long id : ids) {
        s += " " + std::to_string(id);
    }
    return s;
}

/// The network of the lines kept: the edges of every line some cleaned line is made of.
CurveNetwork keptNetwork(CurveNetwork network, const std::vector<CleanedLine>& lines)
{
    std::set<long> kept;
    for (const CleanedLine& line : lines) {
        kept.insert(line.ids.begin(), line.ids.end());
    }
    std::vector<featurelines::NetworkEdge> edges;
    for (featurelines::NetworkEdge& e : network.edges) {
        if (kept.count(e.line)) {
            edges.push_back(std::move(e));
        }
    }
    network.edges = std::move(edges);
    return network;
}

/// Each line's wire on its fitted edges; a line whose edges make no wire is its polyline.
LineWires fittedWires(const std::vector<CleanedLine>& lines, const CurveNetwork& network,
                      const featurelines::cad::NetworkShapes& shapes, const Base::Matrix4D& toWorld,
                      std::vector<std::string>& problems)
{
    std::multimap<long, size_t> edgesOfLine;
    for (size_t e = 0; e < network.edges.size(); ++e) {
        edgesOfLine.emplace(network.edges[e].line, e);
    }
    return makeWires(lines, [&](const CleanedLine& line, TopoDS_Wire& wire) {
        TopTools_ListOfShape edges;
        for (long id : line.ids) {
            const auto [begin, end] = edgesOfLine.equal_range(id);
            for (auto it = begin; it != end; ++it) {
                if (!shapes.edges[it->second].IsNull()) {
                    edges.Append(shapes.edges[it->second]);
                }
            }
        }
        if (!edges.IsEmpty()) {
            // MakeWire orders the edges of a merged line by their shared vertices.
            BRepBuilderAPI_MakeWire make;
            make.Add(edges);
            if (make.IsDone()) {
                wire = make.Wire();
                return true;
            }
        }
        problems.push_back(linesName(line.ids) +
                           (edges.IsEmpty() ? ": no fitted edge" : ": its edges do not join") +
                           "; drawn as its polyline");
        return polylineWire(line, toWorld, wire);
    });
}

/// Per edge of the wires' compound, in TopExp's order, the kind of its curve.
std::vector<std::string> curveKindsOf(const LineWires& wires, const CurveNetwork& network,
                                      const featurelines::cad::NetworkShapes& shapes)
{
    TopTools_IndexedMapOfShape fitted;
    for (const TopoDS_Edge& e : shapes.edges) {
        fitted.Add(e); // a null edge too, so that the map's index is the edge's row + 1
    }
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(makeCompoundOfAll(wires), TopAbs_EDGE, edges);
    std::vector<std::string> kinds;
    for (int i = 1; i <= edges.Extent(); ++i) {
        const int row = fitted.FindIndex(edges(i)) - 1;
        const bool onCurve = row >= 0 && !shapes.polyline[static_cast<size_t>(row)];
        kinds.emplace_back(onCurve
                               ? curveKindName(network.edges[static_cast<size_t>(row)].curve.kind)
                               : "polyline");
    }
    return kinds;
}

/// "Edge3 Edge7 ...": the wire's edges by their names in `edges` (1-based, as FreeCAD names
/// sub-shapes).
std::string edgeNames(const TopoDS_Wire& wire, const TopTools_IndexedMapOfShape& edges)
{
    std::string names;
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(wire, TopAbs_EDGE, own);
    for (int i = 1; i <= own.Extent(); ++i) {
        names += (names.empty() ? "Edge" : " Edge") + std::to_string(edges.FindIndex(own(i)));
    }
    return names;
}

void addBorders(NetworkOutputs& out, const CurveNetwork& network,
                const featurelines::cad::NetworkShapes& shapes, const ExtractionResult& result,
                const PointMatrix& P)
{
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(makeCompoundOfAll(out.wires), TopAbs_EDGE, edges);
    for (const featurelines::PatchBorder& border : featurelines::patchBorders(network, result, P)) {
        const featurelines::cad::BorderWires wires = makeBorderWires(border, shapes);
        if (wires.wires.empty()) {
            out.openPatches.push_back(border.patch);
            out.openPatchReasons.push_back(wires.problem);
        }
        for (const TopoDS_Wire& w : wires.wires) {
            out.borderWires.push_back(w);
            out.borderPatches.push_back(border.patch);
            out.borderEdgeNames.push_back(edgeNames(w, edges));
        }
    }
}

/// A fitted curve farther than this many point spacings from its polyline anywhere is a failed
/// fit (an oscillating B-spline can pass every polyline vertex and loop out between them); the
/// core fits within 0.25 spacing, or three times the noise.
constexpr double maxStray = 2.0;

} // namespace

gp_Trsf toTrsf(const Base::Matrix4D& m)
{
    gp_Trsf trsf;
    trsf.SetValues(m[0][0], m[0][1], m[0][2], m[0][3], //
                   m[1][0], m[1][1], m[1][2], m[1][3], //
                   m[2][0], m[2][1], m[2][2], m[2][3]);
    return trsf;
}

NetworkOutputs makeNetworkOutputs(const ExtractionResult& result, const PointMatrix& P,
                                  const std::vector<CleanedLine>& lines,
                                  const Base::Matrix4D& toWorld, double cornerAngle)
{
    NetworkOutputs out;
    CurveNetwork network;
    try {
        featurelines::CurveFitOptions fit;
        fit.cornerAngle = cornerAngle;
        network = keptNetwork(featurelines::fitCurveNetwork(result, fit), lines);
    } catch (const std::exception& e) {
        // Never a failed recompute for want of curves: the lines stay, as polylines.
        out.curveProblems.push_back(std::string("the curves could not be fitted (") + e.what() +
                                    "); every line is drawn as its polyline");
        out.wires = makePolylineWires(lines, toWorld);
        out.curveKinds = curveKindsOf(out.wires, {}, {});
        return out;
    }
    const featurelines::cad::NetworkShapes shapes =
        featurelines::cad::makeNetworkShapes(network, toTrsf(toWorld), maxStray * result.spacing);
    out.curveProblems = shapes.problems;
    out.wires = fittedWires(lines, network, shapes, toWorld, out.curveProblems);
    out.curveKinds = curveKindsOf(out.wires, network, shapes);
    try {
        addBorders(out, network, shapes, result, P);
    } catch (const std::exception& e) {
        out.curveProblems.push_back(std::string("the patches' borders could not be traced (") +
                                    e.what() + ")");
    } catch (const Standard_Failure& e) {
        out.curveProblems.push_back(
            std::string("the patches' borders could not be traced (OpenCASCADE: ") +
            e.GetMessageString() + ")");
    }
    return out;
}

} // namespace FeatureLines
