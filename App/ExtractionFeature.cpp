// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "ExtractionFeature.h"

#include <Base/Console.h>
#include <Base/Exception.h>
#include <Mod/Points/App/PointsFeature.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "ExtractionCache.h"
#include "ExtractionProgress.h"
#include "StoredResult.h"

using namespace FeatureLines;

using featurelines::ExtractionResult;
using featurelines::PointMatrix;

namespace {

/// FreeCAD keeps a pointer to a property's constraints: one instance per parameter, for good.
template <class Constraints> const Constraints* constraintsOf(const Parameter& p)
{
    static std::map<const Parameter*, Constraints> all;
    auto it = all.find(&p);
    if (it == all.end()) {
        Constraints c;
        c.LowerBound = p.minimum;
        c.UpperBound = p.maximum;
        c.StepSize = p.step;
        it = all.emplace(&p, c).first;
    }
    return &it->second;
}

bool hasKind(const App::Property& prop, ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Integer:
        return prop.isDerivedFrom(App::PropertyIntegerConstraint::getClassTypeId());
    case ParameterKind::Float:
    case ParameterKind::Spacing:
        return prop.isDerivedFrom(App::PropertyFloatConstraint::getClassTypeId());
    case ParameterKind::Angle:
        return prop.isDerivedFrom(App::PropertyAngle::getClassTypeId());
    case ParameterKind::Switch:
        return prop.isDerivedFrom(App::PropertyBool::getClassTypeId());
    case ParameterKind::Choice:
        return prop.isDerivedFrom(App::PropertyEnumeration::getClassTypeId());
    }
    return false;
}

double readProperty(const App::Property& prop, ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Integer:
        return double(static_cast<const App::PropertyIntegerConstraint&>(prop).getValue());
    case ParameterKind::Float:
    case ParameterKind::Spacing:
        return static_cast<const App::PropertyFloatConstraint&>(prop).getValue();
    case ParameterKind::Angle:
        return static_cast<const App::PropertyAngle&>(prop).getValue();
    case ParameterKind::Switch:
        return static_cast<const App::PropertyBool&>(prop).getValue() ? 1.0 : 0.0;
    case ParameterKind::Choice:
        return double(static_cast<const App::PropertyEnumeration&>(prop).getValue());
    }
    return 0.0;
}

void writeProperty(App::Property& prop, ParameterKind kind, double value)
{
    switch (kind) {
    case ParameterKind::Integer:
        static_cast<App::PropertyIntegerConstraint&>(prop).setValue(std::lround(value));
        break;
    case ParameterKind::Float:
    case ParameterKind::Spacing:
        static_cast<App::PropertyFloatConstraint&>(prop).setValue(value);
        break;
    case ParameterKind::Angle:
        static_cast<App::PropertyAngle&>(prop).setValue(value);
        break;
    case ParameterKind::Switch:
        static_cast<App::PropertyBool&>(prop).setValue(value != 0.0);
        break;
    case ParameterKind::Choice:
        static_cast<App::PropertyEnumeration&>(prop).setValue(std::lround(value));
        break;
    }
}

constexpr App::PropertyType outputType = App::PropertyType(App::Prop_Output | App::Prop_ReadOnly);
constexpr App::PropertyType perPointType =
    App::PropertyType(App::Prop_Output | App::Prop_ReadOnly | App::Prop_Hidden);

std::string labelOf(const App::DocumentObject* obj)
{
    return obj->Label.getStrValue();
}

