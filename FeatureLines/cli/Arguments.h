// SPDX-License-Identifier: LGPL-2.1-or-later
// Command-line parsing for the featurelines tool: standard library only, locale-independent.
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace featurelines::cli {

/// A mistake in how the tool was called (exit code 2), as opposed to bad input data (exit 1).
struct UsageError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

/// One option of a command: "--name VALUE" or "--name=VALUE" when valueName is set, else a
/// flag.
struct OptionSpec
{
    std::string name;
    std::string valueName;
    std::string help;
    /// An optional one-letter alias such as "-o".
    std::string shortName = {};
};

/// The parsed command line of one command: positional words, option values and flags.
class Arguments
{
public:
    /// Parses `args` (the words after the command name) against `specs`. Throws UsageError for
    /// an unknown option, a missing value, or an option given twice.
    Arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const { return given_.count(name) != 0; }

    std::string text(const std::string& name, const std::string& fallback = {}) const
    {
        const auto it = values_.find(name);
        return it == values_.end() ? fallback : it->second;
    }

    /// The integer value of `name`, `fallback` when absent; UsageError unless it is an integer
    /// in [minimum, maximum].
    long integer(const std::string& name, long fallback, long minimum, long maximum) const;

    /// The finite number value of `name`; UsageError unless minimum <= v and v < (or <=)
    /// maximum.
    double number(const std::string& name, double fallback, double minimum, double maximum,
                  bool maximumIncluded) const;

    /// Parses a finite decimal number (no locale, no hex, no NaN or infinity).
    static double parseNumber(const std::string& name, const std::string& s);

    /// Shortest decimal text that reads back to the same double, independent of the locale.
    static std::string format(double v)
    {
        char buffer[64];
        const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
        return ec == std::errc() ? std::string(buffer, end) : std::string("nan");
    }

private:
    /// Reads the option args[i] ("--name", "--name=VALUE" or "-x"), and its value from the
    /// next word when it takes one (i then moves on to it).
    void readOption(const std::vector<std::string>& args, std::size_t& i,
                    const std::vector<OptionSpec>& specs);

    static bool isNumber(const std::string& word)
    {
        double v = 0.0;
        const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
        return ec == std::errc() && end == word.data() + word.size();
    }

    static const OptionSpec* find(const std::vector<OptionSpec>& specs, const std::string& name)
    {
        for (const OptionSpec& s : specs) {
            if (s.name == name || (!s.shortName.empty() && s.shortName == name)) {
                return &s;
            }
        }
        return nullptr;
    }

    /// "at least LO", or "at least LO and at most HI" / "... and below HI"; HI empty: no bound.
    static std::string range(const std::string& lo, const std::string& hi, bool hiIncluded)
    {
        if (hi.empty()) {
            return "at least " + lo;
        }
        return "at least " + lo + " and " + (hiIncluded ? "at most " : "below ") + hi;
    }

    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> given_;
};

inline Arguments::Arguments(const std::vector<std::string>& args,
                            const std::vector<OptionSpec>& specs)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        const bool isLong = word.size() > 2 && word.compare(0, 2, "--") == 0;
        const bool isShort = !isLong && word.size() > 1 && word[0] == '-' && !isNumber(word);
        if (!isLong && !isShort) {
            positional_.push_back(word);
            continue;
        }
        readOption(args, i, specs);
    }
}

inline void Arguments::readOption(const std::vector<std::string>& args, std::size_t& i,
                                  const std::vector<OptionSpec>& specs)
{
    const std::string& word = args[i];
    const bool isLong = word.size() > 2 && word.compare(0, 2, "--") == 0;
    std::string name = word;
    std::string value;
    bool inlineValue = false;
    if (const auto eq = name.find('='); isLong && eq != std::string::npos) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        inlineValue = true;
    }
    const OptionSpec* spec = find(specs, name);
    if (!spec) {
        throw UsageError("unknown option '" + name + "'");
    }
    if (given_.count(spec->name)) {
        throw UsageError("option '" + spec->name + "' is given twice");
    }
    given_.insert(spec->name);
    if (spec->valueName.empty()) {
        if (inlineValue) {
            throw UsageError("option '" + name + "' takes no value");
        }
        return;
    }
    if (!inlineValue) {
        if (i + 1 >= args.size()) {
            throw UsageError("option '" + name + "' needs a value (" + spec->valueName + ")");
        }
        value = args[++i];
    }
    values_[spec->name] = value;
}

inline long Arguments::integer(const std::string& name, long fallback, long minimum,
                               long maximum) const
{
    const auto it = values_.find(name);
    if (it == values_.end()) {
        return fallback;
    }
    long v = 0;
    const std::string& s = it->second;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) {
        throw UsageError(name + " needs a whole number, got '" + s + "'");
    }
    if (v < minimum || v > maximum) {
        const std::string hi =
            maximum == std::numeric_limits<long>::max() ? std::string() : std::to_string(maximum);
        throw UsageError(name + " must be " + range(std::to_string(minimum), hi, true) + ", got " +
                         s);
    }
    return v;
}

inline double Arguments::number(const std::string& name, double fallback, double minimum,
                                double maximum, bool maximumIncluded) const
{
    const auto it = values_.find(name);
    if (it == values_.end()) {
        return fallback;
    }
    const double v = parseNumber(name, it->second);
    if (v < minimum || v > maximum || (!maximumIncluded && v == maximum)) {
        const std::string hi = std::isinf(maximum) ? std::string() : format(maximum);
        throw UsageError(name + " must be " + range(format(minimum), hi, maximumIncluded) +
                         ", got " + it->second);
    }
    return v;
}

inline double Arguments::parseNumber(const std::string& name, const std::string& s)
{
    double v = 0.0;
    const char* first = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
    const auto [end, ec] =
        std::from_chars(first, s.data() + s.size(), v, std::chars_format::general);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
        throw UsageError(name + " needs a finite number, got '" + s + "'");
    }
    return v;
}

} // namespace featurelines::cli
