// SPDX-License-Identifier: LGPL-2.1-or-later
// Hostile and careless input (issue 22): headers that promise more than the file holds,
// malformed PLY and PCD, and coordinates the neighbour search and the fits cannot resolve.
// Each is refused with a std::invalid_argument whose message names the problem, at once
// (nothing is allocated from a header's counts before they are checked against the bytes).
// docs/RELIABILITY.md lists the same classes.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "FeatureLines/Extraction.h"
#include "FeatureLines/io/CloudFormats.h"
#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"

using namespace featurelines;

namespace {

/// The message of the std::invalid_argument that parsing `bytes` as file `name` throws.
std::string parseError(const std::string& name, const std::string& bytes)
{
    try {
        detail::parseCloud(bytes, name);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

/// The message of the std::invalid_argument that `f` throws.
template <class F> std::string errorOf(F f)
{
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

#define EXPECT_MESSAGE(message, part)                                                              \
    EXPECT_NE((message).find(part), std::string::npos)                                             \
        << "\"" << (message) << "\" lacks \"" << (part) << "\""

const std::string plyFloatXyz = "property float x\nproperty float y\nproperty float z\n";

std::string floats(std::initializer_list<float> values)
{
    std::string bytes;
    for (const float v : values) {
        char b[4];
        std::memcpy(b, &v, 4);
        bytes.append(b, 4);
    }
    return bytes;
}

const std::string pcdXyz = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

/// n points on the unit square's lattice (z = x y / 2: a surface, not a plane).
PointMatrix lattice(int side)
{
    PointMatrix P(side * side, 3);
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            const double x = double(i) / side, y = double(j) / side;
            P.row(i * side + j) << x, y, 0.5 * x * y;
        }
    }
    return P;
}

} // namespace

TEST(HostilePly, CountsBeyondTheFileAreRefusedBeforeAllocating)
{
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 4294967296\n" +
                               plyFloatXyz + "end_header\n";
    EXPECT_MESSAGE(parseError("big.ply", header + floats({0, 0, 0})),
                   "big.ply: the header says 'element vertex 4294967296', the file ends in row 2");
    EXPECT_MESSAGE(parseError("max.ply", "ply\nformat ascii 1.0\nelement vertex "
                                         "18446744073709551615\n" +
                                             plyFloatXyz + "element face 1\nend_header\n0 0 0\n"),
                   "(too many data rows), the file holds 1");
    EXPECT_MESSAGE(parseError("count.ply", "ply\nformat ascii 1.0\nelement vertex 1e9\n" +
                                               plyFloatXyz + "end_header\n0 0 0\n"),
                   "'element vertex 1e9' is not 'element NAME COUNT'");
}

TEST(HostilePly, ListsAreBoundedByTheFile)
{
    // A face list claiming 2^32 - 1 items, and one of a negative length.
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n" +
                               plyFloatXyz + "element face 1\nproperty list uint int idx\n" +
                               "end_header\n";
    EXPECT_MESSAGE(parseError("list.ply", header + floats({0, 0, 0}) + "\xFF\xFF\xFF\xFF"),
                   "the header says 'element face 1', the file ends in row 1");
    const std::string signedList = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n" +
                                   plyFloatXyz + "element face 1\nproperty list char int idx\n" +
                                   "end_header\n";
    EXPECT_MESSAGE(parseError("negative.ply", signedList + floats({0, 0, 0}) + "\xFF"),
                   "row 1 has a negative list length");
    // A list in the vertex element of an ascii file with a length beyond its row.
    EXPECT_MESSAGE(parseError("ascii-list.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                                "property list uchar float n\n" +
                                                    plyFloatXyz + "end_header\n99 1 0 0 0\n"),
                   "ascii-list.ply, line 9: the list length '99' of 'n' is not valid");
    EXPECT_MESSAGE(parseError("xlist.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                           "property list uchar float x\nproperty float y\n"
                                           "property float z\nend_header\n1 0 0 0\n"),
                   "the PLY vertex property 'x' is a list");
    EXPECT_MESSAGE(parseError("floatcount.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" +
                                                    plyFloatXyz +
                                                    "element face 1\nproperty list float int i\n"
                                                    "end_header\n0 0 0\n0\n"),
                   "names no known type or is incomplete");
}

TEST(HostilePly, MalformedHeadersNameTheLine)
{
    const std::string vertex = "element vertex 1\n" + plyFloatXyz;
    EXPECT_MESSAGE(parseError("a.ply", "PLY\n"), "not a PLY file (its first line is not 'ply')");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\n" + vertex),
                   "the PLY header has no 'end_header' line");
    EXPECT_MESSAGE(parseError("a.ply", "ply\n" + vertex + "end_header\n0 0 0\n"),
                   "the PLY header has no 'format' line");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat binary_middle_endian 1.0\n"),
                   "unknown PLY format in the header line 'format binary_middle...'");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\nproperty float x\n"),
                   "comes before any 'element' line");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                       "property float128 x\n"),
                   "'property float128 x' names no known type");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\nsomething else\n"),
                   "unknown PLY header line 'something else'");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n"),
                   "the PLY file has no 'element vertex'");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\nelement vertex 0\n" + plyFloatXyz +
                                           "end_header\n"),
                   "the file holds no point");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\n" + vertex + "end_header\n0 0\n"),
                   "a.ply, line 8: the row ends before its 'element vertex 1' properties do");
    EXPECT_MESSAGE(parseError("a.ply", "ply\nformat ascii 1.0\n" + vertex + "end_header\n0 x 0\n"),
                   "a.ply, line 8: 'x' is not a number");
    // obj_info and comment lines (which PCL 1.13 asserted on) are read past.
    const PointMatrix P = detail::parseCloud("ply\nformat ascii 1.0\nobj_info scanner 3\n"
                                             "comment c\n" +
                                                 vertex + "end_header\n1 2 3\n",
                                             "info.ply");
    ASSERT_EQ(P.rows(), 1);
    EXPECT_EQ(P(0, 2), 3.0);
}

