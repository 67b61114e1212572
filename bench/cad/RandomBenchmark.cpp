// SPDX-License-Identifier: LGPL-2.1-or-later
#include "RandomBenchmark.h"

#include <algorithm>
#include <map>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace featurelines::bench {

namespace {

double f1Of(const LineScore& s, LineType t)
{
    const TypeScore& ts = s.types[static_cast<size_t>(t)];
    return ts.truthSamples > 0 ? ts.f1 : std::nan("");
}

double meanOfDefined(const std::vector<double>& values)
{
    double sum = 0.0;
    int n = 0;
    for (double v : values) {
        if (!std::isnan(v)) {
            sum += v;
            ++n;
        }
    }
    return n ? sum / n : std::nan("");
}

/// One aggregated measure: its name, how it is read off a record, and which end is worse.
struct Measure
{
    std::string name;
    std::function<double(const RandomPartRecord&)> value;
    bool higherIsWorse = false;
};

const std::vector<Measure>& measures()
{
    static const std::vector<Measure> list = {
        {"sharp F1", [](const RandomPartRecord& r) { return f1Of(r.score, LineType::Sharp); }},
        {"smooth F1", [](const RandomPartRecord& r) { return f1Of(r.score, LineType::Smooth); }},
        {"closed", [](const RandomPartRecord& r) { return r.score.closedness; }},
        {"sharp F1 @1h",
         [](const RandomPartRecord& r) { return f1Of(r.scoreAtOneSpacing, LineType::Sharp); }},
        {"smooth F1 @1h",
         [](const RandomPartRecord& r) { return f1Of(r.scoreAtOneSpacing, LineType::Smooth); }},
        {"median dist", [](const RandomPartRecord& r) { return r.quality.medianDistance; }, true},
        {"angle err", [](const RandomPartRecord& r) { return r.quality.medianAngleError; }, true},
        {"radius err", [](const RandomPartRecord& r) { return r.quality.medianRadiusError; },
         true}};
    return list;
}

std::string noiseLabel(double noise)
{
    return formatNumber(noise, 1) + " h";
}

/// Rows "key | parts | mean and worst tenth of each measure", one per distinct key in
/// alphabetical order (noise levels ascending); an "all" row first.
TextTable aggregateBy(const std::string& title, const std::string& keyName,
                      const std::vector<const RandomPartRecord*>& records,
                      const std::function<std::string(const RandomPartRecord&)>& key)
{
    TextTable table;
    table.title = title;
    table.header = {keyName, "parts"};
    for (const Measure& m : measures()) {
        table.header.push_back(m.name + " mean");
        table.header.push_back(m.name + " worst 10%");
    }
    std::vector<std::string> keys;
    for (const RandomPartRecord* r : records) {
        if (std::find(keys.begin(), keys.end(), key(*r)) == keys.end()) {
            keys.push_back(key(*r));
        }
    }
    std::sort(keys.begin(), keys.end());
    keys.insert(keys.begin(), "all");
    for (const std::string& k : keys) {
        std::vector<const RandomPartRecord*> members;
        for (const RandomPartRecord* r : records) {
            if (k == "all" || key(*r) == k) {
                members.push_back(r);
            }
        }
        std::vector<std::string> cells = {k, std::to_string(members.size())};
        for (const Measure& m : measures()) {
            std::vector<double> values;
            for (const RandomPartRecord* r : members) {
                values.push_back(m.value(*r));
            }
            const int decimals = m.higherIsWorse ? 2 : 3;
            cells.push_back(formatNumber(meanOfDefined(values), decimals));
            cells.push_back(formatNumber(worstTenthMean(values, m.higherIsWorse), decimals));
        }
        table.rows.push_back(cells);
    }
    return table;
}

std::uint32_t parseSeed(const std::string& text)
{
    const double v = parseNumber(text, "--random");
    if (v < 0.0 || v > 4294967295.0 || v != std::floor(v)) {
        throw std::invalid_argument("--random expects seeds from 0 to 4294967295, not \"" + text +
                                    "\".");
    }
    return static_cast<std::uint32_t>(v);
}

std::vector<std::string> splitAt(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, separator)) {
        parts.push_back(part);
    }
    return parts;
}

} // namespace

std::string formatNumber(double v, int decimals)
{
    if (std::isnan(v)) {
        return "-";
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

double parseNumber(const std::string& text, const std::string& what)
{
    try {
        size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v)) {
            return v;
        }
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(what + " expects a number, not \"" + text + "\".");
}

std::string randomGroupOfSeed(std::uint32_t seed)
{
    if (seed < 200) {
        return "tuning";
    }
    if (seed >= 1000 && seed < 1200) {
        return "held-out";
    }
    return "other";
}

std::vector<std::uint32_t> parseSeedList(const std::string& text)
{
    std::vector<std::uint32_t> seeds;
    for (const std::string& item : splitAt(text, ',')) {
        const size_t dash = item.find('-');
        if (dash == std::string::npos) {
            seeds.push_back(parseSeed(item));
            continue;
        }
        const std::uint32_t first = parseSeed(item.substr(0, dash));
        const std::uint32_t last = parseSeed(item.substr(dash + 1));
        if (last < first) {
            throw std::invalid_argument("--random: the range " + item + " ends before it starts.");
        }
        for (std::uint64_t s = first; s <= last; ++s) {
            seeds.push_back(static_cast<std::uint32_t>(s));
        }
    }
    if (seeds.empty()) {
        throw std::invalid_argument("--random expects seeds such as 0-199 or 1000,1003.");
    }
    return seeds;
}

double worstTenthMean(std::vector<double> values, bool higherIsWorse)
{
    values.erase(
        std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
        values.end());
    if (values.empty()) {
        return std::nan("");
    }
    std::sort(values.begin(), values.end());
    if (higherIsWorse) {
        std::reverse(values.begin(), values.end());
    }
    const size_t count = std::max<size_t>(1, (values.size() + 9) / 10);
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) {
        sum += values[i];
    }
    return sum / static_cast<double>(count);
}