std::string formatValue(double v)
{
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

/// Why execute() stops: the message the user reads.
struct ExecError
{
    std::string message;
};

/// The Source, checked to be a point cloud.
const Points::Feature& sourceCloud(const App::DocumentObject* source)
{
    if (!source) {
        throw ExecError{
            "No point cloud: set Source to a Points object (File > Import an .xyz, .asc, .ply "
            "or .pcd file)."};
    }
    if (!source->isDerivedFrom(Points::Feature::getClassTypeId())) {
        throw ExecError{"'" + labelOf(source) +
                        "' is not a point cloud: Source must be a Points object, not a " +
                        source->getTypeId().getName() + "."};
    }
    return *static_cast<const Points::Feature*>(source);
}

/// The core's options from the object's parameters, checked to extract something.
featurelines::ExtractionOptions checkedOptions(const Extraction& extraction)
{
    featurelines::ExtractionOptions options;
    try {
        options = toExtractionOptions(extraction.parameterValues());
    } catch (const std::invalid_argument& e) {
        throw ExecError{e.what()};
    }
    if (!options.sharpEdges && !options.smoothEdges && !options.sharp.includeBoundary) {
        throw ExecError{
            "SharpEdges, SmoothEdges and BoundaryLines are all off: nothing to extract."};
    }
    return options;
}

/// Enough points for the neighbourhoods, and none invalid.
void checkPoints(const Points::PointKernel& kernel, const std::string& label,
                 const featurelines::ExtractionOptions& options)
{
    const size_t needed = static_cast<size_t>(options.neighbours.k) + 1;
    if (kernel.size() < needed) {
        throw ExecError{"Too few points: '" + label + "' has " + std::to_string(kernel.size()) +
                        " points; at least " + std::to_string(needed) +
                        " are needed for NeighbourCount = " + std::to_string(options.neighbours.k) +
                        "."};
    }
    const size_t valid = kernel.countValid();
    if (valid != kernel.size()) {
        throw ExecError{"'" + label + "' has " + std::to_string(kernel.size() - valid) +
                        " invalid (NaN) points; drop them first, e.g. in the Python console: "
                        "cloud.Points = cloud.Points.fromValid()"};
    }
}

/// The core's result for the cloud (through the cache), with progress and cancelling; a result
/// without lines is an error.
ExtractionResult extractLines(const PointMatrix& P, const std::string& label,
                              featurelines::ExtractionOptions options)
{
    ExtractionProgress progress("Feature lines of " + label);
    options.progress = progress.callback();
    ExtractionResult result;
    try {
        result = extractCached(P, hashCloud(P), options);
    } catch (const featurelines::ExtractionCancelled&) {
        throw ExecError{
            "Feature line extraction cancelled by the user; the previous lines are kept."};
    } catch (const std::invalid_argument& e) {
        throw ExecError{"'" + label + "': " + e.what()};
    }
    if (result.lines.empty()) {
        throw ExecError{
            "No feature lines found in '" + label + "' (" + std::to_string(P.rows()) +
            " points, spacing " + formatValue(result.spacing) +
            "): no crease turns beyond GrowAngle and no smooth region's curvature histogram has "
            "a significant valley. Lower GrowAngle for shallow creases, or set ThresholdMode to "
            "Explicit and give Thresholds."};
    }
    return result;
}

} // namespace

PROPERTY_SOURCE(FeatureLines::Extraction, Part::Feature)

