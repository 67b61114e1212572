// SPDX-License-Identifier: LGPL-2.1-or-later
#include "PclYardstick.h"

#include <vector>

#include <omp.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace featurelines::bench {

struct PclCloud::Data
{
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud{new pcl::PointCloud<pcl::PointXYZ>};
};

PclCloud::PclCloud(const PointMatrix& P) : data_(new Data)
{
    pcl::PointCloud<pcl::PointXYZ>& cloud = *data_->cloud;
    cloud.resize(static_cast<std::size_t>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        cloud[static_cast<std::size_t>(i)] = pcl::PointXYZ(
            static_cast<float>(P(i, 0)), static_cast<float>(P(i, 1)), static_cast<float>(P(i, 2)));
    }
}

PclCloud::~PclCloud()
{
    delete data_;
}

std::size_t PclCloud::normalEstimationOmp(int k, int threads) const
{
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
    estimation.setNumberOfThreads(static_cast<unsigned>(threads));
    estimation.setInputCloud(data_->cloud);
    // No search method given: compute() builds its own KdTreeFLANN, as a user's code would.
    estimation.setKSearch(k);
    pcl::PointCloud<pcl::Normal> normals;
    estimation.compute(normals);
    return normals.size() * sizeof(pcl::Normal);
}

std::size_t PclCloud::kdTreeFlannKnn(int k, int threads) const
{
    pcl::KdTreeFLANN<pcl::PointXYZ> tree;
    tree.setInputCloud(data_->cloud);
    const pcl::PointCloud<pcl::PointXYZ>& cloud = *data_->cloud;
    const auto n = static_cast<long>(cloud.size());
    std::vector<int> indices(static_cast<std::size_t>(n) * static_cast<std::size_t>(k));
    std::vector<float> distances(indices.size());
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
    {
        std::vector<int> found(static_cast<std::size_t>(k) + 1);
        std::vector<float> squared(static_cast<std::size_t>(k) + 1);
#pragma omp for schedule(static, 4096)
        for (long i = 0; i < n; ++i) {
            tree.nearestKSearch(cloud[static_cast<std::size_t>(i)], k + 1, found, squared);
            // The first hit is the point itself (or a duplicate of it): keep the next k.
            for (int j = 0; j < k; ++j) {
                indices[static_cast<std::size_t>(i * k + j)] =
                    found[static_cast<std::size_t>(j + 1)];
                distances[static_cast<std::size_t>(i * k + j)] =
                    squared[static_cast<std::size_t>(j + 1)];
            }
        }
    }
    return indices.size() * sizeof(int) + distances.size() * sizeof(float);
}

} // namespace featurelines::bench
