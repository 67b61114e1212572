// SPDX-License-Identifier: LGPL-2.1-or-later
// What the functions of the Python module share: Python arguments read as the core's types
// (clouds, numbers, parameters) and lists handed back.
#pragma once

#include <Base/Matrix.h>
#include <CXX/Objects.hxx>

#include <string>
#include <vector>

#include "ExtractionParameters.h"

namespace Points {
class PointKernel;
}

namespace FeatureLines {

class Extraction;

/// A cloud handed to a function: its points and the matrix to world coordinates.
struct Cloud
{
    featurelines::PointMatrix points;
    Base::Matrix4D toWorld;
};

/// The kernel of a Points object (Points.Points) or a Points::Feature; nullptr for others.
const Points::PointKernel* kernelOf(PyObject* obj);
/// A Points object (Points.Points), a Points::Feature, or a sequence of vectors.
Cloud cloudOf(PyObject* obj);
/// The FeatureLines::Extraction object, nullptr for any other object.
Extraction* extractionOf(PyObject* obj);

/// The arguments (extraction, min_points=0) of makePatchClouds, patchBorders and fitSurfaces.
struct PatchArguments
{
    Extraction& extraction;
    int minPoints;
};

/// The arguments of `function`, the extraction's stored result checked to be current (its lists
/// come from the last recompute or from the file: trusted only when current and consistent with
/// one another and with the source). Throws a Python TypeError or ValueError naming `function`.
PatchArguments patchArguments(const Py::Tuple& args, const Py::Dict& keywords,
                              const std::string& function);

/// A list of numbers, or a text of numbers (parseThresholds); `what` names it in errors.
std::vector<double> numbersOf(const Py::Object& value, const std::string& what);

/// The keyword arguments named like the document object's properties, except `skip`.
ParameterValues parametersOf(const Py::Dict& keywords, const std::vector<std::string>& skip = {});

template <class Container> Py::List intList(const Container& values)
{
    Py::List list(static_cast<int>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        list.setItem(static_cast<int>(i), Py::Long(long(values[i])));
    }
    return list;
}

Py::List floatList(const std::vector<double>& values);
/// floatList with None for each NaN (a value not estimated).
Py::List estimateList(const std::vector<double>& values);
Py::List stringList(const std::vector<std::string>& values);

} // namespace FeatureLines
