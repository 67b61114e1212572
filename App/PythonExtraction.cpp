// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions of an extraction: extract, makeExtraction, parameters, cleanLines.
#include <FCConfig.h>

#include <App/Document.h>
#include <App/DocumentObjectPy.h>
#include <Base/VectorPy.h>
#include <Mod/Part/App/TopoShapeWirePy.h>
#include <Mod/Points/App/PointsFeature.h>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <algorithm>
#include <set>
#include <sstream>

#include "ExtractionCache.h"
#include "ExtractionFeature.h"
#include "ExtractionOutputs.h"
#include "ExtractionParameters.h"
#include "ExtractionProgress.h"
#include "PythonModule.h"
#include "PythonValues.h"

namespace FeatureLines {

namespace {

Py::List wireList(const std::vector<TopoDS_Wire>& wires)
{
    Py::List list;
    for (const TopoDS_Wire& wire : wires) {
        list.append(Py::asObject(new Part::TopoShapeWirePy(new Part::TopoShape(wire))));
    }
    return list;
}

/// The dict extract() returns (its doc string lists the keys).
Py::Dict extractionDict(const ExtractionOutputs& o)
{
    const LineWires& w = o.network.wires;
    Py::Dict out;
    out["sharp"] = wireList(w.sharp);
    out["smooth"] = wireList(w.smooth);
    out["boundary"] = wireList(w.boundary);
    Py::Dict polylines;
    polylines["sharp"] = wireList(o.polylines.sharp);
    polylines["smooth"] = wireList(o.polylines.smooth);
    polylines["boundary"] = wireList(o.polylines.boundary);
    out["polylines"] = polylines;
    out["curve_kinds"] = stringList(o.network.curveKinds);
    out["curve_problems"] = stringList(o.network.curveProblems);
    Py::Dict borders;
    for (size_t i = 0; i < o.network.borderWires.size(); ++i) {
        const Py::Long patch(o.network.borderPatches[i]);
        if (!borders.hasKey(patch)) {
            borders[patch] = Py::List();
        }
        Py::List(borders[patch])
            .append(Py::asObject(
                new Part::TopoShapeWirePy(new Part::TopoShape(o.network.borderWires[i]))));
    }
    out["patch_borders"] = borders;
    Py::Dict open;
    for (size_t i = 0; i < o.network.openPatches.size(); ++i) {
        open[Py::Long(o.network.openPatches[i])] = Py::String(o.network.openPatchReasons[i]);
    }
    out["open_patches"] = open;
    out["smooth_regions"] = intList(w.smoothRegion);
    out["smooth_thresholds"] = estimateList(w.smoothThreshold);
    out["sharp_angles"] = estimateList(w.sharpAngle);
    out["smooth_blend_radii"] = estimateList(w.smoothBlendRadius);
    out["closed"] = Py::Long(w.closed);
    Py::Dict thresholds;
    for (const auto& [region, list] : o.thresholdsByRegion) {
        thresholds[Py::Long(region)] = floatList(list);
    }
    out["thresholds"] = thresholds;
    out["regions"] = intList(o.region);
    out["patches"] = intList(o.patch);
    out["labels"] = intList(o.label);
    out["curvature"] = floatList(o.curvature);
    Py::List junctions;
    for (const Base::Vector3d& junction : o.junctions) {
        junctions.append(Py::asObject(new Base::VectorPy(junction)));
    }
    out["junctions"] = junctions;
    out["spacing"] = Py::Float(o.spacing);
    return out;
}

/// The Extraction object `arg` is, or a TypeError.
Extraction& extractionArgument(const Py::Object& arg, const char* function)
{
    if (PyObject_TypeCheck(arg.ptr(), &App::DocumentObjectPy::Type)) {
        App::DocumentObject* obj =
            static_cast<App::DocumentObjectPy*>(arg.ptr())->getDocumentObjectPtr();
        if (obj && obj->isDerivedFrom(Extraction::getClassTypeId())) {
            return *static_cast<Extraction*>(obj);
        }
    }
    throw Py::TypeError(std::string(function) +
                        " needs a FeatureLines::Extraction object (from makeExtraction or the "
                        "Extract feature lines command)");
}

/// The line ids of wire `wire` of the extraction's Shape (LineIds), checked.
std::vector<long> idsOfWire(const Extraction& e, long wire)
{
    TopTools_IndexedMapOfShape wires;
    TopExp::MapShapes(e.Shape.getValue(), TopAbs_WIRE, wires);
    const std::vector<std::string>& ids = e.LineIds.getValues();
    if (ids.size() != static_cast<size_t>(wires.Extent())) {
        throw Py::ValueError("'" + std::string(e.Label.getValue()) + "' has " +
                             std::to_string(wires.Extent()) + " wires but " +
                             std::to_string(ids.size()) +
                             " line ids: recompute it before removing lines");
    }
    if (wire < 0 || wire >= wires.Extent()) {
        throw Py::ValueError("no wire " + std::to_string(wire) + ": '" +
                             std::string(e.Label.getValue()) + "' has wires 0 to " +
                             std::to_string(wires.Extent() - 1));
    }
    std::istringstream s(ids[static_cast<size_t>(wire)]);
    std::vector<long> out;
    for (long id = 0; s >> id;) {
        out.push_back(id);
    }
    return out;
}

} // namespace

void Module::addExtractionFunctions()
{
    add_keyword_method(
        "extract", &Module::extract,
        "extract(points, **parameters) -> dict\n"
        "Extracts the closed feature lines of a cloud: `points` is a Points object, a\n"
        "Points feature or a list of vectors; the keyword parameters are the properties of a\n"
        "FeatureLines::Extraction object (FeatureLines.parameters() lists them), e.g.\n"
        "extract(cloud, ThresholdMode='Explicit', Thresholds=[0.1]).\n"
        "Returns a dict:\n"
        "  'sharp', 'smooth', 'boundary': lists of Part.Wire in world coordinates, one per\n"
        "      line, on the fitted curves (lines, arcs, circles, B-splines) that share one\n"
        "      vertex where lines meet\n"
        "  'polylines': {'sharp', 'smooth', 'boundary'}: the same lines as the polylines the\n"
        "      curves were fitted to; 'curve_kinds': per edge of the wires (in the order of\n"
        "      Part.makeCompound(sharp + smooth + boundary).Edges) 'segment', 'arc', 'circle',\n"
        "      'bspline' or 'polyline' (no curve fitted: 'curve_problems' says why)\n"
        "  'patch_borders': {patch: [outer wire, hole wires...]} on the same edges;\n"
        "      'open_patches': {patch: why its border is not closed}\n"
        "  'smooth_regions', 'smooth_thresholds': per smooth wire, its region and threshold\n"
        "      (-1 and None for the lines of a blend typed by its profile)\n"
        "  'sharp_angles': per sharp wire, the angle between the faces meeting on it (degrees\n"
        "      inside their wedge); 'smooth_blend_radii': per smooth wire, the radius of the\n"
        "      blend it borders; None where not estimated\n"
        "  'thresholds': {region: [thresholds used, high to low]}\n"
        "  'regions', 'patches', 'labels', 'curvature': per input point (-1 / NaN outside\n"
        "      every region; labels 0 low, 1 inner, 2 border, 3 noisy)\n"
        "  'junctions': vectors where three or more lines meet; 'spacing': mean point\n"
        "      spacing; 'closed': number of closed wires.\n"
        "Raises ValueError for a bad cloud or parameter, RuntimeError when cancelled.");
    add_keyword_method(
        "makeExtraction", &Module::makeExtraction,
        "makeExtraction(points_feature, name='FeatureLines', **parameters) -> object\n"
        "Adds a FeatureLines::Extraction object reading `points_feature` (a Points feature)\n"
        "to its document, with the given parameters (property names). Recompute the\n"
        "document to extract.");
    add_keyword_method(
        "cleanLines", &Module::cleanLines,
        "cleanLines(extraction, minLength=None, remove=None, mergeEndToEnd=None,\n"
        "           restore=False)\n"
        "Cleans the lines of a FeatureLines::Extraction through its Cleaning properties,\n"
        "kept by recomputes: minLength drops lines shorter than it (0 keeps all);\n"
        "remove=[i, ...] deletes wires i of extraction.Shape.Wires (0-based) by adding\n"
        "their line ids (LineIds) to RemovedLines; mergeEndToEnd=True joins two lines\n"
        "whose ends meet where no other line ends. restore=True first brings every\n"
        "line back (RemovedLines, MinLineLength and MergeEndToEnd cleared). Recompute the\n"
        "document to see the result.");
    add_varargs_method(
        "parameters", &Module::listParameters,
        "parameters() -> list of dict\n"
        "Every parameter of an extraction: name, group, doc, kind, default, minimum,\n"
        "maximum, choices. The names are the property names and the keywords of extract().");
}

Py::Object Module::extract(const Py::Tuple& args, const Py::Dict& keywords)
{
    if (args.size() != 1) {
        throw Py::TypeError("extract(points, **parameters) takes one positional argument");
    }
    const Cloud cloud = cloudOf(args[0].ptr());
    featurelines::ExtractionOptions options = toExtractionOptions(parametersOf(keywords));
    ExtractionProgress progress("Feature lines");
    options.progress = progress.callback();
    const featurelines::ExtractionResult r =
        extractCached(cloud.points, hashCloud(cloud.points), options);
    return extractionDict(toOutputs(r, cloud.points, cloud.toWorld));
}

Py::Object Module::makeExtraction(const Py::Tuple& args, const Py::Dict& keywords)
{
    if (args.size() < 1 || args.size() > 2) {
        throw Py::TypeError("makeExtraction(points_feature, name='FeatureLines', "
                            "**parameters)");
    }
    App::DocumentObject* source = nullptr;
    if (PyObject_TypeCheck(args[0].ptr(), &App::DocumentObjectPy::Type)) {
        source = static_cast<App::DocumentObjectPy*>(args[0].ptr())->getDocumentObjectPtr();
    }
    if (!source || !source->isDerivedFrom(Points::Feature::getClassTypeId())) {
        throw Py::TypeError("makeExtraction needs a Points feature of a document (e.g. from "
                            "File > Import), not a " +
                            std::string(Py_TYPE(args[0].ptr())->tp_name));
    }
    std::string name = "FeatureLines";
    if (args.size() == 2) {
        name = Py::String(args[1]).as_std_string();
    } else if (keywords.hasKey("name")) {
        name = Py::String(keywords.getItem("name")).as_std_string();
    }
    const ParameterValues values = parametersOf(keywords, {"name"});
    toExtractionOptions(values); // refuses bad values before the object is added
    auto* obj = static_cast<Extraction*>(
        source->getDocument()->addObject("FeatureLines::Extraction", name.c_str()));
    obj->Source.setValue(source);
    obj->setParameterValues(values);
    return Py::asObject(obj->getPyObject());
}

Py::Object Module::listParameters(const Py::Tuple& args)
{
    if (!PyArg_ParseTuple(args.ptr(), "")) {
        throw Py::Exception();
    }
    static const char* kinds[] = {"Integer", "Float", "Spacing", "Angle", "Switch", "Choice"};
    Py::List list;
    for (const Parameter& p : parameters()) {
        Py::Dict d;
        d["name"] = Py::String(p.name);
        d["group"] = Py::String(p.group);
        d["doc"] = Py::String(p.doc);
        d["kind"] = Py::String(kinds[int(p.kind)]);
        d["default"] = Py::Float(defaultValue(p));
        d["minimum"] = Py::Float(p.minimum);
        d["maximum"] = Py::Float(p.maximum);
        Py::List choices;
        for (int i = 0; p.choices && p.choices[i]; ++i) {
            choices.append(Py::String(p.choices[i]));
        }
        d["choices"] = choices;
        list.append(d);
    }
    for (const auto& [name, doc] : {std::pair(thresholdsName, thresholdsDoc),
                                    std::pair(regionThresholdsName, regionThresholdsDoc)}) {
        Py::Dict d;
        d["name"] = Py::String(name);
        d["group"] = Py::String("Thresholds");
        d["doc"] = Py::String(doc);
        d["kind"] = Py::String(std::string(name) == thresholdsName ? "FloatList" : "Map");
        list.append(d);
    }
    return list;
}

} // namespace FeatureLines

