// SPDX-License-Identifier: LGPL-2.1-or-later
// First-order segmentation (Demarsin et al. 2007): region growing on the normals. Flat and
// smoothly curved areas become large clusters; where the estimated normals turn quickly, near a
// sharp edge, the growing stops and the points left over form small clusters: the candidate
// feature points.
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

/// The paper states region growing on normal variation; the criterion, its thresholds and
/// the meaning of "small" are designed here (see each option).
///
/// Why two measures. PCA normals over k = 16 neighbours (a ball of radius R ~ 2.7 spacings)
/// blur a crease over about 2R, so a crease turning the normal by a looks, to the normals
/// alone, like a fillet of radius 2R / a: a 45 degree chamfer edge like a fillet of radius
/// 7 spacings. What still tells them apart is the shape of the points: across a crease the
/// heights above the tangent plane follow |x| (a kink), across a fillet x^2 / 2r (a
/// parabola), and the kink leaves three to six times the plane-fit residual. So a point stops
/// the growing only when both its normals spread and its points bend like a crease.
struct FirstOrderSegmentationOptions
{
    /// Degrees. A point may stop the growing only when the normals of its k neighbours
    /// spread more than the spread limit around its own (largest angle); this is the limit's
    /// upper bound. Measured with k = 16: noise of 0.3 spacing along the normal gives spreads
    /// of 9-10 degrees (median), up to 17; a 45 degree crease 25-30 at its centre, a 35
    /// degree crease about 20, a 90 degree crease 50-65; a fillet of radius 8 spacings 16, of
    /// 6 spacings 23 (fillets are told from creases by the planarity excess below, not by
    /// the spread).
    double growAngle = 20.0;
    /// The spread limit follows the noise: this many times the cloud's median spread (what
    /// noise gives on the smooth patches that hold most points), clamped to
    /// [joinAngle, growAngle]. Noise of 0.3 spacing reaches about twice its median spread
    /// (17 against 9 degrees), so 2 keeps noisy planes growing and gives 20 there; a clean
    /// cloud of planes gets joinAngle, so creases of 35 degrees, whose centre spreads about
    /// 20, stop the growing there too (the benchmark's chamfered box: sharp recall 0.944 ->
    /// 0.957 clean). A large factor keeps growAngle whatever the noise.
    double noiseSpreadFactor = 2.0;
    /// Noise alone spreads the normals of a smooth patch's points beyond this many times the
    /// cloud's median spread at 5 % of them (1.55 measured on the benchmark's planes at noise
    /// 0.3 and 0.5 spacing; a 45 degree crease beyond it at 70 % of its points even at 0.5).
    /// The flat points of shallowCreaseAngle's faces spread no more than this (within
    /// [joinAngle, growAngle]): at noise 0.3 the normals on the wall of a hole of 8 spacings'
    /// radius and at the centre of a 35 degree crease spread about the limit, mostly beyond
    /// this, so the wall does not fall into faces with creases between them (benchmark: the
    /// noisy plate's smallest hole keeps no false line). The sharp stage joins across gaps
    /// only along points that spread beyond it (FirstOrderSegmentation::noiseSpreadLimit,
    /// SharpEdges.h).
    double noiseSpreadTail = 1.6;
    /// Degrees. A neighbour joins the cluster of a growing point when their normals differ by
    /// less than this. Half the spread limit: the points on a crease, whose normals lie half
    /// way between those of the two faces, join neither face.
    double joinAngle = 10.0;
    /// Spacings. A point may stop the growing only when its surface variation, less the
    /// cloud's median as the noise floor, exceeds that of a spherical blend of this radius,
    /// R^2 / (24 r^2) (a cylindrical fillet gives R^2 / (32 r^2), less). Fillets and corner
    /// blends of this radius or more stay smooth (at 5 spacings they partly turn sharp); a
    /// clean crease reaches 0.14 tan^2(a/2) at its centre whatever R, so at the fine scale
    /// (fineNeighbours) creases turning the normal by 35 degrees or more stop the growing on
    /// a clean cloud (the 45 and 35 degree edges of a chamfered box); at 30 degrees the points
    /// beside the crease still grow across it. 6 is the smallest fillet the tests and the
    /// benchmark ask to keep smooth.
    double minFilletRadius = 6.0;
    /// ... and exceeds this many standard deviations of the noise on the surface variation
    /// (estimated from the cloud's median absolute deviation). On a clean cloud this is
    /// nothing; with noise of 0.3 spacing along the normal the deviation is ~0.01, about the
    /// fillet limit above, while a 90 degree crease reaches 0.08 and a 45 degree one 0.02.
    /// At 2, noisy 45 degree edges are mostly lost; below 1, noisy fillets of 7 spacings start
    /// to leave candidate chains.
    double noiseMargin = 1.0;
    /// The planarity excess is measured over the point and all k neighbours, and over the
    /// point and its nearest fineNeighbours; the scale whose limit (minFilletRadius,
    /// noiseMargin) is lower is used. A crease's excess is the same at both scales, a
    /// blend's halves at the finer one and the noise's doubles: the fine scale wins on clean
    /// clouds, where creases of 35 degrees then stand clear of blends of minFilletRadius
    /// (the benchmark's clean chamfered box: sharp recall 0.957 -> 0.996 with the two-sided
    /// rule of segmentByNormals), the full one on noisy clouds. The price: on a clean cloud a
    /// blend just under minFilletRadius turns partly sharp sooner (the benchmark's boss
    /// fillet at 20 000 points, 5.7 spacings: sharp precision 0.99 -> 0.90 on that part).
    /// 0: the full neighbourhood only.
    int fineNeighbours = 8;
    /// Degrees; 0 turns the rule off. Noise lets the growing leak across a shallow crease:
    /// where a few of its points happen to pass the planarity test, a chain of growing points
    /// whose normals turn by less than joinAngle per step crosses it, somewhere along a long
    /// edge there always is one, and the two faces become one cluster (on the benchmark's
    /// noisy chamfered boxes every face of the part is one cluster). The rule of
    /// segmentByNormals that keeps a point between two face-sized clusters as a candidate then
    /// never applies, and most of the crease's points join a face. So faces are also read
    /// from the points that are flat by the normals alone (spread within noiseSpreadTail):
    /// joined within joinAngle, groups of more than k of them; no flat point lies within about a
    /// neighbourhood of a crease, so these faces do not leak. A point that cannot grow stays
    /// a candidate when the neighbours of its neighbours hold flat points of two faces whose
    /// planes there (the mean point and mean normal of those flat points) differ by less than
    /// this angle and by more than joinAngle and meet where the point lies
    /// (creasePlaneTolerance, creaseLineReach), and the growing points there do not join the
    /// two (a leak elsewhere does not count; a surface that is only noisy or curved, such as
    /// the wall of a small hole, has its growing points all round the point). Steeper creases
    /// stop the growing by themselves (a 90 degree crease's planarity excess is ten noise
    /// deviations at 0.3 spacing) and are left to the cluster rule, which also keeps this rule
    /// from turning sharp the fillets under minFilletRadius between perpendicular faces.
    /// Benchmark, noise 0.3 spacing: the noisy chamfered box keeps 64-65 % of the points
    /// within a spacing of its creases as candidates instead of 30-33 % (50 000 and 150 000
    /// points); at noise 0.5 its sharp recall goes from 0.51 to 0.88. A crease under about
    /// 40 degrees (at noise 0.3; 20 on a clean cloud) spreads its centre's normals no more
    /// than noise does and is not helped. A curved surface whose normals turn by about
    /// noiseSpreadTail across a neighbourhood can break into faces of flat points with
    /// candidates between them (with flat points read at the spread limit instead, the
    /// benchmark's noisy plate gained a false line on the wall of its smallest hole).
    double shallowCreaseAngle = 60.0;
    /// For shallowCreaseAngle, each face's plane is fitted to at least this many of its flat
    /// points among the neighbours of the point's neighbours: three fit a plane. Fewer are
    /// mostly the first flat points of a small fillet's ends, whose normals lean with the
    /// fillet (on the benchmark's noisy chamfered box 85 % of the points the rule keeps next
    /// to its creases see three or more on both faces, a third of those on the 20 000-point
    /// fillets of 5-6 spacings).
    int minFacePoints = 3;
    /// Spacings: for shallowCreaseAngle, the point lies within this distance of one of the
    /// two planes: a crease point lies on the face it belongs to, up to the noise, while a
    /// point half way round a fillet of radius r between perpendicular faces lies 0.29 r off
    /// both.
    double creasePlaneTolerance = 1.0;
    /// Spacings: ... and within this distance of the line where the two planes meet (the
    /// candidate band of a crease is 3-4 spacings wide; SharpEdgeOptions::maxCreaseShift).
    double creaseLineReach = 2.5;
    /// A cluster is large (a surface patch) when at least this many of its points have all
    /// their k neighbours inside it; otherwise it is small and its points are candidates.
    /// Counting whole neighbourhoods rather than points is the design's reading of "small":
    /// a thin chain of points with similar normals running along a crease can hold many
    /// points, yet none of them is surrounded by its own cluster.
    int minInteriorPoints = 1;
    /// Worker threads (0: OpenMP's default).
    int threads = 0;
};

