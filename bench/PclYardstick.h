// SPDX-License-Identifier: LGPL-2.1-or-later
// PCL as the yardstick of the performance benchmark. Only PclYardstick.cpp sees PCL's headers
// (slow to compile); the benchmark itself sees Eigen and the standard library.
#pragma once

#include <cstddef>

#include "FeatureLines/PointCloud.h"

namespace featurelines::bench {

/// A cloud converted once to PCL's point type, as a PCL user would already hold it.
class PclCloud
{
public:
    explicit PclCloud(const PointMatrix& P);
    ~PclCloud();
    PclCloud(const PclCloud&) = delete;
    PclCloud& operator=(const PclCloud&) = delete;

    /// pcl::NormalEstimationOMP<PointXYZ, Normal> with setKSearch(k) and `threads` threads (0:
    /// PCL's default, all cores), kd-tree build included as compute() does it. Returns the
    /// bytes of its output (the pcl::Normal cloud), which is freed before returning.
    std::size_t normalEstimationOmp(int k, int threads) const;

    /// pcl::KdTreeFLANN<PointXYZ>: the build, then the k nearest other points of every point
    /// (nearestKSearch with k + 1, the point itself dropped), queries spread over `threads`
    /// OpenMP threads. Returns the bytes of the index and distance output.
    std::size_t kdTreeFlannKnn(int k, int threads) const;

private:
    struct Data;
    Data* data_;
};

} // namespace featurelines::bench
