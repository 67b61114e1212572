// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines::Extraction: the document object that turns a Points object into Part wires.
// execute() gathers the source cloud and the properties, runs the core through the cache
// (ExtractionCache.h) and sets the outputs (converted by ExtractionOutputs.h); everything it needs
// to know about a parameter is in ExtractionParameters.h and its table, ParameterTable.h.
#pragma once

#include <App/PropertyGeo.h>
#include <App/PropertyLinks.h>
#include <App/PropertyStandard.h>
#include <App/PropertyUnits.h>
#include <Mod/Part/App/PartFeature.h>
#include <Mod/Part/App/PropertyTopoShape.h>

#include <string>

#include "ExtractionOutputs.h"
#include "ExtractionParameters.h"
#include "PropertyPointIndices.h"

namespace FeatureLines {

/// The property type of a parameter of each kind.
template <ParameterKind kind> struct ParameterProperty;
template <> struct ParameterProperty<ParameterKind::Integer>
{
    using type = App::PropertyIntegerConstraint;
};
template <> struct ParameterProperty<ParameterKind::Float>
{
    using type = App::PropertyFloatConstraint;
};
template <> struct ParameterProperty<ParameterKind::Spacing>
{
    using type = App::PropertyFloatConstraint;
};
template <> struct ParameterProperty<ParameterKind::Angle>
{
    using type = App::PropertyAngle;
};
template <> struct ParameterProperty<ParameterKind::Switch>
{
    using type = App::PropertyBool;
};
template <> struct ParameterProperty<ParameterKind::Choice>
{
    using type = App::PropertyEnumeration;
};

class Extraction : public Part::Feature
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLines::Extraction);

public:
    Extraction();

    /// The point cloud: a Points::Feature.
    App::PropertyLink Source;

    /// The scalar parameters: one property per row of ParameterTable.h, named as the row.
#define FEATURELINES_PARAMETER(name, kind, ...) ParameterProperty<ParameterKind::kind>::type name;
#include "ParameterTable.h"
#undef FEATURELINES_PARAMETER
    /// The list parameters (ExtractionParameters.h).
    App::PropertyFloatList Thresholds;
    App::PropertyMap RegionThresholds;

    /// Cleaning of the lines, applied when the wires are built (LineCleaning): lines shorter
    /// than MinLineLength dropped, the lines RemovedLines names left out, lines meeting end to
    /// end merged when MergeEndToEnd is on. FeatureLines.cleanLines() sets them.
    App::PropertyLength MinLineLength;
    App::PropertyIntegerList RemovedLines;
    App::PropertyBool MergeEndToEnd;
    /// Below 180 degrees: the fitted curves are also cut at the lines' corners.
    App::PropertyAngle CornerAngle;

    // Output: the lines by type (Shape holds them all: sharp, then smooth, then boundary), one
    // wire per line on the fitted network's edges (NetworkOutputs.h).
    Part::PropertyPartShape SharpWires;
    Part::PropertyPartShape SmoothWires;
    Part::PropertyPartShape BoundaryWires;
    App::PropertyInteger SharpLineCount;
    App::PropertyInteger SmoothLineCount;
    App::PropertyInteger BoundaryLineCount;
    App::PropertyInteger ClosedLineCount;
    /// Per wire of SmoothWires: its region and threshold.
    App::PropertyIntegerList SmoothLineRegions;
    App::PropertyFloatList SmoothLineThresholds;
    /// Per wire of SharpWires: the angle between the faces meeting on it, degrees inside their
    /// wedge; per wire of SmoothWires: the radius of the blend it borders. NaN where not
    /// estimated; empty on a document saved before they existed, until it is recomputed.
    App::PropertyFloatList SharpAngles;
    App::PropertyFloatList SmoothBlendRadii;
    /// Per wire of Shape: the ids of the extraction's lines it is made of ("3", or "3 7" for
    /// merged lines), the ids RemovedLines holds.
    App::PropertyStringList LineIds;
    /// The lines as the polylines the curves were fitted to, wire for wire as in Shape.
    Part::PropertyPartShape Polylines;
    /// Per edge of Shape: its curve, "segment", "arc", "circle", "bspline" or "polyline".
    App::PropertyStringList CurveKinds;
    /// One line per edge or line drawn as its polyline because its curve made no edge.
    App::PropertyStringList CurveProblems;
    /// The closed border wires of the patches (outer wire, then holes, patch by patch) on the
    /// edges of Shape, and the patch of each wire.
    Part::PropertyPartShape PatchBorders;
    App::PropertyIntegerList PatchBorderPatches;
    /// Per wire of PatchBorders: its edges' names in Shape, "Edge3 Edge7 ...".
    App::PropertyStringList PatchBorderEdges;
    /// The patches the lines found leave open (no wire in PatchBorders), and why.
    App::PropertyIntegerList OpenPatches;
    App::PropertyStringList OpenPatchReasons;
    App::PropertyVectorList Junctions;
    App::PropertyLength Spacing;
    App::PropertyInteger RegionCount;
    App::PropertyInteger PatchCount;
    /// The thresholds used, high to low per region, and their regions (parallel lists).
    App::PropertyFloatList UsedThresholds;
    App::PropertyIntegerList UsedThresholdRegions;
    /// Per point of the source, in its order.
    PropertyPointIndices PointRegion;
    PropertyPointIndices PointPatch;
    PropertyPointIndices PointLabel;
    App::PropertyFloatList PointCurvature;

    App::DocumentObjectExecReturn* execute() override;
    /// Also true after a restore found the stored result damaged, so a recompute rebuilds it.
    short mustExecute() const override;
    /// Lines coloured by type, the task panel on double click (Gui/ViewProviderExtraction.h);
    /// FreeCAD loads FeatureLinesGui for it when a document holding the object is opened.
    const char* getViewProviderName() const override
    {
        return "FeatureLinesGui::ViewProviderExtraction";
    }

    /// The parameter values the properties hold, for toExtractionOptions().
    ParameterValues parameterValues() const;
    /// Sets the properties of the parameters given (the others keep their values).
    void setParameterValues(const ParameterValues& values);

protected:
    void onChanged(const App::Property* prop) override;
    /// Checks what was read back (StoredResult.h): a damaged result puts the object in error
    /// with a message naming the property (FreeCAD logs an exception thrown here as the
    /// object's error) and asks for a recompute.
    void onDocumentRestored() override;

private:
    void initParameter(App::Property& property, const char* name);
    void setOutputs(const ExtractionOutputs& outputs);
    /// The network's problems in the report view: edges drawn as polylines, open patches.
    void reportNetwork(const NetworkOutputs& network) const;
    /// The cleaning the properties ask for.
    LineCleaning lineCleaning() const;

    /// Set by onDocumentRestored when the stored result is damaged, cleared by execute().
    bool damagedOnRestore = false;
};

} // namespace FeatureLines
