// SPDX-License-Identifier: LGPL-2.1-or-later
// The options of the smooth-edge stage (Sec. 2-4 of the 2008 paper), one struct read by its
// steps: RegionGeometry.h, SmoothEdgeLevel.h, AutomaticThresholds.h, ClusterRefinement.h.
#pragma once

#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "FeatureLines/network/ClusterGraph.h"
#include "FeatureLines/smooth/HistogramThreshold.h"
#include "FeatureLines/smooth/LinePlacement.h"
#include "FeatureLines/smooth/PointLabels.h"

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

} // namespace featurelines
