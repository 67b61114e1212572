// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python module FeatureLines: its functions for macros, by concern, each group in a file of
// its own: clouds (PythonClouds.cpp), extraction (PythonExtraction.cpp), thresholds
// (PythonThresholds.cpp), surfaces (PythonSurfaces.cpp), the cache and progress
// (PythonCache.cpp). Keyword parameters of the
// functions are the document object's property names, mapped onto the core's options by the
// one table of ExtractionParameters.h.
#pragma once

#include <CXX/Extensions.hxx>
#include <CXX/Objects.hxx>

namespace FeatureLines {

class Module : public Py::ExtensionModule<Module>
{
public:
    Module();

    // PyCXX passes only Python exceptions on: any other exception leaving a function would end
    // FreeCAD. Every function's call goes through here, and the core's exceptions become
    // Python's (bad input: ValueError; cancelled or failed: RuntimeError).
    Py::Object invoke_method_varargs(void* method, const Py::Tuple& args) override;
    Py::Object invoke_method_keyword(void* method, const Py::Tuple& args,
                                     const Py::Dict& keywords) override;

private:
    // Clouds: reading a file, the patches of an extraction as clouds and with their borders.
    void addCloudFunctions();
    Py::Object readCloud(const Py::Tuple& args);
    Py::Object makePatchClouds(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object patchBorders(const Py::Tuple& args, const Py::Dict& keywords);

    // Extraction: the lines of a cloud, the document object, the parameters, cleaning the lines.
    void addExtractionFunctions();
    Py::Object extract(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object makeExtraction(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object listParameters(const Py::Tuple& args);
    Py::Object cleanLines(const Py::Tuple& args, const Py::Dict& keywords);

    // Thresholds: curvature histograms and the interactive thresholding of Sec. 2.3.
    void addThresholdFunctions();
    Py::Object histogram(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object regionHistogramOf(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object searchThresholdOf(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object regionLabelsOf(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object regionPatchesOf(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object repeatedThresholdOf(const Py::Tuple& args, const Py::Dict& keywords);

    // Surfaces: a surface per patch, trimmed by its border, sewn.
    void addSurfaceFunctions();
    Py::Object fitSurfaces(const Py::Tuple& args, const Py::Dict& keywords);
    Py::Object makeSurfaces(const Py::Tuple& args, const Py::Dict& keywords);

    // The cache of analyses and the progress observer.
    void addCacheFunctions();
    Py::Object cacheStatistics(const Py::Tuple& args);
    Py::Object clearCache(const Py::Tuple& args);
    Py::Object setCacheCapacity(const Py::Tuple& args);
    Py::Object setObserver(const Py::Tuple& args);
};

} // namespace FeatureLines
