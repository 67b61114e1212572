// SPDX-License-Identifier: LGPL-2.1-or-later
// PLY (ascii, binary little and big endian): the x, y, z of the element "vertex". The header
// is read first and every count it states is checked against the bytes that follow before
// anything is allocated from it; the other elements (faces, edges) are stepped over.
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "FeatureLines/io/CloudFormats.h"

namespace featurelines::detail {

namespace {

ScalarType plyType(std::string_view name)
{
    if (name == "char" || name == "int8") {
        return {ScalarType::Signed, 1};
    }
    if (name == "uchar" || name == "uint8") {
        return {ScalarType::Unsigned, 1};
    }
    if (name == "short" || name == "int16") {
        return {ScalarType::Signed, 2};
    }
    if (name == "ushort" || name == "uint16") {
        return {ScalarType::Unsigned, 2};
    }
    if (name == "int" || name == "int32") {
        return {ScalarType::Signed, 4};
    }
    if (name == "uint" || name == "uint32") {
        return {ScalarType::Unsigned, 4};
    }
    if (name == "float" || name == "float32") {
        return {ScalarType::Float, 4};
    }
    if (name == "double" || name == "float64") {
        return {ScalarType::Float, 8};
    }
    return {};
}

struct PlyProperty
{
    std::string name;
    ScalarType type;      ///< of the scalar, or of a list's items
    ScalarType countType; ///< of a list's length; size 0 for a scalar
    bool isList() const { return countType.size > 0; }
};

struct PlyElement
{
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;