struct FirstOrderSegmentation
{
    /// #P cluster id of every point, 0 .. #C-1, numbered in the order of their first point.
    std::vector<int> cluster;
    /// #C points per cluster.
    std::vector<int> clusterSize;
    /// #C nonzero for small clusters, whose points are the candidate feature points.
    std::vector<char> smallCluster;
    /// #P face of every flat point (spread within noiseSpreadTail, shallowCreaseAngle): the
    /// groups of flat points joined within joinAngle, of more than k points, each numbered by
    /// its lowest point; -1 for the other points and when the rule is off.
    std::vector<int> face;
    /// #P normal spread of every point in degrees: the largest angle between its normal and
    /// those of its k neighbours (normals are unoriented, so at most 90).
    Eigen::VectorXd spread;
    /// #P surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the point and its
    /// neighbours, read along the given normal, less the cloud's median.
    Eigen::VectorXd planarityExcess;
    /// The excess above which a point may stop the growing (minFilletRadius, noiseMargin).
    double minExcess = 0.0;
    /// The neighbours (nearest first) the planarity excess was measured over (k or
    /// fineNeighbours).
    int excessNeighbours = 0;
    /// Degrees: the spread limit used (growAngle, noiseSpreadFactor).
    double growAngle = 0.0;
    /// Degrees: noiseSpreadTail times the cloud's median spread, beyond which a spread is not
    /// noise's.
    double noiseSpreadLimit = 0.0;

