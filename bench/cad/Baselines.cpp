// SPDX-License-Identifier: LGPL-2.1-or-later
#include "Baselines.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

namespace featurelines::bench {

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Tree = pcl::search::KdTree<pcl::PointXYZ>;

/// The cloud in PCL's form with its kd-tree, and PCA normals with surface variation.
struct PclNormals
{
    Cloud::Ptr cloud;
    Tree::Ptr tree;
    pcl::PointCloud<pcl::Normal> normals;
};

PclNormals estimateNormals(const PointMatrix& P, const BaselineOptions& options)
{
    if (options.k < 3) {
        throw std::invalid_argument("The baselines need at least 3 neighbours per point.");
    }
    if (P.rows() <= options.k) {
        throw std::invalid_argument("The cloud has too few points for the baselines' "
                                    "neighbourhoods.");
    }
    PclNormals result;
    result.cloud = pcl::make_shared<Cloud>();
    result.cloud->resize(static_cast<size_t>(P.rows()));
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        (*result.cloud)[static_cast<size_t>(i)] = pcl::PointXYZ(
            static_cast<float>(P(i, 0)), static_cast<float>(P(i, 1)), static_cast<float>(P(i, 2)));
    }
    result.tree = pcl::make_shared<Tree>();
    result.tree->setInputCloud(result.cloud);

    pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
    estimation.setInputCloud(result.cloud);
    estimation.setSearchMethod(result.tree);
    // PCL counts the query point among its k nearest; the project's k counts other points.
    estimation.setKSearch(options.k + 1);
    estimation.compute(result.normals);
    return result;
}

} // namespace

std::vector<double> surfaceVariation(const PointMatrix& P, const BaselineOptions& options)
{
    const PclNormals pcl = estimateNormals(P, options);
    std::vector<double> values(pcl.normals.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const float c = pcl.normals[i].curvature;
        values[i] = std::isfinite(c) ? c : 0.0;
    }
    return values;
}

std::vector<double> normalAngleDegrees(const PointMatrix& P, const BaselineOptions& options)
{
    const PclNormals pcl = estimateNormals(P, options);
    std::vector<double> values(pcl.normals.size());
    std::vector<int> neighbours;
    std::vector<float> distances;
    for (size_t i = 0; i < values.size(); ++i) {
        const pcl::Normal& ni = pcl.normals[i];
        const Eigen::Vector3f a(ni.normal_x, ni.normal_y, ni.normal_z);
        pcl.tree->nearestKSearch(static_cast<int>(i), options.k + 1, neighbours, distances);
        double smallestCos = 1.0;
        for (int j : neighbours) {
            const pcl::Normal& nj = pcl.normals[static_cast<size_t>(j)];
            const Eigen::Vector3f b(nj.normal_x, nj.normal_y, nj.normal_z);
            if (a.allFinite() && b.allFinite()) {
                smallestCos = std::min(smallestCos, std::abs(static_cast<double>(a.dot(b))));
            }
        }
        values[i] = std::acos(std::clamp(smallestCos, 0.0, 1.0)) * 180.0 / 3.14159265358979323846;
    }
    return values;
}

PointMatrix pointsAbove(const PointMatrix& P, const std::vector<double>& values, double threshold)
{
    if (static_cast<Eigen::Index>(values.size()) != P.rows()) {
        throw std::invalid_argument("One value per point is needed to flag points.");
    }
    Eigen::Index count = 0;
    for (double v : values) {
        count += v > threshold ? 1 : 0;
    }
    PointMatrix flagged(count, 3);
    Eigen::Index row = 0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        if (values[static_cast<size_t>(i)] > threshold) {
            flagged.row(row++) = P.row(i);
        }
    }
    return flagged;
}

} // namespace featurelines::bench
