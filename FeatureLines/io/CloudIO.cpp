// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/io/CloudIO.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "FeatureLines/io/CloudFormats.h"
#include "FeatureLines/support/HugePages.h"

namespace featurelines {

namespace {

namespace fs = std::filesystem;

bool isSeparator(char c)
{
    return c == ' ' || c == '\t' || c == ',';
}

/// True for a row such as "1,5 2,25 3,125": numbers separated by white space with a comma
/// between two digits inside one of them. A row of commas alone ("1.5,2.5,3.5" or "1, 2, 3")
/// is a CSV row; a comma between digits where white space also separates the numbers can
/// only be a decimal comma, and reading it as a separator would give other numbers.
bool hasDecimalComma(const char* p, const char* lineEnd)
{
    bool spaceBetweenWords = false, commaInWord = false;
    for (const char* c = p; c < lineEnd; ++c) {
        if ((*c == ' ' || *c == '\t') && c > p && c + 1 < lineEnd && c[-1] != ',' && c[-1] != ' ' &&
            c[-1] != '\t' && c[1] != ' ' && c[1] != '\t' && c[1] != ',') {
            spaceBetweenWords = true;
        }
        if (*c == ',' && c > p && c + 1 < lineEnd &&
            std::isdigit(static_cast<unsigned char>(c[-1])) &&
            std::isdigit(static_cast<unsigned char>(c[1]))) {
            commaInWord = true;
        }
    }
    return spaceBetweenWords && commaInWord;
}

/// The bytes of the file at `path`.
std::string fileText(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw std::invalid_argument(path + ": the file cannot be opened for reading");
    }
    file.seekg(0, std::ios::end);
    std::string text(static_cast<std::size_t>(std::max<std::streamoff>(0, file.tellg())), '\0');
    file.seekg(0, std::ios::beg);
    file.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (!file) {
        throw std::invalid_argument(path + ": reading the file failed");
    }
    return text;
}

/// Appends to xyz the number that starts at p, after any separators, on the line ending at
/// lineEnd: coordinate `coordinate` of its point. Returns the end of the number's token.
/// Messages start with `where`.
const char* readCoordinate(const char* p, const char* lineEnd, int coordinate,
                           const std::string& where, std::vector<double>& xyz)
{
    while (p < lineEnd && isSeparator(*p)) {
        ++p;
    }
    if (p == lineEnd) {
        throw std::invalid_argument(where + "only " + std::to_string(coordinate) +
                                    " number(s), a point needs x y z");
    }
    const char* tokenEnd = std::find_if(p, lineEnd, isSeparator);
    const std::string_view token(p, tokenEnd - p);
    const char* start = p;
    if (*start == '+' && start + 1 < tokenEnd) { // from_chars takes no '+'
        ++start;
    }
    double value = 0.0;
    const auto [parsedEnd, error] = std::from_chars(start, tokenEnd, value);
    if (error == std::errc::result_out_of_range) {
        throw std::invalid_argument(where + detail::quoted(token) + " is out of range");
    }
    if (error != std::errc() || parsedEnd != tokenEnd) {
        throw std::invalid_argument(where + detail::quoted(token) + " is not a number");
    }
    if (!std::isfinite(value)) {
        throw std::invalid_argument(where + "coordinate " + detail::quoted(token) +
                                    " is not a finite number");
    }
    if (std::abs(value) > FLT_MAX) {
        throw std::invalid_argument(where + "coordinate " + detail::quoted(token) +
                                    " is beyond the float range (3.4e38)");
    }
    xyz.push_back(value);
    return tokenEnd;
}

/// The text formats: one point per line, the first three numbers of a line are x y z.
/// std::from_chars is exact, fast and does not follow the process locale (FreeCAD's GUI
/// may run under one whose decimal separator is a comma).
PointMatrix readText(std::string_view text, const std::string& path)
{
    if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF") {
        throw std::invalid_argument(path + ": is UTF-16 text; save it as UTF-8 or ASCII");
    }
    std::vector<double> xyz;
    xyz.reserve(text.size() / 16);
    adviseHugePages(xyz.data(), xyz.capacity() * sizeof(double));
    const char* cursor = text.data();
    const char* const end = text.data() + text.size();
    if (text.substr(0, 3) == "\xEF\xBB\xBF") { // UTF-8 byte order mark
        cursor += 3;
    }
    long lineNumber = 0;
    while (cursor < end) {
        ++lineNumber;
        const char* lineEnd = std::find(cursor, end, '\n');
        const char* next = lineEnd == end ? end : lineEnd + 1;
        if (lineEnd > cursor && lineEnd[-1] == '\r') { // CRLF
            --lineEnd;
        }
        const char* p = cursor;
        cursor = next;
        while (p < lineEnd && (*p == ' ' || *p == '\t')) {
            ++p;
        }
        // Blank lines, comments, and header lines such as FreeCAD's "# ..." are skipped.
        if (p == lineEnd || *p == '#' || *p == '%' ||
            (*p == '/' && p + 1 < lineEnd && p[1] == '/')) {
            continue;
        }
        const std::string where = path + ", line " + std::to_string(lineNumber) + ": ";
        if (hasDecimalComma(p, lineEnd)) {
            throw std::invalid_argument(path + ": decimal commas are not supported, line " +
                                        std::to_string(lineNumber) +
                                        " (write 1.5, not 1,5; commas separate x,y,z)");
        }
        for (int coordinate = 0; coordinate < 3; ++coordinate) {
            p = readCoordinate(p, lineEnd, coordinate, where, xyz);
        }
        // Further columns (normals, colours, intensities) are ignored.
    }
    if (xyz.empty()) {
        throw std::invalid_argument(path + ": the file holds no point");
    }
    const Eigen::Index n = static_cast<Eigen::Index>(xyz.size() / 3);
    return Eigen::Map<const PointMatrix>(xyz.data(), n, 3);
}

} // namespace

