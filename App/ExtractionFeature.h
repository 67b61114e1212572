// SPDX-License-Identifier: LGPL-2.1-or-later
// FeatureLines::Extraction: the document object that turns a Points object into Part wires.
// execute() gathers the source cloud and the properties, runs the core through the cache
// (ExtractionCache.h) and sets the outputs; everything it needs to know about a parameter is in
// ExtractionParameters.h.
#pragma once

#include <App/PropertyGeo.h>
#include <App/PropertyLinks.h>
#include <App/PropertyStandard.h>
#include <App/PropertyUnits.h>
#include <Mod/Part/App/PartFeature.h>
#include <Mod/Part/App/PropertyTopoShape.h>
#include <TopoDS_Wire.hxx>

#include <string>
#include <vector>

#include "ExtractionParameters.h"
#include "PropertyPointIndices.h"

namespace Points {
class PointKernel;
}

namespace FeatureLines {

class Extraction : public Part::Feature
{
    PROPERTY_HEADER_WITH_OVERRIDE(FeatureLines::Extraction);

public:
    Extraction();

    /// The point cloud: a Points::Feature.
    App::PropertyLink Source;

    // Neighbourhood
    App::PropertyIntegerConstraint NeighbourCount;
    // Sharp edges
    App::PropertyBool SharpEdges;
    App::PropertyBool BoundaryLines;
    App::PropertyAngle GrowAngle;
    App::PropertyAngle JoinAngle;
    App::PropertyFloatConstraint MinFilletRadius;
    App::PropertyFloatConstraint CreaseFitRadius;
    App::PropertyAngle MinCreaseAngle;
    App::PropertyAngle BoundaryGapAngle;
    // Smooth edges
    App::PropertyBool SmoothEdges;
    App::PropertyFloatConstraint BandWidth;
    App::PropertyEnumeration Smoothing;
    App::PropertyIntegerConstraint SmoothingIterations;
    App::PropertyFloatConstraint NoiseThreshold;
    App::PropertyBool SignedCurvature;
    App::PropertyFloatConstraint MaxCurvatureScale;
    App::PropertyBool PlaceCoarseLines;
    // Line graph
    App::PropertyFloatConstraint NodeRadius;
    App::PropertyFloatConstraint ExtendedRadius;
    App::PropertyFloatConstraint MaxEdgeLength;
    App::PropertyFloatConstraint MinBranchLength;
    App::PropertyFloatConstraint ReconnectRadius;
    App::PropertyAngle ReconnectAngle;
    App::PropertyFloatConstraint MinComponentLength;
    App::PropertyFloatConstraint ResampleSpacing;
    // Thresholds
    App::PropertyEnumeration ThresholdMode;
    App::PropertyIntegerConstraint HistogramBins;
    App::PropertyFloatConstraint OutlierPercent;
    App::PropertyFloatConstraint MinPeakPercent;
    App::PropertyIntegerConstraint MaxThresholds;
    App::PropertyFloatConstraint MinValleyRatio;
    App::PropertyFloatConstraint MinContrast;
    App::PropertyFloatList Thresholds;
    App::PropertyMap RegionThresholds;

    // Output: the lines by type (Shape holds them all: sharp, then smooth, then boundary).
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

private:
    void initParameter(App::Property& property, const char* name);
    void setOutputs(const featurelines::ExtractionResult& result, const Base::Matrix4D& toWorld);
};

/// The source cloud's points in its own coordinates (the kernel's stored points) and the
/// matrix to world coordinates (its placement).
featurelines::PointMatrix kernelPoints(const Points::PointKernel& kernel);

/// "sharp" wires etc. in world coordinates; lines whose vertices all coincide are skipped.
struct LineWires
{
    std::vector<TopoDS_Wire> sharp, smooth, boundary;
    /// Per smooth wire: the region and threshold of its line.
    std::vector<long> smoothRegion;
    std::vector<double> smoothThreshold;
    int closed = 0;
};
LineWires makeWires(const featurelines::ExtractionResult& result, const Base::Matrix4D& toWorld);
TopoDS_Shape makeCompound(const std::vector<TopoDS_Wire>& wires);

} // namespace FeatureLines
