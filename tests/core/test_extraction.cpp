// SPDX-License-Identifier: LGPL-2.1-or-later
// The whole method on shapes whose feature lines are known: a cube's twelve edges, a rounded
// cube's fillet borders (Fig. 7 b), a plane, a sphere, an open sheet; and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "FeatureLines/Extraction.h"
#include "SampledShapes.h"

using namespace featurelines;

namespace {

std::vector<const FeatureLine*> linesOf(const ExtractionResult& r, LineType type, int level = -1)
{
    std::vector<const FeatureLine*> out;
    for (const FeatureLine& l : r.lines) {
        if (l.type == type && (level < 0 || l.level == level)) {
            out.push_back(&l);
        }
    }
    return out;
}

// Distance from p to the border of the flat square of the rounded cube's face with the given
// axis and side: the tangent line between that face and its fillets.
double distanceToFlatBorder(const Eigen::RowVector3d& p, int axis, double side, double half,
                            double a)
{
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double du = std::abs(p[u]), dv = std::abs(p[v]);
    // Closest point on the square outline max(|u|, |v|) = a in the plane p[axis] = side * half.
    double cu = std::min(du, a), cv = std::min(dv, a);
    if (std::max(du, dv) < a) {
        (a - du < a - dv) ? cu = a : cv = a;
    }
    return std::sqrt((du - cu) * (du - cu) + (dv - cv) * (dv - cv) +
                     (p[axis] - side * half) * (p[axis] - side * half));
}

TEST(Extraction, CubeGivesTwelveSharpEdgesEnclosingSixFaces)
{
    const shapes::Sample cube = shapes::cube(20.0, 0.5, 11);
    const ExtractionResult r = extractFeatureLines(cube.points);
    EXPECT_EQ(r.countLines(LineType::Sharp), 12);
    EXPECT_EQ(r.countLines(LineType::Boundary), 0) << "a closed surface has no boundary";
    EXPECT_EQ(r.countLines(LineType::Smooth), 0) << "flat faces have no curvature valley";
    EXPECT_EQ(r.junctions.rows(), 8);
    // The sharp lines divide the cube into its six faces (Sec. 1.2: smooth regions).
    ASSERT_EQ(r.regions.size(), 6u);
    std::vector<std::set<int>> facesOfRegion(6);
    for (size_t i = 0; i < cube.part.size(); ++i) {
        if (r.region[i] >= 0) {
            facesOfRegion[r.region[i]].insert(cube.part[i]);
        }
    }
    for (const std::set<int>& faces : facesOfRegion) {
        EXPECT_EQ(faces.size(), 1u) << "a region is one face";
    }
}

// Sec. 2.3, Fig. 7 b: planes | fillets | corners, two thresholds; at the first a closed loop
// around each of the 8 spherical corners, at the second around each of the 6 flat faces, every
// vertex within `tolerance` of its tangent line.
void expectRoundedCubeLoops(const ExtractionResult& r, double edge, double radius, double tolerance)
{
    EXPECT_EQ(r.countLines(LineType::Sharp), 0) << "fillets of radius 12 spacings are smooth";
    ASSERT_EQ(r.regions.size(), 1u);
    ASSERT_EQ(r.regions[0].thresholds.size(), 2u) << "planes | fillets | corners";
    const double tau1 = r.regions[0].thresholds[0], tau2 = r.regions[0].thresholds[1];
    EXPECT_GT(tau1, 1.0 / (2 * radius));
    EXPECT_LT(tau1, 1.0 / radius);
    EXPECT_GT(tau2, 0.0);
    EXPECT_LT(tau2, 1.0 / (2 * radius));

    const double half = edge / 2, a = half - radius;
    // tau1: one closed loop around each of the 8 spherical corners, on the corner|fillet border.
    const auto corners = linesOf(r, LineType::Smooth, 0);
    EXPECT_EQ(corners.size(), 8u);
    for (const FeatureLine* l : corners) {
        EXPECT_TRUE(l->closed);
        const Eigen::RowVector3d c = l->points.colwise().mean();
        const Eigen::RowVector3d centre(std::copysign(a, c.x()), std::copysign(a, c.y()),
                                        std::copysign(a, c.z()));
        for (Eigen::Index i = 0; i < l->points.rows(); ++i) {
            const Eigen::RowVector3d d = l->points.row(i) - centre;
            EXPECT_NEAR(d.norm(), radius, tolerance) << "on the corner sphere";
            EXPECT_LT(d.cwiseAbs().minCoeff(), tolerance) << "on a corner|fillet tangent arc";
        }
    }
    // tau2: one closed loop around each of the 6 flat faces, on the plane|fillet border.
    const auto faces = linesOf(r, LineType::Smooth, 1);
    EXPECT_EQ(faces.size(), 6u);
    for (const FeatureLine* l : faces) {
        EXPECT_TRUE(l->closed);
        const Eigen::RowVector3d c = l->points.colwise().mean();
        Eigen::Index axis;
        c.cwiseAbs().maxCoeff(&axis);
        const double side = c[axis] > 0 ? 1.0 : -1.0;
        for (Eigen::Index i = 0; i < l->points.rows(); ++i) {
            EXPECT_LT(distanceToFlatBorder(l->points.row(i), static_cast<int>(axis), side, half, a),
                      tolerance);
        }
    }
}

/// A rib's cap, open: the profile in the xz plane runs up a wall x = -(w/2 + r) from
/// z = -r - wall to z = -r, round a convex fillet of radius r (centre (-w/2, -r)), along a flat
/// top z = 0 of width w, round a second fillet and down the other wall; extruded over
/// y in [-length/2, length/2]. Jittered grid of the given spacing in (arc length, y), as the
/// shapes of SampledShapes.h. Smooth edges: four lines along y, at (x, z) = (+-w/2, 0) and
/// (+-(w/2 + r), -r).
shapes::Sample ribCap(double w, double r, double wall, double length, double h, unsigned seed)
{
    const double pi = std::acos(-1.0);
    const double arc = pi / 2 * r;
    const double profile = 2 * wall + 2 * arc + w;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    const int nu = static_cast<int>(std::lround(profile / h));
    const int ny = static_cast<int>(std::lround(length / h));
    shapes::Sample s;
    s.points.resize(nu * ny, 3);
    s.normals.resize(nu * ny, 3);
    s.meanCurvature.resize(nu * ny);
    s.part.resize(static_cast<size_t>(nu * ny));
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nu; ++i) {
            const double u = (i + 0.5 + jitter(rng)) * profile / nu;
            const double y = (j + 0.5 + jitter(rng)) * length / ny - length / 2;
            // Unfold the profile from its middle, which is symmetric: t >= 0 on the right half.
            const double t = std::abs(u - profile / 2);
            const double side = u < profile / 2 ? -1.0 : 1.0;
            double x, z, nx, nz;
            int part;
            if (t <= w / 2) {
                x = t, z = 0, nx = 0, nz = 1, part = 0;
            } else if (t <= w / 2 + arc) {
                const double phi = (t - w / 2) / r; // 0 at the top, pi/2 at the wall
                nx = std::sin(phi), nz = std::cos(phi);
                x = w / 2 + r * nx, z = -r + r * nz, part = 1;
            } else {
                x = w / 2 + r, z = -r - (t - w / 2 - arc), nx = 1, nz = 0, part = 2;
            }
            const int p = j * nu + i;
            s.points.row(p) << side * x, y, z;
            s.normals.row(p) << side * nx, 0.0, nz;
            s.meanCurvature[p] = part == 1 ? 1.0 / (2 * r) : 0.0;
            s.part[static_cast<size_t>(p)] = part;
        }
    }
    return s;
}

} // namespace

