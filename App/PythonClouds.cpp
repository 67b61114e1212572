// SPDX-License-Identifier: LGPL-2.1-or-later
// The Python functions for clouds: readCloud, makePatchClouds.
#include <FCConfig.h>

#include <App/Document.h>
#include <App/DocumentObjectGroup.h>
#include <Mod/Points/App/Points.h>
#include <Mod/Points/App/PointsFeature.h>
#include <Mod/Points/App/PointsPy.h>

#include <map>

#include "ExtractionFeature.h"
#include "FeatureLines/io/CloudIO.h"
#include "PythonModule.h"
#include "PythonValues.h"
#include "StoredResult.h"

namespace FeatureLines {

using featurelines::PointMatrix;

void Module::addCloudFunctions()
{
    add_varargs_method(
        "readCloud", &Module::readCloud,
        "readCloud(path) -> Points.Points\n"
        "Reads a point cloud file (.xyz, .txt, .asc, .csv, .ply, .pcd) into a Points kernel,\n"
        "e.g. Points.show(FeatureLines.readCloud('part.xyz')).\n"
        "Raises ValueError naming the problem for a bad or empty file.");
    add_keyword_method(
        "makePatchClouds", &Module::makePatchClouds,
        "makePatchClouds(extraction, min_points=0) -> list of Points features\n"
        "One Points feature per patch of a recomputed extraction (the points of one smooth\n"
        "region between the same two curvature thresholds), in a new group, so a patch can\n"
        "be handed to surface fitting. Patches of fewer than min_points points are left out\n"
        "(0: twice NeighbourCount, the fewest a surface fit can lean on); no group is made\n"
        "when no patch is left. Raises ValueError naming the problem when the extraction\n"
        "is out of date, failed its last recompute, or holds a damaged result.");
}

Py::Object Module::readCloud(const Py::Tuple& args)
{
    char* path = nullptr;
    if (!PyArg_ParseTuple(args.ptr(), "et", "utf-8", &path)) {
        throw Py::Exception();
    }
    std::string file(path);
    PyMem_Free(path);
    const PointMatrix P = featurelines::readCloud(file);
    auto* kernel = new Points::PointKernel(static_cast<Points::PointKernel::size_type>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        kernel->setPoint(static_cast<int>(i), Base::Vector3d(P(i, 0), P(i, 1), P(i, 2)));
    }
    return Py::asObject(new Points::PointsPy(kernel));
}

Py::Object Module::makePatchClouds(const Py::Tuple& args, const Py::Dict& keywords)
{
    PyObject* object = nullptr;
    int minPoints = 0;
    static const char* names[] = {"extraction", "min_points", nullptr};
    if (!PyArg_ParseTupleAndKeywords(args.ptr(), keywords.ptr(), "O|i", const_cast<char**>(names),
                                     &object, &minPoints)) {
        throw Py::Exception();
    }
    Extraction* e = extractionOf(object);
    if (!e) {
        throw Py::TypeError("makePatchClouds needs a FeatureLines::Extraction object");
    }
    // The lists come from the last recompute or from the file: trusted only when current and
    // consistent with one another and with the source.
    requireCurrentResult(*e, "makePatchClouds");
    auto* source = static_cast<Points::Feature*>(e->Source.getValue());
    const std::vector<long>& patch = e->PointPatch.getValues();
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

} // namespace FeatureLines
