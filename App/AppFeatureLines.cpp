// SPDX-License-Identifier: LGPL-2.1-or-later
// The FreeCAD App module FeatureLines: Python functions over the core library.
#include <FCConfig.h>

#include <Base/Console.h>
#include <Base/Interpreter.h>
#include <Base/PyObjectBase.h>
#include <CXX/Extensions.hxx>
#include <CXX/Objects.hxx>
#include <Mod/Points/App/Points.h>
#include <Mod/Points/App/PointsPy.h>

#include <stdexcept>

#include "FeatureLines/CloudIO.h"

namespace FeatureLinesApp {

class Module : public Py::ExtensionModule<Module>
{
public:
    Module()
        : Py::ExtensionModule<Module>("FeatureLines")
    {
        add_varargs_method("readCloud", &Module::readCloud,
                           "readCloud(path) -> Points.Points\n"
                           "Reads a point cloud file (.xyz, .txt, .asc, .csv, .ply, .pcd) into a\n"
                           "Points kernel, e.g. Points.show(FeatureLines.readCloud('part.xyz')).\n"
                           "Raises ValueError naming the problem for a bad or empty file.");
        initialize("Closed feature lines (sharp edges, fillet borders) from point clouds.");
    }

private:
    Py::Object readCloud(const Py::Tuple& args)
    {
        char* path = nullptr;
        if (!PyArg_ParseTuple(args.ptr(), "et", "utf-8", &path)) {
            throw Py::Exception();
        }
        std::string file(path);
        PyMem_Free(path);
        featurelines::PointMatrix P;
        try {
            P = featurelines::readCloud(file);
        }
        catch (const std::invalid_argument& e) {
            throw Py::ValueError(e.what());
        }
        auto* kernel = new Points::PointKernel(static_cast<Points::PointKernel::size_type>(P.rows()));
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            kernel->setPoint(static_cast<int>(i),
                             Base::Vector3d(P(i, 0), P(i, 1), P(i, 2)));
        }
        return Py::asObject(new Points::PointsPy(kernel));
    }
};

} // namespace FeatureLinesApp

PyMOD_INIT_FUNC(FeatureLines)
{
    try {
        Base::Interpreter().loadModule("Part");
        Base::Interpreter().loadModule("Points");
    }
    catch (const Base::Exception& e) {
        PyErr_SetString(PyExc_ImportError, e.what());
        PyMOD_Return(nullptr);
    }
    PyObject* mod = Base::Interpreter().addModule(new FeatureLinesApp::Module);
    Base::Console().Log("Loading FeatureLines module... done\n");
    PyMOD_Return(mod);
}
