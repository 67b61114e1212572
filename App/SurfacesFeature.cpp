// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines::PatchSurfaces and the gathering of an extraction's patches for the surface fits.
#include <FCConfig.h>

#include <Mod/Points/App/PointsFeature.h>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include "ExtractionFeature.h"
#include "StoredResult.h"
#include "SurfacesFeature.h"

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

featurelines::surfaces::PatchSurfaces surfacesOf(const Extraction& e, int minPoints,
                                                 const std::string& caller,
                                                 std::vector<double>* pointDeviations)
{
    requireCurrentResult(e, caller);
    if (minPoints <= 0) {
        minPoints = 2 * static_cast<int>(e.NeighbourCount.getValue());
    }
    const Points::PointKernel& kernel =
        static_cast<Points::Feature*>(e.Source.getValue())->Points.getValue();
    const std::vector<long>& patch = e.PointPatch.getValues();
    std::map<long, std::vector<size_t>> members;
    for (size_t i = 0; i < patch.size(); ++i) {
        if (patch[i] >= 0) {
            members[patch[i]].push_back(i);
        }
    }
    const std::map<long, std::vector<TopoDS_Wire>> wires = borderWires(e);
    const double spacing = e.Spacing.getValue();
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
        // The noise (< 0) is estimated from each patch's own points.
        faces.push_back(featurelines::surfaces::fitPatchFace(
            static_cast<int>(id), points,
            found == wires.end() ? std::vector<TopoDS_Wire>() : found->second, spacing, -1.0));
        if (found == wires.end()) {
            faces.back().problem = "patch " + std::to_string(id) + ": its border is not closed";
        }
    }
    featurelines::surfaces::PatchSurfaces sewn =
        featurelines::surfaces::sewPatchFaces(std::move(faces), spacing);
    if (pointDeviations) {
        pointDeviations->assign(patch.size(), std::numeric_limits<double>::quiet_NaN());
        for (const featurelines::surfaces::PatchFace& f : sewn.faces) {
            const std::vector<size_t>& rows = members.at(f.patch);
            for (size_t r = 0; r < f.deviations.size() && r < rows.size(); ++r) {
                (*pointDeviations)[rows[r]] = f.deviations[r];
            }
        }
    }
    return sewn;
}

PROPERTY_SOURCE(FeatureLines::PatchSurfaces, Part::Feature)

PatchSurfaces::PatchSurfaces()
{
    ADD_PROPERTY_TYPE(Source, (nullptr), "Surfaces", App::Prop_None,
                      "The extraction whose patches get surfaces: a FeatureLines object.");
    static const App::PropertyIntegerConstraint::Constraints minPoints = {0, 100000000, 1};
    ADD_PROPERTY_TYPE(MinPoints, (0), "Surfaces", App::Prop_None,
                      "Patches of fewer points get no surface (0: twice the extraction's "
                      "NeighbourCount).");
    MinPoints.setConstraints(&minPoints);
    const auto output = static_cast<App::PropertyType>(App::Prop_Output | App::Prop_ReadOnly);
    ADD_PROPERTY_TYPE(FacePatches, (), "Result", output, "Per patch tried: its number.");
    ADD_PROPERTY_TYPE(FaceKinds, (), "Result", output,
                      "Per patch tried: its surface (plane, sphere, cylinder, cone, torus, "
                      "bspline; empty without a face).");
    ADD_PROPERTY_TYPE(FaceRmsDeviations, (), "Result", output,
                      "Per patch tried: its points' RMS distance from the surface (mm).");
    ADD_PROPERTY_TYPE(FaceMaxDeviations, (), "Result", output,
                      "Per patch tried: its points' largest distance from the surface (mm).");
    ADD_PROPERTY_TYPE(Problems, (), "Result", output, "Why a patch got no face.");
    ADD_PROPERTY_TYPE(IsSolid, (false), "Result", output,
                      "The faces close into one solid.");
    ADD_PROPERTY_TYPE(IsValid, (false), "Result", output,
                      "OpenCASCADE's check finds the sewn shape valid.");
    ADD_PROPERTY_TYPE(SewingTolerance, (0.0), "Result", output,
                      "The largest edge or vertex tolerance after sewing (mm).");
    ADD_PROPERTY_TYPE(PointDeviations, (), "Result", output,
                      "Per point of the cloud: its signed distance from its patch's surface, "
                      "positive on the side the face's normal points to (out of a solid; mm); "
                      "NaN for a point of no face.");
}

App::DocumentObjectExecReturn* PatchSurfaces::execute()
{
    auto* extraction = dynamic_cast<Extraction*>(Source.getValue());
    if (!extraction) {
        return new App::DocumentObjectExecReturn(
            "Source must be a FeatureLines extraction (FeatureLines.makeExtraction)");
    }
    featurelines::surfaces::PatchSurfaces sewn;
    std::vector<double> deviations;
    try {
        sewn = surfacesOf(*extraction, static_cast<int>(MinPoints.getValue()),
                          std::string(Label.getValue()), &deviations);
    } catch (const std::exception& e) {
        return new App::DocumentObjectExecReturn(e.what());
    }
    if (sewn.shape.IsNull()) {
        // The faces of the run before stay.
        return new App::DocumentObjectExecReturn(
            "no patch of '" + std::string(extraction->Label.getValue()) + "' got a surface" +
            (sewn.problems.empty() ? std::string(": it has no patch")
                                   : " (" + sewn.problems.front() + ", ...)"));
    }
    std::vector<long> patches;
    std::vector<std::string> kinds;
    std::vector<double> rms;
    std::vector<double> largest;
    for (const featurelines::surfaces::PatchFace& f : sewn.faces) {
        const bool fitted = !f.face.IsNull();
        patches.push_back(f.patch);
        kinds.push_back(fitted ? featurelines::surfaces::surfaceKindName(f.surface.kind) : "");
        rms.push_back(fitted ? f.surface.rmsDeviation : 0.0);
        largest.push_back(fitted ? f.surface.maxDeviation : 0.0);
    }
    Shape.setValue(sewn.shape);
    FacePatches.setValues(patches);
    FaceKinds.setValues(kinds);
    FaceRmsDeviations.setValues(rms);
    FaceMaxDeviations.setValues(largest);
    Problems.setValues(sewn.problems);
    IsSolid.setValue(sewn.solid);
    IsValid.setValue(sewn.valid);
    SewingTolerance.setValue(sewn.tolerance);
    PointDeviations.setValues(deviations);
    return App::DocumentObject::StdReturn;
}

} // namespace FeatureLines
