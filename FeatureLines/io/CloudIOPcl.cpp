// SPDX-License-Identifier: LGPL-2.1-or-later
// .ply and .pcd reading through PCL; the only file of the library that includes PCL.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include "FeatureLines/PointCloud.h"

namespace featurelines::detail {

/// HeaderRows.cpp: throw naming the header field when the data rows of a PLY (PCD) file are
/// fewer or more than its header says.
void checkPlyRows(const std::string& path);
void checkPcdRows(const std::string& path);

namespace {

/// PCL prints its own diagnostics to stderr; the caller gets ours in the exception instead.
class QuietPcl
{
public:
    QuietPcl() : previous_(pcl::console::getVerbosityLevel())
    {
        pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    }
    ~QuietPcl() { pcl::console::setVerbosityLevel(previous_); }
    QuietPcl(const QuietPcl&) = delete;
    QuietPcl& operator=(const QuietPcl&) = delete;

private:
    pcl::console::VERBOSITY_LEVEL previous_;
};

template <class T> double readAs(const std::uint8_t* data)
{
    T value;
    std::memcpy(&value, data, sizeof(T));
    return static_cast<double>(value);
}

/// One scalar of any of PCL's field types, in host byte order.
double readScalar(const std::uint8_t* data, std::uint8_t datatype)
{
    switch (datatype) {
    case pcl::PCLPointField::INT8:
        return readAs<std::int8_t>(data);
    case pcl::PCLPointField::UINT8:
        return readAs<std::uint8_t>(data);
    case pcl::PCLPointField::INT16:
        return readAs<std::int16_t>(data);
    case pcl::PCLPointField::UINT16:
        return readAs<std::uint16_t>(data);
    case pcl::PCLPointField::INT32:
        return readAs<std::int32_t>(data);
    case pcl::PCLPointField::UINT32:
        return readAs<std::uint32_t>(data);
    case pcl::PCLPointField::FLOAT32:
        return readAs<float>(data);
    case pcl::PCLPointField::FLOAT64:
        return readAs<double>(data);
    default:
        return 0.0; // rejected before reading
    }
}

std::size_t scalarSize(std::uint8_t datatype)
{
    switch (datatype) {
    case pcl::PCLPointField::INT8:
    case pcl::PCLPointField::UINT8:
        return 1;
    case pcl::PCLPointField::INT16:
    case pcl::PCLPointField::UINT16:
        return 2;
    case pcl::PCLPointField::INT32:
    case pcl::PCLPointField::UINT32:
    case pcl::PCLPointField::FLOAT32:
        return 4;
    case pcl::PCLPointField::FLOAT64:
        return 8;
    default:
        return 0;
    }
}

/// PCL 1.13's PCD reader dereferences a null pointer on a header that ends before its
/// FIELDS line (an empty or truncated file): the header is checked here before PCL sees it.
/// True when the header names its fields, sizes, types, point count and data encoding.
bool pcdHeaderIsComplete(const std::string& path)
{
    std::ifstream file(path, std::ios::binary);
    std::set<std::string> keys;
    std::string line;
    // A valid header has about a dozen lines; a file without DATA in the first hundred is not
    // a PCD file.
    for (int lineNumber = 0; lineNumber < 100 && std::getline(file, line); ++lineNumber) {
        std::istringstream words(line);
        std::string key, value;
        if (!(words >> key) || key[0] == '#') {
            continue;
        }
        if (!(words >> value)) {
            return false;
        }
        keys.insert(key);
        if (key == "DATA") {
            for (const char* required : {"FIELDS", "SIZE", "TYPE", "WIDTH", "POINTS"}) {
                if (keys.count(required) == 0) {
                    return false;
                }
            }
            return value == "ascii" || value == "binary" || value == "binary_compressed";
        }
    }
    return false;
}

} // namespace

PointMatrix readPclCloud(const std::string& path, bool ply)
{
    pcl::PCLPointCloud2 cloud;
    int status = -1;
    if (ply || pcdHeaderIsComplete(path)) {
        if (ply) {
            checkPlyRows(path);
        } else {
            checkPcdRows(path);
        }
        const QuietPcl quiet;
        try {
            status = ply ? pcl::io::loadPLYFile(path, cloud) : pcl::io::loadPCDFile(path, cloud);
        } catch (const std::exception&) {
            status = -1;
        }
    }
    const char* format = ply ? "PLY" : "PCD";
    if (status < 0) {
        throw std::invalid_argument(path + ": not a readable " + std::string(format) +
                                    " file (bad header or truncated data)");
    }

    // x, y, z as stored (float, double or integer), kept in double.
    const pcl::PCLPointField* fields[3] = {nullptr, nullptr, nullptr};
    const char* names[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) {
        const int index = pcl::getFieldIndex(cloud, names[d]);
        if (index < 0) {
            throw std::invalid_argument(path + ": the " + std::string(format) + " file has no '" +
                                        names[d] + "' coordinate");
        }
        fields[d] = &cloud.fields[index];
        const std::size_t size = scalarSize(fields[d]->datatype);
        if (size == 0 || fields[d]->offset + size > cloud.point_step) {
            throw std::invalid_argument(path + ": the '" + std::string(names[d]) +
                                        "' coordinate has a type that cannot be read");
        }
    }
    const std::size_t width = cloud.width;
    const std::size_t height = cloud.height;
    const std::size_t n = width * height;
    if (n == 0) {
        throw std::invalid_argument(path + ": the file holds no point");
    }
    if (cloud.row_step < width * cloud.point_step || cloud.data.size() < height * cloud.row_step) {
        throw std::invalid_argument(path + ": the " + std::string(format) +
                                    " file is shorter than its header says");
    }

    PointMatrix P(static_cast<Eigen::Index>(n), 3);
    for (std::size_t row = 0; row < height; ++row) {
        for (std::size_t column = 0; column < width; ++column) {
            const std::uint8_t* point =
                cloud.data.data() + row * cloud.row_step + column * cloud.point_step;
            const Eigen::Index i = static_cast<Eigen::Index>(row * width + column);
            for (int d = 0; d < 3; ++d) {
                P(i, d) = readScalar(point + fields[d]->offset, fields[d]->datatype);
            }
        }
    }
    return P;
}

} // namespace featurelines::detail
