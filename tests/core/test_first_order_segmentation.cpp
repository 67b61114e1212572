// SPDX-License-Identifier: LGPL-2.1-or-later
// First-order segmentation on shapes whose answer is known: a plane and a fillet-rounded cube
// are one smooth patch each; a cube is six faces with candidates only along its edges; a
// ridge of 35 degrees separates its two faces; the spread limit and the scale of the excess
// follow the noise; a noisy ridge of 45 degrees keeps its points as candidates although the
// growing leaks across it, while a noisy cylinder and plane gain none.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "FeatureLines/sharp/FirstOrderSegmentation.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

struct Prepared
{
    Neighbourhoods neighbours;
    NormalEstimate normals;
    double spacing = 0.0;
};

Prepared prepare(const shapes::Sample& s)
{
    Prepared p;
    p.neighbours = nearestNeighbours(s.points);
    p.spacing = meanSpacing(p.neighbours);
    p.normals = pcaNormals(s.points, p.neighbours);
    return p;
}

FirstOrderSegmentation segment(const shapes::Sample& s, const Prepared& p)
{
    return segmentByNormals(s.points, p.normals.normals, p.neighbours, p.spacing);
}

int largeClusters(const FirstOrderSegmentation& seg)
{
    int count = 0;
    for (char small : seg.smallCluster) {
        count += small ? 0 : 1;
    }
    return count;
}

/// Distance from a point to the nearest edge of the cube [-h, h]^3.
double distanceToCubeEdge(const Eigen::RowVector3d& p, double h)
{
    double best = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const double along = std::max(0.0, std::abs(p[axis]) - h);
        const double du = std::abs(p[u]) - h, dv = std::abs(p[v]) - h;
        best = std::min(best, std::sqrt(along * along + du * du + dv * dv));
    }
    return best;
}

} // namespace

TEST(FirstOrderSegmentation, PlaneIsOneClusterWithoutCandidates)
{
    for (double sigma : {0.0, 0.3}) {
        shapes::Sample plane = shapes::plane(30.0, 1.0, 1);
        shapes::addNormalNoise(plane, sigma, 2);
        const Prepared p = prepare(plane);
        const FirstOrderSegmentation seg = segment(plane, p);
        EXPECT_EQ(largeClusters(seg), 1) << "noise sigma " << sigma;
        int candidates = 0;
        for (Eigen::Index i = 0; i < plane.size(); ++i) {
            candidates += seg.isCandidate(i) ? 1 : 0;
        }
        EXPECT_EQ(candidates, 0) << "noise sigma " << sigma;
    }
}

TEST(FirstOrderSegmentation, CubeHasSixFacesAndCandidatesOnlyAlongItsEdges)
{
    const double edge = 30.0;
    const shapes::Sample cube = shapes::cube(edge, 1.0, 3);
    const Prepared p = prepare(cube);
    const FirstOrderSegmentation seg = segment(cube, p);
    ASSERT_EQ(seg.cluster.size(), static_cast<size_t>(cube.size()));
    EXPECT_EQ(largeClusters(seg), 6);

    // Every face's points away from the edges share one large cluster, a different one per
    // face; candidates lie on the blurred crease, within the reach of a neighbourhood.
    std::map<int, std::map<int, int>> clustersOfFace;
    int candidates = 0;
    for (Eigen::Index i = 0; i < cube.size(); ++i) {
        const double d = distanceToCubeEdge(cube.points.row(i), edge / 2) / p.spacing;
        if (seg.isCandidate(i)) {
            ++candidates;
            EXPECT_LT(d, 3.0) << "candidate far from every edge at point " << i;
        }
        if (d > 4.0) {
            EXPECT_FALSE(seg.isCandidate(i)) << "point " << i;
            ++clustersOfFace[cube.part[i]][seg.cluster[i]];
        }
    }
    EXPECT_GT(candidates, 0);
    std::set<int> faceClusters;
    for (const auto& [face, clusters] : clustersOfFace) {
        EXPECT_EQ(clusters.size(), 1u) << "face " << face << " is split";
        faceClusters.insert(clusters.begin()->first);
    }
    EXPECT_EQ(faceClusters.size(), 6u);

    // Cluster sizes add up and small clusters are exactly those of the candidates.
    long total = 0;
    for (int size : seg.clusterSize) {
        total += size;
    }
    EXPECT_EQ(total, cube.size());
}

TEST(FirstOrderSegmentation, FilletsOfSixSpacingsKeepTheRoundedCubeOnePatch)
{
    // The normals turn by 90 degrees across each fillet, but smoothly: no crease stops the
    // growing, so faces, fillets and corner blends are one cluster.
    const shapes::Sample rounded = shapes::roundedCube(30.0, 6.0, 1.0, 5);
    const Prepared p = prepare(rounded);
    const double radiusInSpacings = 6.0 / p.spacing;
    ASSERT_GE(radiusInSpacings, 6.0);
    const FirstOrderSegmentation seg = segment(rounded, p);
    EXPECT_EQ(largeClusters(seg), 1);
    int candidates = 0;
    for (Eigen::Index i = 0; i < rounded.size(); ++i) {
        candidates += seg.isCandidate(i) ? 1 : 0;
    }
    EXPECT_LT(candidates, rounded.size() / 100) << "at most stray points, no band";
}

