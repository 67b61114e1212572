// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions of the cache of analyses (ExtractionCache.h) and of the progress observer
// (ExtractionProgress.h).
#include <FCConfig.h>

#include "ExtractionCache.h"
#include "ExtractionProgress.h"
#include "PythonModule.h"

namespace FeatureLines {

void Module::addCacheFunctions()
{
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
}

Py::Object Module::cacheStatistics(const Py::Tuple& args)
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

Py::Object Module::clearCache(const Py::Tuple& args)
{
    if (!PyArg_ParseTuple(args.ptr(), "")) {
        throw Py::Exception();
    }
    FeatureLines::clearCache();
    return Py::None();
}

Py::Object Module::setCacheCapacity(const Py::Tuple& args)
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

Py::Object Module::setObserver(const Py::Tuple& args)
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

} // namespace FeatureLines
