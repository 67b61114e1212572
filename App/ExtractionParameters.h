// SPDX-License-Identifier: LGPL-2.1-or-later
// The named parameters of a feature line extraction: one table (ParameterTable.h, one row per
// parameter) that maps every name onto a field of featurelines::ExtractionOptions. The document
// object's properties and the keyword arguments of the Python functions both go through it, so a
// name means the same thing everywhere and the defaults are the core's own (read from a
// default-constructed ExtractionOptions).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "FeatureLines/Extraction.h"

namespace FeatureLines {

/// How a parameter is shown as a FreeCAD property.
enum class ParameterKind
{
    Integer, ///< App::PropertyIntegerConstraint
    Float,   ///< App::PropertyFloatConstraint
    Spacing, ///< App::PropertyFloatConstraint, a length in multiples of the mean point spacing
    Angle,   ///< App::PropertyAngle, degrees
    Switch,  ///< App::PropertyBool
    Choice,  ///< App::PropertyEnumeration, the value is the index into `choices`
};

/// The first cached step of the pipeline a parameter affects (Extraction.h): changing it re-runs
/// that step and the later ones, and nothing before.
enum class ParameterStage
{
    Cloud,   ///< analyseCloud: neighbours, spacing, normals
    Regions, ///< analyseRegions: sharp edges, boundary, smooth regions, their curvature
    Lines,   ///< extractFeatureLines: thresholds, labels, smooth-edge lines
};

struct Parameter
{
    /// Property name and Python keyword.
    const char* name;
    /// Property group.
    const char* group;
    /// Property tool tip and Python documentation.
    const char* doc;
    ParameterKind kind;
    ParameterStage stage;
    double minimum;
    double maximum;
    double step;
    /// Choice only: the names of the values, null-terminated.
    const char* const* choices;
    double (*read)(const featurelines::ExtractionOptions&);
    void (*write)(featurelines::ExtractionOptions&, double);
};

/// Every scalar parameter, in the order the properties are listed.
const std::vector<Parameter>& parameters();
/// nullptr when no scalar parameter has this name.
const Parameter* findParameter(const std::string& name);
/// The core's default of the parameter.
double defaultValue(const Parameter& parameter);

/// The two list parameters, not in parameters(): ThresholdMode Explicit applies
/// RegionThresholds to the regions it names and Thresholds to every other region.
constexpr const char* thresholdsName = "Thresholds";
constexpr const char* regionThresholdsName = "RegionThresholds";
extern const char* const thresholdsDoc;
extern const char* const regionThresholdsDoc;

/// Parameter values by name; a name not given keeps the core's default.
struct ParameterValues
{
    std::map<std::string, double> scalars;
    std::optional<std::vector<double>> thresholds;
    std::optional<std::map<int, std::vector<double>>> regionThresholds;
};

/// Maps the values onto the core's options. Throws std::invalid_argument naming the parameter
/// for an unknown name, a value out of its range or a negative or non-finite threshold.
featurelines::ExtractionOptions toExtractionOptions(const ParameterValues& values);

/// The values of every parameter whose stage is at most `stage`, as text: two option sets
/// with equal keys give equal results up to that step, so the key names a cache entry.
std::string stageKey(const featurelines::ExtractionOptions& options, ParameterStage stage);

/// "0.12 0.05" (white space or commas between numbers) -> {0.12, 0.05}. Throws
/// std::invalid_argument naming `what` for a word that is not a number.
std::vector<double> parseThresholds(const std::string& text, const std::string& what);
/// The inverse of parseThresholds, full precision.
std::string formatThresholds(const std::vector<double>& thresholds);

/// A region number written as text ("0", "12"). Throws std::invalid_argument otherwise.
int parseRegion(const std::string& text);

/// RegionThresholds as stored in a property map: "region number" -> "t1 t2 ...".
std::map<int, std::vector<double>>
parseRegionThresholds(const std::map<std::string, std::string>& text);
std::map<std::string, std::string>
formatRegionThresholds(const std::map<int, std::vector<double>>& thresholds);

} // namespace FeatureLines
