// SPDX-License-Identifier: LGPL-2.1-or-later
#include "ExtractionParameters.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace FeatureLines {

using featurelines::ExtractionOptions;

namespace {

const char* const smoothingChoices[] = {"Automatic", "Always", "Never", nullptr};
const char* const thresholdModeChoices[] = {"Automatic", "First", "Explicit", nullptr};

// The option a row of ParameterTable.h maps to, as a number: integers, lengths, angles, switches
// (0 or 1) and choices (the index of the value) alike.
double asNumber(int v)
{
    return double(v);
}
double asNumber(double v)
{
    return v;
}
double asNumber(bool v)
{
    return v ? 1.0 : 0.0;
}
template <class Enum, std::enable_if_t<std::is_enum_v<Enum>, int> = 0> double asNumber(Enum v)
{
    return double(int(v));
}

void assign(int& option, double v)
{
    option = int(v);
}
void assign(double& option, double v)
{
    option = v;
}
void assign(bool& option, double v)
{
    option = v != 0.0;
}
template <class Enum, std::enable_if_t<std::is_enum_v<Enum>, int> = 0>
void assign(Enum& option, double v)
{
    option = Enum(int(v));
}

// The graph of Demarsin et al. 2007 turns candidate points into lines for sharp edges, the
// boundary and (Sec. 3 of the 2008 paper) smooth edges alike: one set of lengths for all. Read
// from the smooth edges' graph, written to both.
template <double featurelines::ClusterGraphOptions::*field, class Options> struct GraphLength
{
    Options& o;
};
template <double featurelines::ClusterGraphOptions::*field>
GraphLength<field, const ExtractionOptions> graphLength(const ExtractionOptions& o)
{
    return {o};
}
template <double featurelines::ClusterGraphOptions::*field>
GraphLength<field, ExtractionOptions> graphLength(ExtractionOptions& o)
{
    return {o};
}
template <double featurelines::ClusterGraphOptions::*field>
double asNumber(GraphLength<field, const ExtractionOptions> length)
{
    return length.o.smooth.graph.*field;
}
template <double featurelines::ClusterGraphOptions::*field>
void assign(GraphLength<field, ExtractionOptions> length, double v)
{
    length.o.sharp.graph.*field = v;
    length.o.smooth.graph.*field = v;
}

// ResampleSpacing: the graphs' step, and the sharp lines' too (they are resampled after crease
// placement).
template <class Options> struct ResampleSpacing
{
    Options& o;
};
ResampleSpacing<const ExtractionOptions> resampleSpacing(const ExtractionOptions& o)
{
    return {o};
}
ResampleSpacing<ExtractionOptions> resampleSpacing(ExtractionOptions& o)
{
    return {o};
}
double asNumber(ResampleSpacing<const ExtractionOptions> spacing)
{
    return asNumber(graphLength<&featurelines::ClusterGraphOptions::resampleSpacing>(spacing.o));
}
void assign(ResampleSpacing<ExtractionOptions> spacing, double v)
{
    assign(graphLength<&featurelines::ClusterGraphOptions::resampleSpacing>(spacing.o), v);
    spacing.o.sharp.resampleSpacing = v;
}

std::vector<Parameter> makeParameters()
{
    // One Parameter per row of the table.
    // clang-format off
#define FEATURELINES_PARAMETER(name, kind, stage, group, minimum, maximum, step, choices, option, \
                               doc)                                                               \
    {#name, group, doc, ParameterKind::kind, ParameterStage::stage, minimum, maximum, step,       \
     choices,                                                                                     \
     [](const ExtractionOptions& o) { return asNumber(option); },                                 \
     [](ExtractionOptions& o, double v) { assign(option, v); }},
    // clang-format on
    return {
#include "ParameterTable.h"
    };
#undef FEATURELINES_PARAMETER
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
