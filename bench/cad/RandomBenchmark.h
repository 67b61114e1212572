// SPDX-License-Identifier: LGPL-2.1-or-later
// The random parts' benchmark (issue 16, docs/ACCURACY.md "Held-out random parts"): one
// record per part and detector, the per-part table, and the aggregates per family, sampling
// model and noise level, each as the mean and the worst tenth. Plain tables of text; the
// driver (accuracy.cpp) measures and prints.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "LineScore.h"

namespace featurelines::bench {

/// One random part as one line detector saw it.
struct RandomPartRecord
{
    std::uint32_t seed = 0;
    /// randomGroupOfSeed(seed).
    std::string group;
    std::string family;
    /// scanModelName of the drawn model.
    std::string model;
    /// Normal noise, in spacings.
    double noise = 0.0;
    long points = 0;
    /// Mean nearest spacing of the clean cloud (model units).
    double spacing = 0.0;
    /// Time to build the part, sample it and cut its truth; extraction time (seconds).
    double buildSeconds = 0.0;
    double seconds = 0.0;
    /// At the benchmark's 3 h, at 1 h, and the line quality.
    LineScore score;
    LineScore scoreAtOneSpacing;
    LineQuality quality;
};

/// "tuning" for seeds 0-199, "held-out" for 1000-1199, "other" otherwise (the protocol of
/// docs/ACCURACY.md, "Random parts").
std::string randomGroupOfSeed(std::uint32_t seed);

/// `v` with `decimals` decimals, "-" for NaN: every number of the benchmark's tables.
std::string formatNumber(double v, int decimals = 3);

/// The finite number `text` is, whole; else std::invalid_argument "<what> expects a number".
double parseNumber(const std::string& text, const std::string& what);

/// "A-B" ranges and single seeds, comma separated ("0-47,1000"), in the order given. Throws
/// std::invalid_argument on anything else or a range whose end precedes its start.
std::vector<std::uint32_t> parseSeedList(const std::string& text);

/// Mean of the lowest ceil(10 %) of the defined (non-NaN) values, at least one of them; the
/// highest instead when `higherIsWorse` (distances). NaN when no value is defined.
double worstTenthMean(std::vector<double> values, bool higherIsWorse = false);

/// A table of text cells with a title line.
struct TextTable
{
    std::string title;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

/// One row per record: seed, family, model, noise, points, and the scores.
TextTable randomPartTable(const std::vector<RandomPartRecord>& records);

/// Per group ("tuning", "held-out", "other", in that order; apart): one table over all parts
/// and per family, per sampling model and per noise level, each with the mean and the worst
/// tenth of sharp F1, smooth F1, closedness, sharp and smooth F1 at 1 h and median distance.
std::vector<TextTable> randomAggregateTables(const std::vector<RandomPartRecord>& records);

/// The measures a floor can be put on: mean sharp F1, smooth F1, closedness over records.
struct RandomMeans
{
    double sharpF1 = 0.0;
    double smoothF1 = 0.0;
    double closedness = 0.0;
};
RandomMeans randomMeans(const std::vector<RandomPartRecord>& records);

/// Lowest acceptable means; NaN: no floor.
struct RandomFloors
{
    double sharpF1 = std::numeric_limits<double>::quiet_NaN();
    double smoothF1 = std::numeric_limits<double>::quiet_NaN();
    double closedness = std::numeric_limits<double>::quiet_NaN();
};

/// "name=value,..." given to `option` (e.g. "--floor"), each name one of `names`, each value a
/// number. Throws std::invalid_argument naming the option and the item otherwise.
std::map<std::string, double> parseNamedNumbers(const std::string& text, const std::string& option,
                                                const std::vector<std::string>& names);

/// "sharp=0.6,smooth=0.3,closed=0.8" (any subset). Throws std::invalid_argument otherwise.
RandomFloors parseFloors(const std::string& text);

/// One sentence per mean below its floor (a NaN mean is below), empty when all pass.
std::vector<std::string> floorFailures(const RandomMeans& means, const RandomFloors& floors);

} // namespace featurelines::bench
