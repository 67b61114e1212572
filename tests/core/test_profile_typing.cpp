// SPDX-License-Identifier: LGPL-2.1-or-later
// Typing by profile on an L of two perpendicular faces joined by a crease or by a round of
// radius r: the round's sharp line becomes its two tangent lines, r is estimated, the crease
// stays one sharp line whose angle is 90 degrees; a narrow third face on one side is no blend;
// a round under 1.2 spacings is one smooth line; the rounded nose of an acute wedge gives its
// borders; a round at the foot of a thin wall, whose far foot crowds the profile, still gives
// its borders; the other sheet of a thin wall is no face.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "FeatureLines/sharp/ProfileTyping.h"
#include "FeatureLines/sharp/SharpEdges.h"

using namespace featurelines;

namespace {

/// A profile in the (y, z) plane swept along x from 0 to `length`, sampled one spacing apart
/// in x and along the profile.
struct Swept
{
    PointMatrix P;
    FirstOrderSegmentation seg;
    LineNetwork network;
};

/// The swept cloud of `points` (each in cluster `cluster[i]`; clusters 0, 1 and 3 are faces,
/// 2 is the small cluster between them) with the sharp stage's line along x through `line` in
/// (y, z), one spacing apart, from x = 0 to `length`.
Swept swept(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& cluster,
            double length, const Eigen::Vector2d& line)
{
    Swept s;
    s.P.resize(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        s.P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    s.seg.cluster = cluster;
    s.seg.clusterSize = {0, 0, 0, 0};
    for (int c : s.seg.cluster) {
        ++s.seg.clusterSize[c];
    }
    s.seg.smallCluster = {0, 0, 1, 0};
    Polyline l;
    const int m = static_cast<int>(length) + 1;
    l.points.resize(m, 3);
    for (int x = 0; x < m; ++x) {
        l.points.row(x) << x, line.x(), line.y();
    }
    l.label = sharpLineLabel;
    s.network.lines.push_back(l);
    s.network.junctions.resize(0, 3);
    return s;
}

/// `profile` swept along x, one spacing apart, each profile point in its cluster (0: face A,
/// z = 0; 1: face B, y = 0; 2: the small cluster between them). `noise` moves the faces'
/// points along their normals (a seeded normal distribution); the sharp stage's line runs
/// along the corner (y = z = 0).
Swept sweep(const std::vector<Eigen::Vector2d>& profile, const std::vector<int>& cluster,
            double length, double noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::vector<Eigen::Vector3d> points;
    std::vector<int> clusters;
    for (int x = 0; x <= static_cast<int>(length); ++x) {
        for (size_t i = 0; i < profile.size(); ++i) {
            // Normals of the faces: z for face A, y for face B, none added on the cut.
            Eigen::Vector3d p(x, profile[i].x(), profile[i].y());
            if (noise > 0.0) {
                const double d = noise * gauss(rng);
                if (cluster[i] == 0) {
                    p.z() += d;
                } else if (cluster[i] == 1) {
                    p.y() += d;
                }
            }
            points.push_back(p);
            clusters.push_back(cluster[i]);
        }
    }
    return swept(points, clusters, length, Eigen::Vector2d::Zero());
}

/// A piece of a profile: a polyline in (y, z) and its cluster.
struct Piece
{
    std::vector<Eigen::Vector2d> points;
    int cluster;
};

/// The pieces swept along x, one spacing apart, each sampled one spacing apart along its
/// length from an offset that moves by the golden ratio's fraction from one x to the next:
/// across the slices every part of a narrow round is sampled, as in a scanned cloud, where a
/// regular grid would only ever sample the same few places.
Swept staggered(const std::vector<Piece>& pieces, double length, const Eigen::Vector2d& line)
{
    std::vector<Eigen::Vector3d> points;
    std::vector<int> clusters;
    for (int x = 0; x <= static_cast<int>(length); ++x) {
        const double offset = std::fmod(0.6180339887 * x, 1.0);
        for (const Piece& piece : pieces) {
            double at = offset;
            for (size_t k = 1; k < piece.points.size(); ++k) {
                const Eigen::Vector2d a = piece.points[k - 1];
                const double step = (piece.points[k] - a).norm();
                for (; at < step; at += 1.0) {
                    const Eigen::Vector2d q = a + (piece.points[k] - a) * (at / step);
                    points.emplace_back(x, q.x(), q.y());
                    clusters.push_back(piece.cluster);
                }
                at -= step;
            }
        }
    }
    return swept(points, clusters, length, line);
}

/// A circular arc of radius r about `centre` from angle t0 to t1 (radians), as a fine polyline.
std::vector<Eigen::Vector2d> arc(const Eigen::Vector2d& centre, double r, double t0, double t1)
{
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i <= 100; ++i) {
        const double t = t0 + (t1 - t0) * i / 100.0;
        points.push_back(centre + r * Eigen::Vector2d(std::cos(t), std::sin(t)));
    }
    return points;
}

/// Face A from y = -12 to -r, a quarter circle of radius r to (0, r), face B up to z = 12; the
/// round's points are the small cluster.
Swept roundedL(double r, double length, double noise = 0.0, unsigned seed = 1)
{
    std::vector<Eigen::Vector2d> profile;
    std::vector<int> cluster;
    auto add = [&](double y, double z, int face) {
        profile.emplace_back(y, z);
        cluster.push_back(face);
    };
    for (double y = -12.0; y < -r; y += 1.0) {
        add(y, 0.0, 0);
    }
    const int arcSteps = std::max(1, static_cast<int>(std::round(r * M_PI / 2.0)));
    for (int i = 0; i <= arcSteps && r > 0.0; ++i) {
        const double t = -M_PI / 2.0 + (M_PI / 2.0) * i / arcSteps;
        add(-r + r * std::cos(t), r + r * std::sin(t), 2);
    }
    for (double z = r + 1.0; z <= 12.0; z += 1.0) {
        add(0.0, z, 1);
    }
    return sweep(profile, cluster, length, noise, seed);
}

/// The distance from p to the line along x through (y0, z0).
double offLine(const Eigen::RowVector3d& p, double y0, double z0)
{
    return std::hypot(p(1) - y0, p(2) - z0);
}

/// `t`'s lines are two blend borders along x, one on face A at y = -r, the other on face B at
/// z = r, each within a quarter spacing over x in [8, 32] (away from the ends, where the
/// borders run to the sharp line's end points).
void expectBordersOnTheFaces(const ProfileTyping& t, double r)
{
    int onA = 0;
    int onB = 0;
    for (const Polyline& border : t.network.lines) {
        EXPECT_EQ(border.label, blendBorderLabel);
        double a = 0.0;
        double b = 0.0;
        int inner = 0;
        for (Eigen::Index i = 0; i < border.points.rows(); ++i) {
            const Eigen::RowVector3d p = border.points.row(i);
            if (p(0) < 8.0 || p(0) > 32.0) {
                continue;
            }
            a = std::max(a, offLine(p, -r, 0.0));
            b = std::max(b, offLine(p, 0.0, r));
            ++inner;
        }
        ASSERT_GT(inner, 20);
        onA += a < 0.25 ? 1 : 0;
        onB += b < 0.25 ? 1 : 0;
    }
    EXPECT_EQ(onA, 1);
    EXPECT_EQ(onB, 1);
}

TEST(ProfileTyping, RoundOfThreeSpacingsBecomesItsTwoTangentLines)
{
    const double r = 3.0;
    const Swept s = roundedL(r, 40.0);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 2u);
    ASSERT_EQ(t.profiles.size(), 2u);
    EXPECT_TRUE(t.profiles[0].blend);
    EXPECT_NEAR(t.profiles[0].radius, r, 0.3);
    EXPECT_NEAR(t.profiles[0].angle, 90.0, 2.0);
    expectBordersOnTheFaces(t, r);
}