namespace FeatureLines {

Py::Object Module::cleanLines(const Py::Tuple& args, const Py::Dict& keywords)
{
    if (args.size() != 1) {
        throw Py::TypeError("cleanLines(extraction, minLength=None, remove=None, "
                            "mergeEndToEnd=None, restore=False) takes one positional argument");
    }
    Extraction& e = extractionArgument(args[0], "cleanLines");
    const std::set<std::string> known = {"minLength", "remove", "mergeEndToEnd", "restore"};
    for (const auto& key : keywords.keys()) {
        const std::string name = Py::String(key).as_std_string();
        if (!known.count(name)) {
            throw Py::TypeError("cleanLines() has no keyword '" + name +
                                "'; it takes minLength, remove, mergeEndToEnd and restore");
        }
    }
    auto given = [&](const char* name) {
        return keywords.hasKey(name) && keywords.getItem(name).ptr() != Py_None;
    };
    // Everything is read and checked before anything changes.
    double minLength = e.MinLineLength.getValue();
    if (given("minLength")) {
        minLength = Py::Float(keywords.getItem("minLength")).as_double();
        if (!(minLength >= 0.0)) {
            throw Py::ValueError("minLength must be 0 or more, not " + std::to_string(minLength));
        }
    }
    const bool restore = given("restore") && keywords.getItem("restore").isTrue();
    std::vector<long> removed;
    if (!restore) {
        removed = e.RemovedLines.getValues();
    }
    if (given("remove")) {
        const Py::Sequence wires(keywords.getItem("remove"));
        for (Py_ssize_t i = 0; i < wires.length(); ++i) {
            const Py::Object wire = wires[i];
            const std::vector<long> ids = idsOfWire(e, Py::Long(wire).as_long());
            removed.insert(removed.end(), ids.begin(), ids.end());
        }
    }
    std::sort(removed.begin(), removed.end());
    removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
    bool merge = !restore && e.MergeEndToEnd.getValue();
    if (given("mergeEndToEnd")) {
        merge = keywords.getItem("mergeEndToEnd").isTrue();
    }
    if (restore && !given("minLength")) {
        minLength = 0.0;
    }
    e.MinLineLength.setValue(minLength);
    e.RemovedLines.setValues(removed);
    e.MergeEndToEnd.setValue(merge);
    return Py::None();
}

} // namespace FeatureLines