Extraction::Extraction()
{
    ADD_PROPERTY_TYPE(Source, (nullptr), "Extraction", App::Prop_None,
                      "The point cloud: a Points object (File > Import an .xyz, .asc, .ply or "
                      ".pcd file).");

    // The scalar parameters, one per row of ParameterTable.h, then the two lists.
#define FEATURELINES_PARAMETER(name, ...) initParameter(name, #name);
#include "ParameterTable.h"
#undef FEATURELINES_PARAMETER
    _ADD_PROPERTY_TYPE(thresholdsName, Thresholds, (), "Thresholds", App::Prop_None, thresholdsDoc);
    _ADD_PROPERTY_TYPE(regionThresholdsName, RegionThresholds, (), "Thresholds", App::Prop_None,
                       regionThresholdsDoc);
    ADD_PROPERTY_TYPE(MinLineLength, (0.0), "Cleaning", App::Prop_None,
                      "Lines shorter than this are dropped (after merging); 0 keeps every line.");
    ADD_PROPERTY_TYPE(RemovedLines, (), "Cleaning", App::Prop_None,
                      "The lines deleted by the user: their ids (see LineIds), which name the "
                      "same lines as long as the cloud and the parameters do not change.");
    ADD_PROPERTY_TYPE(MergeEndToEnd, (false), "Cleaning", App::Prop_None,
                      "Two lines of one kind whose ends meet at a point where no other line "
                      "ends become one line.");
    ADD_PROPERTY_TYPE(CornerAngle, (180.0), "Cleaning", App::Prop_None,
                      "Below 180: the fitted curves are also cut where a line's direction breaks "
                      "by this angle or more, so that a flat face's border between fillets is its "
                      "edges meeting at its corners rather than one closed curve. For clean "
                      "clouds (30 degrees): on noisy or straying lines most corners found are not "
                      "the part's. 180: cut at junctions only.");
    static const App::PropertyQuantityConstraint::Constraints cornerAngles{0.0, 180.0, 5.0};
    CornerAngle.setConstraints(&cornerAngles);

    ADD_PROPERTY_TYPE(SharpWires, (TopoDS_Shape()), "Output", outputType,
                      "The sharp edges: a compound of wires.");
    ADD_PROPERTY_TYPE(SmoothWires, (TopoDS_Shape()), "Output", outputType,
                      "The smooth edges (fillet borders): a compound of wires, one closed set per "
                      "threshold of each region.");
    ADD_PROPERTY_TYPE(BoundaryWires, (TopoDS_Shape()), "Output", outputType,
                      "The boundary of an open cloud: a compound of wires.");
    ADD_PROPERTY_TYPE(SharpLineCount, (0), "Output", outputType, "Wires in SharpWires.");
    ADD_PROPERTY_TYPE(SmoothLineCount, (0), "Output", outputType, "Wires in SmoothWires.");
    ADD_PROPERTY_TYPE(BoundaryLineCount, (0), "Output", outputType, "Wires in BoundaryWires.");
    ADD_PROPERTY_TYPE(ClosedLineCount, (0), "Output", outputType,
                      "Closed wires; the others end on junctions where three or more lines meet.");
    ADD_PROPERTY_TYPE(SmoothLineRegions, (), "Output", outputType,
                      "Per wire of SmoothWires: its smooth region; -1 for the lines of a blend "
                      "typed by its profile (they lie in no region).");
    ADD_PROPERTY_TYPE(SmoothLineThresholds, (), "Output", outputType,
                      "Per wire of SmoothWires: the curvature threshold it borders; NaN for the "
                      "lines of a blend typed by its profile.");
    ADD_PROPERTY_TYPE(SharpAngles, (), "Output", outputType,
                      "Per wire of SharpWires: the angle between the two faces meeting on it, in "
                      "degrees inside their wedge (90 on a box edge, near 180 for a shallow "
                      "crease); NaN where not estimated.");
    ADD_PROPERTY_TYPE(SmoothBlendRadii, (), "Output", outputType,
                      "Per wire of SmoothWires: the radius of the blend (fillet) it borders; NaN "
                      "where not estimated.");
    ADD_PROPERTY_TYPE(LineIds, (), "Output", perPointType,
                      "Per wire of Shape: the ids of the extraction's lines it is made of "
                      "('3', or '3 7' for merged lines), the ids RemovedLines holds.");
    ADD_PROPERTY_TYPE(Polylines, (TopoDS_Shape()), "Output", outputType,
                      "The lines as the polylines the curves of Shape were fitted to, wire for "
                      "wire as in Shape.");
    ADD_PROPERTY_TYPE(CurveKinds, (), "Output", outputType,
                      "Per edge of Shape: its curve (segment, arc, circle, bspline, or polyline "
                      "where no curve could be fitted).");
    ADD_PROPERTY_TYPE(CurveProblems, (), "Output", outputType,
                      "Edges drawn as their polyline because their curve made no edge, and why.");
    ADD_PROPERTY_TYPE(PatchBorders, (TopoDS_Shape()), "Output", outputType,
                      "The closed border wires of the patches, on the edges of Shape: per patch "
                      "its outer wire, then its holes (e.g. for Surface > Filling).");
    ADD_PROPERTY_TYPE(PatchBorderPatches, (), "Output", outputType,
                      "Per wire of PatchBorders: its patch (see PointPatch).");
    ADD_PROPERTY_TYPE(PatchBorderEdges, (), "Output", outputType,
                      "Per wire of PatchBorders: its edges' names in Shape ('Edge3 Edge7 ...'), "
                      "e.g. for a Surface::Filling's BoundaryEdges.");
    ADD_PROPERTY_TYPE(OpenPatches, (), "Output", outputType,
                      "Patches whose border the lines found do not close: no wire in "
                      "PatchBorders.");
    ADD_PROPERTY_TYPE(OpenPatchReasons, (), "Output", outputType,
                      "Per patch of OpenPatches: why its border is not closed.");
    ADD_PROPERTY_TYPE(Junctions, (), "Output", outputType,
                      "Points where three or more lines meet.");
    ADD_PROPERTY_TYPE(Spacing, (0.0), "Output", outputType,
                      "Mean point spacing of the cloud: the unit of every 'x point spacing' "
                      "parameter.");
    ADD_PROPERTY_TYPE(RegionCount, (0), "Output", outputType,
                      "Smooth regions: the parts of the cloud the sharp edges enclose (Sec. 1.2).");
    ADD_PROPERTY_TYPE(PatchCount, (0), "Output", outputType,
                      "Patches: connected points of one region between the same two thresholds.");
    ADD_PROPERTY_TYPE(UsedThresholds, (), "Output", outputType,
                      "The curvature thresholds applied, high to low within each region.");
    ADD_PROPERTY_TYPE(UsedThresholdRegions, (), "Output", outputType,
                      "The region of each of UsedThresholds.");
    ADD_PROPERTY_TYPE(PointRegion, (), "Output", perPointType,
                      "Per source point: its smooth region, -1 on the band of a sharp edge.");
    ADD_PROPERTY_TYPE(PointPatch, (), "Output", perPointType,
                      "Per source point: its patch, -1 outside every region.");
    ADD_PROPERTY_TYPE(PointLabel, (), "Output", perPointType,
                      "Per source point: its Sec. 3 label at its region's first threshold: 0 low, "
                      "1 inner, 2 border, 3 noisy, -1 outside every region.");
    ADD_PROPERTY_TYPE(PointCurvature, (), "Output", perPointType,
                      "Per source point: its mean curvature in its region (NaN outside).");
    // A new object has no result yet: the next recompute runs it (or says what it lacks), as
    // Part::Primitive does. Reopening a document clears this.
    touch();
}