PointMatrix detail::parseTextCloud(std::string_view bytes, const std::string& name)
{
    return readText(bytes, name);
}

PointMatrix readCloud(const std::string& path)
{
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status)) {
        throw std::invalid_argument(path + ": no such file");
    }
    if (fs::is_directory(status)) {
        throw std::invalid_argument(path + ": is a folder, not a point cloud file");
    }
    // A FIFO would block the read forever, a device would never end: only regular files
    // (links to them included) are read.
    if (!fs::is_regular_file(status)) {
        throw std::invalid_argument(path + ": is not a regular file (a pipe, socket or device); "
                                           "save the cloud to a file first");
    }
    return detail::parseCloud(fileText(path), path);
}

void writeXyz(const std::string& path, const PointMatrix& P)
{
    std::ofstream file(path, std::ios::binary);
    if (!file) {
        throw std::invalid_argument(path + ": the file cannot be opened for writing");
    }
    // Shortest representation that reads back to the same double (std::to_chars).
    std::string buffer;
    char number[32];
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        for (int d = 0; d < 3; ++d) {
            const auto result = std::to_chars(number, number + sizeof(number), P(i, d));
            buffer.append(number, result.ptr);
            buffer.push_back(d < 2 ? ' ' : '\n');
        }
        if (buffer.size() > (1 << 20)) {
            file.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
            buffer.clear();
        }
    }
    file.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    file.close();
    if (!file) {
        throw std::invalid_argument(path + ": writing the file failed");
    }
}

void checkFloatRange(const PointMatrix& P, const std::string& what)
{
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if ((P.row(i).array().abs() > FLT_MAX).any()) {
            throw std::invalid_argument(what + ": point " + std::to_string(i + 1) +
                                        " has a coordinate beyond the float range (3.4e38)");
        }
    }
}

void checkFinite(const PointMatrix& P, const std::string& what, Eigen::Index minimumPoints)
{
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (!P.row(i).allFinite()) {
            throw std::invalid_argument(what + ": point " + std::to_string(i + 1) +
                                        " has a coordinate that is not a finite number");
        }
    }
    if (P.rows() < minimumPoints) {
        throw std::invalid_argument(what + ": " + std::to_string(minimumPoints) +
                                    " points at least are needed, there are " +
                                    std::to_string(P.rows()));
    }
}

} // namespace featurelines
