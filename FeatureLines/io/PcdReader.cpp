// SPDX-License-Identifier: LGPL-2.1-or-later
// PCD v0.5-0.7 (ascii, binary, binary_compressed): the fields x, y, z. The header is read
// first and every count it states is checked against the bytes that follow before anything
// is allocated from it. binary_compressed data is LZF, unpacked by PCL's bounded decoder.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <pcl/io/lzf.h>

#include "FeatureLines/io/CloudFormats.h"

namespace featurelines::detail {

namespace {

/// The most bytes of padding a binary PCD may carry after its last point.
constexpr std::uint64_t maxPadding = 64;

/// LZF turns at most 3 bytes into 264: no real compressed block unpacks to more than this
/// many times its size, so a header asking for more is refused before the allocation.
constexpr std::uint64_t maxLzfRatio = 100;

/// The most values a point may have (the sum of COUNT): far above any real file (a point
/// with a 308-value descriptor has a few hundred).
constexpr std::uint64_t maxValuesPerPoint = 1 << 16;

struct PcdField
{
    std::string name;
    ScalarType type;
    std::uint64_t count = 1;
};

struct PcdHeader
{
    std::vector<PcdField> fields;
    std::uint64_t width = 0, height = 1, points = 0;
    bool hasWidth = false, hasPoints = false;
    std::string encoding;
    std::size_t dataStart = 0;
    long lines = 0;
};

std::string notReadable(const std::string& name, const std::string& why)
{
    return name + ": not a readable PCD file (" + why + ")";
}

PcdHeader readHeader(std::string_view bytes, const std::string& name)
{
    PcdHeader h;
    std::vector<std::string_view> sizes, types, counts;
    bool hasFields = false;
    std::size_t at = 0;
    std::string_view line;
    while (nextLine(bytes, at, line)) {
        ++h.lines;
        const std::vector<std::string_view> words = wordsOf(line);
        if (words.empty() || words[0][0] == '#') {
            continue;
        }
        const std::string_view key = words[0];
        const std::vector<std::string_view> values(words.begin() + 1, words.end());
        const auto count = [&](std::uint64_t& value) {
            if (values.size() != 1 || !parseCount(values[0], value)) {
                throw std::invalid_argument(notReadable(name, "the header line " +
                                                                  quoted(line.substr(0, 40)) +
                                                                  " needs one whole number"));
            }
        };
        if (key == "VERSION" || key == "VIEWPOINT") {
            continue;
        }
        if (key == "FIELDS" || key == "COLUMNS") {
            hasFields = true;
            for (const std::string_view v : values) {
                h.fields.push_back({std::string(v), {}, 1});
            }
        } else if (key == "SIZE") {
            sizes = values;
        } else if (key == "TYPE") {
            types = values;
        } else if (key == "COUNT") {
            counts = values;
        } else if (key == "WIDTH") {
            count(h.width);
            h.hasWidth = true;
        } else if (key == "HEIGHT") {
            count(h.height);
        } else if (key == "POINTS") {
            count(h.points);
            h.hasPoints = true;
        } else if (key == "DATA") {
            if (values.empty()) {
                throw std::invalid_argument(notReadable(name, "'DATA' names no encoding"));
            }
            h.encoding = std::string(values[0]);
            h.dataStart = std::min(at, bytes.size());
            break;
        } else {
            throw std::invalid_argument(
                notReadable(name, "unknown header line " + quoted(line.substr(0, 40))));
        }
    }
    if (h.encoding.empty()) {
        throw std::invalid_argument(notReadable(name, "its header has no 'DATA' line"));
    }
    if (h.encoding != "ascii" && h.encoding != "binary" && h.encoding != "binary_compressed") {
        throw std::invalid_argument(
            notReadable(name, "unknown encoding 'DATA " + h.encoding.substr(0, 40) + "'"));
    }
    if (!hasFields || h.fields.empty() || !h.hasWidth) {
        throw std::invalid_argument(
            notReadable(name, "its header lacks 'FIELDS' or 'WIDTH' before 'DATA'"));
    }
    const std::size_t n = h.fields.size();
    if (sizes.size() != n || types.size() != n || (!counts.empty() && counts.size() != n)) {
        throw std::invalid_argument(notReadable(
            name, "the header's FIELDS names " + std::to_string(n) + " fields, SIZE gives " +
                      std::to_string(sizes.size()) + ", TYPE " + std::to_string(types.size()) +
                      ", COUNT " + std::to_string(counts.size())));
    }
    std::uint64_t values = 0;
    for (std::size_t f = 0; f < n; ++f) {
        PcdField& field = h.fields[f];
        std::uint64_t size = 0;
        const bool sized =
            parseCount(sizes[f], size) && (size == 1 || size == 2 || size == 4 || size == 8);
        const std::string_view type = types[f];
        field.type.size = static_cast<int>(size);
        field.type.kind = type == "F"   ? ScalarType::Float
                          : type == "U" ? ScalarType::Unsigned
                                        : ScalarType::Signed;
        if (!sized || (type != "F" && type != "U" && type != "I") || (type == "F" && size < 4)) {
            throw std::invalid_argument(
                notReadable(name, "field '" + field.name.substr(0, 40) + "' has SIZE " +
                                      quoted(sizes[f]) + " and TYPE " + quoted(type) +
                                      "; known: I and U of 1, 2, 4, 8 bytes, F of 4 or 8"));
        }
        if (!counts.empty() && (!parseCount(counts[f], field.count) || field.count == 0 ||
                                field.count > maxValuesPerPoint - values)) {
            throw std::invalid_argument(
                notReadable(name, "field '" + field.name.substr(0, 40) + "' has COUNT " +
                                      quoted(counts[f]) + "; a point may have 1 to " +
                                      std::to_string(maxValuesPerPoint) + " values"));
        }
        values += field.count;
    }
    if (!h.hasPoints) {
        h.points = h.width * h.height;
    }
    if (h.height == 0 || h.width > UINT64_MAX / h.height || h.width * h.height != h.points) {
        throw std::invalid_argument(name + ": the header says 'WIDTH " + std::to_string(h.width) +
                                    "' and 'HEIGHT " + std::to_string(h.height) +
                                    "', which make no 'POINTS " + std::to_string(h.points) + "'");
    }
    return h;
}

/// Per x, y, z: its field, and its first value's index among a point's values.
struct Coordinates
{
    const PcdField* field[3] = {nullptr, nullptr, nullptr};
    std::uint64_t column[3] = {0, 0, 0};
    std::uint64_t byteOffset[3] = {0, 0, 0};
};

Coordinates coordinatesOf(const PcdHeader& h, const std::string& name)
{
    Coordinates c;
    const char* names[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) {
        std::uint64_t column = 0, offset = 0;
        for (const PcdField& f : h.fields) {
            if (f.name == names[d]) {
                c.field[d] = &f;
                c.column[d] = column;
                c.byteOffset[d] = offset;
                break;
            }
            column += f.count;
            offset += f.count * static_cast<std::uint64_t>(f.type.size);
        }
        if (c.field[d] == nullptr) {
            throw std::invalid_argument(name + ": the PCD file has no '" + names[d] +
                                        "' coordinate");
        }
    }
    if (h.points == 0) {
        throw std::invalid_argument(name + ": the file holds no point");
    }
    return c;
}

std::uint64_t pointSize(const PcdHeader& h)
{
    std::uint64_t size = 0;
    for (const PcdField& f : h.fields) {
        size += f.count * static_cast<std::uint64_t>(f.type.size);
    }
    return size;
}

std::string pointsField(const PcdHeader& h)
{
    return "'POINTS " + std::to_string(h.points) + "'";
}

PointMatrix readAscii(std::string_view bytes, const std::string& name, const PcdHeader& h,
                      const Coordinates& c)
{
    std::uint64_t rows = 0;
    std::size_t at = h.dataStart;
    std::string_view line;
    while (nextLine(bytes, at, line)) {
        rows += onlyPadding(line) ? 0 : 1;
    }
    if (rows != h.points) {
        throw std::invalid_argument(name + ": the header says " + pointsField(h) +
                                    ", the file holds " + std::to_string(rows) + " data rows");
    }
    std::uint64_t values = 0;
    for (const PcdField& f : h.fields) {
        values += f.count;
    }
    PointMatrix P(static_cast<Eigen::Index>(h.points), 3);
    at = h.dataStart;
    long lineNumber = h.lines;
    Eigen::Index row = 0;
    while (nextLine(bytes, at, line)) {
        ++lineNumber;
        if (onlyPadding(line)) {
            continue;
        }
        const std::string where = name + ", line " + std::to_string(lineNumber) + ": ";
        const std::vector<std::string_view> words = wordsOf(line);
        if (words.size() != values) {
            throw std::invalid_argument(where + std::to_string(words.size()) +
                                        " values, the header's fields make " +
                                        std::to_string(values));
        }
        for (int d = 0; d < 3; ++d) {
            P(row, d) = storedAs(parseNumber(words[static_cast<std::size_t>(c.column[d])], where),
                                 c.field[d]->type);
        }
        ++row;
    }
    return P;
}

PointMatrix readBinary(std::string_view bytes, const std::string& name, const PcdHeader& h,
                       const Coordinates& c)
{
    const std::string_view data = bytes.substr(h.dataStart);
    const std::uint64_t step = pointSize(h);
    const std::uint64_t size = data.size();
    const bool fits = h.points <= size / step;
    const std::uint64_t needed = fits ? h.points * step : 0;
    if (!fits ||
        (size != needed && !(size - needed <= maxPadding &&
                             onlyPadding(data.substr(static_cast<std::size_t>(needed)))))) {
        throw std::invalid_argument(
            name + ": the header says " + pointsField(h) + " (" +
            (fits || h.points <= UINT64_MAX / step ? std::to_string(h.points * step)
                                                   : std::string("too many")) +
            " bytes of data), the file holds " + std::to_string(size) +
            (size % step == 0 ? " (" + std::to_string(size / step) + " points)" : std::string()));
    }
    const auto* base = reinterpret_cast<const unsigned char*>(data.data());
    PointMatrix P(static_cast<Eigen::Index>(h.points), 3);
    for (std::uint64_t i = 0; i < h.points; ++i) {
        for (int d = 0; d < 3; ++d) {
            P(static_cast<Eigen::Index>(i), d) =
                readScalar(base + i * step + c.byteOffset[d], c.field[d]->type, false);
        }
    }
    return P;
}

/// binary_compressed: two 32-bit sizes (compressed, unpacked) and an LZF block that unpacks
/// to each field's values for all points in turn.
PointMatrix readCompressed(std::string_view bytes, const std::string& name, const PcdHeader& h,
                           const Coordinates& c)
{
    const std::string_view data = bytes.substr(h.dataStart);
    if (data.size() < 8) {
        throw std::invalid_argument(name + ": the compressed data ends before its sizes");
    }
    std::uint32_t packed = 0, unpacked = 0;
    const auto* base = reinterpret_cast<const unsigned char*>(data.data());
    packed = static_cast<std::uint32_t>(readScalar(base, {ScalarType::Unsigned, 4}, false));
    unpacked = static_cast<std::uint32_t>(readScalar(base + 4, {ScalarType::Unsigned, 4}, false));
    const std::uint64_t step = pointSize(h);
    if (packed > data.size() - 8) {
        throw std::invalid_argument(name + ": the compressed data says " + std::to_string(packed) +
                                    " bytes, the file holds " + std::to_string(data.size() - 8));
    }
    if (h.points > UINT64_MAX / step || h.points * step != unpacked ||
        unpacked > maxLzfRatio * std::uint64_t(packed)) {
        throw std::invalid_argument(name + ": the header says " + pointsField(h) + " (" +
                                    std::to_string(h.points) + " x " + std::to_string(step) +
                                    " bytes), the compressed data unpacks to " +
                                    std::to_string(unpacked));
    }
    std::vector<unsigned char> values(unpacked);
    if (unpacked > 0 && pcl::lzfDecompress(base + 8, packed, values.data(), unpacked) != unpacked) {
        throw std::invalid_argument(name + ": the compressed data is damaged");
    }
    PointMatrix P(static_cast<Eigen::Index>(h.points), 3);
    for (int d = 0; d < 3; ++d) {
        // Field by field: the fields before this one fill points x their bytes each.
        const std::uint64_t start = c.byteOffset[d] * h.points;
        const std::uint64_t stride = c.field[d]->count * std::uint64_t(c.field[d]->type.size);
        for (std::uint64_t i = 0; i < h.points; ++i) {
            P(static_cast<Eigen::Index>(i), d) =
                readScalar(values.data() + start + i * stride, c.field[d]->type, false);
        }
    }
    return P;
}

} // namespace

PointMatrix parsePcdCloud(std::string_view bytes, const std::string& name)
{
    const PcdHeader h = readHeader(bytes, name);
    const Coordinates c = coordinatesOf(h, name);
    if (h.encoding == "ascii") {
        return readAscii(bytes, name, h, c);
    }
    return h.encoding == "binary" ? readBinary(bytes, name, h, c)
                                  : readCompressed(bytes, name, h, c);
}

} // namespace featurelines::detail
