// SPDX-License-Identifier: LGPL-2.1-or-later
// The FreeCAD App module FeatureLines: registers the document object types and the Python
// module (PythonModule.h, its functions by concern in Python*.cpp).
#include <FCConfig.h>

#include <App/Application.h>
#include <App/Document.h>
#include <Base/Console.h>
#include <Base/Exception.h>
#include <Base/Interpreter.h>
#include <Base/PyObjectBase.h>
#include <Standard_Failure.hxx>

#include <set>
#include <stdexcept>
#include <string>

#include "ExtractionFeature.h"
#include "PropertyPointIndices.h"
#include "PythonModule.h"
#include "SurfacesFeature.h"

namespace FeatureLines {

namespace {

template <class Call> Py::Object translated(Call call)
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

/// A FreeCAD without this module opens a document holding extractions without them, and saving
/// it there drops them for good (docs/freecad-app.md). Said once per document and session, in
/// the report view, when such a document is saved: the only moment FreeCAD's App side offers.
void warnOnSaving(const App::Document& doc, const std::string& file)
{
    static std::set<std::string> warned;
    if (doc.getObjectsOfType(Extraction::getClassTypeId()).empty() || !warned.insert(file).second) {
        return;
    }
    Base::Console().Message(
        "%s holds FeatureLines extractions: a FreeCAD without the FeatureLines module opens it "
        "without them (the Points objects stay) and, if saved there, drops them for good.\n",
        file.c_str());
}

} // namespace

Module::Module() : Py::ExtensionModule<Module>("FeatureLines")
{
    addCloudFunctions();
    addExtractionFunctions();
    addThresholdFunctions();
    addSurfaceFunctions();
    addCacheFunctions();
    initialize("Closed feature lines (sharp edges, fillet borders) from point clouds.");
}

Py::Object Module::invoke_method_varargs(void* method, const Py::Tuple& args)
{
    return translated(
        [&] { return Py::ExtensionModule<Module>::invoke_method_varargs(method, args); });
}

Py::Object Module::invoke_method_keyword(void* method, const Py::Tuple& args,
                                         const Py::Dict& keywords)
{
    return translated(
        [&] { return Py::ExtensionModule<Module>::invoke_method_keyword(method, args, keywords); });
}

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
    FeatureLines::PatchSurfaces::init();
    PyObject* mod = Base::Interpreter().addModule(new FeatureLines::Module);
    // Lives as long as the process, as the module does.
    App::GetApplication().signalStartSaveDocument.connect(&FeatureLines::warnOnSaving);
    Base::Console().Log("Loading FeatureLines module... done\n");
    PyMOD_Return(mod);
}
