// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines::Surfaces: the parametric document object of issue 21's first step. Its Source is
// an Extraction; execute() fits a surface to every patch whose border the lines close, trims it
// by that border and sews the faces (Surfaces/PatchSurfaces.h), so the faces follow the lines
// when the extraction recomputes. A recompute that makes no face fails with the reason and keeps
// the faces of the run before.
#pragma once

#include <App/PropertyLinks.h>
#include <App/PropertyStandard.h>
#include <Mod/Part/App/PartFeature.h>

#include <string>

#include "PatchSurfaces.h"

namespace FeatureLines {

class Extraction;

/// The patches of `extraction`'s stored result (checked current: requireCurrentResult, naming
/// `caller`) of at least `minPoints` points (0: twice NeighbourCount), each with its points
/// (world coordinates) and its closed border wires from PatchBorders, fitted and sewn.
featurelines::surfaces::PatchSurfaces surfacesOf(const Extraction& extraction, int minPoints,
                                                 const std::string& caller);

class Surfaces : public Part::Feature
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLines::Surfaces);

public:
    Surfaces();

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

    App::DocumentObjectExecReturn* execute() override;
};

} // namespace FeatureLines
