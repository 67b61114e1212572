// SPDX-License-Identifier: LGPL-2.1-or-later
#include <FCConfig.h>

#include "InteractiveThresholds.h"

#include <Mod/Points/App/PointsFeature.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "ExtractionFeature.h"
#include "FeatureLines/smooth/AutomaticThresholds.h"

namespace FeatureLines {

using featurelines::PointLabel;
using featurelines::RegionGeometry;
using featurelines::SmoothEdgeOptions;
using featurelines::ThresholdResult;

namespace {

constexpr double none = std::numeric_limits<double>::quiet_NaN();

/// The core's outlier rule (smooth/SmoothEdgeOptions.h, SmoothEdgeOptions::histogram): a negative
/// percentage means 1 % for a smoothed region and none for a clean one (Sec. 2.4: outliers
/// come with noise).
double outlierPercent(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    const double p = options.histogram.outlierPercent;
    return p >= 0.0 ? p : (region.smoothed ? 1.0 : 0.0);
}

/// The largest value kept when `percent` % of the highest values are dropped, as the core's
/// search drops them (HistogramThreshold.cpp): floor(n percent / 100) values go, ties with the
/// cut stay. +infinity when none are dropped.
double outlierCut(const std::vector<double>& values, double percent)
{
    const size_t dropped = static_cast<size_t>(std::floor(values.size() * percent / 100.0));
    if (dropped == 0 || dropped >= values.size()) {
        return std::numeric_limits<double>::infinity();
    }
    std::vector<double> sorted(values);
    const auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(values.size() - dropped - 1);
    std::nth_element(sorted.begin(), nth, sorted.end());
    return *nth;
}

std::vector<double> regionValues(const RegionGeometry& region)
{
    return std::vector<double>(region.curvature.data(),
                               region.curvature.data() + region.curvature.size());
}

} // namespace

ExtractionInput extractionInput(const Extraction& extraction, const ParameterValues& changes)
{
    const App::DocumentObject* source = extraction.Source.getValue();
    if (!source) {
        throw std::invalid_argument("No point cloud: set Source to a Points object.");
    }
    if (!source->isDerivedFrom(Points::Feature::getClassTypeId())) {
        throw std::invalid_argument("'" + std::string(source->Label.getValue()) +
                                    "' is not a point cloud: Source must be a Points object.");
    }
    ParameterValues values = extraction.parameterValues();
    for (const auto& [name, value] : changes.scalars) {
        values.scalars[name] = value;
    }
    if (changes.thresholds) {
        values.thresholds = changes.thresholds;
    }
    if (changes.regionThresholds) {
        values.regionThresholds = changes.regionThresholds;
    }
    ExtractionInput input;
    input.options = toExtractionOptions(values);
    const Points::PointKernel& kernel =
        static_cast<const Points::Feature*>(source)->Points.getValue();
    input.points = kernelPoints(kernel);
    input.cloudHash = hashCloud(input.points);
    input.toWorld = kernel.getTransform();
    return input;
}

const RegionGeometry& regionGeometry(const CloudAnalysis& analysis, int region)
{
    if (!analysis.regions) {
        throw std::invalid_argument("the cloud has not been analysed");
    }
    for (const RegionGeometry& g : analysis.regions->geometry) {
        if (g.region == region) {
            return g;
        }
    }
    const int count = static_cast<int>(analysis.regions->geometry.size());
    throw std::invalid_argument(
        count == 0 ? "the cloud has no smooth region (SmoothEdges is off, or the sharp edges "
                     "leave no region)"
                   : "there is no smooth region " + std::to_string(region) + ": the cloud has " +
                         std::to_string(count) + " (0 to " + std::to_string(count - 1) + ")");
}

RegionHistogram regionHistogram(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    const std::vector<double> values = regionValues(region);
    RegionHistogram h;
    h.outlierCut = none;
    if (values.empty()) {
        return h;
    }
    const double cut = outlierCut(values, outlierPercent(region, options));
    const double lo = *std::min_element(values.begin(), values.end());
    const double hi = std::isfinite(cut) ? cut : *std::max_element(values.begin(), values.end());
    const int bins = std::max(2, options.histogram.bins);
    h.minimum = lo;
    if (!(hi > lo)) {
        // One value: one full bin of an arbitrary width, the core's histogram does the same.
        h.binWidth = std::max(std::abs(lo), 1.0) * 1e-3;
        h.counts.assign(1, static_cast<long>(values.size()));
        return h;
    }
    h.binWidth = (hi - lo) / bins;
    int shown = bins;
    if (std::isfinite(cut)) {
        h.outlierCut = cut;
        shown += std::max(1, bins / 10);
    }
    h.counts.assign(static_cast<size_t>(shown), 0);
    for (double v : values) {
        const double position = std::floor((v - lo) / h.binWidth);
        // The core's last bin also holds its maximum (here the cut): so does this one.
        const int bin = v == hi ? bins - 1 : static_cast<int>(std::min(position, double(shown)));
        if (bin >= 0 && bin < shown) {
            ++h.counts[static_cast<size_t>(bin)];
        }
    }
    return h;
}

ThresholdResult searchThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options,
                                double lower, double upper)
{
    std::vector<double> values = regionValues(region);
    if (values.empty()) {
        throw std::invalid_argument("the region has no curvature values");
    }
    // Sec. 2.4 on all of the region's values first, so a bounded search is not drawn to them.
    const double cut = outlierCut(values, outlierPercent(region, options));
    // Sec. 2.3: only the values between the neighbouring thresholds.
    values.erase(std::remove_if(values.begin(), values.end(),
                                [&](double v) {
                                    return v > cut || (std::isfinite(lower) && !(v > lower)) ||
                                           (std::isfinite(upper) && !(v <= upper));
                                }),
                 values.end());
    if (values.empty()) {
        throw std::invalid_argument("there are no curvature values in that range");
    }
    featurelines::ThresholdOptions search = options.histogram;
    search.outlierPercent = 0.0;
    ThresholdResult t = featurelines::findThreshold(values, search);
    t.outlierCut = std::isfinite(cut) ? cut : t.outlierCut;
    return t;
}

