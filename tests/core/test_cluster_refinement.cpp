// SPDX-License-Identifier: LGPL-2.1-or-later
// ClusterRefinement.h: the histogram step again inside one large cluster (Sec. 4) on a
// region whose curvature is prescribed: a disc at 0.1 holding a core at 0.2.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "FeatureLines/smooth/ClusterRefinement.h"
#include "RegionLattice.h"

using namespace featurelines;

TEST(ClusterRefinement, TheLevelInsideALargeClusterIsFound)
{
    // Plane 0; a disc of radius 25 at 0.1 around (40, 35); inside it a core of radius 10 at
    // 0.2 (both steps blurred over 4 spacings, as the fit blurs them). At tau = 0.05 the disc
    // is one large cluster with a loop around it; refined inside that cluster, the histogram
    // of its values parts 0.1 from 0.2 and the lines ring the core.
    const RegionGeometry g = latticeRegion(80, 70, [](double x, double y) {
        const double r = std::hypot(x - 40.0, y - 35.0);
        return step(r, 25.0, 0.1, 0.0, 4.0) + step(r, 10.0, 0.1, 0.0, 4.0);
    });
    const SmoothEdgeLevel level = smoothEdgesAtThreshold(g, 0.05);
    Eigen::Index centre = 0;
    (g.points.leftCols<2>().rowwise() - Eigen::RowVector2d(40.0, 35.0))
        .rowwise()
        .squaredNorm()
        .minCoeff(&centre);
    const int disc = level.clusters.cluster[static_cast<size_t>(centre)];
    ASSERT_GE(disc, 0);
    const SmoothEdgeLevel core = refineInCluster(g, level, disc);
    EXPECT_GT(core.threshold, 0.1);
    EXPECT_LT(core.threshold, 0.2);
    ASSERT_EQ(core.network.lines.size(), 1u);
    const Polyline& loop = core.network.lines[0];
    EXPECT_TRUE(loop.closed);
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i) {
        EXPECT_NEAR(std::hypot(loop.points(i, 0) - 40.0, loop.points(i, 1) - 35.0), 10.0, 3.0);
    }
    // Not a large cluster of that level: refused.
    EXPECT_THROW(refineInCluster(g, level, -1), std::invalid_argument);
    EXPECT_THROW(refineInCluster(g, level, static_cast<int>(level.clusters.size.size())),
                 std::invalid_argument);
}
