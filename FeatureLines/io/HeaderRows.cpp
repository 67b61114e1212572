// SPDX-License-Identifier: LGPL-2.1-or-later
// The data rows of a PLY or PCD file against the counts its header states. PCL reads as many
// rows as the header says and drops the rest without a word, and fails without naming the
// field when rows are missing: both are checked here, before PCL reads the file.
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace featurelines::detail {

namespace {

/// The bytes of a PLY or PCD header line's type name, 0 for an unknown name.
std::size_t plyTypeSize(const std::string& type)
{
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") {
        return 1;
    }
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") {
        return 2;
    }
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32") {
        return 4;
    }
    if (type == "double" || type == "float64") {
        return 8;
    }
    return 0;
}

struct PlyProperty
{
    std::size_t size = 0;      ///< bytes of a scalar, or of a list's items
    std::size_t countSize = 0; ///< bytes of a list's length, 0 for a scalar
};

struct PlyElement
{
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;

    /// "element vertex 100", as the header says it.
    std::string field() const { return "'element " + name + " " + std::to_string(count) + "'"; }
};

/// Non-blank lines from the stream's position to its end.
std::uint64_t dataLines(std::istream& in)
{
    std::uint64_t rows = 0;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") != std::string::npos) {
            ++rows;
        }
    }
    return rows;
}

/// The elements' fields joined: "'element vertex 8', 'element face 6'".
std::string fieldsOf(const std::vector<PlyElement>& elements)
{
    std::string fields;
    for (const PlyElement& e : elements) {
        fields += (fields.empty() ? "" : ", ") + e.field();
    }
    return fields;
}

/// The unsigned integer of `size` bytes at `data`, stored little or big endian.
std::uint64_t listLength(const unsigned char* data, std::size_t size, bool bigEndian)
{
    std::uint64_t value = 0;
    for (std::size_t b = 0; b < size; ++b) {
        value |= std::uint64_t(data[bigEndian ? size - 1 - b : b]) << (8 * b);
    }
    return value;
}

/// The most bytes of padding a binary PCD may carry after its last point.
constexpr std::uint64_t maxPadding = 64;

/// True when `text` holds only line ends and blanks: what some writers leave after the last
/// binary row (a final newline), which is no data row. NUL bytes are data (a zero float).
bool onlyPadding(const std::string& text)
{
    return text.find_first_not_of(" \t\r\n") == std::string::npos;
}

/// Walks the binary rows of every element; throws naming the element whose rows run past the
/// end of the file, or the last element when bytes other than padding are left over.
void checkBinaryPly(const std::string& path, std::istream& in, bool bigEndian,
                    const std::vector<PlyElement>& elements)
{
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    std::size_t at = 0;
    for (const PlyElement& e : elements) {
        for (std::uint64_t row = 0; row < e.count; ++row) {
            for (const PlyProperty& p : e.properties) {
                std::uint64_t items = 1;
                if (p.countSize > 0) {
                    if (at + p.countSize > data.size()) {
                        at = data.size() + 1;
                        break;
                    }
                    items = listLength(bytes + at, p.countSize, bigEndian);
                    at += p.countSize;
                }
                at += static_cast<std::size_t>(items * p.size);
                if (at > data.size()) {
                    break;
                }
            }
            if (at > data.size()) {
                throw std::invalid_argument(path + ": the header says " + e.field() +
                                            ", the file ends in row " + std::to_string(row + 1));
            }
        }
    }
    if (at < data.size() && !onlyPadding(data.substr(at))) {
        throw std::invalid_argument(path + ": the file goes on past the header's " +
                                    fieldsOf(elements) + " (" + std::to_string(data.size() - at) +
                                    " bytes more)");
    }
}

} // namespace

void checkPlyRows(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string line, format;
    std::vector<PlyElement> elements;
    bool ended = false;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "format") {
            words >> format;
        } else if (key == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count)) {
                return; // a malformed header: PCL's own check reports it
            }
            elements.push_back(e);
        } else if (key == "property" && !elements.empty()) {
            std::string type, countType, itemType;
            words >> type;
            PlyProperty p;
            if (type == "list") {
                words >> countType >> itemType;
                p.countSize = plyTypeSize(countType);
                p.size = plyTypeSize(itemType);
                if (p.countSize == 0) {
                    return;
                }
            } else {
                p.size = plyTypeSize(type);
            }
            if (p.size == 0) {
                return;
            }
            elements.back().properties.push_back(p);
        } else if (key == "end_header") {
            ended = true;
            break;
        }
    }
    if (!ended || elements.empty()) {
        return;
    }
    if (format == "ascii") {
        std::uint64_t expected = 0;
        for (const PlyElement& e : elements) {
            expected += e.count;
        }
        const std::uint64_t rows = dataLines(in);
        if (rows != expected) {
            throw std::invalid_argument(path + ": the header says " + fieldsOf(elements) + " (" +
                                        std::to_string(expected) + " data rows), the file holds " +
                                        std::to_string(rows));
        }
    } else if (format == "binary_little_endian" || format == "binary_big_endian") {
        checkBinaryPly(path, in, format == "binary_big_endian", elements);
    }
}

void checkPcdRows(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::string line, encoding;
    std::vector<std::size_t> sizes, counts;
    std::uint64_t points = 0;
    bool pointsGiven = false;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        std::size_t value = 0;
        if (key == "SIZE") {
            while (words >> value) {
                sizes.push_back(value);
            }
        } else if (key == "COUNT") {
            while (words >> value) {
                counts.push_back(value);
            }
        } else if (key == "POINTS") {
            pointsGiven = static_cast<bool>(words >> points);
        } else if (key == "DATA") {
            words >> encoding;
            break;
        }
    }
    if (!pointsGiven) {
        return; // PCL's own check reports the header
    }
    const std::string field = "'POINTS " + std::to_string(points) + "'";
    if (encoding == "ascii") {
        const std::uint64_t rows = dataLines(in);
        if (rows != points) {
            throw std::invalid_argument(path + ": the header says " + field + ", the file holds " +
                                        std::to_string(rows) + " data rows");
        }
    } else if (encoding == "binary") {
        std::size_t pointSize = 0;
        for (std::size_t f = 0; f < sizes.size(); ++f) {
            pointSize += sizes[f] * (f < counts.size() ? counts[f] : 1);
        }
        const std::streamoff start = in.tellg();
        in.seekg(0, std::ios::end);
        const auto bytes = static_cast<std::uint64_t>(in.tellg() - start);
        const std::uint64_t needed = points * pointSize;
        if (pointSize > 0 && bytes > needed && bytes - needed <= maxPadding) {
            std::string tail(static_cast<std::size_t>(bytes - needed), ' ');
            in.seekg(start + static_cast<std::streamoff>(needed));
            in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
            if (onlyPadding(tail)) {
                return;
            }
        }
        if (pointSize > 0 && bytes != needed) {
            throw std::invalid_argument(
                path + ": the header says " + field + " (" + std::to_string(points * pointSize) +
                " bytes of data), the file holds " + std::to_string(bytes) +
                (bytes % pointSize == 0 ? " (" + std::to_string(bytes / pointSize) + " points)"
                                        : std::string()));
        }
    }
    // binary_compressed states its own sizes, which PCL checks.
}

} // namespace featurelines::detail
