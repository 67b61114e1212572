// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines::PatchSurfaces: the parametric document object of issue 21's first step. Its Source is
// an Extraction; execute() fits a surface to every patch whose border the lines close, trims it
// by that border and sews the faces (Surfaces/PatchSurfaces.h), so the faces follow the lines
// when the extraction recomputes. A recompute that makes no face fails with the reason and keeps
// the faces of the run before.
#pragma once

#include <App/PropertyLinks.h>
#include <App/PropertyStandard.h>
#include <Mod/Part/App/PartFeature.h>

#include <string>
#include <vector>

#include "PatchSurfaces.h"

namespace FeatureLines {

class Extraction;

/// The patches of `extraction`'s stored result (checked current: requireCurrentResult, naming
/// `caller`) of at least `minPoints` points (0: twice NeighbourCount), each with its points
/// (world coordinates) and its closed border wires from PatchBorders, fitted and sewn. With
/// `pointDeviations`, per point of the extraction's cloud its deviation from its face
/// (PatchFace::deviations), NaN for the points of no face.
featurelines::surfaces::PatchSurfaces surfacesOf(const Extraction& extraction, int minPoints,
                                                 const std::string& caller,
                                                 std::vector<double>* pointDeviations = nullptr);

class PatchSurfaces : public Part::Feature
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLines::PatchSurfaces);

public:
    PatchSurfaces();

    /// The extraction whose patches get surfaces: a FeatureLines::Extraction.
    App::PropertyLink Source;
    /// Patches of fewer points get no surface (0: twice the extraction's NeighbourCount).
    App::PropertyIntegerConstraint MinPoints;

    /// Per patch tried, in patch order: its number, its surface's kind ("plane", "sphere",
    /// "cylinder", "cone", "torus", "bspline"; "" without a face), and its points' RMS and
    /// largest distance from the surface (mm; 0 without a face).
    App::PropertyIntegerList FacePatches;
    App::PropertyStringList FaceKinds;
    App::PropertyFloatList FaceRmsDeviations;
    App::PropertyFloatList FaceMaxDeviations;
    /// Why a patch got no face, one line per such patch.
    App::PropertyStringList Problems;
    /// The faces closed into one solid; BRepCheck finds the shape valid; the largest edge or
    /// vertex tolerance after sewing (mm).
    App::PropertyBool IsSolid;
    App::PropertyBool IsValid;
    App::PropertyFloat SewingTolerance;
    /// Per point of the source cloud: its signed distance from its patch's surface, positive
    /// on the side the face's normal points to (out of the solid), NaN for the points of no
    /// face (mm). The view's deviation colour map shows it.
    App::PropertyFloatList PointDeviations;

    App::DocumentObjectExecReturn* execute() override;
    const char* getViewProviderName() const override
    {
        return "FeatureLinesGui::ViewProviderPatchSurfaces";
    }
};

} // namespace FeatureLines