TEST(Extraction, RoundedCubeGivesCornerLoopsAndFaceLoopsAtTwoThresholds)
{
    const double edge = 40.0, radius = 6.0, h = 0.5;
    const shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    expectRoundedCubeLoops(extractFeatureLines(s.points), edge, radius, 3 * h);
}

TEST(Extraction, RoundedCubePatchesAreItsFacesItsCornersAndOneFilletNetwork)
{
    // Two thresholds cut the curvature into three levels: the six flat faces (|H| = 0) apart,
    // the eight corners (|H| = 1/r) apart, and the twelve fillets (|H| = 1/(2r)), which meet
    // each other around every corner, one connected piece.
    const double edge = 40.0, radius = 6.0, h = 0.5;
    const shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
    const ExtractionResult r = extractFeatureLines(s.points);
    ASSERT_EQ(r.regions.size(), 1u);
    ASSERT_EQ(r.regions[0].thresholds.size(), 2u);
    std::map<int, std::array<int, 3>> partsOfPatch; // points per part (flat, fillet, corner)
    for (size_t i = 0; i < r.patch.size(); ++i) {
        ASSERT_GE(r.patch[i], 0) << "point " << i;
        ++partsOfPatch[r.patch[i]][static_cast<size_t>(s.part[i])];
    }
    // A face's points; its patch loses a rim about one fit radius wide to the fillets' (where
    // the fit's blur lifts the curvature over the lower threshold): (56 - 4)^2 of 56^2 points
    // is 0.86 of them.
    const double facePoints = std::count(s.part.begin(), s.part.end(), 0) / 6.0;
    int flat = 0, fillet = 0, corner = 0;
    for (const auto& [patch, count] : partsOfPatch) {
        const int total = count[0] + count[1] + count[2];
        if (count[0] == total) {
            ++flat;
            EXPECT_GT(total, 0.85 * facePoints) << "patch " << patch;
            EXPECT_LE(total, facePoints + 1) << "patch " << patch;
        } else if (count[2] > total / 2) {
            ++corner;
        } else if (count[1] > total / 2) {
            ++fillet;
            EXPECT_GT(count[1], 0.95 * std::count(s.part.begin(), s.part.end(), 1));
        } else {
            ADD_FAILURE() << "patch " << patch << " mixes the parts: " << count[0] << " flat, "
                          << count[1] << " fillet, " << count[2] << " corner points";
        }
    }
    EXPECT_EQ(flat, 6);
    EXPECT_EQ(corner, 8);
    EXPECT_EQ(fillet, 1);
}

