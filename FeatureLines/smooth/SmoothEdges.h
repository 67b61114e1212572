// SPDX-License-Identifier: LGPL-2.1-or-later
// Smooth edges of one smooth region (Sec. 2-4 of the 2008 paper): optional smoothing, mean
// curvature, histogram thresholds, the low / inner / border labels, region growing on them, and
// the cluster graph that turns the single-point clusters into closed lines — one set of closed
// lines per threshold. Also the automatic choice of thresholds and the multi-step refinement
// inside one large cluster (Sec. 4, Fig. 13 e).
#pragma once

#include <memory>
#include <vector>

#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/smooth/LinePlacement.h"
#include "FeatureLines/smooth/PointLabels.h"
#include "FeatureLines/neighbourhoods/RingNeighbourhood.h"
#include "FeatureLines/curvature/Smoothing.h"

namespace featurelines {

enum class SmoothingMode
{
    /// Smooth when the region's estimated noise exceeds SmoothEdgeOptions::noiseThreshold.
    Automatic,
    Always,
    Never,
};

/// The automatic mode, designed beyond the paper (which leaves the number of thresholds to
/// the user, Sec. 2.3): the first threshold of the region's histogram is searched; a threshold
/// is accepted when it is significant; the values below and above an accepted threshold are
/// searched again (the paper's "lower" and "higher" steps). A refused threshold sends the
/// search on too: below it when no patch lies above it (the valley after the highest peak),
/// above it when it splits one curvature level (a peak and its noise tail, Sec. 4, Fig. 9 a).
/// A range is searched after at most maxMisses refusals in a row, and only when its values
/// could hold two levels (their extremes meet the contrast and separation below). The search
/// stops when maxThresholds are accepted or maxSearches weighed.
/// A threshold is significant when all of these hold, the patches being the values between
/// the nearest accepted thresholds below and above it:
///  - its valley ratio e(tau) = b1 / b2 is at least minRatio (a peak, then a valley), and
///    the peak b1 holds at least minInnerPoints values (a patch's worth);
///  - the levels above and below it each hold a patch: a connected cluster of at least
///    minInnerPoints points of the level whose whole 1-ring lies in the level (the inner
///    points of Sec. 3). Scattered noise above a threshold in a peak's tail is no patch, nor
///    is the thin band of values a curvature step passes through between two patches;
///  - the curvature contrast (c_above + c_flat) / (c_below + c_flat), with c_above and c_below
///    the median curvatures of the patches above and below, is at least minContrast: two
///    curvature levels, not one level split in two. c_flat = 1 / (flatRadius x spacing) is
///    the curvature that cannot be told from a plane at this sampling, so the round-off values
///    of a flat face (all ~0) never make a contrast;
///  - c_above - c_below is at least minSeparation curvature noise floors
///    (RegionGeometry::curvatureNoise): the two levels are farther apart than noise spreads
///    one level;
///  - at most maxStraddle of the border points at tau lie near a level outside the two
///    patches: the level above is bordered by the level below, not by the slope down to a
///    third level (a curvature drifting along a fillet).
/// Accepted thresholds are applied in the middle of their valleys (centreThresholds).
struct AutomaticThresholdOptions
{
    int maxThresholds = 3;
    /// Thresholds weighed at most (accepted or not): each costs a labelling of the region.
    int maxSearches = 16;
    /// Refused thresholds in a row after which a range is given up: one to step from a valley
    /// above the highest peak down to the patches' valley, one more to step over a noise tail.
    int maxMisses = 2;
    double minRatio = 2.0;
    /// 0: 2 k, two neighbourhoods' worth of points.
    int minInnerPoints = 0;
    /// A fillet (cylinder, |H| = 1 / 2r) against the corner that joins it has contrast 2 for
    /// a spherical corner and 1 + r / R for a toroidal one (tube r, ring radius R, at most
    /// about 3 r): 1.3 keeps both, and refuses one level split by its round-off (a clean
    /// cylinder's values spread by a few percent). Drifting levels are the straddle rule's.
    double minContrast = 1.3;
    /// x spacing. Over a neighbourhood of radius 2.5 spacings a sphere of radius 200 spacings
    /// departs from its tangent plane by 0.016 spacing, below any scanner's noise.
    double flatRadius = 200.0;
    /// In curvature noise floors (standard deviations of a flat face's curvature). Two levels
    /// 4 floors apart put a threshold between them 2 floors from each: 2 % of each patch's
    /// points fall on the wrong side, which the labels of Sec. 3 absorb as noisy points. A
    /// noise tail split off a flat face (folded normal) has medians this far apart only above
    /// 4.5 floors, where fewer than 1 point in 100 000 lies, and those do not form a patch.
    double minSeparation = 4.0;
    /// Apply each accepted threshold in the middle of its valley (ThresholdDecision::applied):
    /// between the histogram's tau, where the valley starts after the lower peak, and the
    /// rise to the next peak. The fit blurs a curvature step symmetrically, so the middle
    /// level crosses on the tangent line; the valley's start can lie up to a neighbourhood
    /// radius off it, onto the flatter side.
    bool centreThresholds = true;
    /// Border points whose surroundings are looked at for the straddle share (evenly
    /// strided); a share is known to about 1 % from that many.
    int straddleSamples = 2000;
    /// Largest share of the border points of a threshold that may lie within two fit radii of
    /// a level below the patch under it (or above the patch over it). A higher share means the
    /// level above is bordered by the transition down to another threshold's level rather
    /// than by the level under it: its lines would trace another threshold's lines again,
    /// shifted onto the slope when the level above drifts (a variable-radius fillet split
    /// along its length). Half: a patch's border may meet other levels at its ends.
    double maxStraddle = 0.5;
    /// x the fit radius (the k-th neighbour's distance): how far from a border point a level
    /// outside the two patches counts as straddled.
    double straddleReach = 2.0;
};

/// The flat patch on which the curvature noise floor is measured (RegionGeometry::
/// curvatureNoise): a jittered square grid of patchSide x patchSide points, heights drawn
/// from a normal distribution (seeded) so that its estimated noise is the region's.
struct SyntheticNoiseOptions
{
    /// 80 x 80 points: the central 40 x 40, 20 spacings from the rim (where smoothing and
    /// fits are one-sided), give the floor to about 5 % (a plane of 6400 points sampled like
    /// the tests' shapes shows a spread within 7 % of it at every noise from 0.02 to 0.5).
    int patchSide = 80;
    unsigned seed = 1;
};

struct SmoothEdgeOptions
{
    SmoothingMode smoothing = SmoothingMode::Automatic;
    /// Noise level (x spacing, see estimateNoise) above which Automatic smoothing applies.
    /// Without smoothing the quadric fit of Sec. 2.1 turns noise n into curvature noise of
    /// about 0.27 n / spacing^2 (the noise floor's flat patch measures it): noise of 0.02
    /// spacing gives a flat face a curvature spread of 1 / (185 spacings), the flatRadius
    /// level; above it smoothing pays for its blur. A clean surface shows below 0.005 at any
    /// curvature (the estimate fits a quadric).
    double noiseThreshold = 0.02;
    /// Taubin passes when smoothing. Twenty passes of lambda|mu bring noise of 0.3 spacing
    /// below the curvature contrast of a fillet of radius 6 spacings.
    SmoothingOptions smoothingOptions{20, 0.5, -0.53};
    /// Passes of averaging the curvature over each point's neighbourhood, in smoothed regions
    /// only (beyond Sec. 2.4). Smoothing the points leaves the quadric fit a residual noise that
    /// still spreads a flat face's curvature over a fillet's. The signed curvature is averaged
    /// (over normals oriented alike), so a flat face's noise, of either sign, cancels instead
    /// of adding up. Each pass spreads a curvature step over one more neighbourhood radius,
    /// symmetrically about the tangent line; two passes halve the noise floor of a region
    /// smoothed from 0.3 spacing of noise (RegionGeometry::curvatureNoise, 0.0098 -> 0.0047
    /// per spacing) and leave a flat of 6 spacings between two fillets its own level
    /// (2 x 2.5 spacings of blur); a third pass would gain a fifth more and merge it.
    int curvatureAveragingPasses = 2;
    /// Points sampled for the noise estimate (every n-th point so that at most this many are
    /// fitted; 0: all). The estimate is a median, which 20 000 samples fix to within 1 %.
    int noiseSamples = 20000;
    SyntheticNoiseOptions noiseFloor;
    CurvatureOptions curvature;
    /// L_start, outliers and search of Sec. 2.2-2.4. outlierPercent < 0 chooses: 1 % for a
    /// smoothed (noisy) region, none for a clean one (Sec. 2.4: outliers come with noise).
    ThresholdOptions histogram{50, -1.0};
    LabelOptions labels;
    /// In curvature noise floors (RegionGeometry::curvatureNoise): a connected piece of points
    /// above tau whose values (their 90th percentile) stay within this of tau is noise of the
    /// level below, and joins it; likewise a piece below tau within this of it joins the level
    /// above. A patch of the level above lies at least minSeparation / 2 = 2 floors above tau;
    /// noise lifts a level 2 floors below tau past tau in 2 % of its points, in islands whose
    /// values mostly stay within a floor of tau.
    double islandMargin = 1.5;
    /// In curvature noise floors: a line whose high side (within two fit radii, the median over
    /// its points) exceeds its low side by less than this is dropped before the line ends are
    /// processed. A level difference of minSeparation (4) floors, blurred over about two fit
    /// radii, leaves about half of it across the line; the edge of a noise island, or a
    /// curvature that only drifts through tau, leaves about one floor. Two fit radii of the
    /// scale the curvature was read at (lineContrast).
    double minLineContrast = 2.0;
    /// Sec. 3: "small clusters" are the clusters of at most this many points (the single
    /// points met at a label change).
    int maxCandidateClusterSize = 1;
    /// The graph of Sec. 3. Its open-piece filter (minOpenComponentLength) is applied after
    /// the line ends are anchored.
    ClusterGraphOptions graph;
    /// x spacing: candidate points this close to an anchor line (the boundary of an open
    /// cloud runs through a region; sharp lines are SmoothRegionOptions::bandWidth away) are
    /// left out of the graph. Their neighbourhoods are cut by the rim, so the fit, and in a
    /// noisy region the smoothing, is one-sided there: a band of high curvature along the rim
    /// would join the ends of neighbouring lines. The sharp lines' band, 2.5 spacings.
    double anchorBand = 2.5;
    /// x spacing: a free line end this close to a sharp or boundary line is extended to it.
    /// The region ends SmoothRegionOptions::bandWidth (2.5) from a sharp line, and the graph
    /// ends a line up to a node radius (1.5) and its smoothing short of its last candidate:
    /// 5 spacings reach across, and stay below the gap of two lines' ends facing each other.
    double anchorReach = 5.0;
    /// Degrees between the line's direction at its end and the way to the anchor point: the
    /// anchor must not lie behind the end (the line would have run past it). The direction is
    /// taken over the last anchorReach of the line, which noise can bend by tens of degrees
    /// near an end, so anything ahead counts.
    double anchorAngle = 90.0;
    AutomaticThresholdOptions automatic;
    /// Where the region's curvature was read at a coarser scale (RegionGeometry::
    /// curvatureScale > 1), the lines follow that scale's field, a few of the region's
    /// spacings off the border in places: they are moved onto the curvature step of the
    /// region's points under them (LinePlacement.h, beyond the paper). At the region's own
    /// scale the lines already lie within a spacing of the border and stay as they are.
    bool placeCoarseLines = true;
    LinePlacementOptions placement;
    /// The scale of the curvature (CurvatureScaleOptions, RegionGeometry::curvatureScale).
    CurvatureScaleOptions scales;
    /// Seed of the random choice of growing seeds (Sec. 3).
    unsigned seed = 1;
};

/// One region's own geometry: its (possibly smoothed) points, their neighbourhoods within the
/// region, normals, 1-rings and mean curvature. Everything a threshold needs, computed once.
struct RegionGeometry
{
    int region = -1;
    /// Region point i is cloud point members[i].
    std::vector<int> members;
    PointMatrix points;
    Neighbourhoods neighbours;
    NormalMatrix normals;
    RingNeighbourhoods ring;
    Eigen::VectorXd curvature;
    /// Estimated noise (x spacing) before smoothing, and whether the region was smoothed.
    double noise = 0.0;
    bool smoothed = false;
    /// The curvature noise floor (1 / length unit): the standard deviation of the curvature a
    /// flat face of this region's noise shows after the region's smoothing, fit and averaging.
    double curvatureNoise = 0.0;
    double spacing = 0.0;
    /// The spacing of the sampling the curvature was computed at, x spacing: 1, or the
    /// coarser scale chosen for the region (see analyseRegion). Lengths that depend on the fit
    /// (the flat radius, the reach of the contrast and straddle tests) scale with it.
    double curvatureScale = 1.0;