TEST(ProfileTyping, RoundOfTwoSpacingsIsStillTwoBorders)
{
    const Swept s = roundedL(2.0, 40.0);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 2u);
    EXPECT_TRUE(t.profiles[0].blend);
    EXPECT_NEAR(t.profiles[0].radius, 2.0, 0.3);
}

TEST(ProfileTyping, CreaseStaysOneSharpLineWithItsAngle)
{
    const Swept s = roundedL(0.0, 40.0);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_EQ(t.network.lines[0].label, sharpLineLabel);
    EXPECT_FALSE(t.profiles[0].blend);
    EXPECT_NEAR(t.profiles[0].angle, 90.0, 1.0);
    EXPECT_LT(t.profiles[0].radius, 0.5);
    EXPECT_TRUE(t.network.lines[0].points.isApprox(s.network.lines[0].points));
}

TEST(ProfileTyping, NoiseOfAThirdSpacingKeepsBothAnswers)
{
    const Swept round = roundedL(3.0, 40.0, 0.3, 7);
    const ProfileTyping a = typeByProfile(round.P, {}, round.seg, {}, round.network, 1.0);
    ASSERT_EQ(a.network.lines.size(), 2u);
    EXPECT_NEAR(a.profiles[0].radius, 3.0, 0.6);
    const Swept crease = roundedL(0.0, 40.0, 0.3, 7);
    const ProfileTyping b = typeByProfile(crease.P, {}, crease.seg, {}, crease.network, 1.0);
    ASSERT_EQ(b.network.lines.size(), 1u);
    EXPECT_FALSE(b.profiles[0].blend);
    EXPECT_NEAR(b.profiles[0].angle, 90.0, 3.0);
}