TextTable randomPartTable(const std::vector<RandomPartRecord>& records)
{
    TextTable table;
    table.title = "Random parts (noise in spacings h; scores at 3 h, F1 @1h at one spacing, "
                  "median distance in spacings; median error of the sharp lines' angle in "
                  "degrees and of the smooth lines' radius relative to the true one)";
    table.header = {"seed",        "group",  "family",       "model",
                    "noise",       "points", "sharp F1",     "smooth F1",
                    "bnd F1",      "closed", "sharp F1 @1h", "smooth F1 @1h",
                    "median dist", "angle err", "radius err", "lines", "build s", "time s"};
    for (const RandomPartRecord& r : records) {
        table.rows.push_back(
            {std::to_string(r.seed), r.group, r.family, r.model, formatNumber(r.noise, 1),
             std::to_string(r.points), formatNumber(f1Of(r.score, LineType::Sharp)),
             formatNumber(f1Of(r.score, LineType::Smooth)),
             formatNumber(f1Of(r.score, LineType::Boundary)), formatNumber(r.score.closedness),
             formatNumber(f1Of(r.scoreAtOneSpacing, LineType::Sharp)),
             formatNumber(f1Of(r.scoreAtOneSpacing, LineType::Smooth)),
             formatNumber(r.quality.medianDistance, 2), formatNumber(r.quality.medianAngleError, 1),
             formatNumber(r.quality.medianRadiusError, 2), std::to_string(r.score.lineCount),
             formatNumber(r.buildSeconds, 1), formatNumber(r.seconds, 1)});
    }
    return table;
}

std::vector<TextTable> randomAggregateTables(const std::vector<RandomPartRecord>& records)
{
    std::vector<TextTable> tables;
    for (const char* group : {"tuning", "held-out", "other"}) {
        std::vector<const RandomPartRecord*> members;
        for (const RandomPartRecord& r : records) {
            if (r.group == group) {
                members.push_back(&r);
            }
        }
        if (members.empty()) {
            continue;
        }
        const std::string prefix = std::string(group) + " seeds, ";
        tables.push_back(aggregateBy(prefix + "per family", "family", members,
                                     [](const RandomPartRecord& r) { return r.family; }));
        tables.push_back(aggregateBy(prefix + "per sampling model", "model", members,
                                     [](const RandomPartRecord& r) { return r.model; }));
        tables.push_back(
            aggregateBy(prefix + "per noise level", "noise", members,
                        [](const RandomPartRecord& r) { return noiseLabel(r.noise); }));
    }
    return tables;
}

RandomMeans randomMeans(const std::vector<RandomPartRecord>& records)
{
    std::vector<double> sharp, smooth, closed;
    for (const RandomPartRecord& r : records) {
        sharp.push_back(f1Of(r.score, LineType::Sharp));
        smooth.push_back(f1Of(r.score, LineType::Smooth));
        closed.push_back(r.score.closedness);
    }
    return {meanOfDefined(sharp), meanOfDefined(smooth), meanOfDefined(closed)};
}

std::map<std::string, double> parseNamedNumbers(const std::string& text, const std::string& option,
                                                const std::vector<std::string>& names)
{
    std::map<std::string, double> out;
    for (const std::string& item : splitAt(text, ',')) {
        const size_t eq = item.find('=');
        const std::string name = item.substr(0, eq);
        if (eq == std::string::npos) {
            throw std::invalid_argument(option + " expects name=value, not \"" + item + "\".");
        }
        const double value = parseNumber(item.substr(eq + 1), option + " " + name);
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            std::string known;
            for (size_t i = 0; i < names.size(); ++i) {
                known += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
            }
            throw std::invalid_argument(option + " knows " + known + ", not \"" + name + "\".");
        }
        out[name] = value;
    }
    return out;
}

RandomFloors parseFloors(const std::string& text)
{
    RandomFloors floors;
    for (const auto& [name, value] :
         parseNamedNumbers(text, "--floor", {"sharp", "smooth", "closed"})) {
        (name == "sharp" ? floors.sharpF1 : name == "smooth" ? floors.smoothF1
                                                              : floors.closedness) = value;
    }
    return floors;
}

std::vector<std::string> floorFailures(const RandomMeans& means, const RandomFloors& floors)
{
    std::vector<std::string> failures;
    const auto check = [&](const char* name, double mean, double floor) {
        if (!std::isnan(floor) && !(mean >= floor)) {
            failures.push_back(std::string("mean ") + name + " " + formatNumber(mean) +
                               " is below its floor " + formatNumber(floor) + ".");
        }
    };
    check("sharp F1", means.sharpF1, floors.sharpF1);
    check("smooth F1", means.smoothF1, floors.smoothF1);
    check("closedness", means.closedness, floors.closedness);
    return failures;
}

} // namespace featurelines::bench