    /// At a coarser scale: the region averaged onto that scale's grid, with its own smoothing,
    /// 1-rings, curvature and noise floor. The automatic thresholds are decided on it (its
    /// patches and reaches are in its own sampling); the curvature above is its curvature
    /// carried back to the region's points, on which the lines are drawn. Null at scale 1.
    std::shared_ptr<const RegionGeometry> coarse;
    /// At a coarser scale: per point of the region, its row in `coarse` (the centroid of the
    /// cell it was averaged into). Empty at scale 1.
    std::vector<int> coarseRowOf;
    /// Every scale weighed for the region: its spacing (x the region's), its number of points
    /// and the thresholds the automatic rule accepts there; -1 at the region's own scale when
    /// no coarser one accepted any (it was not weighed: it keeps the region whatever it finds).
    struct ScaleTrial
    {
        double scale = 1.0;
        int points = 0;
        double noise = 0.0;
        int acceptedThresholds = -1;
        /// The least separation (noise floors, ThresholdDecision::separation) among them.
        double separation = 0.0;
    };
    std::vector<ScaleTrial> scaleTrials;
};

/// Builds a region's geometry from the cloud's.
///   P, N        the cloud and its k nearest neighbours
///   region      #P region of every point (-1: none), members: the points of regionId
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {});

