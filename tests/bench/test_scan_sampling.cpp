// SPDX-License-Identifier: LGPL-2.1-or-later
// The scanner models (bench/cad/ScanSampling.h) on boxes, whose surface, faces and areas are
// known exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <vector>

#include <BRepPrimAPI_MakeBox.hxx>
#include <gp_Pnt.hxx>

#include <gtest/gtest.h>

#include "ScanSampling.h"
#include "ShapeSampling.h"

using namespace featurelines::bench;

namespace {

TopoDS_Shape makeBox(const Eigen::Vector3d& size)
{
    return BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), size.x(), size.y(), size.z()).Shape();
}

/// Distance from p to the surface of the box [0, size].
double distanceToBox(const Eigen::Vector3d& p, const Eigen::Vector3d& size)
{
    const Eigen::Vector3d inside = p.cwiseMax(Eigen::Vector3d::Zero()).cwiseMin(size);
    if ((p - inside).norm() > 0.0) {
        return (p - inside).norm();
    }
    return p.cwiseMin(size - p).minCoeff();
}

const std::vector<ScanModel> allModels = {ScanModel::UniformRandom, ScanModel::PoissonDisk,
                                          ScanModel::ScanLines, ScanModel::MergedViews,
                                          ScanModel::DensityGradient};

ScanView view(const Eigen::Vector3d& direction, const Eigen::Vector3d& row)
{
    ScanView v;
    v.direction = direction.normalized();
    v.rowDirection = row.normalized();
    return v;
}

} // namespace

TEST(ScanSampling, EveryModelLiesOnTheSurfaceWithAboutTheAskedCount)
{
    const Eigen::Vector3d size(50, 40, 30);
    const TopoDS_Shape box = makeBox(size);
    for (ScanModel model : allModels) {
        ScanOptions options;
        options.model = model;
        options.points = 20000;
        options.misregistration = 0.0;
        options.seed = 7;
        const ScannedCloud cloud = sampleLikeAScanner(box, options);
        SCOPED_TRACE(scanModelName(model));
        EXPECT_NEAR(static_cast<double>(cloud.points.rows()), options.points,
                    0.15 * options.points);
        double farthest = 0.0;
        for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
            farthest = std::max(farthest, distanceToBox(cloud.points.row(i).transpose(), size));
            EXPECT_NEAR(cloud.normals.row(i).norm(), 1.0, 1e-9);
        }
        EXPECT_LT(farthest, 1e-6);
        EXPECT_GT(cloud.spacing, 0.0);
        EXPECT_EQ(cloud.view.size(), static_cast<size_t>(cloud.points.rows()));
        EXPECT_EQ(cloud.outlier.size(), static_cast<size_t>(cloud.points.rows()));
    }
}

TEST(ScanSampling, ScanLinesAreFinerAlongTheRowsThanAcross)
{
    // Seen from straight above, only the top face: its sides are seen edge-on.
    const Eigen::Vector3d size(50, 40, 30);
    for (double ratio : {3.0, 4.0, 5.0}) {
        ScanOptions options;
        options.model = ScanModel::ScanLines;
        options.points = 10000;
        options.rowSpacingRatio = ratio;
        options.views = {view({0, 0, -1}, {1, 0, 0})};
        const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
        std::map<long, std::vector<double>> rows; // y in nanometres -> x along the row
        for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
            EXPECT_NEAR(cloud.points(i, 2), size.z(), 1e-9);
            rows[std::lround(cloud.points(i, 1) * 1e6)].push_back(cloud.points(i, 0));
        }
        std::vector<double> along;
        std::vector<double> across;
        long previousRow = 0;
        bool first = true;
        for (auto& [y, xs] : rows) {
            std::sort(xs.begin(), xs.end());
            for (size_t k = 1; k < xs.size(); ++k) {
                along.push_back(xs[k] - xs[k - 1]);
            }
            if (!first) {
                across.push_back(static_cast<double>(y - previousRow) * 1e-6);
            }
            previousRow = y;
            first = false;
        }
        ASSERT_GT(along.size(), 100u);
        ASSERT_GT(across.size(), 10u);
        const double alongMax = *std::max_element(along.begin(), along.end());
        const double alongMin = *std::min_element(along.begin(), along.end());
        const double acrossMean =
            std::accumulate(across.begin(), across.end(), 0.0) / static_cast<double>(across.size());
        EXPECT_NEAR(alongMin, cloud.rowStep, 1e-6 * cloud.rowStep);
        EXPECT_NEAR(alongMax, cloud.rowStep, 1e-6 * cloud.rowStep);
        EXPECT_NEAR(acrossMean / cloud.rowStep, ratio, 1e-4);
        EXPECT_NEAR(static_cast<double>(cloud.points.rows()), options.points,
                    0.05 * options.points);
    }
}