void Extraction::initParameter(App::Property& property, const char* name)
{
    const Parameter* p = findParameter(name);
    if (!p || !hasKind(property, p->kind)) {
        throw Base::RuntimeError(std::string("FeatureLines::Extraction: no parameter ") + name +
                                 " of this property type");
    }
    switch (p->kind) {
    case ParameterKind::Integer: {
        auto& prop = static_cast<App::PropertyIntegerConstraint&>(property);
        prop.setConstraints(constraintsOf<App::PropertyIntegerConstraint::Constraints>(*p));
        break;
    }
    case ParameterKind::Float:
    case ParameterKind::Spacing: {
        auto& prop = static_cast<App::PropertyFloatConstraint&>(property);
        prop.setConstraints(constraintsOf<App::PropertyFloatConstraint::Constraints>(*p));
        break;
    }
    case ParameterKind::Angle: {
        auto& prop = static_cast<App::PropertyAngle&>(property);
        prop.setConstraints(constraintsOf<App::PropertyQuantityConstraint::Constraints>(*p));
        break;
    }
    case ParameterKind::Choice:
        static_cast<App::PropertyEnumeration&>(property).setEnums(
            const_cast<const char**>(p->choices));
        break;
    case ParameterKind::Switch:
        break;
    }
    writeProperty(property, p->kind, defaultValue(*p));
    property.setContainer(this);
    propertyData.addProperty(static_cast<App::PropertyContainer*>(this), p->name, &property,
                             p->group, App::Prop_None, p->doc);
}

