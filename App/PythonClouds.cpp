// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions for clouds: readCloud, makePatchClouds, patchBorders.
#include <FCConfig.h>

#include <App/Document.h>
#include <App/DocumentObjectGroup.h>
#include <Base/VectorPy.h>
#include <Mod/Part/App/TopoShapeWirePy.h>
#include <Mod/Points/App/Points.h>
#include <Mod/Points/App/PointsFeature.h>
#include <Mod/Points/App/PointsPy.h>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <map>
#include <sstream>

#include "ExtractionFeature.h"
#include "FeatureLines/io/CloudIO.h"
#include "PythonModule.h"
#include "PythonValues.h"
#include "StoredResult.h"

namespace FeatureLines {

using featurelines::PointMatrix;

PatchArguments patchArguments(const Py::Tuple& args, const Py::Dict& keywords,
                              const std::string& function)
{
    PyObject* object = nullptr;
    int minPoints = 0;
    static const char* names[] = {"extraction", "min_points", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|i", const_cast<char**>(names),
                                     &object, &minPoints)) {
        throw Py::Exception();
    }
    Extraction* e = extractionOf(object);
    if (!e) {
        throw Py::TypeError(function + " needs a FeatureLines::Extraction object");
    }
    requireCurrentResult(*e, function);
    return {*e, minPoints};
}

namespace {

/// Per patch of the extraction's points of at least `minPoints` points (0: twice
/// NeighbourCount, the fewest a surface fit can lean on), its points' rows.
std::map<long, std::vector<size_t>> patchMembers(const Extraction& e, int minPoints)
{
    if (minPoints <= 0) {
        minPoints = 2 * static_cast<int>(e.NeighbourCount.getValue());
    }
    const std::vector<long>& patch = e.PointPatch.getValues();
    std::map<long, std::vector<size_t>> members;
    for (size_t i = 0; i < patch.size(); ++i) {
        if (patch[i] >= 0) {
            members[patch[i]].push_back(i);
        }
    }
    for (auto it = members.begin(); it != members.end();) {
        it = static_cast<int>(it->second.size()) < minPoints ? members.erase(it) : std::next(it);
    }
    return members;
}

/// Per patch, its wires in PatchBorders (outer wire first), in world coordinates, and each
/// wire's edge names in Shape (PatchBorderEdges) as a list.
struct BorderWiresOfPatch
{
    Py::List wires, edgeNames;
};
std::map<long, BorderWiresOfPatch> borderWiresOf(const Extraction& e)
{
    std::map<long, BorderWiresOfPatch> out;
    const std::vector<long>& patches = e.PatchBorderPatches.getValues();
    const std::vector<std::string>& names = e.PatchBorderEdges.getValues();
    size_t i = 0;
    const TopoDS_Shape& all = e.PatchBorders.getValue();
    for (TopoDS_Iterator it(all); it.More() && i < patches.size(); it.Next(), ++i) {
        if (it.Value().ShapeType() != TopAbs_WIRE) {
            continue;
        }
        BorderWiresOfPatch& patch = out[patches[i]];
        patch.wires.append(
            Py::asObject(new Part::TopoShapeWirePy(new Part::TopoShape(TopoDS::Wire(it.Value())))));
        Py::List wireNames;
        std::istringstream words(i < names.size() ? names[i] : std::string());
        for (std::string name; words >> name;) {
            wireNames.append(Py::String(name));
        }
        patch.edgeNames.append(wireNames);
    }
    return out;
}

} // namespace

void Module::addCloudFunctions()
{
    add_varargs_method(
        "readCloud", &Module::readCloud,
        "readCloud(path) -> Points.Points\n"
        "Reads a point cloud file (.xyz, .txt, .asc, .csv, .ply, .pcd) into a Points kernel,\n"
        "e.g. Points.show(FeatureLines.readCloud('part.xyz')).\n"
        "Raises ValueError naming the problem for a bad or empty file.");
    add_keyword_method(
        "makePatchClouds", &Module::makePatchClouds,
        "makePatchClouds(extraction, min_points=0) -> list of Points features\n"
        "One Points feature per patch of a recomputed extraction (the points of one smooth\n"
        "region between the same two curvature thresholds), in a new group, so a patch can\n"
        "be handed to surface fitting. Patches of fewer than min_points points are left out\n"
        "(0: twice NeighbourCount, the fewest a surface fit can lean on); no group is made\n"
        "when no patch is left. Raises ValueError naming the problem when the extraction\n"
        "is out of date, failed its last recompute, or holds a damaged result.");
    add_keyword_method(
        "patchBorders", &Module::patchBorders,
        "patchBorders(extraction, min_points=0) -> list of dict\n"
        "Each patch of a recomputed extraction (as makePatchClouds: patches of fewer than\n"
        "min_points points left out) with its points and its border, for surface fitting:\n"
        "  'patch', 'region': its number (PointPatch) and smooth region\n"
        "  'points': its points, a list of FreeCAD.Vector in world coordinates\n"
        "  'wires': its closed border, the outer Part.Wire first, then one per hole, on the\n"
        "      edges of extraction.Shape; 'edge_names': per wire its edges' names in\n"
        "      extraction.Shape, e.g. filling.BoundaryEdges = [(extraction, n) for n in\n"
        "      patch['edge_names'][0]] (Surface::Filling)\n"
        "  'closed': whether the lines close its border; 'reason': why not ('' if closed;\n"
        "      then 'wires' is empty).\n"
        "Raises ValueError as makePatchClouds does.");
}