    int clusterCount() const { return static_cast<int>(clusterSize.size()); }
    bool isCandidate(Eigen::Index i) const { return smallCluster[cluster[i]] != 0; }
};

/// Segments a cloud by region growing on its (unoriented) normals.
///   P        #P by 3 points
///   normals  #P by 3 unit normals, e.g. from pcaNormals()
///   N        the k nearest neighbours the normals were estimated on
///   spacing  the cloud's mean point spacing (meanSpacing())
/// A point grows its cluster unless both its normal spread and its planarity excess are
/// high. A point that does not grow joins the cluster of its growing neighbour of closest
/// normal (within joinAngle), unless its growing neighbours belong to two clusters of at
/// least k + 1 growing points (two faces, as large clusters need an interior point): then
/// it lies on a crease too shallow to leave a band of candidates wider than a neighbourhood
/// and stays a candidate; so does a point between two faces on a shallow crease
/// (shallowCreaseAngle). Every point ends in exactly one cluster, and the result does not
/// depend on the point order beyond cluster and face numbering. Throws std::invalid_argument when
/// the sizes disagree, a normal is not finite, the spacing is not positive, an angle is not in (0,
/// 90] (shallowCreaseAngle in [0, 90]), a crease length is not positive or minFacePoints is
/// below 3.
FirstOrderSegmentation segmentByNormals(const PointMatrix& P, const NormalMatrix& normals,
                                        const Neighbourhoods& N, double spacing,
                                        const FirstOrderSegmentationOptions& options = {});

} // namespace featurelines
