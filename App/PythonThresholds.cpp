// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions of curvature thresholds: histogram, and the interactive thresholding of
// Sec. 2.3 on an extraction's cached analysis (InteractiveThresholds.h): regionHistogram,
// searchThreshold, regionLabels, regionPatches.
#include <FCConfig.h>

#include <cmath>
#include <limits>

#include "ExtractionCache.h"
#include "ExtractionFeature.h"
#include "ExtractionOutputs.h"
#include "ExtractionProgress.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "InteractiveThresholds.h"
#include "PythonModule.h"
#include "PythonValues.h"
#include "StoredResult.h"

namespace FeatureLines {

namespace {

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

/// histogram()'s values: an extraction's curvature (of one region or all), a cloud's mean
/// curvature, or the numbers given.
std::vector<double> histogramValues(PyObject* source, PyObject* region)
{
    std::vector<double> values;
    if (Extraction* e = extractionOf(source)) {
        requireCurrentResult(*e, "histogram");
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
               (PySequence_Size(source) > 0 && !PyNumber_Check(Py::Sequence(source)[0].ptr()))) {
        const Cloud cloud = cloudOf(source);
        const auto g = geometryCached(cloud.points, hashCloud(cloud.points), {});
        const Eigen::VectorXd h =
            featurelines::meanCurvature(g->points, g->normals.normals, g->neighbours);
        values.assign(h.data(), h.data() + h.size());
    } else {
        values = numbersOf(Py::Object(source), "values");
    }
    return values;
}

Py::Dict thresholdDict(const featurelines::ThresholdResult& t)
{
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

} // namespace

void Module::addThresholdFunctions()
{
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
        "the values have no valley to threshold, or when an Extraction is out of date,\n"
        "failed its last recompute or holds a damaged result.");
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
    add_keyword_method(
        "repeatedThreshold", &Module::repeatedThresholdOf,
        "repeatedThreshold(extraction, region, candidate, accepted) -> float or None\n"
        "The accepted threshold whose lines the candidate would repeat: one of the two levels\n"
        "the candidate cuts from the accepted thresholds around it holds no patch of its own\n"
        "(no 2 k connected inner points), so the candidate gives the same patches and lines\n"
        "beside that threshold's. None when the candidate adds a patch. The task panel never\n"
        "offers or accepts such a candidate.");
}

Py::Object Module::histogram(const Py::Tuple& args, const Py::Dict& keywords)
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
                                     const_cast<char**>(names), &source, &bins, &outliers, &below,
                                     &above, &region)) {
        throw Py::Exception();
    }
    const std::vector<double> values = histogramValues(source, region);
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
    return thresholdDict(t);
}

Py::Object Module::regionHistogramOf(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int region = 0;
    static const char* names[] = {"extraction", "region", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|i", const_cast<char**>(names),
                                     &object, &region)) {
        throw Py::Exception();
    }
    const AnalysedExtraction a = analysedExtraction(object, "regionHistogram");
    const RegionHistogram h = regionHistogram(regionGeometry(a.analysis, region), a.options.smooth);
    Py::Dict out;
    out["counts"] = intList(h.counts);
    out["minimum"] = Py::Float(h.minimum);
    out["bin_width"] = Py::Float(h.binWidth);
    out["outlier_cut"] = Py::Float(h.outlierCut);
    return out;
}

Py::Object Module::searchThresholdOf(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int region = 0;
    PyObject* lower = Py_None;
    PyObject* upper = Py_None;
    static const char* names[] = {"extraction", "region", "lower", "upper", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|iOO", const_cast<char**>(names),
                                     &object, &region, &lower, &upper)) {
        throw Py::Exception();
    }
    const AnalysedExtraction a = analysedExtraction(object, "searchThreshold");
    const featurelines::ThresholdResult t =
        searchThreshold(regionGeometry(a.analysis, region), a.options.smooth, optionalNumber(lower),
                        optionalNumber(upper));
    return Py::Float(t.threshold);
}

Py::Object Module::regionLabelsOf(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int region = 0;
    double threshold = 0.0;
    static const char* names[] = {"extraction", "region", "threshold", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "Oid", const_cast<char**>(names),
                                     &object, &region, &threshold)) {
        throw Py::Exception();
    }
    const AnalysedExtraction a = analysedExtraction(object, "regionLabels");
    const featurelines::RegionGeometry& g = regionGeometry(a.analysis, region);
    const std::vector<featurelines::PointLabel> labels =
        regionLabels(g, threshold, a.options.smooth);
    return perSourcePoint(a, g, labelValues<int>(labels));
}

Py::Object Module::regionPatchesOf(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int region = 0;
    PyObject* thresholds = nullptr;
    static const char* names[] = {"extraction", "region", "thresholds", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "OiO", const_cast<char**>(names),
                                     &object, &region, &thresholds)) {
        throw Py::Exception();
    }
    const std::vector<double> levels = numbersOf(Py::Object(thresholds), "thresholds");
    const AnalysedExtraction a = analysedExtraction(object, "regionPatches");
    const featurelines::RegionGeometry& g = regionGeometry(a.analysis, region);
    std::vector<int> patch;
    featurelines::labelPatches(g, levels, 0, patch);
    return perSourcePoint(a, g, patch);
}

Py::Object Module::repeatedThresholdOf(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int region = 0;
    double candidate = 0.0;
    PyObject* accepted = nullptr;
    static const char* names[] = {"extraction", "region", "candidate", "accepted", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "OidO", const_cast<char**>(names),
                                     &object, &region, &candidate, &accepted)) {
        throw Py::Exception();
    }
    const std::vector<double> levels = numbersOf(Py::Object(accepted), "accepted");
    const AnalysedExtraction a = analysedExtraction(object, "repeatedThreshold");
    const double repeated =
        repeatedThreshold(regionGeometry(a.analysis, region), a.options.smooth, candidate, levels);
    return std::isnan(repeated) ? Py::None() : Py::Object(Py::Float(repeated));
}

} // namespace FeatureLines
