// SPDX-License-Identifier: LGPL-2.1-or-later
#include "ExtractionParameters.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace FeatureLines {

using featurelines::ExtractionOptions;

namespace {

const char* const smoothingChoices[] = {"Automatic", "Always", "Never", nullptr};
const char* const thresholdModeChoices[] = {"Automatic", "First", "Explicit", nullptr};

// The graph of Demarsin et al. 2007 turns candidate points into lines for sharp edges, the
// boundary and (Sec. 3 of the 2008 paper) smooth edges alike: one set of lengths for all.
template <double featurelines::ClusterGraphOptions::*field>
double readGraph(const ExtractionOptions& o)
{
    return o.smooth.graph.*field;
}

template <double featurelines::ClusterGraphOptions::*field>
void writeGraph(ExtractionOptions& o, double v)
{
    o.sharp.graph.*field = v;
    o.smooth.graph.*field = v;
}

using featurelines::ClusterGraphOptions;
using PK = ParameterKind;
using PS = ParameterStage;

std::vector<Parameter> makeParameters()
{
    return {
        // Neighbourhood
        {"NeighbourCount", "Neighbourhood",
         "k: the nearest neighbours of every point used for normals, curvature and the graphs "
         "(Sec. 2.1). More neighbours smooth noise but blur small features.",
         PK::Integer, PS::Cloud, 3, 1000, 1, nullptr,
         [](const ExtractionOptions& o) { return double(o.neighbours.k); },
         [](ExtractionOptions& o, double v) { o.neighbours.k = int(v); }},

        // Sharp edges
        {"SharpEdges", "Sharp edges",
         "Extract sharp edges (tangent discontinuities) by first-order segmentation (Demarsin et "
         "al. 2007). They divide the cloud into the smooth regions whose curvature is thresholded "
         "on its own (Sec. 1.2).",
         PK::Switch, PS::Regions, 0, 1, 1, nullptr,
         [](const ExtractionOptions& o) { return o.sharpEdges ? 1.0 : 0.0; },
         [](ExtractionOptions& o, double v) { o.sharpEdges = v != 0.0; }},
        {"BoundaryLines", "Sharp edges",
         "Extract the external boundary of an open cloud (a scan of one side of a part) and let "
         "sharp lines end on it (Sec. 1.2, Fig. 1 c).",
         PK::Switch, PS::Regions, 0, 1, 1, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.includeBoundary ? 1.0 : 0.0; },
         [](ExtractionOptions& o, double v) { o.sharp.includeBoundary = v != 0.0; }},
        {"GrowAngle", "Sharp edges",
         "A point may stop the growing of a surface cluster only when the normals of its "
         "neighbours spread more than this around its own (and its points bend like a crease, "
         "see MinFilletRadius). Lower it to find shallower creases.",
         PK::Angle, PS::Regions, 1, 90, 1, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.segmentation.growAngle; },
         [](ExtractionOptions& o, double v) { o.sharp.segmentation.growAngle = v; }},
        {"JoinAngle", "Sharp edges",
         "A neighbour joins the cluster of a growing point when their normals differ by less "
         "than this; points on a crease join neither face.",
         PK::Angle, PS::Regions, 1, 90, 1, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.segmentation.joinAngle; },
         [](ExtractionOptions& o, double v) { o.sharp.segmentation.joinAngle = v; }},
        {"MinFilletRadius", "Sharp edges",
         "Blends of this radius (x point spacing) or more are smooth edges, found by the "
         "curvature histogram; tighter bends are sharp edges.",
         PK::Spacing, PS::Regions, 0.5, 1000, 0.5, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.segmentation.minFilletRadius; },
         [](ExtractionOptions& o, double v) { o.sharp.segmentation.minFilletRadius = v; }},
        {"CreaseFitRadius", "Sharp edges",
         "Sharp lines are moved onto the intersection of planes fitted to the faces within this "
         "radius (x point spacing).",
         PK::Spacing, PS::Regions, 0.5, 100, 0.5, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.fitRadius; },
         [](ExtractionOptions& o, double v) { o.sharp.fitRadius = v; }},
        {"MinCreaseAngle", "Sharp edges",
         "Two fitted faces closer to parallel than this define no crease: the line stays where "
         "the points are.",
         PK::Angle, PS::Regions, 0, 90, 1, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.minCreaseAngle; },
         [](ExtractionOptions& o, double v) { o.sharp.minCreaseAngle = v; }},
        {"BoundaryGapAngle", "Sharp edges",
         "A point is on the boundary when its neighbours, seen in its tangent plane, leave an "
         "empty sector wider than this.",
         PK::Angle, PS::Regions, 10, 350, 5, nullptr,
         [](const ExtractionOptions& o) { return o.sharp.boundary.minGapAngle; },
         [](ExtractionOptions& o, double v) { o.sharp.boundary.minGapAngle = v; }},

        // Smooth edges
        {"SmoothEdges", "Smooth edges",
         "Extract smooth edges (curvature discontinuities such as fillet borders) by histogram "
         "thresholding of the mean curvature in every smooth region (Sec. 2-3).",
         PK::Switch, PS::Regions, 0, 1, 1, nullptr,
         [](const ExtractionOptions& o) { return o.smoothEdges ? 1.0 : 0.0; },
         [](ExtractionOptions& o, double v) { o.smoothEdges = v != 0.0; }},
        {"BandWidth", "Smooth edges",
         "Points closer than this to a sharp line (x point spacing) belong to no smooth region: "
         "their neighbourhoods straddle the crease.",
         PK::Spacing, PS::Regions, 0, 50, 0.5, nullptr,
         [](const ExtractionOptions& o) { return o.regions.bandWidth; },
         [](ExtractionOptions& o, double v) { o.regions.bandWidth = v; }},
        {"Smoothing", "Smooth edges",
         "Taubin smoothing of a region before its curvature is estimated (Sec. 2.4): Automatic "
         "smooths the regions whose noise exceeds NoiseThreshold.",
         PK::Choice, PS::Regions, 0, 2, 1, smoothingChoices,
         [](const ExtractionOptions& o) { return double(int(o.smooth.smoothing)); },
         [](ExtractionOptions& o, double v) {
             o.smooth.smoothing = featurelines::SmoothingMode(int(v));
         }},
        {"SmoothingIterations", "Smooth edges", "Taubin smoothing passes (Sec. 2.4).", PK::Integer,
         PS::Regions, 0, 1000, 1, nullptr,
         [](const ExtractionOptions& o) { return double(o.smooth.smoothingOptions.iterations); },
         [](ExtractionOptions& o, double v) { o.smooth.smoothingOptions.iterations = int(v); }},
        {"NoiseThreshold", "Smooth edges",
         "Noise (x point spacing) above which Automatic smoothing applies; a clean surface shows "
         "less than 0.005.",
         PK::Spacing, PS::Regions, 0, 10, 0.01, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.noiseThreshold; },
         [](ExtractionOptions& o, double v) { o.smooth.noiseThreshold = v; }},
        {"SignedCurvature", "Smooth edges",
         "Threshold the signed mean curvature instead of its magnitude (concave and convex "
         "fillets of one radius then fall in different histogram peaks).",
         PK::Switch, PS::Regions, 0, 1, 1, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.curvature.signedCurvature ? 1.0 : 0.0; },
         [](ExtractionOptions& o, double v) { o.smooth.curvature.signedCurvature = v != 0.0; }},

        {"MaxCurvatureScale", "Smooth edges",
         "Coarsest scale (x point spacing) at which a noisy region's curvature is also computed, "
         "averaged onto coarser grids, when the noise would hide fillets larger than this at the "
         "cloud's own spacing; the scale with the most significant thresholds is used. 1: the "
         "cloud's own spacing only, as the paper.",
         PK::Spacing, PS::Regions, 1, 64, 1, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.scales.maxScale; },
         [](ExtractionOptions& o, double v) { o.smooth.scales.maxScale = v; }},
        {"PlaceCoarseLines", "Smooth edges",
         "Where a region's curvature was read at a coarser scale, move its smooth lines onto the "
         "curvature step of the points under them (a fit of the surface's profile across each "
         "line): the coarse scale alone leaves them a few point spacings off the fillet border.",
         PK::Switch, PS::Lines, 0, 1, 1, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.placeCoarseLines ? 1.0 : 0.0; },
         [](ExtractionOptions& o, double v) { o.smooth.placeCoarseLines = v != 0.0; }},

        // Line graph (Demarsin et al. 2007, reused for smooth edges in Sec. 3)
        {"NodeRadius", "Line graph",
         "Candidate points within this radius (x point spacing) form one graph node, so a band "
         "of candidates becomes a chain one node wide.",
         PK::Spacing, PS::Regions, 0, 20, 0.5, nullptr, readGraph<&ClusterGraphOptions::nodeRadius>,
         writeGraph<&ClusterGraphOptions::nodeRadius>},
        {"ExtendedRadius", "Line graph",
         "Nodes closer than this (x point spacing) are joined, bridging gaps of missing "
         "candidates (G_extended).",
         PK::Spacing, PS::Regions, 0, 50, 0.5, nullptr,
         readGraph<&ClusterGraphOptions::extendedRadius>,
         writeGraph<&ClusterGraphOptions::extendedRadius>},
        {"MaxEdgeLength", "Line graph",
         "Spanning tree edges longer than this (x point spacing) are cut: they join two "
         "features, not two pieces of one.",
         PK::Spacing, PS::Regions, 0.5, 100, 0.5, nullptr,
         readGraph<&ClusterGraphOptions::maxEdgeLength>,
         writeGraph<&ClusterGraphOptions::maxEdgeLength>},
        {"MinBranchLength", "Line graph",
         "Branches to a free end shorter than this (x point spacing) are pruned.", PK::Spacing,
         PS::Regions, 0, 100, 0.5, nullptr, readGraph<&ClusterGraphOptions::minBranchLength>,
         writeGraph<&ClusterGraphOptions::minBranchLength>},
        {"ReconnectRadius", "Line graph",
         "A free line end is joined to the nearest node ahead of it within this distance (x "
         "point spacing), so lines close.",
         PK::Spacing, PS::Regions, 0, 200, 0.5, nullptr,
         readGraph<&ClusterGraphOptions::reconnectRadius>,
         writeGraph<&ClusterGraphOptions::reconnectRadius>},
        {"ReconnectAngle", "Line graph",
         "\"Ahead\" of a free end is within this angle of the line's direction.", PK::Angle,
         PS::Regions, 0, 180, 5, nullptr, readGraph<&ClusterGraphOptions::reconnectAngle>,
         writeGraph<&ClusterGraphOptions::reconnectAngle>},
        {"MinComponentLength", "Line graph",
         "Connected pieces of lines shorter than this in total (x point spacing) are dropped as "
         "noise.",
         PK::Spacing, PS::Regions, 0, 10000, 1, nullptr,
         readGraph<&ClusterGraphOptions::minComponentLength>,
         writeGraph<&ClusterGraphOptions::minComponentLength>},
        {"ResampleSpacing", "Line graph",
         "Lines are resampled at this step (x point spacing); 0 keeps one vertex per node.",
         PK::Spacing, PS::Regions, 0, 100, 0.5, nullptr,
         readGraph<&ClusterGraphOptions::resampleSpacing>,
         [](ExtractionOptions& o, double v) {
             writeGraph<&ClusterGraphOptions::resampleSpacing>(o, v);
             o.sharp.resampleSpacing = v; // sharp lines are resampled after crease placement
         }},

        // Thresholds
        {"ThresholdMode", "Thresholds",
         "Automatic: per region, every significant valley of the curvature histogram (Sec. "
         "2.3); First: the first threshold only; Explicit: Thresholds and RegionThresholds.",
         PK::Choice, PS::Lines, 0, 2, 1, thresholdModeChoices,
         [](const ExtractionOptions& o) { return double(int(o.thresholdMode)); },
         [](ExtractionOptions& o, double v) {
             o.thresholdMode = featurelines::ThresholdMode(int(v));
         }},
        {"HistogramBins", "Thresholds",
         "L_start: the bins of the start histogram of the multi-resolution search (Sec. 2.2; "
         "the paper's default is 50).",
         PK::Integer, PS::Lines, 2, 100000, 1, nullptr,
         [](const ExtractionOptions& o) { return double(o.smooth.histogram.bins); },
         [](ExtractionOptions& o, double v) { o.smooth.histogram.bins = int(v); }},
        {"OutlierPercent", "Thresholds",
         "Percentage of the highest curvature values dropped before the histogram is built "
         "(Sec. 2.4); -1 chooses 1 % for a smoothed (noisy) region and none for a clean one.",
         PK::Float, PS::Lines, -1, 50, 0.5, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.histogram.outlierPercent; },
         [](ExtractionOptions& o, double v) { o.smooth.histogram.outlierPercent = v; }},
        {"MinPeakPercent", "Thresholds",
         "Smallest histogram peak a threshold may follow, in percent of the values; 0 is the "
         "paper as is (Sec. 2.2).",
         PK::Float, PS::Lines, 0, 50, 0.5, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.histogram.minPeakPercent; },
         [](ExtractionOptions& o, double v) { o.smooth.histogram.minPeakPercent = v; }},
        {"MaxThresholds", "Thresholds", "Automatic mode: at most this many thresholds per region.",
         PK::Integer, PS::Lines, 1, 20, 1, nullptr,
         [](const ExtractionOptions& o) { return double(o.smooth.automatic.maxThresholds); },
         [](ExtractionOptions& o, double v) { o.smooth.automatic.maxThresholds = int(v); }},
        {"MinValleyRatio", "Thresholds",
         "Automatic mode: a threshold needs a valley ratio e = b1 / b2 of at least this (Sec. "
         "2.2).",
         PK::Float, PS::Lines, 1, 1000, 0.1, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.automatic.minRatio; },
         [](ExtractionOptions& o, double v) { o.smooth.automatic.minRatio = v; }},
        {"MinContrast", "Thresholds",
         "Automatic mode: the median curvature above a threshold over the median below it must "
         "reach this (two curvature levels, not one split in two).",
         PK::Float, PS::Lines, 1, 1000, 0.1, nullptr,
         [](const ExtractionOptions& o) { return o.smooth.automatic.minContrast; },
         [](ExtractionOptions& o, double v) { o.smooth.automatic.minContrast = v; }},
    };
}

