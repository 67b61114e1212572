// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions of an extraction: extract, makeExtraction, parameters.
#include <FCConfig.h>

#include <App/Document.h>
#include <App/DocumentObjectPy.h>
#include <Base/VectorPy.h>
#include <Mod/Part/App/TopoShapeWirePy.h>
#include <Mod/Points/App/PointsFeature.h>

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
    const LineWires& w = o.wires;
    Py::Dict out;
    out["sharp"] = wireList(w.sharp);
    out["smooth"] = wireList(w.smooth);
    out["boundary"] = wireList(w.boundary);
    out["smooth_regions"] = intList(w.smoothRegion);
    out["smooth_thresholds"] = floatList(w.smoothThreshold);
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
        "  'sharp', 'smooth', 'boundary': lists of Part.Wire in world coordinates\n"
        "  'smooth_regions', 'smooth_thresholds': per smooth wire, its region and threshold\n"
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
    return extractionDict(toOutputs(r, cloud.toWorld));
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
