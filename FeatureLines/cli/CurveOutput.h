// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted curve network in the featurelines tool's outputs: its JSON (in the lines file)
// and the --curves file, polylines sampled along the curves as OBJ or PLY.
#pragma once

#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "FeatureLines/cli/Arguments.h"
#include "FeatureLines/cli/Json.h"
#include "FeatureLines/cli/OutputFiles.h"
#include "FeatureLines/curves/CurveFit.h"
#include "FeatureLines/curves/CurveNetwork.h"

namespace featurelines::cli {

/// One edge: its line, vertices, curve kind and parameters, and deviations (model units).
inline std::string networkEdgeJson(const NetworkEdge& e)
{
    using namespace json;
    const FittedCurve& c = e.curve;
    Object edge;
    edge.add("type", string(lineTypeName(e.type)))
        .add("line", number(static_cast<long>(e.line)))
        .add("start_vertex", number(static_cast<long>(e.startVertex)))
        .add("end_vertex", number(static_cast<long>(e.endVertex)))
        .add("kind", string(curveKindName(c.kind)));
    if (c.kind == CurveKind::Arc || c.kind == CurveKind::Circle) {
        edge.add("centre", point(c.centre))
            .add("axis", point(c.axis))
            .add("radius", number(c.radius));
    }
    if (c.kind == CurveKind::BSpline) {
        std::vector<long> multiplicities(c.multiplicities.begin(), c.multiplicities.end());
        edge.add("degree", number(static_cast<long>(c.degree)))
            .add("periodic", c.periodic ? "true" : "false")
            .add("poles", points(c.poles))
            .add("knots", array(c.knots))
            .add("multiplicities", array(multiplicities));
    }
    edge.add("length", number(curveLength(c)))
        .add("rms_deviation", number(c.rmsDeviation))
        .add("max_deviation", number(c.maxDeviation));
    return edge.str();
}

inline std::string patchBorderJson(const PatchBorder& b)
{
    using namespace json;
    std::string loops = "[";
    for (std::size_t k = 0; k < b.loops.size(); ++k) {
        loops += k ? ", [" : "[";
        for (std::size_t i = 0; i < b.loops[k].size(); ++i) {
            const LoopEdge& le = b.loops[k][i];
            loops += (i ? ", " : "") + Object()
                                           .add("edge", number(static_cast<long>(le.edge)))
                                           .add("reversed", le.reversed ? "true" : "false")
                                           .str();
        }
        loops += "]";
    }
    loops += "]";
    std::vector<long> open(b.openEdges.begin(), b.openEdges.end());
    return Object()
        .add("patch", number(static_cast<long>(b.patch)))
        .add("closed", b.closed() ? "true" : "false")
        .add("loops", loops)
        .add("open_edges", array(open))
        .str();
}

/// The "network" member of the lines file: vertices, edges and the patches' borders.
inline std::string networkJson(const CurveNetwork& net, const std::vector<PatchBorder>& borders)
{
    std::string edges = "[";
    for (std::size_t i = 0; i < net.edges.size(); ++i) {
        edges += (i ? ",\n    " : "\n    ") + networkEdgeJson(net.edges[i]);
    }
    edges += net.edges.empty() ? "]" : "\n  ]";
    std::string patches = "[";
    for (std::size_t i = 0; i < borders.size(); ++i) {
        patches += (i ? ",\n    " : "\n    ") + patchBorderJson(borders[i]);
    }
    patches += borders.empty() ? "]" : "\n  ]";
    return json::Object()
        .add("vertices", json::points(net.vertices))
        .add("edges", edges)
        .add("patch_borders", patches)
        .str();
}

/// The formats of --curves, by the file's extension.
enum class CurveFileFormat
{
    Obj,
    Ply,
};

/// The format --curves FILE asks for; UsageError for an extension other than .obj or .ply.
inline CurveFileFormat curveFileFormat(const std::string& path)
{
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (extension == ".obj") {
        return CurveFileFormat::Obj;
    }
    if (extension == ".ply") {
        return CurveFileFormat::Ply;
    }
    throw UsageError("--curves " + path + ": the file name must end in .obj or .ply");
}

/// The network as polylines: the vertices first (shared by the edges that meet there), then
/// per edge the samples along its curve at most `step` apart between its two vertices.
struct CurvePolylines
{
    std::vector<Eigen::Vector3d> points;
    std::vector<std::vector<int>> lines;
};

inline CurvePolylines curvePolylines(const CurveNetwork& net, double step)
{
    CurvePolylines out;
    for (Eigen::Index v = 0; v < net.vertices.rows(); ++v) {
        out.points.push_back(net.vertices.row(v).transpose());
    }
    for (const NetworkEdge& e : net.edges) {
        const PointMatrix S = sampleCurve(e.curve, step);
        std::vector<int> line{e.startVertex};
        for (Eigen::Index i = 1; i + 1 < S.rows(); ++i) {
            line.push_back(static_cast<int>(out.points.size()));
            out.points.push_back(S.row(i).transpose());
        }
        line.push_back(e.endVertex);
        out.lines.push_back(std::move(line));
    }
    return out;
}

/// The --curves file's text: OBJ (v and l records, one l per edge) or ASCII PLY (vertex and
/// edge elements, one edge per polyline segment).
inline std::string curveFileText(const CurveNetwork& net, double step, CurveFileFormat format)
{
    const CurvePolylines p = curvePolylines(net, step);
    std::ostringstream out;
    out.precision(9);
    if (format == CurveFileFormat::Obj) {
        out << "# featurelines: " << net.edges.size() << " fitted curves as polylines, "
            << net.vertices.rows() << " shared vertices first\n";
        for (const Eigen::Vector3d& q : p.points) {
            out << "v " << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
        }
        for (std::size_t i = 0; i < p.lines.size(); ++i) {
            const FittedCurve& c = net.edges[i].curve;
            out << "# edge " << i << ' ' << lineTypeName(net.edges[i].type) << ' '
                << curveKindName(c.kind) << '\n'
                << 'l';
            for (int v : p.lines[i]) {
                out << ' ' << v + 1;
            }
            out << '\n';
        }
        return out.str();
    }
    std::size_t segments = 0;
    for (const std::vector<int>& line : p.lines) {
        segments += line.size() - 1;
    }
    out << "ply\nformat ascii 1.0\ncomment featurelines: " << net.edges.size()
        << " fitted curves as polylines\nelement vertex " << p.points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement edge " << segments
        << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    for (const Eigen::Vector3d& q : p.points) {
        out << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
    }
    for (const std::vector<int>& line : p.lines) {
        for (std::size_t k = 0; k + 1 < line.size(); ++k) {
            out << line[k] << ' ' << line[k + 1] << '\n';
        }
    }
    return out.str();
}

} // namespace featurelines::cli