/// The same, given the cloud's normals over N (pcaNormals): a region point whose k nearest
/// neighbours all lie in the region keeps its cloud normal (the same fit); only the points
/// whose neighbourhood the region cuts are fitted again.
RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const NormalMatrix& normals, const std::vector<int>& region,
                             const std::vector<int>& members, int regionId, double spacing,
                             const SmoothEdgeOptions& options = {});

/// The same for a region of every point of P (no sharp edge or boundary band cuts the cloud),
/// taking over P's neighbourhoods N, which are the region's own: the one-shot extraction and the
/// coarse curvature scales spare their copy (190 MiB per million points at k = 16). normals may
/// be empty (fitted here).
RegionGeometry analyseRegion(const PointMatrix& P, Neighbourhoods&& N, const NormalMatrix& normals,
                             int regionId, double spacing, const SmoothEdgeOptions& options = {});

/// The noise estimate of SmoothEdgeOptions::noiseThreshold (x spacing): the median distance of
/// a point from the quadric fitted to its neighbours (in its normal's frame, the point itself
/// left out). Insensitive to curvature; about 0.9 sigma for normal noise sigma. At most
/// maxSamples points are fitted (every n-th; 0: all).
double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing, int maxSamples = 0);

/// The closed lines at one threshold of a region.
struct SmoothEdgeLevel
{
    double threshold = 0.0;
    /// Per region point: its Sec. 3 label at this threshold and its label cluster.
    std::vector<PointLabel> labels;
    LabelClusters clusters;
    /// Lines on the region's (possibly smoothed) points.
    LineNetwork network;
    ClusterGraphCounts counts;
};