TEST(Extraction, NoisyRoundedCubeGivesTheSameClosedLoops)
{
    // Noise of 0.3 spacing along the normal: the region is smoothed, its curvature averaged,
    // and both valleys stand 4 noise floors clear of the noise (Sec. 2.4).
    const double edge = 40.0, radius = 6.0, h = 0.5;
    for (unsigned seed : {5u, 6u}) {
        shapes::Sample s = shapes::roundedCube(edge, radius, h, seed);
        shapes::addNormalNoise(s, 0.3 * h, seed + 10);
        const ExtractionResult r = extractFeatureLines(s.points);
        ASSERT_EQ(r.regions.size(), 1u);
        EXPECT_TRUE(r.regions[0].smoothed);
        expectRoundedCubeLoops(r, edge, radius, 3 * h);
    }
}

// Sec. 4, Fig. 9: two fillets close to each other. A flat of 6 spacings between two fillets of
// radius 10 spacings, walls beside them: all four borders, each a line along the whole cap
// that ends on the boundary at both ends (Sec. 1.2), clean and with noise of 0.3 spacing.
TEST(Extraction, CloseFilletsGiveAllFourBordersEndingOnTheBoundary)
{
    const double h = 0.5, w = 6 * h, r = 10 * h, length = 80 * h;
    const double truthX[4] = {-w / 2, w / 2, -(w / 2 + r), w / 2 + r};
    const double truthZ[4] = {0.0, 0.0, -r, -r};
    for (double noise : {0.0, 0.3 * h}) {
        shapes::Sample s = ribCap(w, r, 16 * h, length, h, 3);
        if (noise > 0.0) {
            shapes::addNormalNoise(s, noise, 4);
        }
        const ExtractionResult r0 = extractFeatureLines(s.points);
        EXPECT_EQ(r0.countLines(LineType::Sharp), 0) << "noise " << noise;
        const auto smooth = linesOf(r0, LineType::Smooth);
        ASSERT_EQ(smooth.size(), 4u) << "noise " << noise;
        const auto boundary = linesOf(r0, LineType::Boundary);
        std::set<int> found;
        for (const FeatureLine* l : smooth) {
            // The true border nearest to the line's middle vertex; every vertex near it.
            const Eigen::RowVector3d m = l->points.row(l->points.rows() / 2);
            int nearest = 0;
            for (int t = 1; t < 4; ++t) {
                if (std::hypot(m.x() - truthX[t], m.z() - truthZ[t]) <
                    std::hypot(m.x() - truthX[nearest], m.z() - truthZ[nearest])) {
                    nearest = t;
                }
            }
            found.insert(nearest);
            for (Eigen::Index i = 0; i < l->points.rows(); ++i) {
                EXPECT_LT(std::hypot(l->points(i, 0) - truthX[nearest],
                                     l->points(i, 2) - truthZ[nearest]),
                          3 * h)
                    << "noise " << noise;
            }
            // Both ends on the boundary, a spacing or two inside the rim of the sheet.
            for (Eigen::Index end : {Eigen::Index(0), l->points.rows() - 1}) {
                const Eigen::RowVector3d e = l->points.row(end);
                double toBoundary = std::numeric_limits<double>::infinity();
                for (const FeatureLine* b : boundary) {
                    for (Eigen::Index i = 0; i < b->points.rows(); ++i) {
                        toBoundary = std::min(toBoundary, (b->points.row(i) - e).norm());
                    }
                }
                EXPECT_LT(toBoundary, 1.0 * h) << "noise " << noise;
                EXPECT_GT(std::abs(e.y()), length / 2 - 3 * h) << "noise " << noise;
            }
        }
        EXPECT_EQ(found.size(), 4u) << "every border found, noise " << noise;
    }
}