TEST(ScanSampling, ScanLinesSeeOnlyTheFacesTurnedToTheView)
{
    const Eigen::Vector3d size(50, 40, 30);
    ScanOptions options;
    options.model = ScanModel::ScanLines;
    options.points = 10000;
    options.views = {view({-1, -2, -3}, {1, 0, 0})}; // sees the faces x = 50, y = 40, z = 30
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    std::array<int, 3> onFace{};
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        const Eigen::Vector3d p = cloud.points.row(i).transpose();
        const Eigen::Vector3d gapToFar = size - p;
        EXPECT_LT(gapToFar.minCoeff(), 1e-6) << "a point on a face turned away";
        for (int a = 0; a < 3; ++a) {
            onFace[static_cast<size_t>(a)] += gapToFar[a] < 1e-6 ? 1 : 0;
        }
    }
    // Each face gets points in proportion to its area projected on the view's plane.
    const Eigen::Vector3d d = Eigen::Vector3d(1, 2, 3).normalized();
    const Eigen::Vector3d projected(size.y() * size.z() * d.x(), size.x() * size.z() * d.y(),
                                    size.x() * size.y() * d.z());
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(onFace[static_cast<size_t>(a)] / static_cast<double>(cloud.points.rows()),
                    projected[a] / projected.sum(), 0.02);
    }
}

TEST(ScanSampling, TruthIsCutToWhatTheCloudCovers)
{
    // Seen from straight above: the top face's four edges in full, the vertical edges near
    // their upper ends only, the bottom edges not at all.
    const Eigen::Vector3d size(50, 40, 30);
    const TopoDS_Shape box = makeBox(size);
    ScanOptions options;
    options.model = ScanModel::ScanLines;
    options.points = 10000;
    options.views = {view({0, 0, -1}, {1, 0, 0})};
    const ScannedCloud cloud = sampleLikeAScanner(box, options);
    TruthOptions truthOptions;
    truthOptions.step = 0.1 * cloud.spacing;
    const std::vector<TypedPolyline> truth = truthEdges(box, truthOptions);
    ASSERT_EQ(truth.size(), 12u);
    // Farther than the rows are apart, so that the edges along the rows are reached.
    const double across = options.rowSpacingRatio * cloud.rowStep;
    const double reach = 1.5 * across;
    const std::vector<TypedPolyline> covered = truthCoveredBy(truth, cloud.points, reach);
    double topLength = 0.0;
    double verticalLength = 0.0;
    for (const TypedPolyline& line : covered) {
        EXPECT_EQ(line.type, LineType::Sharp);
        for (Eigen::Index k = 1; k < line.points.rows(); ++k) {
            const double length = (line.points.row(k) - line.points.row(k - 1)).norm();
            const double z = line.points(k, 2);
            EXPECT_GT(z, size.z() - reach - 1e-9);
            const bool top =
                std::abs(z - size.z()) < 1e-9 && std::abs(line.points(k - 1, 2) - size.z()) < 1e-9;
            (top ? topLength : verticalLength) += length;
        }
    }
    EXPECT_NEAR(topLength, 2 * (size.x() + size.y()), 1e-6);
    // A corner's nearest point lies within a step along and a row across.
    EXPECT_GT(verticalLength, 4 * (reach - std::hypot(cloud.rowStep, across)));
    EXPECT_LE(verticalLength, 4 * reach + 1e-9);
}

TEST(ScanSampling, MergedViewsOverlapAtDoubleDensity)
{
    // Two views at 45 degrees either side of the vertical: both see the top, each one side.
    const Eigen::Vector3d size(60, 60, 30);
    ScanOptions options;
    options.model = ScanModel::MergedViews;
    options.points = 20000;
    options.misregistration = 0.0;
    options.views = {view({1, 0, -1}, {0, 1, 0}), view({-1, 0, -1}, {0, 1, 0})};
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    int top = 0;
    int sideSeenByFirst = 0;
    std::set<int> viewsOnTop;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        if (std::abs(cloud.points(i, 2) - size.z()) < 1e-6) {
            ++top;
            viewsOnTop.insert(cloud.view[static_cast<size_t>(i)]);
        } else if (std::abs(cloud.points(i, 0)) < 1e-6) {
            ++sideSeenByFirst;
            EXPECT_EQ(cloud.view[static_cast<size_t>(i)], 0);
        }
    }
    const double topDensity = top / (size.x() * size.y());
    const double sideDensity = sideSeenByFirst / (size.y() * size.z());
    EXPECT_NEAR(topDensity / sideDensity, 2.0, 0.1);
    EXPECT_EQ(viewsOnTop, (std::set<int>{0, 1}));
}