    /// "'element vertex 100'", as the header says it.
    std::string field() const { return "'element " + name + " " + std::to_string(count) + "'"; }
    /// Bytes of a binary row without lists.
    std::uint64_t fixedRowSize() const
    {
        std::uint64_t size = 0;
        for (const PlyProperty& p : properties) {
            size += static_cast<std::uint64_t>(p.type.size);
        }
        return size;
    }
    bool hasLists() const
    {
        return std::any_of(properties.begin(), properties.end(),
                           [](const PlyProperty& p) { return p.isList(); });
    }
};

struct PlyHeader
{
    std::string format;
    std::vector<PlyElement> elements;
    std::size_t dataStart = 0; ///< offset of the first data byte
    long lines = 0;            ///< lines of the header
};

std::string joined(std::string_view line)
{
    return quoted(line.substr(0, 60));
}

PlyHeader readHeader(std::string_view bytes, const std::string& name)
{
    const std::string where = name + ": ";
    PlyHeader h;
    std::size_t at = 0;
    std::string_view line;
    if (!nextLine(bytes, at, line) || line != "ply") {
        throw std::invalid_argument(where + "not a PLY file (its first line is not 'ply')");
    }
    h.lines = 1;
    while (nextLine(bytes, at, line)) {
        ++h.lines;
        const std::vector<std::string_view> words = wordsOf(line);
        if (words.empty() || words[0] == "comment" || words[0] == "obj_info") {
            continue;
        }
        const std::string_view key = words[0];
        if (key == "end_header") {
            if (h.format.empty()) {
                throw std::invalid_argument(where + "the PLY header has no 'format' line");
            }
            h.dataStart = std::min(at, bytes.size());
            return h;
        }
        if (key == "format") {
            if (words.size() < 2 || (words[1] != "ascii" && words[1] != "binary_little_endian" &&
                                     words[1] != "binary_big_endian")) {
                throw std::invalid_argument(where + "unknown PLY format in the header line " +
                                            joined(line));
            }
            h.format = std::string(words[1]);
        } else if (key == "element") {
            PlyElement e;
            if (words.size() != 3 || !parseCount(words[2], e.count)) {
                throw std::invalid_argument(where + "the PLY header line " + joined(line) +
                                            " is not 'element NAME COUNT'");
            }
            e.name = std::string(words[1]);
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) {
                throw std::invalid_argument(where + "the PLY header line " + joined(line) +
                                            " comes before any 'element' line");
            }
            PlyProperty p;
            const bool list = words.size() >= 2 && words[1] == "list";
            if (list && words.size() == 5) {
                p.countType = plyType(words[2]);
                p.type = plyType(words[3]);
                p.name = std::string(words[4]);
            } else if (!list && words.size() == 3) {
                p.type = plyType(words[1]);
                p.name = std::string(words[2]);
            }
            if (p.type.size == 0 ||
                (list && (p.countType.size == 0 || p.countType.kind == ScalarType::Float))) {
                throw std::invalid_argument(where + "the PLY header line " + joined(line) +
                                            " names no known type or is incomplete");
            }
            h.elements.back().properties.push_back(std::move(p));
        } else {
            throw std::invalid_argument(where + "unknown PLY header line " + joined(line));
        }
    }
    throw std::invalid_argument(where + "the PLY header has no 'end_header' line");
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

/// Where x, y, z are among the vertex element's properties; throws when one is missing.
struct VertexLayout
{
    const PlyElement* vertex = nullptr;
    int property[3] = {-1, -1, -1};
};

VertexLayout vertexLayout(const PlyHeader& h, const std::string& name)
{
    VertexLayout layout;
    for (const PlyElement& e : h.elements) {
        if (e.name == "vertex") {
            layout.vertex = &e;
            break;
        }
    }
    if (layout.vertex == nullptr) {
        throw std::invalid_argument(name + ": the PLY file has no 'element vertex'");
    }
    const char* names[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) {
        const auto& properties = layout.vertex->properties;
        for (std::size_t p = 0; p < properties.size(); ++p) {
            if (properties[p].name == names[d]) {
                layout.property[d] = static_cast<int>(p);
            }
        }
        if (layout.property[d] < 0) {
            throw std::invalid_argument(name + ": the PLY file has no '" + names[d] +
                                        "' coordinate");
        }
        if (properties[static_cast<std::size_t>(layout.property[d])].isList()) {
            throw std::invalid_argument(name + ": the PLY vertex property '" + names[d] +
                                        "' is a list, not a coordinate");
        }
    }
    if (layout.vertex->count == 0) {
        throw std::invalid_argument(name + ": the file holds no point");
    }
    return layout;
}

/// Ascii: one line per row of each element in turn; the rows of the vertex element hold one
/// value per scalar property and, per list, its length and then its items.
PointMatrix readAscii(std::string_view bytes, const std::string& name, const PlyHeader& h,
                      const VertexLayout& layout)
{
    // Every count against the data lines first: nothing is allocated from the header alone.
    std::uint64_t expected = 0, rows = 0;
    bool overflow = false;
    for (const PlyElement& e : h.elements) {
        overflow = overflow || e.count > UINT64_MAX - expected;
        expected += e.count;
    }
    std::size_t at = h.dataStart;
    std::string_view line;
    while (nextLine(bytes, at, line)) {
        rows += onlyPadding(line) ? 0 : 1;
    }
    if (overflow || rows != expected) {
        throw std::invalid_argument(
            name + ": the header says " + fieldsOf(h.elements) + " (" +
            (overflow ? std::string("too many") : std::to_string(expected)) +
            " data rows), the file holds " + std::to_string(rows));
    }
    std::uint64_t before = 0; // rows of the elements before the vertex element
    for (const PlyElement& e : h.elements) {
        if (&e == layout.vertex) {
            break;
        }
        before += e.count;
    }
    const PlyElement& vertex = *layout.vertex;
    PointMatrix P(static_cast<Eigen::Index>(vertex.count), 3);
    at = h.dataStart;
    long lineNumber = h.lines;
    std::uint64_t row = 0;
    while (row < before + vertex.count && nextLine(bytes, at, line)) {
        ++lineNumber;
        if (onlyPadding(line)) {
            continue;
        }
        if (row++ < before) {
            continue;
        }
        const std::string where = name + ", line " + std::to_string(lineNumber) + ": ";
        const std::vector<std::string_view> words = wordsOf(line);
        std::size_t word = 0;
        const auto take = [&]() {
            if (word >= words.size()) {
                throw std::invalid_argument(where + "the row ends before its " + vertex.field() +
                                            " properties do");
            }
            return words[word++];
        };
        for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
            const PlyProperty& property = vertex.properties[p];
            if (property.isList()) {
                std::uint64_t items = 0;
                const std::string_view length = take();
                if (!parseCount(length, items) || items > words.size()) {
                    throw std::invalid_argument(where + "the list length " + quoted(length) +
                                                " of '" + property.name + "' is not valid");
                }
                for (std::uint64_t i = 0; i < items; ++i) {
                    take();
                }
                continue;
            }
            const std::string_view token = take();
            for (int d = 0; d < 3; ++d) {
                if (layout.property[d] == static_cast<int>(p)) {
                    P(static_cast<Eigen::Index>(row - before - 1), d) =
                        storedAs(parseNumber(token, where), property.type);
                }
            }
        }
    }
    return P;
}

/// Binary: the rows of each element in turn, lists with their length first. Each element's
/// rows are checked against the bytes left before a row is read.
PointMatrix readBinary(std::string_view bytes, const std::string& name, const PlyHeader& h,
                       const VertexLayout& layout)
{
    const bool bigEndian = h.format == "binary_big_endian";
    const std::string_view data = bytes.substr(h.dataStart);
    const auto* base = reinterpret_cast<const unsigned char*>(data.data());
    std::size_t at = 0;
    PointMatrix P;
    for (const PlyElement& e : h.elements) {
        const auto endsIn = [&](std::uint64_t row) {
            return std::invalid_argument(name + ": the header says " + e.field() +
                                         ", the file ends in row " + std::to_string(row + 1));
        };
        if (!e.hasLists()) {
            const std::uint64_t rowSize = e.fixedRowSize();
            const std::uint64_t rowsLeft = rowSize == 0 ? e.count : (data.size() - at) / rowSize;
            if (e.count > rowsLeft) {
                throw endsIn(rowsLeft);
            }
            if (&e == layout.vertex) {
                P.resize(static_cast<Eigen::Index>(e.count), 3);
                std::uint64_t offset[3] = {0, 0, 0};
                for (int d = 0; d < 3; ++d) {
                    for (int p = 0; p < layout.property[d]; ++p) {
                        offset[d] += e.properties[static_cast<std::size_t>(p)].type.size;
                    }
                }
                for (std::uint64_t row = 0; row < e.count; ++row) {
                    for (int d = 0; d < 3; ++d) {
                        const PlyProperty& p =
                            e.properties[static_cast<std::size_t>(layout.property[d])];
                        P(static_cast<Eigen::Index>(row), d) =
                            readScalar(base + at + row * rowSize + offset[d], p.type, bigEndian);
                    }
                }
            }
            at += static_cast<std::size_t>(e.count * rowSize);
            continue;
        }
        // Rows with lists are walked one by one; each takes at least one byte (a list's
        // length), so the walk ends within the file's size whatever the count says.
        if (e.count > data.size() - at) {
            throw endsIn(data.size() - at);
        }
        if (&e == layout.vertex) {
            P.resize(static_cast<Eigen::Index>(e.count), 3);
        }
        for (std::uint64_t row = 0; row < e.count; ++row) {
            for (std::size_t p = 0; p < e.properties.size(); ++p) {
                const PlyProperty& property = e.properties[p];
                std::uint64_t items = 1;
                if (property.isList()) {
                    if (data.size() - at < static_cast<std::size_t>(property.countType.size)) {
                        throw endsIn(row);
                    }
                    const double length = readScalar(base + at, property.countType, bigEndian);
                    if (length < 0) {
                        throw std::invalid_argument(name + ": the header says " + e.field() +
                                                    ", row " + std::to_string(row + 1) +
                                                    " has a negative list length");
                    }
                    items = static_cast<std::uint64_t>(length);
                    at += static_cast<std::size_t>(property.countType.size);
                }
                const auto size = static_cast<std::uint64_t>(property.type.size);
                if (items > (data.size() - at) / size) {
                    throw endsIn(row);
                }
                if (&e == layout.vertex && !property.isList()) {
                    for (int d = 0; d < 3; ++d) {
                        if (layout.property[d] == static_cast<int>(p)) {
                            P(static_cast<Eigen::Index>(row), d) =
                                readScalar(base + at, property.type, bigEndian);
                        }
                    }
                }
                at += static_cast<std::size_t>(items * size);
            }
        }
    }
    if (at < data.size() && !onlyPadding(data.substr(at))) {
        throw std::invalid_argument(name + ": the file goes on past the header's " +
                                    fieldsOf(h.elements) + " (" + std::to_string(data.size() - at) +
                                    " bytes more)");
    }
    return P;
}

} // namespace

PointMatrix parsePlyCloud(std::string_view bytes, const std::string& name)
{
    const PlyHeader h = readHeader(bytes, name);
    const VertexLayout layout = vertexLayout(h, name);
    return h.format == "ascii" ? readAscii(bytes, name, h, layout)
                               : readBinary(bytes, name, h, layout);
}

} // namespace featurelines::detail