ParameterValues Extraction::parameterValues() const
{
    ParameterValues values;
    for (const Parameter& p : parameters()) {
        const App::Property* prop = getPropertyByName(p.name);
        if (!prop) {
            // A parameter of the table without its property: a build error, reported, not a
            // crash.
            throw std::invalid_argument(std::string("the parameter ") + p.name +
                                        " has no property");
        }
        values.scalars[p.name] = readProperty(*prop, p.kind);
    }
    values.thresholds = Thresholds.getValues();
    values.regionThresholds = parseRegionThresholds(RegionThresholds.getValues());
    return values;
}

void Extraction::setParameterValues(const ParameterValues& values)
{
    toExtractionOptions(values); // validates before anything changes
    for (const auto& [name, value] : values.scalars) {
        const Parameter* p = findParameter(name);
        writeProperty(*getPropertyByName(p->name), p->kind, value);
    }
    if (values.thresholds) {
        Thresholds.setValues(*values.thresholds);
    }
    if (values.regionThresholds) {
        RegionThresholds.setValues(formatRegionThresholds(*values.regionThresholds));
    }
}

App::DocumentObjectExecReturn* Extraction::execute()
{
    // Gathers the checked inputs, calls the core, sets the outputs; a check that fails or a run
    // that ends without lines returns its message.
    damagedOnRestore = false;
    try {
        const Points::Feature& cloud = sourceCloud(Source.getValue());
        const featurelines::ExtractionOptions options = checkedOptions(*this);
        const Points::PointKernel& kernel = cloud.Points.getValue();
        checkPoints(kernel, labelOf(&cloud), options);
        const PointMatrix P = kernelPoints(kernel);
        const ExtractionResult result = extractLines(P, labelOf(&cloud), options);
        const ExtractionOutputs outputs =
            toOutputs(result, P, kernel.getTransform(), lineCleaning());
        setOutputs(outputs);
        reportNetwork(outputs.network);
    } catch (const ExecError& e) {
        return new App::DocumentObjectExecReturn(e.message);
    }
    return App::DocumentObject::StdReturn;
}

void Extraction::reportNetwork(const NetworkOutputs& network) const
{
    // Said in the report view; the lists stay on the object (CurveProblems, OpenPatchReasons).
    for (const std::string& problem : network.curveProblems) {
        Base::Console().Warning("%s: %s\n", Label.getValue(), problem.c_str());
    }
    if (!network.openPatches.empty()) {
        Base::Console().Message(
            "%s: %zu of %zu patches have no closed border (OpenPatchReasons "
            "says why)\n",
            Label.getValue(), network.openPatches.size(),
            network.openPatches.size() +
                std::set<long>(network.borderPatches.begin(), network.borderPatches.end()).size());
    }
}

LineCleaning Extraction::lineCleaning() const
{
    LineCleaning cleaning;
    cleaning.minLength = MinLineLength.getValue();
    const std::vector<long>& removed = RemovedLines.getValues();
    cleaning.removed.assign(removed.begin(), removed.end());
    cleaning.mergeEndToEnd = MergeEndToEnd.getValue();
    cleaning.cornerAngle = CornerAngle.getValue();
    return cleaning;
}