std::string formatNumber(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

} // namespace

const char* const thresholdsDoc =
    "ThresholdMode Explicit: the curvature thresholds (1 / length unit) of every region not "
    "named in RegionThresholds, one closed set of smooth-edge lines each (Sec. 2.3).";
const char* const regionThresholdsDoc =
    "ThresholdMode Explicit: per smooth region (its number, as in UsedThresholdRegions), the "
    "thresholds as text, e.g. \"0.12 0.05\".";

const std::vector<Parameter>& parameters()
{
    static const std::vector<Parameter> table = makeParameters();
    return table;
}

const Parameter* findParameter(const std::string& name)
{
    for (const Parameter& p : parameters()) {
        if (name == p.name) {
            return &p;
        }
    }
    return nullptr;
}

double defaultValue(const Parameter& parameter)
{
    return parameter.read(ExtractionOptions{});
}

ExtractionOptions toExtractionOptions(const ParameterValues& values)
{
    ExtractionOptions options;
    for (const auto& [name, value] : values.scalars) {
        const Parameter* p = findParameter(name);
        if (!p) {
            throw std::invalid_argument("unknown feature line parameter '" + name + "'");
        }
        if (!std::isfinite(value) || value < p->minimum || value > p->maximum) {
            throw std::invalid_argument(name + " = " + formatNumber(value) + " is outside " +
                                        formatNumber(p->minimum) + " .. " +
                                        formatNumber(p->maximum));
        }
        if ((p->kind == ParameterKind::Integer || p->kind == ParameterKind::Choice) &&
            value != std::floor(value)) {
            throw std::invalid_argument(name + " must be a whole number");
        }
        p->write(options, value);
    }
    auto check = [](const std::vector<double>& list, const std::string& what) {
        for (double t : list) {
            if (!std::isfinite(t) || t < 0.0) {
                throw std::invalid_argument(what +
                                            ": curvature thresholds must be finite and "
                                            "not negative, got " +
                                            formatNumber(t));
            }
        }
    };
    if (values.thresholds) {
        check(*values.thresholds, thresholdsName);
        options.thresholds = *values.thresholds;
    }
    if (values.regionThresholds) {
        for (const auto& [region, list] : *values.regionThresholds) {
            if (region < 0) {
                throw std::invalid_argument(std::string(regionThresholdsName) +
                                            ": region numbers start at 0, got " +
                                            std::to_string(region));
            }
            check(list, std::string(regionThresholdsName) + " of region " + std::to_string(region));
        }
        options.regionThresholds = *values.regionThresholds;
    }
    return options;
}