TEST(ProfileTyping, NarrowThirdFaceOnOneSideIsNoBlend)
{
    // Face A stops at y = -1; a third face from there to (0, 3) on face B: a cut set back one
    // spacing on A and three on B, which a round fits too but a flat cut fits far better.
    std::vector<Eigen::Vector2d> profile;
    std::vector<int> cluster;
    for (double y = -12.0; y <= -1.0; y += 1.0) {
        profile.emplace_back(y, 0.0);
        cluster.push_back(y < -2.0 ? 0 : 2);
    }
    for (double t = 0.25; t < 1.0; t += 0.25) {
        profile.emplace_back(-1.0 + t, 3.0 * t);
        cluster.push_back(2);
    }
    for (double z = 3.0; z <= 12.0; z += 1.0) {
        profile.emplace_back(0.0, z);
        cluster.push_back(z > 4.0 ? 1 : 2);
    }
    const Swept s = sweep(profile, cluster, 40.0, 0.0, 1);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_FALSE(t.profiles[0].blend);
    EXPECT_EQ(t.network.lines[0].label, sharpLineLabel);
    // The flat cut was found where it is.
    EXPECT_NEAR(t.profiles[0].setback[0], 1.0, 0.5);
    EXPECT_NEAR(t.profiles[0].setback[1], 3.0, 0.5);
}

TEST(ProfileTyping, SplitBlendsOffKeepsTheLineButMeasuresIt)
{
    const Swept s = roundedL(3.0, 40.0);
    ProfileTypingOptions o;
    o.splitBlends = false;
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0, o);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_FALSE(t.profiles[0].blend);
    EXPECT_NEAR(t.profiles[0].radius, 3.0, 0.3);
}

TEST(ProfileTyping, FacesOfOneClusterAreToldApartByTheirNormals)
{
    // Noise can let the region growing run round a blend, so that both faces are one cluster:
    // the faces are then the cluster's two groups of normals.
    Swept s = roundedL(3.0, 40.0);
    NormalMatrix normals(s.P.rows(), 3);
    for (Eigen::Index i = 0; i < s.P.rows(); ++i) {
        const int c = s.seg.cluster[i];
        normals.row(i) = c == 0   ? Eigen::RowVector3d(0, 0, 1)
                         : c == 1 ? Eigen::RowVector3d(0, 1, 0)
                                  : Eigen::RowVector3d(0, 1, -1).normalized();
        if (c == 1) {
            s.seg.cluster[i] = 0;
        }
    }
    s.seg.clusterSize = {s.seg.clusterSize[0] + s.seg.clusterSize[1], 0, s.seg.clusterSize[2]};
    // Without the normals, no station fits two faces (the one cluster's plane passes off the
    // line: the line is not even kept unless asked).
    ProfileTypingOptions keep;
    keep.minFaceShare = 0.0;
    EXPECT_EQ(typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0, keep).profiles[0].stations, 0);
    EXPECT_TRUE(typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0).network.lines.empty());
    const ProfileTyping t = typeByProfile(s.P, normals, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 2u);
    EXPECT_NEAR(t.profiles[0].radius, 3.0, 0.3);
}

