// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python function fitSurfaces: the patches of a recomputed extraction as fitted surfaces
// trimmed by their closed borders and sewn (Surfaces/PatchSurfaces.h; issue 21, first step).
#include <FCConfig.h>

#include <Mod/Part/App/TopoShape.h>
#include <Mod/Part/App/TopoShapeFacePy.h>
#include <Mod/Part/App/TopoShapePy.h>
#include <Mod/Points/App/PointsFeature.h>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <map>
#include <vector>

#include "ExtractionFeature.h"
#include "PatchSurfaces.h"
#include "PythonModule.h"
#include "PythonValues.h"
#include "StoredResult.h"

namespace FeatureLines {

namespace {

/// Per patch with a closed border: its wires in PatchBorders (world coordinates), outer first.
std::map<long, std::vector<TopoDS_Wire>> borderWires(const Extraction& e)
{
    std::map<long, std::vector<TopoDS_Wire>> out;
    const std::vector<long>& patches = e.PatchBorderPatches.getValues();
    size_t i = 0;
    for (TopoDS_Iterator it(e.PatchBorders.getValue()); it.More() && i < patches.size();
         it.Next(), ++i) {
        if (it.Value().ShapeType() == TopAbs_WIRE) {
            out[patches[i]].push_back(TopoDS::Wire(it.Value()));
        }
    }
    return out;
}

} // namespace

void Module::addSurfaceFunctions()
{
    add_keyword_method(
        "fitSurfaces", &Module::fitSurfaces,
        "fitSurfaces(extraction, min_points=0) -> dict\n"
        "A surface per patch of a recomputed extraction whose border the lines close: a plane,\n"
        "sphere, cylinder, cone or torus where the patch's points fit one within 0.2 spacing or\n"
        "1.5 times their noise, else a B-spline height field; each trimmed by the patch's border\n"
        "wires, the faces sewn (a solid where they close). Patches of fewer than min_points\n"
        "points are left out (0: twice NeighbourCount). Returns\n"
        "  'shape': the sewn Part.Shape (a solid, a shell or a compound; null without faces)\n"
        "  'solid', 'valid': the faces closed into one solid; BRepCheck finds it valid\n"
        "  'tolerance': the largest edge or vertex tolerance after sewing (mm)\n"
        "  'faces': per patch a dict: 'patch', 'points', 'kind' ('plane', 'sphere', 'cylinder',\n"
        "      'cone', 'torus', 'bspline'), 'rms_deviation' and 'max_deviation' of its points\n"
        "      from the surface (mm), 'radius' (sphere, cylinder, cone at its centre, torus\n"
        "      major), 'face' (Part.Face, or None) and 'problem' ('' when it has a face)\n"
        "e.g. Part.show(FeatureLines.fitSurfaces(extraction)['shape']). Raises ValueError as\n"
        "makePatchClouds does.");
}

Py::Object Module::fitSurfaces(const Py::Tuple& args, const Py::Dict& keywords)
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
        throw Py::TypeError("fitSurfaces needs a FeatureLines::Extraction object");
    }
    requireCurrentResult(*e, "fitSurfaces");
    if (minPoints <= 0) {
        minPoints = 2 * static_cast<int>(e->NeighbourCount.getValue());
    }
    const Points::PointKernel& kernel =
        static_cast<Points::Feature*>(e->Source.getValue())->Points.getValue();
    const std::vector<long>& patch = e->PointPatch.getValues();
    std::map<long, std::vector<size_t>> members;
    for (size_t i = 0; i < patch.size(); ++i) {
        if (patch[i] >= 0) {
            members[patch[i]].push_back(i);
        }
    }
    const std::map<long, std::vector<TopoDS_Wire>> wires = borderWires(*e);
    const double spacing = e->Spacing.getValue();
    std::vector<featurelines::surfaces::PatchFace> faces;
    for (const auto& [id, rows] : members) {
        if (static_cast<int>(rows.size()) < minPoints) {
            continue;
        }
        featurelines::PointMatrix points(static_cast<Eigen::Index>(rows.size()), 3);
        for (size_t r = 0; r < rows.size(); ++r) {
            const Base::Vector3d p = kernel.getPoint(rows[r]);
            points.row(static_cast<Eigen::Index>(r)) << p.x, p.y, p.z;
        }
        const auto found = wires.find(id);
        faces.push_back(featurelines::surfaces::fitPatchFace(
            static_cast<int>(id), points,
            found == wires.end() ? std::vector<TopoDS_Wire>() : found->second, spacing, -1.0));
        if (found == wires.end()) {
            faces.back().problem = "patch " + std::to_string(id) + ": its border is not closed";
        }
    }
    const featurelines::surfaces::PatchSurfaces sewn =
        featurelines::surfaces::sewPatchFaces(std::move(faces), spacing);
    Py::List list;
    for (const featurelines::surfaces::PatchFace& f : sewn.faces) {
        Py::Dict d;
        d["patch"] = Py::Long(f.patch);
        d["points"] = Py::Long(f.points);
        const bool fitted = !f.face.IsNull();
        d["kind"] = fitted ? Py::Object(Py::String(featurelines::surfaces::surfaceKindName(f.surface.kind))) : Py::None();
        d["rms_deviation"] = fitted ? Py::Object(Py::Float(f.surface.rmsDeviation)) : Py::None();
        d["max_deviation"] = fitted ? Py::Object(Py::Float(f.surface.maxDeviation)) : Py::None();
        const bool round = f.surface.kind != featurelines::surfaces::SurfaceKind::Plane &&
                           f.surface.kind != featurelines::surfaces::SurfaceKind::BSpline;
        d["radius"] = fitted && round ? Py::Object(Py::Float(f.surface.radius)) : Py::None();
        d["face"] = fitted ? Py::asObject(new Part::TopoShapeFacePy(new Part::TopoShape(f.face)))
                           : Py::None();
        d["problem"] = Py::String(f.problem);
        list.append(d);
    }
    Py::Dict out;
    out["shape"] = Py::asObject(new Part::TopoShapePy(new Part::TopoShape(sewn.shape)));
    out["solid"] = Py::Boolean(sewn.solid);
    out["valid"] = Py::Boolean(sewn.valid);
    out["tolerance"] = Py::Float(sewn.tolerance);
    out["faces"] = list;
    return out;
}

} // namespace FeatureLines