TEST(HostilePly, BinaryWithListsBeforeTheCoordinatesIsRead)
{
    // A vertex element with a list before x y z of mixed types, big endian.
    std::string ply = "ply\nformat binary_big_endian 1.0\nelement vertex 2\n"
                      "property list uchar short n\nproperty int x\nproperty double y\n"
                      "property uchar z\nend_header\n";
    const auto put = [&ply](const void* value, int size) {
        const auto* bytes = static_cast<const char*>(value);
        for (int b = size - 1; b >= 0; --b) {
            ply += bytes[b];
        }
    };
    for (int i = 0; i < 2; ++i) {
        ply += char(2);
        const std::int16_t items[2] = {7, 8};
        put(&items[0], 2);
        put(&items[1], 2);
        const std::int32_t x = -5 * (i + 1);
        const double y = 0.25 * i;
        put(&x, 4);
        put(&y, 8);
        ply += char(200 + i);
    }
    const PointMatrix P = detail::parseCloud(ply, "lists.ply");
    ASSERT_EQ(P.rows(), 2);
    EXPECT_EQ(P(0, 0), -5.0);
    EXPECT_EQ(P(1, 0), -10.0);
    EXPECT_EQ(P(1, 1), 0.25);
    EXPECT_EQ(P(1, 2), 201.0);
}

TEST(HostilePcd, CountsBeyondTheFileAreRefusedBeforeAllocating)
{
    EXPECT_MESSAGE(parseError("count.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
                                           "COUNT 1 1 4000000000\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n"
                                           "DATA binary\n" +
                                               floats({0, 0, 0})),
                   "not a readable PCD file (field 'z' has COUNT '4000000000'; a point may have "
                   "1 to 65536 values)");
    EXPECT_MESSAGE(parseError("points.pcd", pcdXyz +
                                                "WIDTH 1000000000000\nHEIGHT 1\n"
                                                "POINTS 1000000000000\nDATA binary\n" +
                                                floats({0, 0, 0})),
                   "the header says 'POINTS 1000000000000' (12000000000000 bytes of data), the "
                   "file holds 12 (1 points)");
    EXPECT_MESSAGE(parseError("overflow.pcd", pcdXyz +
                                                  "WIDTH 18446744073709551615\nHEIGHT 1\n"
                                                  "DATA binary\n" +
                                                  floats({0, 0, 0})),
                   "(too many bytes of data)");
    EXPECT_MESSAGE(parseError("wh.pcd", pcdXyz + "WIDTH 4294967296\nHEIGHT 4294967296\n"
                                                 "DATA binary\n"),
                   "'WIDTH 4294967296' and 'HEIGHT 4294967296', which make no 'POINTS 0'");
    EXPECT_MESSAGE(parseError("ascii.pcd", pcdXyz + "WIDTH 4294967296\nHEIGHT 1\n"
                                                    "POINTS 4294967296\nDATA ascii\n1 2 3\n"),
                   "the header says 'POINTS 4294967296', the file holds 1 data rows");
}