void Extraction::setOutputs(const ExtractionOutputs& out)
{
    const LineWires& w = out.network.wires;
    Shape.setValue(makeCompoundOfAll(w));
    LineIds.setValues(wireLineIds(w));

    // Placed with Shape's own location (the object's Placement, which Part::Feature gave it),
    // so that an edge of SharpWires or PatchBorders is the very edge of Shape (isSame).
    auto placed = [&](std::vector<TopoDS_Wire> wires, const std::vector<TopoDS_Wire>& more = {},
                      const std::vector<TopoDS_Wire>& andMore = {}) {
        wires.insert(wires.end(), more.begin(), more.end());
        wires.insert(wires.end(), andMore.begin(), andMore.end());
        TopoDS_Shape shape = makeCompound(wires);
        shape.Location(Shape.getValue().Location());
        return shape;
    };
    SharpWires.setValue(placed(w.sharp));
    SmoothWires.setValue(placed(w.smooth));
    BoundaryWires.setValue(placed(w.boundary));
    SharpLineCount.setValue(static_cast<long>(w.sharp.size()));
    SmoothLineCount.setValue(static_cast<long>(w.smooth.size()));
    BoundaryLineCount.setValue(static_cast<long>(w.boundary.size()));
    ClosedLineCount.setValue(w.closed);
    SmoothLineRegions.setValues(w.smoothRegion);
    SmoothLineThresholds.setValues(w.smoothThreshold);
    SharpAngles.setValues(w.sharpAngle);
    SmoothBlendRadii.setValues(w.smoothBlendRadius);

    Polylines.setValue(placed(out.polylines.sharp, out.polylines.smooth, out.polylines.boundary));
    CurveKinds.setValues(out.network.curveKinds);
    CurveProblems.setValues(out.network.curveProblems);
    PatchBorders.setValue(placed(out.network.borderWires));
    PatchBorderPatches.setValues(out.network.borderPatches);
    PatchBorderEdges.setValues(out.network.borderEdgeNames);
    OpenPatches.setValues(out.network.openPatches);
    OpenPatchReasons.setValues(out.network.openPatchReasons);

    Junctions.setValues(out.junctions);
    Spacing.setValue(out.spacing);
    UsedThresholds.setValues(out.usedThresholds);
    UsedThresholdRegions.setValues(out.usedThresholdRegions);

    RegionCount.setValue(out.regionCount);
    PatchCount.setValue(out.patchCount);
    PointRegion.setValues(out.region);
    PointPatch.setValues(out.patch);
    PointLabel.setValues(out.label);
    PointCurvature.setValues(out.curvature);
}

short Extraction::mustExecute() const
{
    return damagedOnRestore ? 1 : Part::Feature::mustExecute();
}

void Extraction::onDocumentRestored()
{
    Part::Feature::onDocumentRestored();
    // An object saved in error keeps its own message; its lists are those of its last good run,
    // which may predate a change of the source, so only their agreement with one another is
    // checked then.
    const std::string problem = storedResultMismatch(*this, !isError());
    if (!problem.empty()) {
        damagedOnRestore = true;
        throw Base::RuntimeError("the saved result cannot be used: " + problem +
                                 ". Recompute to rebuild it from the source.");
    }
}

void Extraction::onChanged(const App::Property* prop)
{
    Part::Feature::onChanged(prop);
    // The other shapes follow the object's placement as Shape does (Part::Feature::onChanged
    // has just moved it), with Shape's very location: their edges stay Shape's (isSame).
    if (prop == &Placement) {
        for (Part::PropertyPartShape* shape :
             {&SharpWires, &SmoothWires, &BoundaryWires, &Polylines, &PatchBorders}) {
            TopoDS_Shape moved = shape->getValue();
            if (!moved.IsNull()) {
                moved.Location(Shape.getValue().Location());
                const_cast<Part::TopoShape&>(shape->getShape()).setShape(moved);
            }
        }
    }
}