/// Face A along z = 0 from y = -12, a quarter round of radius r, face B along y = 0 up to
/// z = 12 (r = 0: a crease), staggered.
Swept staggeredL(double r)
{
    std::vector<Piece> pieces = {{{{-12.0, 0.0}, {-r, 0.0}}, 0}, {{{0.0, r}, {0.0, 12.0}}, 1}};
    if (r > 0.0) {
        pieces.push_back({arc({-r, r}, r, -M_PI / 2.0, 0.0), 2});
    }
    return staggered(pieces, 40.0, Eigen::Vector2d::Zero());
}

TEST(ProfileTyping, RoundTooNarrowForTwoBordersIsOneSmoothLineWithItsRadius)
{
    // A round of 0.9 spacing departs from the crease by 0.37 spacing: the profile sees it, but
    // its borders would lie 1.3 spacings apart.
    const Swept s = staggeredL(0.9);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_EQ(t.network.lines[0].label, blendBorderLabel);
    EXPECT_TRUE(t.profiles[0].blend);
    EXPECT_TRUE(t.profiles[0].narrow);
    EXPECT_NEAR(t.profiles[0].radius, 0.9, 0.3);
    EXPECT_TRUE(t.network.lines[0].points.isApprox(s.network.lines[0].points));
    // The same sampling of a crease stays one sharp line.
    const Swept c = staggeredL(0.0);
    const ProfileTyping u = typeByProfile(c.P, {}, c.seg, {}, c.network, 1.0);
    ASSERT_EQ(u.network.lines.size(), 1u);
    EXPECT_EQ(u.network.lines[0].label, sharpLineLabel);
    EXPECT_FALSE(u.profiles[0].blend);
}

TEST(ProfileTyping, RoundedNoseOfAnAcuteWedgeGivesItsTwoBorders)
{
    // Faces 25 degrees apart joined by a round of 2 spacings: the apex lies 7 spacings beyond
    // the nose, on which the sharp stage's line runs, and the tangent points 9 from the apex.
    const double opening = 25.0 * M_PI / 180.0;
    const double r = 2.0;
    const Eigen::Vector2d u0(-1.0, 0.0);
    const Eigen::Vector2d u1(-std::cos(opening), std::sin(opening));
    const Eigen::Vector2d bisector = (u0 + u1).normalized();
    const Eigen::Vector2d centre = bisector * (r / std::sin(opening / 2.0));
    const double t = r / std::tan(opening / 2.0);
    const Eigen::Vector2d nose = centre - r * bisector;
    std::vector<Piece> pieces = {{{u0 * (t + 12.0), u0 * t}, 0}, {{u1 * t, u1 * (t + 12.0)}, 1}};
    // The round from face A's tangent point (straight below the centre) over the nose to face
    // B's, turning by 180 degrees less the opening.
    pieces.push_back({arc(centre, r, -M_PI / 2.0, M_PI / 2.0 - opening), 2});
    const Swept s = staggered(pieces, 40.0, nose);
    const ProfileTyping typed = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    EXPECT_NEAR(typed.profiles[0].angle, 25.0, 2.0);
    EXPECT_NEAR(typed.profiles[0].radius, r, 0.3);
    ASSERT_EQ(typed.network.lines.size(), 2u);
    EXPECT_TRUE(typed.profiles[0].blend);
    EXPECT_FALSE(typed.profiles[0].narrow);
}

