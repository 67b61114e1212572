// SPDX-License-Identifier: LGPL-2.1-or-later
// What the readers of every format share: the dispatch by extension, header lines and words,
// scalars in either byte order, numbers and counts.
#include "FeatureLines/io/CloudFormats.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "FeatureLines/io/CloudIO.h"

namespace featurelines::detail {

namespace {

std::string lowercaseExtension(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

template <class T> double valueAt(const unsigned char* data, bool bigEndian)
{
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data, sizeof(T));
    if (bigEndian) {
        std::reverse(bytes, bytes + sizeof(T));
    }
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return static_cast<double>(value);
}

} // namespace

PointMatrix parseCloud(std::string_view bytes, const std::string& name)
{
    const std::string extension = lowercaseExtension(name);
    PointMatrix P;
    if (extension == ".xyz" || extension == ".txt" || extension == ".asc" || extension == ".csv") {
        P = parseTextCloud(bytes, name);
    } else if (extension == ".ply") {
        P = parsePlyCloud(bytes, name);
    } else if (extension == ".pcd") {
        P = parsePcdCloud(bytes, name);
    } else {
        throw std::invalid_argument(
            name + ": unknown point cloud format " +
            (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
            "; known: .xyz .txt .asc .csv .ply .pcd");
    }
    checkFinite(P, name);
    checkFloatRange(P, name);
    return P;
}

std::string quoted(std::string_view token)
{
    std::string out = "'";
    for (const char c : token.substr(0, 20)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7F && byte != '\\') {
            out += c;
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
            out += escaped;
        }
    }
    return out + (token.size() > 20 ? "...'" : "'");
}

double readScalar(const unsigned char* data, ScalarType type, bool bigEndian)
{
    switch (type.kind) {
    case ScalarType::Float:
        return type.size == 4 ? valueAt<float>(data, bigEndian) : valueAt<double>(data, bigEndian);
    case ScalarType::Signed:
        switch (type.size) {
        case 1:
            return valueAt<std::int8_t>(data, bigEndian);
        case 2:
            return valueAt<std::int16_t>(data, bigEndian);
        case 4:
            return valueAt<std::int32_t>(data, bigEndian);
        default:
            return valueAt<std::int64_t>(data, bigEndian);
        }
    case ScalarType::Unsigned:
        switch (type.size) {
        case 1:
            return valueAt<std::uint8_t>(data, bigEndian);
        case 2:
            return valueAt<std::uint16_t>(data, bigEndian);
        case 4:
            return valueAt<std::uint32_t>(data, bigEndian);
        default:
            return valueAt<std::uint64_t>(data, bigEndian);
        }
    }
    return 0.0;
}

bool nextLine(std::string_view bytes, std::size_t& at, std::string_view& line)
{
    if (at >= bytes.size()) {
        return false;
    }
    const std::size_t end = std::min(bytes.find('\n', at), bytes.size());
    line = bytes.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') {
        line.remove_suffix(1);
    }
    at = end + 1;
    return true;
}

std::vector<std::string_view> wordsOf(std::string_view line)
{
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) {
            ++at;
        }
        const std::size_t start = at;
        while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r') {
            ++at;
        }
        if (at > start) {
            words.push_back(line.substr(start, at - start));
        }
    }
    return words;
}

bool onlyPadding(std::string_view text)
{
    return text.find_first_not_of(" \t\r\n") == std::string_view::npos;
}

bool parseCount(std::string_view word, std::uint64_t& value)
{
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    return error == std::errc() && end == word.data() + word.size();
}

double parseNumber(std::string_view token, const std::string& where)
{
    const char* start = token.data();
    const char* const end = token.data() + token.size();
    if (start < end && *start == '+' && start + 1 < end) { // from_chars takes no '+'
        ++start;
    }
    double value = 0.0;
    const auto [parsedEnd, error] = std::from_chars(start, end, value);
    if (error == std::errc::result_out_of_range) {
        throw std::invalid_argument(where + quoted(token) + " is out of range");
    }
    if (error != std::errc() || parsedEnd != end) {
        throw std::invalid_argument(where + quoted(token) + " is not a number");
    }
    return value;
}

} // namespace featurelines::detail
