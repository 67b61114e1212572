// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "PythonValues.h"

#include <App/DocumentObjectPy.h>
#include <Base/QuantityPy.h>
#include <Base/VectorPy.h>
#include <Mod/Points/App/Points.h>
#include <Mod/Points/App/PointsFeature.h>
#include <Mod/Points/App/PointsPy.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ExtractionFeature.h"

namespace FeatureLines {

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

namespace {

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

} // namespace

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

namespace {

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

} // namespace

ParameterValues parametersOf(const Py::Dict& keywords, const std::vector<std::string>& skip)
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

Py::List floatList(const std::vector<double>& values)
{
    Py::List list(static_cast<int>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        list.setItem(static_cast<int>(i), Py::Float(values[i]));
    }
    return list;
}

Py::List estimateList(const std::vector<double>& values)
{
    Py::List list(static_cast<int>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) {
        list.setItem(static_cast<int>(i),
                     std::isnan(values[i]) ? Py::None() : Py::Object(Py::Float(values[i])));
    }
    return list;
}

Py::List stringList(const std::vector<std::string>& values)
{
    Py::List list;
    for (const std::string& value : values) {
        list.append(Py::String(value));
    }
    return list;
}

} // namespace FeatureLines
