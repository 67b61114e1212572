// SPDX-License-Identifier: LGPL-2.1-or-later
// The FreeCAD App module FeatureLines: the document object types and the Python functions for
// macros. Keyword parameters of the functions are the document object's property names, mapped
// onto the core's options by the one table of ExtractionParameters.h.
#include <FCConfig.h>

#include <App/Document.h>
#include <App/DocumentObjectGroup.h>
#include <App/DocumentObjectPy.h>
#include <Base/Console.h>
#include <Base/Interpreter.h>
#include <Base/PyObjectBase.h>
#include <Base/QuantityPy.h>
#include <Base/VectorPy.h>
#include <CXX/Extensions.hxx>
#include <CXX/Objects.hxx>
#include <Mod/Part/App/TopoShapeWirePy.h>
#include <Mod/Points/App/Points.h>
#include <Mod/Points/App/PointsFeature.h>
#include <Mod/Points/App/PointsPy.h>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "ExtractionCache.h"
#include "ExtractionFeature.h"
#include "ExtractionParameters.h"
#include "ExtractionProgress.h"
#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "InteractiveThresholds.h"
#include "PropertyPointIndices.h"

namespace FeatureLines {

using featurelines::PointMatrix;

namespace {

/// A cloud handed to a function: its points and the matrix to world coordinates.
struct Cloud
{
    PointMatrix points;
    Base::Matrix4D toWorld;
};

const Points::PointKernel* kernelOf(PyObject* obj)
{
    if (PyObject_TypeCheck(obj, &Points::PointsPy::Type)) {
        return static_cast<Points::PointsPy*>(obj)->getPointKernelPtr();
    }
    if (PyObject_TypeCheck(obj, &App::DocumentObjectPy::Type)) {
        App::DocumentObject* o = static_cast<App::DocumentObjectPy*>(obj)->getDocumentObjectPtr();
        if (o && o->isDerivedFrom(Points::Feature::getClassTypeId())) {
            return &static_cast<Points::Feature*>(o)->Points.getValue();
        }
    }
    return nullptr;
}

Base::Vector3d vectorOf(const Py::Object& item)
{
    if (PyObject_TypeCheck(item.ptr(), &Base::VectorPy::Type)) {
        return *static_cast<Base::VectorPy*>(item.ptr())->getVectorPtr();
    }
    if (item.isSequence() && !PyUnicode_Check(item.ptr())) {
        Py::Sequence xyz(item);
        if (xyz.size() == 3) {
            return Base::Vector3d(double(Py::Float(xyz[0])), double(Py::Float(xyz[1])),
                                  double(Py::Float(xyz[2])));
        }
    }
    throw Py::TypeError("a point must be a FreeCAD.Vector or a sequence of three numbers");
}

/// A Points object (Points.Points), a Points::Feature, or a sequence of vectors.
Cloud cloudOf(PyObject* obj)
{
    if (const Points::PointKernel* kernel = kernelOf(obj)) {
        return {kernelPoints(*kernel), kernel->getTransform()};
    }
    if (PyObject_TypeCheck(obj, &App::DocumentObjectPy::Type)) {
        App::DocumentObject* o = static_cast<App::DocumentObjectPy*>(obj)->getDocumentObjectPtr();
        throw Py::TypeError("'" + std::string(o ? o->Label.getValue() : "?") +
                            "' is not a point cloud: pass a Points object, a Points feature or "
                            "a list of vectors");
    }
    if (!PySequence_Check(obj) || PyUnicode_Check(obj)) {
        throw Py::TypeError("expected a Points object, a Points feature or a list of vectors");
    }
    Py::Sequence items(obj);
    Cloud cloud;
    cloud.points.resize(static_cast<Eigen::Index>(items.size()), 3);
    for (Py::Sequence::size_type i = 0; i < items.size(); ++i) {
        const Base::Vector3d v = vectorOf(items[i]);
        cloud.points.row(static_cast<Eigen::Index>(i)) << v.x, v.y, v.z;
    }
    return cloud;
}

Extraction* extractionOf(PyObject* obj)
{
    if (PyObject_TypeCheck(obj, &App::DocumentObjectPy::Type)) {
        App::DocumentObject* o = static_cast<App::DocumentObjectPy*>(obj)->getDocumentObjectPtr();
        if (o && o->isDerivedFrom(Extraction::getClassTypeId())) {
            return static_cast<Extraction*>(o);
        }
    }
    return nullptr;
}

std::vector<double> numbersOf(const Py::Object& value, const std::string& what)
{
    if (PyUnicode_Check(value.ptr())) {
        return parseThresholds(Py::String(value).as_std_string(), what);
    }
    if (!value.isSequence()) {
        throw Py::TypeError(what + " must be a list of numbers");
    }
    Py::Sequence items(value);
    std::vector<double> out;
    for (Py::Sequence::size_type i = 0; i < items.size(); ++i) {
        if (!PyNumber_Check(items[i].ptr())) {
            throw Py::TypeError(what + " must be a list of numbers");
        }
        out.push_back(double(Py::Float(items[i])));
    }
    return out;
}

std::string parameterNames()
{
    std::string names;
    for (const Parameter& p : parameters()) {
        names += std::string(names.empty() ? "" : ", ") + p.name;
    }
    return names + ", " + thresholdsName + ", " + regionThresholdsName;
}

double scalarOf(const Parameter& p, const Py::Object& value)
{
    PyObject* v = value.ptr();
    switch (p.kind) {
    case ParameterKind::Switch:
        return PyObject_IsTrue(v) ? 1.0 : 0.0;
    case ParameterKind::Choice:
        if (PyUnicode_Check(v)) {
            const std::string name = Py::String(value).as_std_string();
            std::string known;
            for (int i = 0; p.choices[i]; ++i) {
                if (name == p.choices[i]) {
                    return i;
                }
                known += std::string(i ? ", " : "") + p.choices[i];
            }
            throw Py::ValueError(std::string(p.name) + " = '" + name + "': choose one of " + known);
        }
        break;
    case ParameterKind::Angle:
    case ParameterKind::Float:
    case ParameterKind::Spacing:
        if (PyObject_TypeCheck(v, &Base::QuantityPy::Type)) {
            return static_cast<Base::QuantityPy*>(v)->getQuantityPtr()->getValue();
        }
        break;
    case ParameterKind::Integer:
        break;
    }
    if (PyBool_Check(v) || !PyNumber_Check(v)) {
        throw Py::TypeError(std::string(p.name) + " must be a number");
    }
    return double(Py::Float(value));
}

/// The keyword arguments named like the document object's properties, except `skip`.
ParameterValues parametersOf(const Py::Dict& keywords, const std::vector<std::string>& skip = {})
{
    ParameterValues values;
    Py::List keys = keywords.keys();
    for (Py::List::size_type i = 0; i < keys.size(); ++i) {
        const std::string name = Py::String(keys[i]).as_std_string();
        if (std::find(skip.begin(), skip.end(), name) != skip.end()) {
            continue;
        }
        const Py::Object value = keywords.getItem(keys[i]);
        if (name == thresholdsName) {
            values.thresholds = numbersOf(value, name);
        } else if (name == regionThresholdsName) {
            if (!value.isMapping()) {
                throw Py::TypeError(name + " must be a dict {region: [thresholds]}");
            }
            Py::Mapping map(value);
            Py::List regions = map.keys();
            std::map<int, std::vector<double>> byRegion;
            for (Py::List::size_type r = 0; r < regions.size(); ++r) {
                const Py::Object key = regions[r];
                const int region = PyLong_Check(key.ptr())
                                       ? static_cast<int>(Py::Long(key).as_long())
                                       : parseRegion(Py::String(key).as_std_string());
                byRegion[region] = numbersOf(map.getItem(key), name);
            }
            values.regionThresholds = byRegion;
        } else if (const Parameter* p = findParameter(name)) {
            values.scalars[name] = scalarOf(*p, value);
        } else {
            throw Py::TypeError("unknown parameter '" + name + "'; the parameters are " +
                                parameterNames());
        }
    }
    return values;
}

Py::List wireList(const std::vector<TopoDS_Wire>& wires)
{
    Py::List list;
    for (const TopoDS_Wire& wire : wires) {
        list.append(Py::asObject(new Part::TopoShapeWirePy(new Part::TopoShape(wire))));
    }
    return list;
}

template <class Container> Py::List intList(const Container& values)
{
    Py::List list(static_cast<int>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        list.setItem(static_cast<int>(i), Py::Long(long(values[i])));
    }
    return list;
}

Py::List floatList(const std::vector<double>& values)
{
    Py::List list(static_cast<int>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        list.setItem(static_cast<int>(i), Py::Float(values[i]));
    }
    return list;
}

/// An extraction's cloud analysed with its parameters, through the cache (a recomputed object's
/// analysis is a hit), for the functions of the interactive thresholding.
struct AnalysedExtraction
{
    CloudAnalysis analysis;
    featurelines::ExtractionOptions options;
};

AnalysedExtraction analysedExtraction(PyObject* object, const char* function)
{
    Extraction* e = extractionOf(object);
    if (!e) {
        throw Py::TypeError(std::string(function) + " needs a FeatureLines::Extraction object");
    }
    ExtractionInput input = extractionInput(*e);
    ExtractionProgress progress("Feature lines of " + std::string(e->Label.getValue()));
    input.options.progress = progress.callback();
    AnalysedExtraction out;
    out.analysis = analyseCached(input.points, input.cloudHash, input.options);
    out.options = input.options;
    out.options.progress = nullptr;
    return out;
}

/// A region's values per input point of the extraction's source, -1 outside the region.
Py::List perSourcePoint(const AnalysedExtraction& a, const featurelines::RegionGeometry& region,
                        const std::vector<int>& perRegionPoint)
{
    std::vector<int> out(a.analysis.geometry->inputToPoint.size(), -1);
    scatterToInputPoints(*a.analysis.geometry, region, perRegionPoint, out);
    return intList(out);
}

double optionalNumber(PyObject* value)
{
    return value == Py_None ? std::numeric_limits<double>::quiet_NaN()
                            : double(Py::Float(Py::Object(value)));
}

} // namespace

class Module : public Py::ExtensionModule<Module>
{
public:
    Module() : Py::ExtensionModule<Module>("FeatureLines")
    {
        add_varargs_method(
            "readCloud", &Module::readCloud,
            "readCloud(path) -> Points.Points\n"
            "Reads a point cloud file (.xyz, .txt, .asc, .csv, .ply, .pcd) into a Points kernel,\n"
            "e.g. Points.show(FeatureLines.readCloud('part.xyz')).\n"
            "Raises ValueError naming the problem for a bad or empty file.");
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
            "histogram", &Module::histogram,
            "histogram(values, bins=50, outliers=0, below=None, above=None, region=None) -> dict\n"
            "The curvature histogram and its threshold (Sec. 2.2-2.4 of Demarsin et al. 2008),\n"
            "as the task panel shows them. `values` is a list of curvature values, a\n"
            "FeatureLines::Extraction object (its PointCurvature, of one `region` or all), or a\n"
            "cloud (Points object or feature, list of vectors: the mean curvature of the whole\n"
            "cloud, 16 neighbours). bins is L_start, outliers the percentage of highest values\n"
            "dropped; below / above search the next lower / higher threshold (Sec. 2.3).\n"
            "Returns {'threshold', 'ratio', 'counts', 'minimum', 'maximum', 'bin_width',\n"
            "'start', 'joined_bins', 'peak', 'valley', 'outlier_cut'}. Raises ValueError when\n"
            "the values have no valley to threshold.");
        add_keyword_method(
            "makeExtraction", &Module::makeExtraction,
            "makeExtraction(points_feature, name='FeatureLines', **parameters) -> object\n"
            "Adds a FeatureLines::Extraction object reading `points_feature` (a Points feature)\n"
            "to its document, with the given parameters (property names). Recompute the\n"
            "document to extract.");
        add_keyword_method(
            "makePatchClouds", &Module::makePatchClouds,
            "makePatchClouds(extraction, min_points=0) -> list of Points features\n"
            "One Points feature per patch of a recomputed extraction (the points of one smooth\n"
            "region between the same two curvature thresholds), in a new group, so a patch can\n"
            "be handed to surface fitting. Patches of fewer than min_points points are left out\n"
            "(0: twice NeighbourCount, the fewest a surface fit can lean on); no group is made\n"
            "when no patch is left.");
        add_keyword_method(
            "regionHistogram", &Module::regionHistogramOf,
            "regionHistogram(extraction, region=0) -> dict\n"
            "The curvature histogram of one smooth region as the threshold search starts from it\n"
            "(Sec. 2.2, HistogramBins bins; past the outlier cut of Sec. 2.4 the bins go on a\n"
            "tenth of the range): {'counts', 'minimum', 'bin_width', 'outlier_cut' (NaN: none)}.\n"
            "The cloud is analysed with the object's parameters (through the cache).");
        add_keyword_method(
            "searchThreshold", &Module::searchThresholdOf,
            "searchThreshold(extraction, region=0, lower=None, upper=None) -> float\n"
            "Sec. 2.3: the curvature threshold of the region's values in (lower, upper]: with no\n"
            "bound the first threshold, with upper the next lower one, with lower the next higher\n"
            "one, with both a threshold between two accepted ones. Raises ValueError when those\n"
            "values have no valley.");
        add_keyword_method(
            "regionLabels", &Module::regionLabelsOf,
            "regionLabels(extraction, region, threshold) -> list\n"
            "Sec. 3 labels of the region's points at a candidate threshold, per point of the\n"
            "source cloud: 0 low, 1 inner, 2 border, 3 noisy (Fig. 7 a), -1 outside the region.");
        add_keyword_method(
            "regionPatches", &Module::regionPatchesOf,
            "regionPatches(extraction, region, thresholds) -> list\n"
            "Per point of the source cloud its patch at the given thresholds: the connected\n"
            "points of the region between the same two thresholds, numbered from 0; -1 outside\n"
            "the region.");
        add_varargs_method(
            "parameters", &Module::listParameters,
            "parameters() -> list of dict\n"
            "Every parameter of an extraction: name, group, doc, kind, default, minimum,\n"
            "maximum, choices. The names are the property names and the keywords of extract().");
        add_varargs_method(
            "cacheStatistics", &Module::cacheStatistics,
            "cacheStatistics() -> dict\n"
            "Hits and misses of the cache of neighbours/normals ('geometry') and of sharp\n"
            "edges/regions/curvature ('analysis'), entries kept, capacity, and the seconds the\n"
            "last extraction spent in the core library. A threshold change is a hit of both.");
        add_varargs_method("clearCache", &Module::clearCache,
                           "clearCache()\nDrops every cached analysis and resets the counters.");
        add_varargs_method(
            "setCacheCapacity", &Module::setCacheCapacity,
            "setCacheCapacity(entries)\n"
            "Analyses kept per kind (default 2; a million points cost about 0.5 GB per pair).");
        add_varargs_method(
            "setProgressObserver", &Module::setObserver,
            "setProgressObserver(callable or None)\n"
            "callable(fraction_done, stage) is called at every stage of every extraction; it\n"
            "cancels the run by returning False (or raising).");
        initialize("Closed feature lines (sharp edges, fillet borders) from point clouds.");
    }