TEST(ProfileTyping, RoundAtTheFootOfAThinWallGivesItsTwoBorders)
{
    // A wall 3 spacings thick standing on a plate, both feet rounded with radius 2 (a blade on
    // the disc of a fan wheel). The line runs along the near foot. Within the reach
    // lie the far foot's round (candidates too) and the plate beyond it (the near plate's
    // cluster): points neither the crease nor the round explains, whose capped residual,
    // used as the unit of significance, would hide the round. Near the arc the round fits to
    // the sampling.
    const double r = 2.0;
    const double wall = 3.0;
    const std::vector<Piece> pieces = {
        {{{-12.0, 0.0}, {-r, 0.0}}, 0},
        {arc({-r, r}, r, -M_PI / 2.0, 0.0), 2},
        {{{0.0, r}, {0.0, 12.0}}, 1},
        {{{wall, r}, {wall, 12.0}}, 3},
        {arc({wall + r, r}, r, M_PI, 1.5 * M_PI), 2},
        {{{wall + r, 0.0}, {12.0, 0.0}}, 0}};
    const Swept s = staggered(pieces, 40.0, Eigen::Vector2d::Zero());
    ProfileTypingOptions whole;
    whole.significanceWindow = 0.0;
    const ProfileTyping u = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0, whole);
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    // The residual of the whole profile as the unit: the round is not significant.
    EXPECT_FALSE(u.profiles[0].blend);
    EXPECT_GT(t.profiles[0].significance, 10.0 * u.profiles[0].significance);
    ASSERT_EQ(t.network.lines.size(), 2u);
    EXPECT_TRUE(t.profiles[0].blend);
    EXPECT_NEAR(t.profiles[0].radius, r, 0.3);
    EXPECT_NEAR(t.profiles[0].angle, 90.0, 2.0);
    // The round's borders: one on the plate at y = -r, the other on the wall at z = r.
    expectBordersOnTheFaces(t, r);
}

TEST(ProfileTyping, OtherSheetOfAThinWallIsNoFace)
{
    // Under face A, 4 spacings down and tilted 20 degrees away from it, the other sheet of a
    // tapering wall, sampled densely enough to be the largest cluster within reach: it is no
    // face of the line (its plane passes 4 spacings off), so the faces are A and B at 90.
    const double tilt = 20.0 * M_PI / 180.0;
    std::vector<Piece> pieces = {{{{-12.0, 0.0}, {0.0, 0.0}}, 0}, {{{0.0, 0.0}, {0.0, 9.0}}, 1}};
    for (double shift : {0.0, 0.5}) {
        const double y0 = -12.0 + shift;
        pieces.push_back({{{y0, -4.0 + y0 * std::tan(tilt)}, {0.0, -4.0}}, 3});
    }
    const Swept s = staggered(pieces, 40.0, Eigen::Vector2d::Zero());
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_NEAR(t.profiles[0].angle, 90.0, 2.0);
    EXPECT_EQ(t.network.lines[0].label, sharpLineLabel);
    // Taken as a face, it would make the wedge 20 degrees.
    ProfileTypingOptions o;
    o.maxFaceOffset = 100.0;
    EXPECT_NEAR(typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0, o).profiles[0].angle, 20.0, 3.0);
}

TEST(ProfileTyping, OtherLinesAreCopied)
{
    Swept s = roundedL(3.0, 40.0);
    s.network.lines[0].label = boundaryLineLabel;
    const ProfileTyping t = typeByProfile(s.P, {}, s.seg, {}, s.network, 1.0);
    ASSERT_EQ(t.network.lines.size(), 1u);
    EXPECT_EQ(t.network.lines[0].label, boundaryLineLabel);
    EXPECT_EQ(t.profiles[0].stations, 0);
}

} // namespace

// ---- End to end: the extraction of sampled rounded and sharp cubes ---------------------------

#include "FeatureLines/Extraction.h"
#include "SampledShapes.h"