TEST(ScanSampling, MisregistrationMovesEachViewByLessThanItsBound)
{
    const Eigen::Vector3d size(60, 60, 30);
    ScanOptions options;
    options.model = ScanModel::MergedViews;
    options.points = 10000;
    options.viewCount = 3;
    options.misregistration = 0.5;
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    ASSERT_EQ(cloud.views.size(), 3u);
    double farthest = 0.0;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        farthest = std::max(farthest, distanceToBox(cloud.points.row(i).transpose(), size));
    }
    EXPECT_LE(farthest, 0.5 * cloud.rowStep + 1e-9);
    EXPECT_GT(farthest, 0.05 * cloud.rowStep);
}

TEST(ScanSampling, DensityGradientIsFourTimesDenserAtOneEnd)
{
    const Eigen::Vector3d size(100, 20, 20);
    ScanOptions options;
    options.model = ScanModel::DensityGradient;
    options.points = 30000;
    options.densityRatio = 4.0;
    options.gradientDirection = Eigen::Vector3d::UnitX();
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    // The long sides only, in the slabs of the first and last 5 % of the length.
    int sparse = 0;
    int dense = 0;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        const double x = cloud.points(i, 0);
        if (x < 1e-6 || x > size.x() - 1e-6) {
            continue;
        }
        sparse += x < 5.0 ? 1 : 0;
        dense += x > 95.0 ? 1 : 0;
    }
    // Density 1 + 3 t: mean 3.925 over the last 5 %, 1.075 over the first.
    EXPECT_NEAR(static_cast<double>(dense) / sparse, 3.925 / 1.075, 0.1 * 3.925 / 1.075);
    EXPECT_NEAR(static_cast<double>(cloud.points.rows()), options.points, 0.1 * options.points);
}

TEST(ScanSampling, OcclusionHolesLeaveNoPointInside)
{
    const Eigen::Vector3d size(50, 40, 30);
    ScanOptions options;
    options.model = ScanModel::PoissonDisk;
    options.points = 20000;
    options.seed = 3;
    const ScannedCloud whole = sampleLikeAScanner(makeBox(size), options);
    options.occlusionHoles = 3;
    options.holeRadius = 6.0;
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    ASSERT_EQ(cloud.holes.size(), 3u);
    for (const OcclusionHole& hole : cloud.holes) {
        EXPECT_NEAR(hole.radius, 6.0 * cloud.spacing, 1e-12);
        for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
            const Eigen::Vector3d q = cloud.points.row(i).transpose() - hole.point;
            EXPECT_GE((q - q.dot(hole.direction) * hole.direction).norm(), hole.radius);
        }
    }
    // Each hole cuts at least a disc of its radius: about 0.57 / r^2 points per area.
    const double disc = 3.14159 * std::pow(6.0 * cloud.spacing, 2);
    EXPECT_LT(cloud.points.rows(),
              whole.points.rows() -
                  static_cast<Eigen::Index>(3 * 0.5 * disc / std::pow(cloud.spacing, 2)));
}

TEST(ScanSampling, OutliersAreTheStatedShareOffTheSurface)
{
    const Eigen::Vector3d size(50, 40, 30);
    ScanOptions options;
    options.model = ScanModel::UniformRandom;
    options.points = 20000;
    options.outlierShare = 0.01;
    const ScannedCloud cloud = sampleLikeAScanner(makeBox(size), options);
    int off = 0;
    int flagged = 0;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        const double d = distanceToBox(cloud.points.row(i).transpose(), size);
        const bool outlier = cloud.outlier[static_cast<size_t>(i)] != 0;
        flagged += outlier ? 1 : 0;
        off += d > 1.0 * cloud.spacing ? 1 : 0;
        if (outlier) {
            // Outwards within 45 degrees of the normal, at least 3 spacings: off a convex
            // part by at least 3 cos 45 spacings.
            EXPECT_GT(d, 2.1 * cloud.spacing);
            EXPECT_LT(d, 20.0 * cloud.spacing + 1e-9);
        } else {
            EXPECT_LT(d, 1e-6);
        }
    }
    EXPECT_EQ(flagged, std::lround(0.01 * cloud.points.rows()));
    EXPECT_EQ(off, flagged);
}