TEST(FirstOrderSegmentation, SpreadLimitAndScaleFollowTheNoise)
{
    // A clean plane spreads nothing: the limit is the join angle and the excess is measured at
    // the fine scale (a blend's excess halves there, a crease's stays). Noise of 0.3 spacing
    // raises the limit to about twice its median spread and the excess moves to the full
    // neighbourhood, where the noise's own excess is lower.
    const FirstOrderSegmentationOptions defaults;
    for (double sigma : {0.0, 0.3}) {
        shapes::Sample plane = shapes::plane(40.0, 1.0, 8);
        shapes::addNormalNoise(plane, sigma, 9);
        const Prepared p = prepare(plane);
        const FirstOrderSegmentation seg = segment(plane, p);
        SCOPED_TRACE("noise sigma " + std::to_string(sigma));
        if (sigma == 0.0) {
            EXPECT_DOUBLE_EQ(seg.growAngle, defaults.joinAngle);
            EXPECT_EQ(seg.excessNeighbours, defaults.fineNeighbours);
        } else {
            EXPECT_GT(seg.growAngle, defaults.joinAngle + 2.0);
            EXPECT_LE(seg.growAngle, defaults.growAngle);
            EXPECT_EQ(seg.excessNeighbours, p.neighbours.k());
        }
    }
}

TEST(FirstOrderSegmentation, RidgeOfThirtyFiveDegreesSeparatesItsFaces)
{
    // A house-shaped prism whose ridge turns the normal by 35 degrees: on a clean cloud the
    // two roof faces are separate clusters and the points on the ridge, between them, are
    // candidates (not joined to either face).
    const double w = 15.0, pi = 3.14159265358979323846;
    const double rise = w * std::tan(17.5 * pi / 180.0);
    const shapes::Sample house = shapes::prism(
        {{-w, -15.0}, {w, -15.0}, {w, 10.0}, {0.0, 10.0 + rise}, {-w, 10.0}}, 40.0, 1.0, 2);
    const Prepared p = prepare(house);
    const FirstOrderSegmentation seg = segment(house, p);
    EXPECT_EQ(largeClusters(seg), 7) << "five sides and two caps";
    int onRidge = 0, candidates = 0;
    std::set<int> roofClusters;
    for (Eigen::Index i = 0; i < house.size(); ++i) {
        const Eigen::RowVector3d x = house.points.row(i);
        if (std::abs(x.z()) > 15.0) {
            continue; // away from the caps
        }
        if (std::hypot(x.x(), x.y() - 10.0 - rise) < 0.5 * p.spacing) {
            ++onRidge;
            candidates += seg.isCandidate(i) ? 1 : 0;
        }
        // Roof points away from the ridge and the eaves.
        if ((house.part[i] == 2 || house.part[i] == 3) && std::abs(x.x()) > 5.0 &&
            std::abs(x.x()) < 10.0) {
            roofClusters.insert(seg.cluster[i]);
        }
    }
    ASSERT_GT(onRidge, 10);
    EXPECT_GE(candidates, 0.9 * onRidge);
    EXPECT_EQ(roofClusters.size(), 2u);
}

namespace {

/// Noise of sigma spacings along the true normals (the spacing measured on the clean cloud).
void addNoise(shapes::Sample& s, double sigma, unsigned seed)
{
    shapes::addNormalNoise(s, sigma * meanSpacing(nearestNeighbours(s.points)), seed);
}

} // namespace