// Issue 17 item 4: the borders of the same cap on the curvature step. The levels alone put a
// line on the last labelled point, up to a spacing off; the fit of the step across it (at the
// cloud's own scale, SmoothEdgeOptions::placeOwnScaleLines) puts the middle half of each line
// within a quarter spacing of its border, clean.
TEST(Extraction, CloseFilletsBordersLieOnTheCurvatureStep)
{
    const double h = 0.5, w = 6 * h, r = 10 * h, length = 80 * h;
    const double truthX[4] = {-w / 2, w / 2, -(w / 2 + r), w / 2 + r};
    const double truthZ[4] = {0.0, 0.0, -r, -r};
    const shapes::Sample s = ribCap(w, r, 16 * h, length, h, 3);
    auto medianOffset = [&](const ExtractionOptions& options) {
        const ExtractionResult result = extractFeatureLines(s.points, options);
        std::vector<double> offsets;
        for (const FeatureLine* l : linesOf(result, LineType::Smooth)) {
            for (Eigen::Index i = 0; i < l->points.rows(); ++i) {
                if (std::abs(l->points(i, 1)) > length / 4) {
                    continue; // the ends run to the boundary
                }
                double nearest = std::numeric_limits<double>::infinity();
                for (int t = 0; t < 4; ++t) {
                    nearest = std::min(nearest, std::hypot(l->points(i, 0) - truthX[t],
                                                           l->points(i, 2) - truthZ[t]));
                }
                offsets.push_back(nearest);
            }
        }
        EXPECT_GT(offsets.size(), 4u * 40u * 0.8) << "four borders of 40 spacings each";
        std::nth_element(offsets.begin(), offsets.begin() + offsets.size() / 2, offsets.end());
        return offsets[offsets.size() / 2] / h;
    };
    EXPECT_LT(medianOffset({}), 0.25);
    ExtractionOptions levelsOnly;
    levelsOnly.smooth.placeOwnScaleLines = false;
    EXPECT_GT(medianOffset(levelsOnly), 0.25) << "the levels alone leave the lines off the step";
}