TEST(HostilePcd, MalformedHeadersNameTheField)
{
    const std::string tail = "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n";
    EXPECT_MESSAGE(parseError("a.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\n" + tail),
                   "the header's FIELDS names 3 fields, SIZE gives 2, TYPE 3, COUNT 0");
    EXPECT_MESSAGE(parseError("a.pcd", "FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\n" + tail),
                   "field 'z' has SIZE '2' and TYPE 'F'");
    EXPECT_MESSAGE(parseError("a.pcd", "FIELDS x y z\nSIZE 4 4 3\nTYPE F F I\n" + tail),
                   "field 'z' has SIZE '3' and TYPE 'I'");
    EXPECT_MESSAGE(parseError("a.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\n" + tail),
                   "field 'z' has SIZE '4' and TYPE 'Q'");
    EXPECT_MESSAGE(
        parseError("a.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 0\n" + tail),
        "field 'z' has COUNT '0'");
    EXPECT_MESSAGE(parseError("a.pcd", pcdXyz + "WIDTH -1\nHEIGHT 1\nDATA ascii\n"),
                   "the header line 'WIDTH -1' needs one whole number");
    EXPECT_MESSAGE(parseError("a.pcd", pcdXyz + "WIDTH 1\nDATA lzma\n"),
                   "unknown encoding 'DATA lzma'");
    EXPECT_MESSAGE(parseError("a.pcd", pcdXyz + "WIDTH 1\n"), "its header has no 'DATA' line");
    EXPECT_MESSAGE(parseError("a.pcd", "SIZE 4\nDATA ascii\n"), "lacks 'FIELDS' or 'WIDTH'");
    EXPECT_MESSAGE(parseError("a.pcd", "FIELDS a b c\nSIZE 4 4 4\nTYPE F F F\n" + tail),
                   "the PCD file has no 'x' coordinate");
    EXPECT_MESSAGE(parseError("a.pcd", pcdXyz + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2\n"),
                   "a.pcd, line 10: 2 values, the header's fields make 3");
    EXPECT_MESSAGE(parseError("a.pcd", pcdXyz + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n"),
                   "the file holds no point");
}

TEST(HostilePcd, CompressedDataIsBoundedByTheFile)
{
    const std::string header = pcdXyz + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary_compressed\n";
    const auto sizes = [](std::uint32_t packed, std::uint32_t unpacked) {
        std::string bytes(8, '\0');
        std::memcpy(bytes.data(), &packed, 4);
        std::memcpy(bytes.data() + 4, &unpacked, 4);
        return bytes;
    };
    EXPECT_MESSAGE(parseError("c.pcd", header + "\x01\x02"),
                   "the compressed data ends before its sizes");
    EXPECT_MESSAGE(parseError("c.pcd", header + sizes(4000000000u, 24) + "xyz"),
                   "the compressed data says 4000000000 bytes, the file holds 3");
    EXPECT_MESSAGE(parseError("c.pcd", header + sizes(1, 4000000000u) + "x"),
                   "'POINTS 2' (2 x 12 bytes), the compressed data unpacks to 4000000000");
    // A literal run of 24 bytes announced, 4 given: LZF's decoder stops at the end.
    EXPECT_MESSAGE(parseError("c.pcd", header + sizes(5, 24) + "\x17" + "abcd"),
                   "the compressed data is damaged");
    // 24 bytes as one literal run: x x y y z z of two points, field by field.
    const std::string values = floats({1, 2, 3, 4, 5, 6});
    const PointMatrix P = detail::parseCloud(header + sizes(25, 24) + "\x17" + values, "c.pcd");
    ASSERT_EQ(P.rows(), 2);
    EXPECT_EQ(P.row(0), Eigen::RowVector3d(1, 3, 5));
    EXPECT_EQ(P.row(1), Eigen::RowVector3d(2, 4, 6));
}

TEST(HostileText, Utf16IsNamed)
{
    EXPECT_MESSAGE(parseError("u.xyz", std::string("\xFF\xFE"
                                                   "1\0 \0"
                                                   "2\0",
                                                   8)),
                   "u.xyz: is UTF-16 text; save it as UTF-8 or ASCII");
    EXPECT_MESSAGE(parseError("u.xyz", std::string("\xFE\xFF\0"
                                                   "1",
                                                   4)),
                   "is UTF-16 text");
    // Without a byte order mark: the first token, its NUL bytes written out.
    EXPECT_MESSAGE(parseError("u.xyz", std::string("1\0 \0002\0", 6)),
                   "u.xyz, line 1: '1\\x00' is not a number");
}

TEST(HostileCoordinates, WhatTheGridCannotResolveIsRefused)
{
    const PointMatrix base = lattice(12);
    const auto refusal = [](const PointMatrix& P) {
        return errorOf([&P]() { nearestNeighbours(P, {8, 1}); });
    };
    // The size is 11/12 x 1e-310, a denormal (its last digits are rounding).
    EXPECT_MESSAGE(refusal(base * 1e-310), "point cloud: its size (the largest side of its "
                                           "bounding box) is 9.16666666666");
    EXPECT_MESSAGE(refusal(base * 1e-310), "below the smallest supported, 1e-100");
    EXPECT_MESSAGE(refusal(base * 1e-120), "below the smallest supported, 1e-100");
    EXPECT_MESSAGE(refusal(base * 1e300), "point cloud: point 2 has a coordinate beyond the "
                                          "float range (3.4e38)");
    PointMatrix offset = base;
    offset.array() += 1e15;
    // At 1e15 a double steps by 0.125: the lattice's side of 11/12 becomes 0.875.
    EXPECT_MESSAGE(refusal(offset), "point cloud: its coordinates reach 1000000000000000.9, more "
                                    "than 1e8 times its size (0.875): too far from the origin");
    PointMatrix nan = base;
    nan(5, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_MESSAGE(refusal(nan), "point cloud: point 6 has a coordinate that is not a finite");
    // The same refusals through the extraction's own check (the CLI's curvature, threshold,
    // the Python API and the FreeCAD object run it).
    EXPECT_MESSAGE(errorOf([&]() { requireSurfaceCloud(offset, 8); }), "too far from the origin");
    EXPECT_MESSAGE(errorOf([&]() { requireSurfaceCloud(base * 1e-310, 8); }),
                   "below the smallest supported");
}

TEST(HostileCoordinates, TheSupportedRangeIsServed)
{
    // Just inside the bounds: a size of 1e-90, and an offset of 0.9e7 sizes, give the
    // neighbours of the cloud near the origin (random points: no ties to break otherwise).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    PointMatrix base(300, 3);
    for (Eigen::Index i = 0; i < base.rows(); ++i) {
        const double x = u(rng), y = u(rng);
        base.row(i) << x, y, 0.5 * x * y;
    }
    const Neighbourhoods plain = nearestNeighbours(base, {8, 1});
    const Neighbourhoods tiny = nearestNeighbours(base * 1e-90, {8, 1});
    EXPECT_EQ(tiny.indices, plain.indices);
    PointMatrix offset = base;
    offset.col(0).array() += 0.9e7;
    const Neighbourhoods far = nearestNeighbours(offset, {8, 1});
    for (Eigen::Index i = 0; i < base.rows(); ++i) {
        ASSERT_NEAR(std::sqrt(far.squaredDistances(i, 0)), std::sqrt(plain.squaredDistances(i, 0)),
                    1e-8);
    }
}

TEST(HostileCoordinates, AClusterTheKeysCannotSeparateIsRefused)
{
    // 2000 points within 1e-4 and one point 1e4 away: the keys' cells are 5e-3 wide, so the
    // cluster shares one key and the search would compare all pairs in it.
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> u(0.0, 1e-4);
    PointMatrix P(2001, 3);
    for (Eigen::Index i = 0; i < 2000; ++i) {
        P.row(i) << u(rng), u(rng), u(rng);
    }
    P.row(2000) << 1e4, 0.0, 0.0;
    EXPECT_MESSAGE(errorOf([&P]() {
                       nearestNeighbours(P, {8, 1});
                   }),
                   "point cloud: more than 1024 points lie in one cell of 1/2097151 of its size");
    // 1000 such points are searched (the bound is not reached).
    const PointMatrix fewer = P.bottomRows(1001);
    EXPECT_EQ(nearestNeighbours(fewer, {8, 1}).size(), 1001);
}
