// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions fitSurfaces (the patches of a recomputed extraction as fitted surfaces
// trimmed by their closed borders and sewn: Surfaces/PatchSurfaces.h; issue 21, first step) and
// makeSurfaces (the same as a parametric document object, SurfacesFeature.h).
#include <FCConfig.h>

#include <App/Document.h>
#include <Mod/Part/App/TopoShape.h>
#include <Mod/Part/App/TopoShapeFacePy.h>
#include <Mod/Part/App/TopoShapePy.h>

#include <string>

#include "ExtractionFeature.h"
#include "PatchSurfaces.h"
#include "PythonModule.h"
#include "PythonValues.h"
#include "SurfacesFeature.h"

namespace FeatureLines {

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
    add_keyword_method(
        "makeSurfaces", &Module::makeSurfaces,
        "makeSurfaces(extraction, name='Surfaces', min_points=0) -> FeatureLines::PatchSurfaces\n"
        "The parametric object of fitSurfaces: its Source is the extraction, and a recompute\n"
        "fits, trims and sews the faces again when the lines change (FaceKinds,\n"
        "FaceRmsDeviations, FaceMaxDeviations, Problems, IsSolid, IsValid, SewingTolerance,\n"
        "PointDeviations: per point of the cloud its signed distance from its face, NaN off\n"
        "the faces; the view colours the faces by it).\n"
        "A recompute that makes no face fails with the reason and keeps the faces before.\n"
        "Recompute the document to compute it.");
}

Py::Object Module::makeSurfaces(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    const char* name = "Surfaces";
    int minPoints = 0;
    static const char* names[] = {"extraction", "name", "min_points", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|si",
                                     const_cast<char**>(names), &object, &name, &minPoints)) {
        throw Py::Exception();
    }
    Extraction* e = extractionOf(object);
    if (!e) {
        throw Py::TypeError("makeSurfaces needs a FeatureLines::Extraction object");
    }
    if (minPoints < 0) {
        throw Py::ValueError("makeSurfaces: min_points must be 0 or more, got " +
                             std::to_string(minPoints));
    }
    auto* obj = static_cast<PatchSurfaces*>(
        e->getDocument()->addObject("FeatureLines::PatchSurfaces", name));
    obj->Source.setValue(e);
    obj->MinPoints.setValue(minPoints);
    return Py::asObject(obj->getPyObject());
}

Py::Object Module::fitSurfaces(const Py::Tuple& args, const Py::Dict& keywords)
{
    const PatchArguments a = patchArguments(args, keywords, "fitSurfaces");
    const featurelines::surfaces::PatchSurfaces sewn =
        surfacesOf(a.extraction, a.minPoints, "fitSurfaces");
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