TEST(Extraction, NoisyCubeStillGivesTwelveSharpEdges)
{
    shapes::Sample cube = shapes::cube(20.0, 0.5, 3);
    shapes::addNormalNoise(cube, 0.3 * 0.5, 4);
    const ExtractionResult r = extractFeatureLines(cube.points);
    EXPECT_EQ(r.countLines(LineType::Sharp), 12);
    EXPECT_EQ(r.junctions.rows(), 8);
    EXPECT_EQ(r.countLines(LineType::Smooth), 0) << "noise on a plane is no patch";
    // One network on the edges (issue 17): every line ends on a junction; 95 % of the vertices
    // lie within half a spacing of the cube's nearest edge and all within one (the faces'
    // planes read from their normals, which noise of 0.3 spacing tilts far less than it tilts
    // a narrow strip's positions: read from the positions, 1.6 spacings).
    const double half = 10.0, spacing = 0.5;
    double farthest = 0.0;
    int vertices = 0, within = 0;
    for (const FeatureLine& line : r.lines) {
        ASSERT_FALSE(line.closed);
        for (const Eigen::Index end : {Eigen::Index(0), line.points.rows() - 1}) {
            double nearest = std::numeric_limits<double>::infinity();
            for (Eigen::Index j = 0; j < r.junctions.rows(); ++j) {
                nearest = std::min(nearest, (r.junctions.row(j) - line.points.row(end)).norm());
            }
            EXPECT_LT(nearest, 1e-9);
        }
        for (Eigen::Index v = 0; v < line.points.rows(); ++v) {
            std::array<double, 3> off;
            for (int c = 0; c < 3; ++c) {
                off[c] = std::abs(std::abs(line.points(v, c)) - half);
            }
            std::sort(off.begin(), off.end());
            const double d = std::hypot(off[0], off[1]);
            farthest = std::max(farthest, d);
            ++vertices;
            within += d <= 0.5 * spacing ? 1 : 0;
        }
    }
    EXPECT_GE(within, 0.95 * vertices) << within << " of " << vertices;
    EXPECT_LE(farthest, spacing);
}

TEST(Extraction, SphereHasNoFeatureLines)
{
    const shapes::Sample sphere = shapes::sphere(10.0, 0.4, 2);
    const ExtractionResult r = extractFeatureLines(sphere.points);
    EXPECT_TRUE(r.lines.empty());
    ASSERT_EQ(r.regions.size(), 1u);
    EXPECT_TRUE(r.regions[0].thresholds.empty()) << "one curvature level, no valley";
}

TEST(Extraction, OpenPlaneGivesItsBoundaryOnly)
{
    const shapes::Sample plane = shapes::plane(20.0, 0.5, 9);
    const ExtractionResult r = extractFeatureLines(plane.points);
    EXPECT_EQ(r.countLines(LineType::Sharp), 0);
    EXPECT_EQ(r.countLines(LineType::Smooth), 0);
    ASSERT_EQ(r.countLines(LineType::Boundary), 1);
    const FeatureLine& b = *linesOf(r, LineType::Boundary)[0];
    EXPECT_TRUE(b.closed);
    for (Eigen::Index i = 0; i < b.points.rows(); ++i) {
        const double rim = std::max(std::abs(b.points(i, 0)), std::abs(b.points(i, 1)));
        EXPECT_NEAR(rim, 10.0, 1.5) << "on the square's rim";
    }

    ExtractionOptions noBoundary;
    noBoundary.sharp.includeBoundary = false;
    EXPECT_TRUE(extractFeatureLines(plane.points, noBoundary).lines.empty());
}