std::vector<PointLabel> regionLabels(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options)
{
    if (!std::isfinite(threshold)) {
        throw std::invalid_argument("the curvature threshold must be a finite number");
    }
    std::vector<int> all(static_cast<size_t>(region.points.rows()));
    std::iota(all.begin(), all.end(), 0);
    return featurelines::labelPoints(region.curvature, threshold, region.ring, all, options.labels);
}

void scatterToInputPoints(const featurelines::CloudGeometry& cloud, const RegionGeometry& region,
                          const std::vector<int>& perRegionPoint, std::vector<int>& perInputPoint)
{
    if (perRegionPoint.size() != region.members.size() ||
        perInputPoint.size() != cloud.inputToPoint.size()) {
        throw std::invalid_argument("scatterToInputPoints: one value per region point and one "
                                    "entry per input point are needed");
    }
    std::vector<int> indexInRegion(static_cast<size_t>(cloud.points.rows()), -1);
    for (size_t i = 0; i < region.members.size(); ++i) {
        indexInRegion[static_cast<size_t>(region.members[i])] = static_cast<int>(i);
    }
    for (size_t j = 0; j < perInputPoint.size(); ++j) {
        const int i = indexInRegion[static_cast<size_t>(cloud.inputToPoint[j])];
        if (i >= 0) {
            perInputPoint[j] = perRegionPoint[static_cast<size_t>(i)];
        }
    }
}

double repeatedThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options,
                         double candidate, const std::vector<double>& accepted)
{
    double below = none;
    double above = none;
    for (double a : accepted) {
        if (a == candidate) {
            return a;
        }
        if (a < candidate && !(a <= below)) {
            below = a;
        }
        if (a > candidate && !(a >= above)) {
            above = a;
        }
    }
    if (std::isnan(below) && std::isnan(above)) {
        return none;
    }
    const auto [patchAbove, patchBelow] =
        featurelines::largestLevelPatches(region, below, candidate, above);
    const int least = featurelines::minimumPatchPoints(region, options.automatic);
    if (!std::isnan(above) && patchAbove < least) {
        return above;
    }
    if (!std::isnan(below) && patchBelow < least) {
        return below;
    }
    // An open side without a patch (a candidate beyond every curved point): no new patch
    // either; the lines are those of the accepted threshold on the other side.
    if (std::isnan(above) && patchAbove < least) {
        return below;
    }
    if (std::isnan(below) && patchBelow < least) {
        return above;
    }
    return none;
}

std::vector<double> automaticRegionThresholds(const RegionGeometry& region,
                                              const SmoothEdgeOptions& options)
{
    std::vector<double> thresholds;
    for (const featurelines::ThresholdDecision& d :
         featurelines::automaticThresholds(region, options)) {
        if (d.accepted) {
            thresholds.push_back(d.applied);
        }
    }
    std::sort(thresholds.begin(), thresholds.end(), std::greater<double>());
    return thresholds;
}

} // namespace FeatureLines