std::string stageKey(const ExtractionOptions& options, ParameterStage stage)
{
    std::string key;
    for (const Parameter& p : parameters()) {
        if (p.stage <= stage) {
            key += p.name;
            key += '=';
            key += formatNumber(p.read(options));
            key += ';';
        }
    }
    return key;
}

std::vector<double> parseThresholds(const std::string& text, const std::string& what)
{
    std::string spaced = text;
    for (char& c : spaced) {
        if (c == ',' || c == ';') {
            c = ' ';
        }
    }
    std::istringstream words(spaced);
    std::vector<double> values;
    std::string word;
    while (words >> word) {
        size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(word, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != word.size()) {
            throw std::invalid_argument(what + ": '" + word + "' is not a number");
        }
        values.push_back(v);
    }
    return values;
}

std::string formatThresholds(const std::vector<double>& thresholds)
{
    std::string text;
    for (double t : thresholds) {
        if (!text.empty()) {
            text += ' ';
        }
        text += formatNumber(t);
    }
    return text;
}

int parseRegion(const std::string& text)
{
    size_t used = 0;
    int region = -1;
    try {
        region = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size()) {
        throw std::invalid_argument(std::string(regionThresholdsName) + ": '" + text +
                                    "' is not a region number");
    }
    return region;
}

std::map<int, std::vector<double>>
parseRegionThresholds(const std::map<std::string, std::string>& text)
{
    std::map<int, std::vector<double>> out;
    for (const auto& [key, value] : text) {
        out[parseRegion(key)] =
            parseThresholds(value, std::string(regionThresholdsName) + " of region " + key);
    }
    return out;
}

std::map<std::string, std::string>
formatRegionThresholds(const std::map<int, std::vector<double>>& thresholds)
{
    std::map<std::string, std::string> out;
    for (const auto& [region, list] : thresholds) {
        out[std::to_string(region)] = formatThresholds(list);
    }
    return out;
}

} // namespace FeatureLines