/// Sec. 3 at threshold tau over the whole region, or over `subset` (region point indices)
/// only, as the multi-step refinement does. Noise islands are levelled before the labels
/// (SmoothEdgeOptions::islandMargin); lines without contrast across them are dropped
/// (minLineContrast); free line ends are anchored on the `anchors` (the sharp and boundary
/// lines around the region, see anchorLineEnds); short spurs and open pieces shorter than
/// options.graph.minOpenComponentLength with an end on nothing are then dropped.
SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options = {},
                                       const std::vector<int>& subset = {},
                                       const std::vector<Polyline>& anchors = {});

/// The contrast across a line at threshold tau that smoothEdgesAtThreshold asks of it
/// (minLineContrast, in noise floors): the median over the line's `points` (region point
/// indices) of the local contrast, the median curvature above tau minus that at or below it
/// among the points within two fit radii (two hops of the neighbourhoods); points with values
/// on one side only count not, and 0 when none is left. Where the region's curvature was read
/// at a coarser scale (RegionGeometry::coarse) it is taken there, at the cells the points were
/// averaged into: the carried-back values cross tau over the coarse fit's width, of which two
/// fit radii of the region's own sampling see only part.
double lineContrast(const RegionGeometry& region, const Eigen::VectorXd& curvature, double tau,
                    const std::vector<int>& points);

