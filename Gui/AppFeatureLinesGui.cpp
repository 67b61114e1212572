// SPDX-License-Identifier: LGPL-2.1-or-later
// The FreeCAD Gui module FeatureLinesGui: the lines' view provider, the command that opens the
// task panel of the interactive thresholding, and the icons and forms (Resources/FeatureLines.qrc).
// The workbench itself is InitGui.py's.
#include <FCConfig.h>

#include <Base/Console.h>
#include <Base/Interpreter.h>
#include <Base/PyObjectBase.h>
#include <CXX/Extensions.hxx>
#include <Gui/Application.h>
#include <Gui/BitmapFactory.h>

#include <QtGlobal>

#include "ViewProviderExtraction.h"
#include "ViewProviderPatchSurfaces.h"

void CreateFeatureLinesCommands();

namespace FeatureLinesGui {

class Module : public Py::ExtensionModule<Module>
{
public:
    Module() : Py::ExtensionModule<Module>("FeatureLinesGui")
    {
        initialize("The FeatureLines workbench: view provider, command and task panel.");
    }
};

} // namespace FeatureLinesGui

// Q_INIT_RESOURCE must be called from the global namespace.
static void loadFeatureLinesResource()
{
    Q_INIT_RESOURCE(FeatureLines);
}

PyMOD_INIT_FUNC(FeatureLinesGui)
{
    if (!Gui::Application::Instance) {
        PyErr_SetString(PyExc_ImportError, "Cannot load Gui module in console application.");
        PyMOD_Return(nullptr);
    }
    try {
        Base::Interpreter().loadModule("FeatureLines");
        Base::Interpreter().loadModule("PartGui");
        Base::Interpreter().loadModule("PointsGui");
    } catch (const Base::Exception& e) {
        PyErr_SetString(PyExc_ImportError, e.what());
        PyMOD_Return(nullptr);
    }
    loadFeatureLinesResource();
    FeatureLinesGui::ViewProviderExtraction::init();
    FeatureLinesGui::ViewProviderPatchSurfaces::init();
    CreateFeatureLinesCommands();
    PyObject* mod = Base::Interpreter().addModule(new FeatureLinesGui::Module);
    Base::Console().Log("Loading GUI of FeatureLines module... done\n");
    PyMOD_Return(mod);
}