TEST(Extraction, ExplicitThresholdsAreAppliedAsGiven)
{
    const shapes::Sample s = shapes::roundedCube(40.0, 6.0, 0.5, 8);
    ExtractionOptions options;
    options.thresholdMode = ThresholdMode::Explicit;
    options.thresholds = {0.75 / 6.0}; // between fillets (1/12) and corners (1/6)
    const ExtractionResult r = extractFeatureLines(s.points, options);
    ASSERT_EQ(r.regions.size(), 1u);
    ASSERT_EQ(r.regions[0].thresholds.size(), 1u);
    EXPECT_DOUBLE_EQ(r.regions[0].thresholds[0], 0.75 / 6.0);
    EXPECT_EQ(r.countLines(LineType::Smooth), 8) << "one loop per corner";
}

TEST(Extraction, DuplicatesAreMergedAndReportedPerInputPoint)
{
    const shapes::Sample cube = shapes::cube(20.0, 0.5, 1);
    PointMatrix doubled(2 * cube.points.rows(), 3);
    doubled << cube.points, cube.points;
    const ExtractionResult r = extractFeatureLines(doubled);
    EXPECT_EQ(r.countLines(LineType::Sharp), 12);
    ASSERT_EQ(r.region.size(), static_cast<size_t>(doubled.rows()));
    for (Eigen::Index i = 0; i < cube.points.rows(); ++i) {
        EXPECT_EQ(r.region[i], r.region[i + cube.points.rows()]);
    }
}

// The cloud is put into a canonical spatial order first (CloudGeometry::points), so the order
// of the input rows changes nothing: the same lines, junctions, regions and thresholds, and the
// same values per point, on a cube (sharp edges, six regions) and a noisy rounded cube
// (smoothing, two thresholds, patches), duplicates included.
TEST(Extraction, TheInputOrderDoesNotChangeTheResult)
{
    shapes::Sample cube = shapes::cube(20.0, 0.5, 3);
    shapes::addNormalNoise(cube, 0.3 * 0.5, 4);
    shapes::Sample rounded = shapes::roundedCube(40.0, 6.0, 0.5, 5);
    shapes::addNormalNoise(rounded, 0.3 * 0.5, 15);
    for (const PointMatrix* cloud : {&cube.points, &rounded.points}) {
        PointMatrix P(cloud->rows() + 100, 3);
        P << *cloud, cloud->topRows(100);
        std::vector<int> shuffled(static_cast<size_t>(P.rows()));
        std::iota(shuffled.begin(), shuffled.end(), 0);
        std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
        PointMatrix Q(P.rows(), 3); // row r of Q is row shuffled[r] of P
        for (Eigen::Index r = 0; r < Q.rows(); ++r) {
            Q.row(r) = P.row(shuffled[static_cast<size_t>(r)]);
        }
        const ExtractionResult a = extractFeatureLines(P);
        const ExtractionResult b = extractFeatureLines(Q);
        ASSERT_GT(a.lines.size(), 0u);
        ASSERT_EQ(a.lines.size(), b.lines.size());
        for (size_t l = 0; l < a.lines.size(); ++l) {
            EXPECT_EQ(a.lines[l].type, b.lines[l].type);
            EXPECT_EQ(a.lines[l].closed, b.lines[l].closed);
            EXPECT_EQ(a.lines[l].region, b.lines[l].region);
            EXPECT_EQ(a.lines[l].startJunction, b.lines[l].startJunction);
            EXPECT_EQ(a.lines[l].endJunction, b.lines[l].endJunction);
            EXPECT_TRUE(a.lines[l].points == b.lines[l].points) << "line " << l;
        }
        EXPECT_TRUE(a.junctions == b.junctions);
        EXPECT_EQ(a.spacing, b.spacing);
        ASSERT_EQ(a.regions.size(), b.regions.size());
        for (size_t g = 0; g < a.regions.size(); ++g) {
            EXPECT_EQ(a.regions[g].points, b.regions[g].points);
            EXPECT_EQ(a.regions[g].thresholds, b.regions[g].thresholds);
        }
        for (Eigen::Index r = 0; r < Q.rows(); ++r) {
            const size_t i = static_cast<size_t>(shuffled[static_cast<size_t>(r)]);
            const size_t j = static_cast<size_t>(r);
            ASSERT_EQ(a.region[i], b.region[j]);
            ASSERT_EQ(a.patch[i], b.patch[j]);
            ASSERT_EQ(a.label[i], b.label[j]);
            ASSERT_TRUE(a.curvature[i] == b.curvature[j] ||
                        (std::isnan(a.curvature[i]) && std::isnan(b.curvature[j])));
        }
    }
}