namespace {

/// Distance from x to the nearest of the 24 tangent lines of the fillets of the cube
/// [-a, a]^3 rounded to r: two coordinates at (+-a, +-(a - r)) in either order, the third
/// within [-(a - r), a - r].
double toFilletBorder(const Eigen::Vector3d& x, double a, double r)
{
    double best = std::numeric_limits<double>::infinity();
    const double b = a - r;
    for (int free = 0; free < 3; ++free) {
        const int u = (free + 1) % 3;
        const int v = (free + 2) % 3;
        for (double su : {-1.0, 1.0}) {
            for (double sv : {-1.0, 1.0}) {
                for (int onFace = 0; onFace < 2; ++onFace) {
                    Eigen::Vector3d p;
                    p(free) = std::clamp(x(free), -b, b);
                    p(u) = su * (onFace == 0 ? a : b);
                    p(v) = sv * (onFace == 0 ? b : a);
                    best = std::min(best, (x - p).norm());
                }
            }
        }
    }
    return best;
}

/// The lengths of the sharp and smooth lines, the distance of every smooth vertex to the
/// nearest fillet border, and the share of the borders' length (sampled every spacing, two
/// spacings clear of their ends) that has a smooth vertex within a spacing.
struct FilletScore
{
    double sharpLength = 0.0;
    double smoothLength = 0.0;
    std::vector<double> distance;
    double covered = 0.0;
    std::vector<double> radii;
};

FilletScore scoreFillets(const ExtractionResult& result, double a, double r)
{
    FilletScore score;
    std::vector<Eigen::Vector3d> smooth;
    for (const FeatureLine& line : result.lines) {
        for (Eigen::Index i = 0; i + 1 < line.points.rows(); ++i) {
            const double length = (line.points.row(i + 1) - line.points.row(i)).norm();
            (line.type == LineType::Sharp ? score.sharpLength : score.smoothLength) += length;
        }
        if (line.type != LineType::Smooth) {
            continue;
        }
        score.radii.push_back(line.blendRadius);
        for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
            smooth.push_back(line.points.row(i).transpose());
            score.distance.push_back(toFilletBorder(smooth.back(), a, r));
        }
    }
    std::sort(score.distance.begin(), score.distance.end());
    int samples = 0;
    int hit = 0;
    const double b = a - r;
    for (int free = 0; free < 3; ++free) {
        for (double su : {-1.0, 1.0}) {
            for (double sv : {-1.0, 1.0}) {
                for (int onFace = 0; onFace < 2; ++onFace) {
                    for (double t = -b + 2.0; t <= b - 2.0; t += 1.0) {
                        Eigen::Vector3d p;
                        p(free) = t;
                        p((free + 1) % 3) = su * (onFace == 0 ? a : b);
                        p((free + 2) % 3) = sv * (onFace == 0 ? b : a);
                        ++samples;
                        for (const Eigen::Vector3d& q : smooth) {
                            if ((q - p).norm() <= 1.0) {
                                ++hit;
                                break;
                            }
                        }
                    }
                }
            }
        }
    }
    score.covered = static_cast<double>(hit) / samples;
    return score;
}

TEST(ProfileTypingExtraction, FilletsOfTwoSpacingsGiveTwoSmoothBordersEach)
{
    const double a = 15.0;
    const double r = 2.0;
    const shapes::Sample s = shapes::roundedCube(2.0 * a, r, 1.0, 3);
    const FilletScore score = scoreFillets(extractFeatureLines(s.points), a, r);
    // No crease on the part; both borders of all twelve fillets traced, on the border.
    EXPECT_LT(score.sharpLength, 0.05 * score.smoothLength);
    EXPECT_GT(score.covered, 0.9);
    ASSERT_FALSE(score.distance.empty());
    EXPECT_LT(score.distance[score.distance.size() / 2], 0.3);
    for (double radius : score.radii) {
        EXPECT_GT(radius, 0.7 * r);
        EXPECT_LT(radius, 1.5 * r);
    }
}

TEST(ProfileTypingExtraction, NoisyFilletsOfThreeSpacingsStillGiveTheirBorders)
{
    const double a = 15.0;
    const double r = 3.0;
    shapes::Sample s = shapes::roundedCube(2.0 * a, r, 1.0, 4);
    shapes::addNormalNoise(s, 0.3, 9);
    const FilletScore score = scoreFillets(extractFeatureLines(s.points), a, r);
    EXPECT_LT(score.sharpLength, 0.05 * score.smoothLength);
    EXPECT_GT(score.covered, 0.8);
    ASSERT_FALSE(score.distance.empty());
    EXPECT_LT(score.distance[score.distance.size() / 2], 0.5);
}

TEST(ProfileTypingExtraction, CubeEdgesStaySharpAtNinetyDegrees)
{
    const shapes::Sample s = shapes::cube(30.0, 1.0, 3);
    const ExtractionResult result = extractFeatureLines(s.points);
    int sharp = 0;
    for (const FeatureLine& line : result.lines) {
        EXPECT_NE(line.type, LineType::Smooth);
        if (line.type == LineType::Sharp) {
            ++sharp;
            EXPECT_NEAR(line.angle, 90.0, 3.0);
        }
    }
    EXPECT_EQ(sharp, 12);
}

} // namespace