/// Sec. 1.2: the smooth edges of a region end on the sharp edges (or the boundary) around it,
/// but the region stops a band short of them. Every free end (no junction) of an open line
/// that lies within `reach` of an anchor line, and points towards it (within
/// maxAngleDegrees of the line's direction at that end), is extended to the closest point of
/// the anchor lines. Returns per line two flags, start and end: anchored.
std::vector<char> anchorLineEnds(LineNetwork& network, const std::vector<Polyline>& anchors,
                                 double reach, double maxAngleDegrees);

/// Removes the lines flagged in `drop`; a junction left with two line ends joins them into one
/// line (a loop when both are the same line's), left with one, that end is on nothing.
/// Junctions are renumbered; `anchored` (two flags per line, see anchorLineEnds; empty: none)
/// follows the lines.
void dropLines(LineNetwork& network, std::vector<char>& anchored, const std::vector<char>& drop);

/// Removes the lines shorter than minLength that run from a junction to an end on nothing
/// (neither a junction nor, by the `anchored` flags, an anchor line): spurs noise grows off a
/// feature line. A junction left with two line ends joins them into one line (a loop when
/// both are the same line's); left with one, that end is on nothing. Repeated until no such
/// spur is left. `anchored` follows the lines. Returns the number of lines removed.
int pruneDanglingLines(LineNetwork& network, std::vector<char>& anchored, double minLength);

/// Drops the pieces of lines (lines joined through junctions) that have no cycle, are shorter
/// than minLength in total and keep an end on nothing (neither a junction nor, by the
/// `anchored` flags of anchorLineEnds, an anchor line): noise gathered along a surface rather
/// than a feature. Junctions are renumbered. Returns the number of lines dropped.
int dropOpenPieces(LineNetwork& network, const std::vector<char>& anchored, double minLength);

/// The histogram search on the region's curvature (or on `subset`'s) with the region's outlier
/// rule: the first threshold, and the next lower / higher one (Sec. 2.2-2.3).
ThresholdResult regionThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options = {},
                                const std::vector<int>& subset = {});
ThresholdResult regionLowerThreshold(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options = {});
ThresholdResult regionHigherThreshold(const RegionGeometry& region, double threshold,
                                      const SmoothEdgeOptions& options = {});

/// Why a threshold was accepted or refused by the automatic rule, for reports and tests.
struct ThresholdDecision
{
    ThresholdResult result;
    bool accepted = false;
    /// The threshold applied when accepted (AutomaticThresholdOptions::centreThresholds).
    double applied = 0.0;
    /// Inner points at tau (Sec. 3). The largest patches of the levels above and below tau:
    /// connected points of the level whose whole 1-ring is in the level too.
    int innerPoints = 0;
    int largestPatch = 0;
    int largestPatchBelow = 0;
    /// Median curvature of the patches below and above tau (between the nearest accepted
    /// thresholds), their contrast and their separation in curvature noise floors.
    double medianBelow = 0.0;
    double medianAbove = 0.0;
    double contrast = 0.0;
    double separation = 0.0;
    /// Share of the border points at tau within two fit radii of a level outside the two
    /// patches (AutomaticThresholdOptions::maxStraddle).
    double straddle = 0.0;
};

/// The automatic mode (see AutomaticThresholdOptions): every threshold searched, in the order
/// searched, with its decision. The accepted ones' applied values, sorted from high to low,
/// are the region's thresholds. A region with no significant valley (a plane, a sphere) accepts
/// none.
std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options = {});

/// Sec. 4, Fig. 13 e: the histogram step applied again to one large label cluster of a level,
/// for a fillet no valley of the whole region shows. Returns the level found inside the
/// cluster (its threshold and lines), or throws std::invalid_argument when the cluster is not a
/// large cluster of that level or holds too few distinct curvature values.
SmoothEdgeLevel refineInCluster(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                int cluster, const SmoothEdgeOptions& options = {});

} // namespace featurelines
