// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "StoredResult.h"

#include <Mod/Points/App/PointsFeature.h>
#include <TopAbs_ShapeEnum.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "ExtractionFeature.h"

namespace FeatureLines {

namespace {

std::string count(size_t n, const char* what)
{
    return std::to_string(n) + " " + what;
}

/// The wires directly in a compound of wires (the output shapes are built so).
size_t wireCount(const Part::PropertyPartShape& shape)
{
    const TopoDS_Shape& s = shape.getShape().getShape();
    size_t wires = 0;
    if (!s.IsNull()) {
        for (TopoDS_Iterator it(s); it.More(); it.Next()) {
            wires += it.Value().ShapeType() == TopAbs_WIRE ? 1 : 0;
        }
    }
    return wires;
}

/// "" when every value of `list` lies in [lowest, end); else the first one that does not.
std::string outOfRange(const char* name, const std::vector<long>& list, long lowest, long end,
                       const std::string& endName)
{
    for (size_t i = 0; i < list.size(); ++i) {
        if (list[i] < lowest || list[i] >= end) {
            return std::string(name) + "[" + std::to_string(i) + "] = " + std::to_string(list[i]) +
                   " lies outside " + std::to_string(lowest) + " .. " + endName +
                   " - 1 = " + std::to_string(end - 1);
        }
    }
    return {};
}

std::string perPointMismatch(const Extraction& e, bool againstSource)
{
    const std::vector<std::pair<const char*, size_t>> lists = {
        {"PointRegion", e.PointRegion.getSize()},
        {"PointPatch", e.PointPatch.getSize()},
        {"PointLabel", e.PointLabel.getSize()},
        {"PointCurvature", static_cast<size_t>(e.PointCurvature.getSize())}};
    // The odd one out is named against a list of the size most of them share.
    auto shared = [&](size_t size) {
        return std::count_if(lists.begin(), lists.end(),
                             [size](const auto& list) { return list.second == size; });
    };
    const auto reference =
        std::max_element(lists.begin(), lists.end(), [&](const auto& a, const auto& b) {
            return shared(a.second) < shared(b.second);
        });
    for (const auto& [name, size] : lists) {
        if (size != reference->second) {
            return std::string(name) + " holds " + count(size, "values") + " but " +
                   reference->first + " " + std::to_string(reference->second);
        }
    }
    const size_t points = lists.front().second;
    auto* cloud = dynamic_cast<const Points::Feature*>(e.Source.getValue());
    if (againstSource && cloud && points != 0 && cloud->Points.getValue().size() != points) {
        return std::string("the per-point lists (PointRegion ...) hold ") +
               count(points, "values") + " but the source '" + cloud->Label.getValue() + "' has " +
               count(cloud->Points.getValue().size(), "points");
    }
    std::string bad = outOfRange("PointRegion", e.PointRegion.getValues(), -1,
                                 e.RegionCount.getValue(), "RegionCount");
    if (bad.empty()) {
        bad = outOfRange("PointPatch", e.PointPatch.getValues(), -1, e.PatchCount.getValue(),
                         "PatchCount");
    }
    if (bad.empty()) {
        bad = outOfRange("PointLabel", e.PointLabel.getValues(), -1, 4, "4 labels");
    }
    return bad;
}

std::string lineCountMismatch(const Extraction& e)
{
    struct Lines
    {
        const char* countName;
        long count;
        const char* shapeName;
        size_t wires;
    };
    const Lines lines[] = {
        {"SharpLineCount", e.SharpLineCount.getValue(), "SharpWires", wireCount(e.SharpWires)},
        {"SmoothLineCount", e.SmoothLineCount.getValue(), "SmoothWires", wireCount(e.SmoothWires)},
        {"BoundaryLineCount", e.BoundaryLineCount.getValue(), "BoundaryWires",
         wireCount(e.BoundaryWires)}};
    long all = 0;
    for (const Lines& l : lines) {
        if (l.count < 0 || static_cast<size_t>(l.count) != l.wires) {
            return std::string(l.countName) + " is " + std::to_string(l.count) + " but " +
                   l.shapeName + " holds " + count(l.wires, "wires");
        }
        all += l.count;
    }
    if (wireCount(e.Shape) != static_cast<size_t>(all)) {
        return "Shape holds " + count(wireCount(e.Shape), "wires") +
               " but the line counts add "
               "up to " +
               std::to_string(all);
    }
    if (e.ClosedLineCount.getValue() < 0 || e.ClosedLineCount.getValue() > all) {
        return "ClosedLineCount is " + std::to_string(e.ClosedLineCount.getValue()) + " of " +
               count(static_cast<size_t>(all), "lines");
    }
    const long smooth = e.SmoothLineCount.getValue();
    for (const auto& [name, size] :
         {std::pair("SmoothLineRegions", size_t(e.SmoothLineRegions.getSize())),
          std::pair("SmoothLineThresholds", size_t(e.SmoothLineThresholds.getSize()))}) {
        if (size != static_cast<size_t>(smooth)) {
            return std::string(name) + " holds " + count(size, "values") +
                   " but SmoothLineCount is " + std::to_string(smooth);
        }
    }
    // Empty in a document saved before they existed: that is no contradiction.
    for (const auto& [name, size, countName, lineCount] :
         {std::tuple("SharpAngles", size_t(e.SharpAngles.getSize()), "SharpLineCount",
                     e.SharpLineCount.getValue()),
          std::tuple("SmoothBlendRadii", size_t(e.SmoothBlendRadii.getSize()), "SmoothLineCount",
                     smooth)}) {
        if (size != 0 && size != static_cast<size_t>(lineCount)) {
            return std::string(name) + " holds " + count(size, "values") + " but " + countName +
                   " is " + std::to_string(lineCount);
        }
    }
    // -1: the border of a blend typed by its profile, which lies in no region.
    return outOfRange("SmoothLineRegions", e.SmoothLineRegions.getValues(), -1,
                      e.RegionCount.getValue(), "RegionCount");
}

std::string thresholdMismatch(const Extraction& e)
{
    if (e.UsedThresholds.getSize() != e.UsedThresholdRegions.getSize()) {
        return "UsedThresholds holds " + count(size_t(e.UsedThresholds.getSize()), "values") +
               " but UsedThresholdRegions " + std::to_string(e.UsedThresholdRegions.getSize());
    }
    return outOfRange("UsedThresholdRegions", e.UsedThresholdRegions.getValues(), 0,
                      e.RegionCount.getValue(), "RegionCount");
}

} // namespace

std::string storedResultMismatch(const Extraction& e, bool againstSource)
{
    for (const std::string& problem :
         {perPointMismatch(e, againstSource), lineCountMismatch(e), thresholdMismatch(e)}) {
        if (!problem.empty()) {
            return problem;
        }
    }
    return {};
}

void requireCurrentResult(const Extraction& e, const std::string& function)
{
    const std::string object = "'" + std::string(e.Label.getValue()) + "'";
    auto refuse = [&](const std::string& why) {
        throw std::invalid_argument(function + ": " + object + " " + why);
    };
    if (e.isError()) {
        refuse(std::string("failed its last recompute or its restore (") + e.getStatusString() +
               "); its stored lines and per-point lists are not those of its source. Fix the "
               "cause and recompute first.");
    }
    if (e.isTouched() || e.mustExecute() != 0) {
        refuse("changed since its last recompute (it is out of date): recompute it first.");
    }
    auto* cloud = dynamic_cast<const Points::Feature*>(e.Source.getValue());
    if (!cloud) {
        refuse("has no point cloud as Source: its per-point lists belong to no cloud.");
    }
    if (cloud->isTouched() || cloud->isError()) {
        refuse("is out of date: its source '" + std::string(cloud->Label.getValue()) +
               "' changed since; recompute first.");
    }
    if (e.PointPatch.getSize() == 0) {
        refuse("has no patches of its source cloud: recompute it first.");
    }
    const std::string mismatch = storedResultMismatch(e);
    if (!mismatch.empty()) {
        refuse("holds a damaged result: " + mismatch + ". Recompute it to rebuild the result.");
    }
}

} // namespace FeatureLines