namespace {

/// A pin of radius r and height h standing on the plate z = 0 (the square of side `plate`
/// about the origin, less the pin's foot), capped at z = h, sampled at uniformly random places,
/// one point per unit of area (a scan's random sampling, spacing about 1).
PointMatrix randomPin(double r, double h, double plate, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double side = 2.0 * M_PI * r * h;
    const double cap = M_PI * r * r;
    const double ground = plate * plate - cap;
    const auto n = static_cast<Eigen::Index>(side + cap + ground);
    PointMatrix P(n, 3);
    for (Eigen::Index i = 0; i < n;) {
        const double pick = unit(rng) * (side + cap + ground);
        const double t = 2.0 * M_PI * unit(rng);
        if (pick < side) {
            P.row(i++) << r * std::cos(t), r * std::sin(t), h * unit(rng);
        } else if (pick < side + cap) {
            const double rho = r * std::sqrt(unit(rng));
            P.row(i++) << rho * std::cos(t), rho * std::sin(t), h;
        } else {
            const double x = plate * (unit(rng) - 0.5);
            const double y = plate * (unit(rng) - 0.5);
            if (std::hypot(x, y) > r) {
                P.row(i++) << x, y, 0.0;
            }
        }
    }
    return P;
}

/// The length of the sharp lines' pieces whose middles pass `keep` (a point of the piece's
/// middle: whether it counts).
template <typename Keep>
double sharpLengthWhere(const ExtractionResult& result, Keep keep)
{
    double length = 0.0;
    for (const FeatureLine& line : result.lines) {
        if (line.type != LineType::Sharp) {
            continue;
        }
        const Eigen::Index n = line.points.rows();
        for (Eigen::Index i = 0; i + 1 < n + (line.closed ? 1 : 0); ++i) {
            const Eigen::RowVector3d a = line.points.row(i);
            const Eigen::RowVector3d b = line.points.row((i + 1) % n);
            if (keep(0.5 * (a + b))) {
                length += (b - a).norm();
            }
        }
    }
    return length;
}

} // namespace

TEST(ProfileTypingExtraction, PinOfAFewSpacingsRadiusHasNoLineAlongIt)
{
    // A pin of radius 3.5 spacings, 30 high, on a plate, sampled at random: its side turns the
    // normal by 16 degrees from one point to the next, faster than the growing follows, so the
    // segmentation breaks it into candidates and the sharp graph lays a net of lines over it.
    // No face lies within reach of that net: its lines go. The rim at the foot lies on the
    // plate's face and mostly stays; where it ran through the net as pieces shorter than
    // maxSpurLength hanging on dropped lines, those go too (two of the six samplings lose the
    // little of it they had: 7 and 3 spacings of its 22).
    const double r = 3.5;
    const double h = 30.0;
    // On the side, 3 spacings and more from the foot and the top.
    auto onSide = [&](const Eigen::RowVector3d& m) {
        return std::hypot(m(0), m(1)) < r + 3.0 && m(2) > 3.0 && m(2) < h - 3.0;
    };
    // Within a spacing of the foot's circle.
    auto onFoot = [&](const Eigen::RowVector3d& m) {
        return std::hypot(std::hypot(m(0), m(1)) - r, m(2)) < 1.0;
    };
    ExtractionOptions keep;
    keep.sharp.profile.minFaceShare = 0.0;
    double sideBefore = 0.0;
    double sideAfter = 0.0;
    double footBefore = 0.0;
    double footAfter = 0.0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const PointMatrix pin = randomPin(r, h, 40.0, seed);
        const ExtractionResult before = extractFeatureLines(pin, keep);
        const ExtractionResult after = extractFeatureLines(pin);
        sideBefore += sharpLengthWhere(before, onSide);
        sideAfter += sharpLengthWhere(after, onSide);
        footBefore += sharpLengthWhere(before, onFoot);
        footAfter += sharpLengthWhere(after, onFoot);
    }
    EXPECT_GT(sideBefore, 6 * 50.0);
    EXPECT_LT(sideAfter, 0.15 * sideBefore);
    EXPECT_GT(footAfter, 0.75 * footBefore);
}