TEST(FirstOrderSegmentation, NoisyRidgeOfFortyFiveDegreesKeepsItsPointsAsCandidates)
{
    // A house-shaped prism 50 wide and 60 long whose ridge turns the normal by 45 degrees,
    // noise of 0.3 spacing. Somewhere along the ridge the growing leaks across it and the two
    // roof faces become one cluster, so the cluster rule alone lets most ridge points join a
    // face (only those with no growing neighbour of similar normal stay). The faces of flat
    // points do not leak: the roof stays two faces, and every point that cannot grow between
    // them stays a candidate, at least twice as many and at least 40 % of the ridge (enough
    // for the graph to run a line through).
    const double w = 25.0, pi = 3.14159265358979323846;
    const double ridgeY = 10.0 + w * std::tan(22.5 * pi / 180.0);
    for (unsigned seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        shapes::Sample house = shapes::prism(
            {{-w, -15.0}, {w, -15.0}, {w, 10.0}, {0.0, ridgeY}, {-w, 10.0}}, 60.0, 1.0, seed);
        addNoise(house, 0.3, seed + 20);
        const Prepared p = prepare(house);
        const FirstOrderSegmentation seg = segment(house, p);
        FirstOrderSegmentationOptions clusterRuleOnly;
        clusterRuleOnly.shallowCreaseAngle = 0.0;
        const FirstOrderSegmentation without = segmentByNormals(
            house.points, p.normals.normals, p.neighbours, p.spacing, clusterRuleOnly);

        std::set<int> roofFaces, roofClustersWithout;
        int roof = 0, notFlat = 0, onRidge = 0, with = 0, alone = 0;
        for (Eigen::Index i = 0; i < house.size(); ++i) {
            const Eigen::RowVector3d x = house.points.row(i);
            if (std::abs(x.z()) > 25.0) {
                continue; // away from the caps
            }
            if ((house.part[i] == 2 || house.part[i] == 3) && std::abs(x.x()) > 8.0 &&
                std::abs(x.x()) < 16.0) {
                ++roof;
                if (seg.face[i] < 0) {
                    ++notFlat;
                } else {
                    roofFaces.insert(seg.face[i]);
                }
                roofClustersWithout.insert(without.cluster[i]);
            }
            if (std::hypot(x.x(), x.y() - ridgeY) < p.spacing) {
                ++onRidge;
                with += seg.isCandidate(i) ? 1 : 0;
                alone += without.isCandidate(i) ? 1 : 0;
            }
        }
        EXPECT_EQ(roofFaces.size(), 2u);
        // Noise alone spreads 5 % of a plane's normals beyond noiseSpreadTail.
        EXPECT_LE(notFlat, 0.1 * roof);
        EXPECT_EQ(roofClustersWithout.size(), 1u) << "the growing did not leak this time";
        ASSERT_GT(onRidge, 50);
        EXPECT_GE(with, 0.4 * onRidge);
        EXPECT_GE(with, 2 * alone);
    }
}

TEST(FirstOrderSegmentation, NoisyCylinderAndPlaneGainNoCandidates)
{
    // A cylinder of radius 12 spacings and a plane, noise of 0.3 and 0.5 spacing: where a
    // point cannot grow, the growing points around it join it all round (no two faces of flat
    // points meet there at a crease), so the shallow-crease rule keeps none as a candidate.
    for (double sigma : {0.3, 0.5}) {
        SCOPED_TRACE("noise sigma " + std::to_string(sigma));
        shapes::Sample tube = shapes::cylinder(12.0, 40.0, 1.0, 4);
        addNoise(tube, sigma, 5);
        shapes::Sample plane = shapes::plane(40.0, 1.0, 6);
        addNoise(plane, sigma, 7);
        for (const shapes::Sample* s : {&tube, &plane}) {
            const Prepared p = prepare(*s);
            FirstOrderSegmentationOptions off;
            off.shallowCreaseAngle = 0.0;
            const FirstOrderSegmentation with = segment(*s, p);
            const FirstOrderSegmentation without =
                segmentByNormals(s->points, p.normals.normals, p.neighbours, p.spacing, off);
            int added = 0;
            for (Eigen::Index i = 0; i < s->size(); ++i) {
                added += with.isCandidate(i) && !without.isCandidate(i) ? 1 : 0;
            }
            EXPECT_EQ(added, 0);
        }
    }
}

TEST(FirstOrderSegmentation, SameInputSameClusters)
{
    const shapes::Sample cube = shapes::cube(20.0, 1.0, 7);
    const Prepared p = prepare(cube);
    const FirstOrderSegmentation a = segment(cube, p);
    const FirstOrderSegmentation b = segment(cube, p);
    EXPECT_EQ(a.cluster, b.cluster);
    EXPECT_EQ(a.smallCluster, b.smallCluster);
    EXPECT_EQ(a.face, b.face);
}

TEST(FirstOrderSegmentation, BadInputThrows)
{
    const shapes::Sample plane = shapes::plane(10.0, 1.0, 1);
    const Prepared p = prepare(plane);
    NormalMatrix fewer = p.normals.normals.topRows(plane.size() - 1);
    EXPECT_THROW(segmentByNormals(plane.points, fewer, p.neighbours, p.spacing),
                 std::invalid_argument);
    NormalMatrix broken = p.normals.normals;
    broken(3, 1) = std::nan("");
    EXPECT_THROW(segmentByNormals(plane.points, broken, p.neighbours, p.spacing),
                 std::invalid_argument);
    EXPECT_THROW(segmentByNormals(plane.points, p.normals.normals, p.neighbours, 0.0),
                 std::invalid_argument);
    // Absurd options, one at a time.
    for (const auto& set : std::vector<std::function<void(FirstOrderSegmentationOptions&)>>{
             [](FirstOrderSegmentationOptions& o) { o.growAngle = 0.0; },
             [](FirstOrderSegmentationOptions& o) { o.noiseSpreadFactor = -1.0; },
             [](FirstOrderSegmentationOptions& o) { o.shallowCreaseAngle = 120.0; },
             [](FirstOrderSegmentationOptions& o) { o.minFacePoints = 2; },
             [](FirstOrderSegmentationOptions& o) { o.creaseLineReach = 0.0; }}) {
        FirstOrderSegmentationOptions options;
        set(options);
        EXPECT_THROW(
            segmentByNormals(plane.points, p.normals.normals, p.neighbours, p.spacing, options),
            std::invalid_argument);
    }
}