    // PyCXX passes only Python exceptions on: any other exception leaving a function would end
    // FreeCAD. Every function's call goes through here, and the core's exceptions become
    // Python's (bad input: ValueError; cancelled or failed: RuntimeError).
    Py::Object invoke_method_varargs(void* method, const Py::Tuple& args) override
    {
        return translated(
            [&] { return Py::ExtensionModule<Module>::invoke_method_varargs(method, args); });
    }
    Py::Object invoke_method_keyword(void* method, const Py::Tuple& args,
                                     const Py::Dict& keywords) override
    {
        return translated([&] {
            return Py::ExtensionModule<Module>::invoke_method_keyword(method, args, keywords);
        });
    }

private:
    template <class Call> static Py::Object translated(Call call)
    {
        try {
            return call();
        } catch (const Py::Exception&) {
            throw;
        } catch (const std::invalid_argument& e) {
            throw Py::ValueError(e.what());
        } catch (const std::exception& e) {
            throw Py::RuntimeError(e.what());
        } catch (const Base::Exception& e) {
            throw Py::RuntimeError(e.what());
        } catch (const Standard_Failure& e) {
            throw Py::RuntimeError(std::string("OpenCASCADE: ") + e.GetMessageString());
        }
    }

    Py::Object readCloud(const Py::Tuple& args)
    {
        char* path = nullptr;
        if (!PyArg_ParseTuple(args.ptr(), "et", "utf-8", &path)) {
            throw Py::Exception();
        }
        std::string file(path);
        PyMem_Free(path);
        const PointMatrix P = featurelines::readCloud(file);
        auto* kernel =
            new Points::PointKernel(static_cast<Points::PointKernel::size_type>(P.rows()));
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            kernel->setPoint(static_cast<int>(i), Base::Vector3d(P(i, 0), P(i, 1), P(i, 2)));
        }
        return Py::asObject(new Points::PointsPy(kernel));
    }

    Py::Object extract(const Py::Tuple& args, const Py::Dict& keywords)
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
        const LineWires w = makeWires(r, cloud.toWorld);
        Py::Dict out;
        out["sharp"] = wireList(w.sharp);
        out["smooth"] = wireList(w.smooth);
        out["boundary"] = wireList(w.boundary);
        out["smooth_regions"] = intList(w.smoothRegion);
        out["smooth_thresholds"] = floatList(w.smoothThreshold);
        out["closed"] = Py::Long(w.closed);
        Py::Dict thresholds;
        for (const featurelines::RegionReport& report : r.regions) {
            thresholds[Py::Long(report.region)] = floatList(report.thresholds);
        }
        out["thresholds"] = thresholds;
        out["regions"] = intList(r.region);
        out["patches"] = intList(r.patch);
        std::vector<long> labels(r.label.size());
        for (size_t i = 0; i < labels.size(); ++i) {
            labels[i] = r.label[i] == featurelines::PointLabel::Outside ? -1 : long(r.label[i]);
        }
        out["labels"] = intList(labels);
        out["curvature"] = floatList(
            std::vector<double>(r.curvature.data(), r.curvature.data() + r.curvature.size()));
        Py::List junctions;
        for (Eigen::Index j = 0; j < r.junctions.rows(); ++j) {
            junctions.append(Py::asObject(new Base::VectorPy(
                cloud.toWorld *
                Base::Vector3d(r.junctions(j, 0), r.junctions(j, 1), r.junctions(j, 2)))));
        }
        out["junctions"] = junctions;
        out["spacing"] = Py::Float(r.spacing);
        return out;
    }

    Py::Object histogram(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* source = nullptr;
        int bins = 50;
        double outliers = 0.0;
        PyObject* below = Py_None;
        PyObject* above = Py_None;
        PyObject* region = Py_None;
        static const char* names[] = {"values", "bins",   "outliers", "below",
                                      "above",  "region", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|idOOO",
                                         const_cast<char**>(names), &source, &bins, &outliers,
                                         &below, &above, &region)) {
            throw Py::Exception();
        }
        std::vector<double> values;
        if (Extraction* e = extractionOf(source)) {
            const auto& curvature = e->PointCurvature.getValues();
            const auto& regions = e->PointRegion.getValues();
            const long wanted = region == Py_None ? -1 : Py::Long(region).as_long();
            for (size_t i = 0; i < curvature.size() && i < regions.size(); ++i) {
                if (std::isfinite(curvature[i]) && (wanted < 0 || regions[i] == wanted)) {
                    values.push_back(curvature[i]);
                }
            }
            if (values.empty()) {
                throw Py::ValueError("'" + std::string(e->Label.getValue()) +
                                     "' has no curvature values" +
                                     (wanted < 0 ? "" : " in region " + std::to_string(wanted)) +
                                     ": recompute it first");
            }
        } else if (kernelOf(source) || !PySequence_Check(source) ||
                   (PySequence_Size(source) > 0 &&
                    !PyNumber_Check(Py::Sequence(source)[0].ptr()))) {
            const Cloud cloud = cloudOf(source);
            const auto g = geometryCached(cloud.points, hashCloud(cloud.points), {});
            const Eigen::VectorXd h =
                featurelines::meanCurvature(g->points, g->normals.normals, g->neighbours);
            values.assign(h.data(), h.data() + h.size());
        } else {
            values = numbersOf(Py::Object(source), "values");
        }
        featurelines::ThresholdOptions options;
        options.bins = bins;
        options.outlierPercent = outliers;
        if (below != Py_None && above != Py_None) {
            throw Py::ValueError("give below or above, not both");
        }
        featurelines::ThresholdResult t;
        if (below != Py_None) {
            t = featurelines::findLowerThreshold(values, double(Py::Float(below)), options);
        } else if (above != Py_None) {
            t = featurelines::findHigherThreshold(values, double(Py::Float(above)), options);
        } else {
            t = featurelines::findThreshold(values, options);
        }
        Py::Dict out;
        out["threshold"] = Py::Float(t.threshold);
        out["ratio"] = Py::Float(t.ratio);
        out["counts"] = intList(t.histogram.counts);
        out["minimum"] = Py::Float(t.histogram.minimum);
        out["maximum"] = Py::Float(t.histogram.maximum);
        out["bin_width"] = Py::Float(t.histogram.binWidth);
        out["start"] = Py::Float(t.startCurv);
        out["joined_bins"] = Py::Long(t.joinedBins);
        out["peak"] = Py::Long(t.peakCount);
        out["valley"] = Py::Long(t.valleyCount);
        out["outlier_cut"] = Py::Float(t.outlierCut);
        return out;
    }

    Py::Object makeExtraction(const Py::Tuple& args, const Py::Dict& keywords)
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

    Py::Object makePatchClouds(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* object = nullptr;
        int minPoints = 0;
        static const char* names[] = {"extraction", "min_points", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|i",
                                         const_cast<char**>(names), &object, &minPoints)) {
            throw Py::Exception();
        }
        Extraction* e = extractionOf(object);
        if (!e) {
            throw Py::TypeError("makePatchClouds needs a FeatureLines::Extraction object");
        }
        auto* source = dynamic_cast<Points::Feature*>(e->Source.getValue());
        const std::vector<long>& patch = e->PointPatch.getValues();
        if (!source || source->Points.getValue().size() != patch.size() || patch.empty()) {
            throw Py::ValueError("'" + std::string(e->Label.getValue()) +
                                 "' has no patches of its source cloud: recompute it first");
        }
        if (minPoints <= 0) {
            minPoints = 2 * static_cast<int>(e->NeighbourCount.getValue());
        }
        const std::vector<long>& region = e->PointRegion.getValues();
        const auto& stored = source->Points.getValue().getBasicPoints();
        std::map<long, std::vector<size_t>> members;
        for (size_t i = 0; i < patch.size(); ++i) {
            if (patch[i] >= 0) {
                members[patch[i]].push_back(i);
            }
        }
        App::Document* doc = e->getDocument();
        App::DocumentObjectGroup* group = nullptr;
        Py::List created;
        for (const auto& [id, points] : members) {
            if (static_cast<int>(points.size()) < minPoints) {
                continue;
            }
            if (!group) {
                group = static_cast<App::DocumentObjectGroup*>(
                    doc->addObject("App::DocumentObjectGroup", "Patches"));
                group->Label.setValue(std::string(e->Label.getValue()) + " patches");
            }
            Points::PointKernel kernel;
            kernel.reserve(points.size());
            for (size_t i : points) {
                kernel.getBasicPoints().push_back(stored[i]);
            }
            auto* cloud = static_cast<Points::Feature*>(doc->addObject("Points::Feature", "Patch"));
            cloud->Points.setValue(kernel);
            cloud->Placement.setValue(source->Placement.getValue());
            cloud->Label.setValue("Patch " + std::to_string(id) + " (region " +
                                  std::to_string(region[points.front()]) + ", " +
                                  std::to_string(points.size()) + " points)");
            group->addObject(cloud);
            created.append(Py::asObject(cloud->getPyObject()));
        }
        return created;
    }

    Py::Object regionHistogramOf(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* object = nullptr;
        int region = 0;
        static const char* names[] = {"extraction", "region", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|i",
                                         const_cast<char**>(names), &object, &region)) {
            throw Py::Exception();
        }
        const AnalysedExtraction a = analysedExtraction(object, "regionHistogram");
        const RegionHistogram h =
            regionHistogram(regionGeometry(a.analysis, region), a.options.smooth);
        Py::Dict out;
        out["counts"] = intList(h.counts);
        out["minimum"] = Py::Float(h.minimum);
        out["bin_width"] = Py::Float(h.binWidth);
        out["outlier_cut"] = Py::Float(h.outlierCut);
        return out;
    }

    Py::Object searchThresholdOf(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* object = nullptr;
        int region = 0;
        PyObject* lower = Py_None;
        PyObject* upper = Py_None;
        static const char* names[] = {"extraction", "region", "lower", "upper", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|iOO",
                                         const_cast<char**>(names), &object, &region, &lower,
                                         &upper)) {
            throw Py::Exception();
        }
        const AnalysedExtraction a = analysedExtraction(object, "searchThreshold");
        const featurelines::ThresholdResult t =
            searchThreshold(regionGeometry(a.analysis, region), a.options.smooth,
                            optionalNumber(lower), optionalNumber(upper));
        return Py::Float(t.threshold);
    }

    Py::Object regionLabelsOf(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* object = nullptr;
        int region = 0;
        double threshold = 0.0;
        static const char* names[] = {"extraction", "region", "threshold", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "Oid",
                                         const_cast<char**>(names), &object, &region, &threshold)) {
            throw Py::Exception();
        }
        const AnalysedExtraction a = analysedExtraction(object, "regionLabels");
        const featurelines::RegionGeometry& g = regionGeometry(a.analysis, region);
        const std::vector<featurelines::PointLabel> labels =
            regionLabels(g, threshold, a.options.smooth);
        std::vector<int> values(labels.size());
        for (size_t i = 0; i < labels.size(); ++i) {
            values[i] = labels[i] == featurelines::PointLabel::Outside ? -1 : int(labels[i]);
        }
        return perSourcePoint(a, g, values);
    }

    Py::Object regionPatchesOf(const Py::Tuple& args, const Py::Dict& keywords)
    {
        PyObject* object = nullptr;
        int region = 0;
        PyObject* thresholds = nullptr;
        static const char* names[] = {"extraction", "region", "thresholds", nullptr};
        if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "OiO",
                                         const_cast<char**>(names), &object, &region,
                                         &thresholds)) {
            throw Py::Exception();
        }
        const std::vector<double> levels = numbersOf(Py::Object(thresholds), "thresholds");
        const AnalysedExtraction a = analysedExtraction(object, "regionPatches");
        const featurelines::RegionGeometry& g = regionGeometry(a.analysis, region);
        std::vector<int> patch;
        featurelines::labelPatches(g, levels, 0, patch);
        return perSourcePoint(a, g, patch);
    }

    Py::Object listParameters(const Py::Tuple& args)
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

    Py::Object cacheStatistics(const Py::Tuple& args)
    {
        if (!PyArg_ParseTuple(args.ptr(), "")) {
            throw Py::Exception();
        }
        const CacheStatistics s = FeatureLines::cacheStatistics();
        Py::Dict d;
        d["geometry_hits"] = Py::Long(s.geometryHits);
        d["geometry_misses"] = Py::Long(s.geometryMisses);
        d["analysis_hits"] = Py::Long(s.analysisHits);
        d["analysis_misses"] = Py::Long(s.analysisMisses);
        d["geometry_entries"] = Py::Long(s.geometryEntries);
        d["analysis_entries"] = Py::Long(s.analysisEntries);
        d["capacity"] = Py::Long(s.capacity);
        d["last_core_seconds"] = Py::Float(s.lastCoreSeconds);
        return d;
    }

    Py::Object clearCache(const Py::Tuple& args)
    {
        if (!PyArg_ParseTuple(args.ptr(), "")) {
            throw Py::Exception();
        }
        FeatureLines::clearCache();
        return Py::None();
    }

    Py::Object setCacheCapacity(const Py::Tuple& args)
    {
        int entries = 0;
        if (!PyArg_ParseTuple(args.ptr(), "i", &entries)) {
            throw Py::Exception();
        }
        if (entries < 0) {
            throw Py::ValueError("the cache capacity cannot be negative");
        }
        FeatureLines::setCacheCapacity(entries);
        return Py::None();
    }

    Py::Object setObserver(const Py::Tuple& args)
    {
        PyObject* callable = nullptr;
        if (!PyArg_ParseTuple(args.ptr(), "O", &callable)) {
            throw Py::Exception();
        }
        if (callable != Py_None && !PyCallable_Check(callable)) {
            throw Py::TypeError("setProgressObserver needs a callable or None");
        }
        setProgressObserver(callable);
        return Py::None();
    }
};

} // namespace FeatureLines

PyMOD_INIT_FUNC(FeatureLines)
{
    try {
        Base::Interpreter().loadModule("Part");
        Base::Interpreter().loadModule("Points");
    } catch (const Base::Exception& e) {
        PyErr_SetString(PyExc_ImportError, e.what());
        PyMOD_Return(nullptr);
    }
    FeatureLines::PropertyPointIndices::init();
    FeatureLines::Extraction::init();
    PyObject* mod = Base::Interpreter().addModule(new FeatureLines::Module);
    Base::Console().Log("Loading FeatureLines module... done\n");
    PyMOD_Return(mod);
}
