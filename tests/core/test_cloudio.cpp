// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "FeatureLines/io/CloudIO.h"

using namespace featurelines;
namespace fs = std::filesystem;

namespace {

/// A fresh folder under the system's temporary folder, removed afterwards.
class CloudIO : public ::testing::Test
{
protected:
    void SetUp() override
    {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::temp_directory_path() /
                  ("featurelines-cloudio-" + std::to_string(getpid()) + "-" + test->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string path(const std::string& name) const { return (folder_ / name).string(); }

    std::string write(const std::string& name, const std::string& content) const
    {
        std::ofstream(path(name), std::ios::binary) << content;
        return path(name);
    }

    /// The message of the std::invalid_argument that reading `file` throws ("" if none).
    static std::string readError(const std::string& file)
    {
        try {
            readCloud(file);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "";
    }

private:
    fs::path folder_;
};

/// Three points with exact binary values, as the binary files below store them.
PointMatrix threePoints()
{
    PointMatrix P(3, 3);
    P << 1.5, -2.25, 3.0, //
        0.0, 1e-3, -7.5,  //
        100.25, 0.5, 2.0;
    return P;
}

template <class T> void putBytes(std::string& out, T value, bool bigEndian)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (bigEndian) {
        std::reverse(bytes, bytes + sizeof(T));
    }
    out.append(bytes, sizeof(T));
}

} // namespace

TEST_F(CloudIO, XyzRoundTripIsExact)
{
    PointMatrix P(4, 3);
    P << 0.1, 0.2, 0.3,             //
        -1e-300, 3e38, 12345.678,   //
        1.0 / 3.0, -2.0 / 7.0, 0.0, //
        1e6 + 0.001, -2e6, 5e5;
    writeXyz(path("cloud.xyz"), P);
    EXPECT_EQ(readCloud(path("cloud.xyz")), P);
    EXPECT_THROW(writeXyz(path("no-such-folder/cloud.xyz"), P), std::invalid_argument);
}

TEST_F(CloudIO, TextWithCommasExtraColumnsCommentsAndCrlf)
{
    const std::string file = write("scan.CSV", "# FreeCAD ASCII header\r\n"
                                               "// a comment\r\n"
                                               "% another comment\r\n"
                                               "\r\n"
                                               "1.5,-2.25,3,0,0,1\r\n"
                                               "  0 , +1e-3 ,-7.5, 255 255 255\r\n"
                                               "100.25\t0.5  2 intensity-column\r\n");
    EXPECT_EQ(readCloud(file), threePoints());
}

TEST_F(CloudIO, AsciiPlyWithFacesAndExtraProperties)
{
    const std::string file = write("mesh.ply", "ply\n"
                                               "format ascii 1.0\n"
                                               "comment written by a test\n"
                                               "element vertex 3\n"
                                               "property float x\n"
                                               "property float y\n"
                                               "property float z\n"
                                               "property uchar red\n"
                                               "element face 1\n"
                                               "property list uchar int vertex_indices\n"
                                               "end_header\n"
                                               "1.5 -2.25 3 10\n"
                                               "0 0.25 -7.5 20\n"
                                               "100.25 0.5 2 30\n"
                                               "3 0 1 2\n");
    PointMatrix expected = threePoints();
    expected(1, 1) = 0.25;
    EXPECT_EQ(readCloud(file), expected);
}

TEST_F(CloudIO, BinaryPlyLittleAndBigEndian)
{
    const PointMatrix P = threePoints();
    for (const bool bigEndian : {false, true}) {
        // Little endian in float, big endian in double: both must come back exactly.
        std::string content = std::string("ply\nformat ") +
                              (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                              " 1.0\nelement vertex 3\n";
        const char* type = bigEndian ? "double" : "float";
        for (const char* name : {"x", "y", "z"}) {
            content += std::string("property ") + type + " " + name + "\n";
        }
        content += "end_header\n";
        for (Eigen::Index i = 0; i < 3; ++i) {
            for (int d = 0; d < 3; ++d) {
                if (bigEndian) {
                    putBytes(content, P(i, d), true);
                } else {
                    putBytes(content, static_cast<float>(P(i, d)), false);
                }
            }
        }
        const std::string file = write(bigEndian ? "big.ply" : "little.ply", content);
        PointMatrix expected = P;
        if (!bigEndian) {
            expected = P.cast<float>().cast<double>(); // 1e-3 is not a float
        }
        EXPECT_EQ(readCloud(file), expected) << (bigEndian ? "big endian" : "little endian");
    }
}

TEST_F(CloudIO, AsciiAndBinaryPcd)
{
    const PointMatrix P = threePoints().cast<float>().cast<double>();
    const std::string header = "# .PCD v0.7 - Point Cloud Data file format\n"
                               "VERSION 0.7\n"
                               "FIELDS x y z\n"
                               "SIZE 4 4 4\n"
                               "TYPE F F F\n"
                               "COUNT 1 1 1\n"
                               "WIDTH 3\n"
                               "HEIGHT 1\n"
                               "VIEWPOINT 0 0 0 1 0 0 0\n"
                               "POINTS 3\n";
    std::string ascii = header + "DATA ascii\n";
    std::string binary = header + "DATA binary\n";
    for (Eigen::Index i = 0; i < 3; ++i) {
        for (int d = 0; d < 3; ++d) {
            char number[64];
            std::snprintf(number, sizeof(number), "%.9g%c", P(i, d), d < 2 ? ' ' : '\n');
            ascii += number;
            putBytes(binary, static_cast<float>(P(i, d)), false);
        }
    }
    EXPECT_EQ(readCloud(write("ascii.pcd", ascii)), P);
    EXPECT_EQ(readCloud(write("binary.pcd", binary)), P);
}

TEST_F(CloudIO, BadTextInputNamesTheProblem)
{
    const auto expectError = [&](const std::string& name, const std::string& content,
                                 const std::string& part) {
        const std::string message = readError(write(name, content));
        EXPECT_NE(message.find(part), std::string::npos)
            << name << ": message \"" << message << "\" lacks \"" << part << "\"";
        EXPECT_NE(message.find(name), std::string::npos) << "the file is not named: " << message;
    };
    expectError("empty.xyz", "", "no point");
    expectError("comments.xyz", "# only\n// comments\n\n", "no point");
    expectError("word.xyz", "1 2 3\n1.0 abc 3\n", "line 2: 'abc' is not a number");
    expectError("suffix.xyz", "1 2 3x\n", "line 1: '3x' is not a number");
    expectError("nan.xyz", "1 2 3\n4 nan 6\n", "line 2: coordinate 'nan' is not a finite");
    expectError("inf.txt", "-inf 2 3\n", "line 1: coordinate '-inf' is not a finite");
    expectError("short.asc", "1 2 3\r\n4 5\r\n", "line 2: only 2 number(s)");
    expectError("huge.xyz", "1e999 2 3\n", "line 1: '1e999' is out of range");
    expectError("cloud.stl", "solid x\n", "unknown point cloud format '.stl'");
    expectError("noextension", "1 2 3\n", "unknown point cloud format (no extension)");
}

TEST_F(CloudIO, BadFilesNameTheProblem)
{
    EXPECT_NE(readError(path("missing.xyz")).find("no such file"), std::string::npos);
    fs::create_directories(path("folder.xyz"));
    EXPECT_NE(readError(path("folder.xyz")).find("folder"), std::string::npos);

    const std::string truncated = write("truncated.ply", "ply\nformat binary_little_endian 1.0\n"
                                                         "element vertex 10\nproperty float x\n"
                                                         "property float y\nproperty float z\n"
                                                         "end_header\n\x01\x02");
    EXPECT_NE(readError(truncated).find("the header says 'element vertex 10', the file ends in "
                                        "row 1"),
              std::string::npos)
        << readError(truncated);
    const std::string noZ = write("flat.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                              "property float x\nproperty float y\n"
                                              "end_header\n1 2\n");
    EXPECT_NE(readError(noZ).find("no 'z' coordinate"), std::string::npos);
    const std::string garbage = write("garbage.pcd", "this is not a point cloud\n");
    EXPECT_NE(readError(garbage).find("not a readable PCD file"), std::string::npos);
    const std::string nanPcd = write("nan.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\n"
                                                "TYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
                                                "POINTS 2\nDATA ascii\n1 2 3\nnan nan nan\n");
    EXPECT_NE(readError(nanPcd).find("point 2 has a coordinate that is not a finite number"),
              std::string::npos)
        << readError(nanPcd);
}

TEST(CheckFinite, NamesTheFirstBadPointAndTheMinimum)
{
    PointMatrix P = PointMatrix::Zero(5, 3);
    EXPECT_NO_THROW(checkFinite(P, "cloud", 5));
    try {
        checkFinite(P, "selection", 6);
        FAIL() << "no exception for too few points";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("selection"), std::string::npos);
    }
    P(3, 2) = std::numeric_limits<double>::infinity();
    try {
        checkFinite(P, "cloud");
        FAIL() << "no exception for an infinite coordinate";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("point 4"), std::string::npos) << e.what();
    }
}

TEST_F(CloudIO, DecimalCommasAreRefusedCsvRowsAreRead)
{
    // Commas alone separate x,y,z, with or without spaces after them.
    const PointMatrix csv = readCloud(write("rows.csv", "1,2,3\n4, 5, 6\n7.5,8.5,9.5,0,0,1\n"));
    ASSERT_EQ(csv.rows(), 3);
    EXPECT_EQ(csv(2, 0), 7.5);
    EXPECT_EQ(csv(1, 2), 6.0);
    // White space between the numbers and a comma between digits: decimal commas, which read
    // as separators would give the point (1, 5, 2).
    const std::string comma = write("comma.xyz", "0 0 0\n1,5 2,25 3,125\n");
    EXPECT_NE(readError(comma).find("decimal commas are not supported, line 2"), std::string::npos)
        << readError(comma);
    EXPECT_NE(readError(write("tab.txt", "1,5\t2,25\t3,125\n")).find("decimal commas"),
              std::string::npos);
}

TEST_F(CloudIO, RawBytesAreEscapedInMessages)
{
    const std::string binary = write("binary.xyz", std::string("\x1b[2J\x00\x01 0 0\n", 12));
    const std::string message = readError(binary);
    EXPECT_NE(message.find("'\\x1B[2J\\x00\\x01'"), std::string::npos) << message;
    for (const char c : message) {
        EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "byte " << int(static_cast<unsigned char>(c));
    }
}

TEST_F(CloudIO, NonRegularFilesAreRefusedBeforeOpening)
{
    ASSERT_EQ(mkfifo(path("pipe.xyz").c_str(), 0600), 0);
    EXPECT_NE(readError(path("pipe.xyz")).find("is not a regular file"), std::string::npos);
    EXPECT_NE(readError("/dev/null").find("is not a regular file"), std::string::npos);
}

TEST_F(CloudIO, CoordinatesBeyondTheFloatRangeAreRefused)
{
    EXPECT_NE(readError(write("big.xyz", "0 0 0\n1e39 0 0\n"))
                  .find("line 2: coordinate '1e39' is beyond the float range"),
              std::string::npos);
    const std::string ply = write("big.ply", "ply\nformat ascii 1.0\nelement vertex 2\n"
                                             "property double x\nproperty double y\n"
                                             "property double z\nend_header\n0 0 0\n0 -1e300 0\n");
    EXPECT_NE(readError(ply).find("point 2 has a coordinate beyond the float range"),
              std::string::npos)
        << readError(ply);
}

TEST_F(CloudIO, DataRowsMustMatchTheHeader)
{
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\n";
    const std::string more = write("more.ply", header + "0 0 0\n1 0 0\n0 1 0\n");
    EXPECT_NE(readError(more).find("the header says 'element vertex 2' (2 data rows), the file "
                                   "holds 3"),
              std::string::npos)
        << readError(more);
    EXPECT_NE(readError(write("fewer.ply", header + "0 0 0\n")).find("'element vertex 2'"),
              std::string::npos);

    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                         "property float x\nproperty float y\nproperty float z\nend_header\n";
    binary += std::string(24, '\0'); // two points of zeros where the header says one
    EXPECT_NE(readError(write("more-binary.ply", binary))
                  .find("goes on past the header's 'element vertex 1' (12 bytes more)"),
              std::string::npos);

    const std::string pcd = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                            "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n";
    const std::string morePcd = write("more.pcd", pcd + "1 2 3\n4 5 6\n7 8 9\n");
    EXPECT_NE(readError(morePcd).find("the header says 'POINTS 2', the file holds 3 data rows"),
              std::string::npos)
        << readError(morePcd);
    EXPECT_NE(readError(write("fewer.pcd", pcd + "1 2 3\n")).find("'POINTS 2'"), std::string::npos);
}

TEST_F(CloudIO, ALineEndAfterTheLastBinaryRowIsNoRow)
{
    // Some writers end a binary file with a newline: padding, not a row; the point is read.
    const float xyz[3] = {1.0f, 2.0f, 3.0f};
    const std::string data(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n"
                            "property float x\nproperty float y\nproperty float z\nend_header\n";
    const std::string pcd = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                            "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n";
    for (const std::string& path :
         {write("newline.ply", ply + data + "\n"), write("newline.pcd", pcd + data + "\r\n")}) {
        const featurelines::PointMatrix P = featurelines::readCloud(path);
        ASSERT_EQ(P.rows(), 1) << path;
        EXPECT_EQ(P(0, 0), 1.0);
        EXPECT_EQ(P(0, 2), 3.0);
    }
    // A byte that is no padding is still refused.
    EXPECT_NE(readError(write("junk.ply", ply + data + "x")).find("goes on past"),
              std::string::npos);
}