TEST(Extraction, CancelStopsTheRun)
{
    const shapes::Sample cube = shapes::cube(10.0, 0.5, 1);
    ExtractionOptions options;
    options.progress = [](double done, const std::string&) { return done < 0.35; };
    EXPECT_THROW(extractFeatureLines(cube.points, options), ExtractionCancelled);
}

TEST(Extraction, BadCloudsAreRefusedWithAMessage)
{
    auto message = [](const PointMatrix& P) -> std::string {
        try {
            extractFeatureLines(P);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(message(PointMatrix(0, 3)).find("points"), std::string::npos);

    PointMatrix tiny = shapes::plane(2.0, 0.5, 1).points.topRows(10);
    EXPECT_NE(message(tiny).find("at least 17"), std::string::npos);

    PointMatrix line(100, 3);
    for (int i = 0; i < 100; ++i) {
        line.row(i) << i * 0.1, 2 * i * 0.1, 0.0;
    }
    EXPECT_NE(message(line).find("line"), std::string::npos);
    // A long line far from the origin: its moments are summed in many blocks.
    PointMatrix farLine(100000, 3);
    for (int i = 0; i < 100000; ++i) {
        farLine.row(i) << 1e5 + i * 0.01, -3e4 - i * 0.02, 7e4 + i * 0.005;
    }
    EXPECT_NE(message(farLine).find("points lie on a line"), std::string::npos);

    PointMatrix same = PointMatrix::Ones(500, 3);
    EXPECT_NE(message(same).find("distinct"), std::string::npos);

    PointMatrix nan = shapes::plane(5.0, 0.5, 1).points;
    nan(7, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(message(nan).find("point 8"), std::string::npos);
}

TEST(Extraction, SmoothLinesCarryTheRadiusOfTheirBlend)
{
    // Fillets and spherical corners of radius 6 (12 spacings): the corner loops border the
    // spheres (principal curvatures 1/6 twice), the face loops the fillets (1/6 and 0); both
    // give the radius 6, clean and with noise of 0.3 spacing.
    const double edge = 40.0, radius = 6.0, h = 0.5;
    for (double noise : {0.0, 0.3 * h}) {
        shapes::Sample s = shapes::roundedCube(edge, radius, h, 5);
        if (noise > 0.0) {
            shapes::addNormalNoise(s, noise, 15);
        }
        const ExtractionResult r = extractFeatureLines(s.points);
        ASSERT_EQ(r.countLines(LineType::Smooth), 14) << "noise " << noise;
        for (const FeatureLine* line : linesOf(r, LineType::Smooth)) {
            EXPECT_GT(line->blendRadius, 0.75 * radius) << "noise " << noise;
            EXPECT_LT(line->blendRadius, 1.3 * radius) << "noise " << noise;
        }
    }
}

TEST(Extraction, NoBlendRadiusOnSharpOrBoundaryLines)
{
    const shapes::Sample cube = shapes::cube(20.0, 0.5, 3);
    const shapes::Sample plane = shapes::plane(20.0, 0.5, 9);
    for (const shapes::Sample* s : {&cube, &plane}) {
        const ExtractionResult r = extractFeatureLines(s->points);
        ASSERT_FALSE(r.lines.empty());
        for (const FeatureLine& line : r.lines) {
            EXPECT_NE(line.type, LineType::Smooth);
            EXPECT_TRUE(std::isnan(line.blendRadius));
        }
    }
}
