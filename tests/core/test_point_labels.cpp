// SPDX-License-Identifier: LGPL-2.1-or-later
// Sec. 3 labels and label growing on a triangular lattice whose 1-rings are known exactly: the six
// lattice neighbours at distance one spacing.
#include <gtest/gtest.h>

#include <set>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/PointLabels.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"

using namespace featurelines;

namespace {

struct Lattice
{
    PointMatrix points;
    Eigen::VectorXd curvature;
    std::vector<std::vector<int>> latticeNeighbours; // the exact ring, by distance == 1
};

// A triangular lattice of unit spacing, 31 x 31 points; curvature 1 inside a disc of radius 6
// around the centre, 0 elsewhere.
Lattice discLattice()
{
    const int n = 31;
    Lattice l;
    l.points.resize(n * n, 3);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            l.points.row(j * n + i) << i + 0.5 * (j % 2), j * std::sqrt(3.0) / 2.0, 0.0;
        }
    }
    const Eigen::RowVector3d centre = l.points.row((n / 2) * n + n / 2);
    l.curvature.resize(n * n);
    for (int p = 0; p < n * n; ++p) {
        l.curvature[p] = (l.points.row(p) - centre).norm() <= 6.0 ? 1.0 : 0.0;
    }
    l.latticeNeighbours.resize(n * n);
    for (int p = 0; p < n * n; ++p) {
        for (int q = 0; q < n * n; ++q) {
            if (p != q && std::abs((l.points.row(p) - l.points.row(q)).norm() - 1.0) < 1e-9) {
                l.latticeNeighbours[p].push_back(q);
            }
        }
    }
    return l;
}

bool interior(const Lattice& l, int p)
{
    return l.latticeNeighbours[p].size() == 6;
}

} // namespace

TEST(PointLabels, DiscOnLatticeGivesInnerCoreRingedByBorderPoints)
{
    const Lattice l = discLattice();
    const Neighbourhoods N = nearestNeighbours(l.points, {12});
    const RingNeighbourhoods ring =
        ringNeighbourhoods(l.points, pcaNormals(l.points, N).normals, N);
    std::vector<int> region(l.points.rows());
    for (int i = 0; i < static_cast<int>(region.size()); ++i) {
        region[i] = i;
    }
    const std::vector<PointLabel> labels = labelPoints(l.curvature, 0.5, ring, region);

    int inner = 0, border = 0;
    for (int p = 0; p < static_cast<int>(region.size()); ++p) {
        if (!interior(l, p)) {
            continue; // lattice rim: its ring is one-sided, the definition still applies
        }
        const bool high = l.curvature[p] > 0.5;
        bool allHigh = true;
        int innerNeighbours = 0;
        for (int q : l.latticeNeighbours[p]) {
            allHigh = allHigh && l.curvature[q] > 0.5;
        }
        if (!high) {
            EXPECT_EQ(labels[p], PointLabel::Low) << p;
            continue;
        }
        if (allHigh) {
            EXPECT_EQ(labels[p], PointLabel::Inner) << p;
            ++inner;
            continue;
        }
        for (int q : l.latticeNeighbours[p]) {
            bool qInner = l.curvature[q] > 0.5;
            for (int r : l.latticeNeighbours[q]) {
                qInner = qInner && l.curvature[r] > 0.5;
            }
            innerNeighbours += qInner ? 1 : 0;
        }
        EXPECT_EQ(labels[p], innerNeighbours >= 2 ? PointLabel::Border : PointLabel::Noisy) << p;
        border += innerNeighbours >= 2 ? 1 : 0;
    }
    // A disc of radius 6 spacings: a core of inner points and a closed rim of border points.
    EXPECT_GT(inner, 60);
    EXPECT_GT(border, 24);
}

TEST(PointLabels, GrowingGivesOneLowOneInnerClusterAndSingleBorderPoints)
{
    const Lattice l = discLattice();
    const Neighbourhoods N = nearestNeighbours(l.points, {12});
    const RingNeighbourhoods ring =
        ringNeighbourhoods(l.points, pcaNormals(l.points, N).normals, N);
    std::vector<int> region(l.points.rows());
    for (int i = 0; i < static_cast<int>(region.size()); ++i) {
        region[i] = i;
    }
    const std::vector<PointLabel> labels = labelPoints(l.curvature, 0.5, ring, region);
    for (unsigned seed : {1u, 7u, 12345u}) {
        const LabelClusters c = growLabelClusters(labels, ring, region, seed);
        std::set<int> lowClusters, innerClusters;
        for (int p : region) {
            ASSERT_GE(c.cluster[p], 0);
            const int id = c.cluster[p];
            if (labels[p] == PointLabel::Border) {
                EXPECT_EQ(c.size[id], 1) << "a border point is a single-point cluster";
            } else if (labels[p] == PointLabel::Inner && c.size[id] > 1) {
                innerClusters.insert(id);
            } else if (c.size[id] > 1) {
                lowClusters.insert(id);
                EXPECT_EQ(c.label[id], PointLabel::Low);
            }
        }
        // The patch (the disc) is one large cluster, the plane around it another (Sec. 3).
        EXPECT_EQ(innerClusters.size(), 1u) << "seed " << seed;
        EXPECT_EQ(lowClusters.size(), 1u) << "seed " << seed;
    }
}

TEST(PointLabels, PointsOutsideTheRegionAreNeitherLabelledNorClustered)
{
    const Lattice l = discLattice();
    const Neighbourhoods N = nearestNeighbours(l.points, {12});
    const RingNeighbourhoods ring =
        ringNeighbourhoods(l.points, pcaNormals(l.points, N).normals, N);
    std::vector<int> leftHalf;
    for (int p = 0; p < l.points.rows(); ++p) {
        if (l.points(p, 0) < 15.0) {
            leftHalf.push_back(p);
        }
    }
    const std::vector<PointLabel> labels = labelPoints(l.curvature, 0.5, ring, leftHalf);
    const LabelClusters c = growLabelClusters(labels, ring, leftHalf, 3);
    for (int p = 0; p < l.points.rows(); ++p) {
        const bool in = l.points(p, 0) < 15.0;
        EXPECT_EQ(labels[p] == PointLabel::Outside, !in);
        EXPECT_EQ(c.cluster[p] < 0, !in);
    }
}

TEST(PointLabels, RejectsMismatchedSizesAndBadIndices)
{
    RingNeighbourhoods ring;
    ring.offsets = {0, 0, 0};
    Eigen::VectorXd curvature(3);
    curvature.setZero();
    EXPECT_THROW(labelPoints(curvature, 0.1, ring, {0}), std::invalid_argument);
    curvature.resize(2);
    EXPECT_THROW(labelPoints(curvature, 0.1, ring, {5}), std::invalid_argument);
}