TEST(ScanSampling, NoiseAlongTheNormalAndJitterAcrossIt)
{
    const Eigen::Vector3d size(50, 40, 30);
    ScanOptions options;
    options.model = ScanModel::PoissonDisk;
    options.points = 20000;
    const ScannedCloud clean = sampleLikeAScanner(makeBox(size), options);
    options.normalNoise = 0.3;
    const ScannedCloud noisy = sampleLikeAScanner(makeBox(size), options);
    options.normalNoise = 0.0;
    options.tangentialJitter = 0.2;
    const ScannedCloud jittered = sampleLikeAScanner(makeBox(size), options);
    ASSERT_EQ(noisy.points.rows(), clean.points.rows());
    ASSERT_EQ(jittered.points.rows(), clean.points.rows());
    double along = 0.0;
    double across = 0.0;
    for (Eigen::Index i = 0; i < clean.points.rows(); ++i) {
        const Eigen::Vector3d n = clean.normals.row(i).transpose();
        const Eigen::Vector3d dn = (noisy.points.row(i) - clean.points.row(i)).transpose();
        const Eigen::Vector3d dt = (jittered.points.row(i) - clean.points.row(i)).transpose();
        EXPECT_LT((dn - dn.dot(n) * n).norm(), 1e-9);
        EXPECT_LT(std::abs(dt.dot(n)), 1e-9);
        along += dn.squaredNorm();
        across += dt.squaredNorm();
    }
    const double n = static_cast<double>(clean.points.rows());
    EXPECT_NEAR(std::sqrt(along / n), 0.3 * clean.spacing, 0.02 * clean.spacing);
    EXPECT_NEAR(std::sqrt(across / n), std::sqrt(2.0) * 0.2 * clean.spacing, 0.02 * clean.spacing);
}

TEST(ScanSampling, SameSeedSameCloud)
{
    const TopoDS_Shape box = makeBox({50, 40, 30});
    for (ScanModel model : allModels) {
        SCOPED_TRACE(scanModelName(model));
        ScanOptions options;
        options.model = model;
        options.points = 5000;
        options.occlusionHoles = 2;
        options.outlierShare = 0.01;
        options.normalNoise = 0.3;
        options.tangentialJitter = 0.1;
        const ScannedCloud a = sampleLikeAScanner(box, options);
        const ScannedCloud b = sampleLikeAScanner(box, options);
        ASSERT_EQ(a.points.rows(), b.points.rows());
        EXPECT_TRUE(a.points == b.points);
        options.seed = 2;
        const ScannedCloud c = sampleLikeAScanner(box, options);
        EXPECT_FALSE(c.points.rows() == a.points.rows() && c.points == a.points);
    }
}

TEST(ScanSampling, DrawnOptionsStayInTheirRanges)
{
    std::set<ScanModel> models;
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        const ScanOptions o = drawScanOptions(seed);
        const ScanOptions again = drawScanOptions(seed);
        EXPECT_EQ(o.model, again.model);
        EXPECT_EQ(o.points, again.points);
        EXPECT_EQ(o.seed, again.seed);
        models.insert(o.model);
        EXPECT_GE(o.points, 10000.0);
        EXPECT_LE(o.points, 1000000.0);
        EXPECT_TRUE(o.normalNoise == 0.0 || o.normalNoise == 0.1 || o.normalNoise == 0.3 ||
                    o.normalNoise == 0.5);
        EXPECT_GE(o.rowSpacingRatio, 3.0);
        EXPECT_LE(o.rowSpacingRatio, 5.0);
        EXPECT_GE(o.viewCount, 2);
        EXPECT_LE(o.viewCount, 3);
        EXPECT_LE(o.outlierShare, 0.01);
        EXPECT_LE(o.occlusionHoles, 4);
    }
    EXPECT_EQ(models.size(), 5u);
}

TEST(ScanSampling, BadOptionsThrow)
{
    const TopoDS_Shape box = makeBox({50, 40, 30});
    ScanOptions options;
    options.points = 0;
    EXPECT_THROW(sampleLikeAScanner(box, options), std::invalid_argument);
    options = {};
    options.rowSpacingRatio = 0.5;
    EXPECT_THROW(sampleLikeAScanner(box, options), std::invalid_argument);
    options = {};
    options.outlierShare = 1.5;
    EXPECT_THROW(sampleLikeAScanner(box, options), std::invalid_argument);
    options = {};
    options.model = ScanModel::ScanLines;
    options.views = {view({0, 0, -1}, {0, 0, 1})};
    EXPECT_THROW(sampleLikeAScanner(box, options), std::invalid_argument);
    EXPECT_THROW(sampleLikeAScanner(TopoDS_Shape(), ScanOptions{}), std::invalid_argument);
}