Py::Object Module::readCloud(const Py::Tuple& args)
{
    char* path = nullptr;
    if (!PyArg_ParseTuple(args.ptr(), "et", "utf-8", &path)) {
        throw Py::Exception();
    }
    std::string file(path);
    PyMem_Free(path);
    const PointMatrix P = featurelines::readCloud(file);
    auto* kernel = new Points::PointKernel(static_cast<Points::PointKernel::size_type>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        kernel->setPoint(static_cast<int>(i), Base::Vector3d(P(i, 0), P(i, 1), P(i, 2)));
    }
    return Py::asObject(new Points::PointsPy(kernel));
}

Py::Object Module::makePatchClouds(const Py::Tuple& args, const Py::Dict& keywords)
{
    const PatchArguments a = patchArguments(args, keywords, "makePatchClouds");
    Extraction& e = a.extraction;
    auto* source = static_cast<Points::Feature*>(e.Source.getValue());
    const std::vector<long>& region = e.PointRegion.getValues();
    const auto& stored = source->Points.getValue().getBasicPoints();
    App::Document* doc = e.getDocument();
    App::DocumentObjectGroup* group = nullptr;
    Py::List created;
    for (const auto& [id, points] : patchMembers(e, a.minPoints)) {
        if (!group) {
            group = static_cast<App::DocumentObjectGroup*>(
                doc->addObject("App::DocumentObjectGroup", "Patches"));
            group->Label.setValue(std::string(e.Label.getValue()) + " patches");
        }
        Points::PointKernel kernel;
        kernel.reserve(points.size());
        for (size_t i : points) {
            kernel.getBasicPoints().push_back(stored[i]);
        }
        auto* cloud = static_cast<Points::Feature*>(doc->addObject("Points::Feature", "Patch"));
        cloud->Points.setValue(kernel);
        cloud->Placement.setValue(source->Placement.getValue());
        cloud->Label.setValue("Patch " + std::to_string(id) + " (region " +
                              std::to_string(region[points.front()]) + ", " +
                              std::to_string(points.size()) + " points)");
        group->addObject(cloud);
        created.append(Py::asObject(cloud->getPyObject()));
    }
    return created;
}

Py::Object Module::patchBorders(const Py::Tuple& args, const Py::Dict& keywords)
{
    const PatchArguments a = patchArguments(args, keywords, "patchBorders");
    Extraction& e = a.extraction;
    const Points::PointKernel& kernel =
        static_cast<Points::Feature*>(e.Source.getValue())->Points.getValue();
    const std::vector<long>& region = e.PointRegion.getValues();
    std::map<long, std::string> reasons;
    const std::vector<long>& open = e.OpenPatches.getValues();
    const std::vector<std::string>& why = e.OpenPatchReasons.getValues();
    for (size_t i = 0; i < open.size() && i < why.size(); ++i) {
        reasons[open[i]] = why[i];
    }
    std::map<long, BorderWiresOfPatch> borders = borderWiresOf(e);
    Py::List out;
    for (const auto& [id, rows] : patchMembers(e, a.minPoints)) {
        Py::List points;
        for (size_t i : rows) {
            points.append(Py::asObject(new Base::VectorPy(kernel.getPoint(i))));
        }
        const auto reason = reasons.find(id);
        const bool closed = borders.count(id) != 0 && reason == reasons.end();
        Py::Dict patch;
        patch["patch"] = Py::Long(id);
        patch["region"] = Py::Long(region[rows.front()]);
        patch["points"] = points;
        patch["wires"] = closed ? borders[id].wires : Py::List();
        patch["edge_names"] = closed ? borders[id].edgeNames : Py::List();
        patch["closed"] = Py::Boolean(closed);
        patch["reason"] = Py::String(closed ? ""
                                     : reason != reasons.end()
                                         ? reason->second
                                         : "patch " + std::to_string(id) + ": no line borders it");
        out.append(patch);
    }
    return out;
}

} // namespace FeatureLines
