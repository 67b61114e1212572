// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/RegionGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <queue>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/curvature/Curvature.h"
#include "FeatureLines/curvature/CurvatureScale.h"
#include "FeatureLines/curvature/Smoothing.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/AutomaticThresholds.h"
#include "FeatureLines/smooth/LineBand.h"
#include "FeatureLines/smooth/PointValues.h"
#include "FeatureLines/smooth/RegionNeighbourhoods.h"
#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

using detail::allIndices;
using detail::median;

Eigen::VectorXd averageOverNeighbours(const Eigen::VectorXd& values, const Neighbourhoods& N)
{
    Eigen::VectorXd averaged(values.size());
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < values.size(); ++i) {
        double sum = values[i];
        for (int j = 0; j < N.k(); ++j) {
            sum += values[N.indices(i, j)];
        }
        averaged[i] = sum / (N.k() + 1);
    }
    return averaged;
}

/// Normals flipped so that neighbours agree: breadth first over the neighbourhoods from the
/// first point of every connected piece. A smooth region holds no crease, so neighbouring
/// normals differ by far less than 90 degrees and the sign of their dot product is reliable.
NormalMatrix orientedNormals(NormalMatrix normals, const Neighbourhoods& N)
{
    releaseIdleThreads(); // the walk is serial
    const Eigen::Index n = normals.rows();
    std::vector<char> seen(static_cast<size_t>(n), 0);
    std::vector<int> queue;
    queue.reserve(static_cast<size_t>(n));
    for (Eigen::Index s = 0; s < n; ++s) {
        if (seen[s]) {
            continue;
        }
        seen[s] = 1;
        queue.assign(1, static_cast<int>(s));
        for (size_t head = 0; head < queue.size(); ++head) {
            const int p = queue[head];
            for (int j = 0; j < N.k(); ++j) {
                const int q = N.indices(p, j);
                if (!seen[q]) {
                    seen[q] = 1;
                    if (normals.row(q).dot(normals.row(p)) < 0.0) {
                        normals.row(q) *= -1.0;
                    }
                    queue.push_back(q);
                }
            }
        }
    }
    return normals;
}

/// The region's curvature: the quadric fit of Sec. 2.1, then (smoothed regions) averaging
/// passes. The averaging runs on the signed curvature over consistently oriented normals and
/// the magnitude is taken last (unless signed values were asked for): averaging magnitudes
/// would lift a flat face's noise, which has both signs, to a positive level.
Eigen::VectorXd regionCurvature(const PointMatrix& P, const NormalMatrix& normals,
                                const Neighbourhoods& N, int averagingPasses,
                                const CurvatureOptions& options, const ProgressSpan& progress = {})
{
    if (averagingPasses == 0) {
        return meanCurvature(P, normals, N, options, progress);
    }
    CurvatureOptions signedOptions = options;
    signedOptions.signedCurvature = true;
    const NormalMatrix oriented = orientedNormals(normals, N);
    progress.report(0.2);
    Eigen::VectorXd H = meanCurvature(P, oriented, N, signedOptions, progress.part(0.2, 0.7));
    for (int pass = 0; pass < averagingPasses; ++pass) {
        H = averageOverNeighbours(H, N);
        progress.report(0.7 + 0.3 * (pass + 1) / averagingPasses);
    }
    return options.signedCurvature ? H : Eigen::VectorXd(H.cwiseAbs());
}

/// The curvature noise floor per unit of estimated noise, measured on a flat patch sampled as a
/// scan (SyntheticNoiseOptions) with noise of 1.05^step spacings, smoothed (when `smoothed`),
/// fitted with k neighbours and averaged `averaging` times as the region is.
double measuredNoiseFloor(int step, int k, bool smoothed, int averaging,
                          const SmoothEdgeOptions& options)
{
    const SmoothingOptions& so = options.smoothingOptions;
    const SyntheticNoiseOptions& sn = options.noiseFloor;
    const int side = sn.patchSide;
    std::mt19937 rng(sn.seed);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::normal_distribution<double> gauss(0.0, 1.0);
    PointMatrix P(side * side, 3);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            P.row(j * side + i) << i + jitter(rng), j + jitter(rng), gauss(rng);
        }
    }
    NeighbourOptions no;
    no.k = k;
    // The grid's mean spacing, then heights of 1.05^step spacings over the estimate's
    // 0.9 sigma (see estimateNoise).
    PointMatrix flat = P;
    flat.col(2).setZero();
    const double cell = meanSpacing(nearestNeighbours(flat, no));
    P.col(2) *= std::exp(step * std::log(1.05)) / 0.9 * cell;
    const Neighbourhoods N = nearestNeighbours(P, no);
    const double spacing = meanSpacing(N);
    NormalMatrix normals = pcaNormals(P, N).normals;
    const double estimated = estimateNoise(P, normals, N, spacing);
    if (smoothed) {
        P = laplacianSmooth(P, N, allIndices(P.rows()), so);
        normals = pcaNormals(P, N).normals;
    }
    const Eigen::VectorXd H = regionCurvature(P, normals, N, averaging, options.curvature);
    // Away from the patch's rim, where smoothing and fits are one-sided.
    std::vector<double> interior;
    const int margin = side / 4;
    for (int j = margin; j < side - margin; ++j) {
        for (int i = margin; i < side - margin; ++i) {
            interior.push_back(std::abs(H[j * side + i]) * spacing);
        }
    }
    // |H| of a flat face is folded normal noise: its median is 0.674 deviations.
    return estimated > 0.0 ? median(std::move(interior)) / 0.6745 / estimated : 0.0;
}

/// The curvature noise floor (x 1 / spacing) of a region with estimated noise `noise` (x
/// spacing): a flat patch sampled as a scan (a jittered grid) with normal noise goes through
/// the same smoothing, fit and averaging as the region; the spread of its curvature is the
/// curvature a flat face shows from noise alone. The patch's noise is drawn so that its
/// estimate matches the region's: the steps are nearly linear in the heights, but not quite
/// (noise of a few tenths of a spacing changes which points are nearest neighbours). Cached
/// per set of options and noise level (in steps of 5 %).
double curvatureNoiseFloor(double noise, int k, bool smoothed, const SmoothEdgeOptions& options)
{
    if (!(noise > 0.0)) {
        return 0.0;
    }
    const int averaging = smoothed ? options.curvatureAveragingPasses : 0;
    const SmoothingOptions& so = options.smoothingOptions;
    const SyntheticNoiseOptions& sn = options.noiseFloor;
    // Below a hundredth of a spacing every step is linear: one patch serves all levels.
    const double level = std::max(noise, 0.01);
    const int step = static_cast<int>(std::lround(std::log(level) / std::log(1.05)));
    using Key = std::tuple<int, bool, int, double, double, int, int, int, int, unsigned>;
    const Key key{
        k,    smoothed,     so.iterations, so.lambda, so.mu, averaging, options.curvature.k,
        step, sn.patchSide, sn.seed};
    static std::mutex mutex;
    static std::map<Key, double> cache;
    double perNoise = 0.0;
    {
        std::lock_guard<std::mutex> lock(mutex);
        auto it = cache.find(key);
        if (it != cache.end()) {
            perNoise = it->second;
        }
    }
    if (perNoise == 0.0) {
        perNoise = measuredNoiseFloor(step, k, smoothed, averaging, options);
        std::lock_guard<std::mutex> lock(mutex);
        cache[key] = perNoise;
    }
    return noise * perNoise;
}

/// The points within `width` (length unit, along the neighbourhoods) of the rim of a coarse
/// region, nearest the rim first.
std::vector<int> rimBand(const RegionGeometry& g, double width)
{
    const Eigen::Index n = g.points.rows();
    const Neighbourhoods& N = g.neighbours;
    // The grid's cells are a regular sampling: a 90 degree gap already marks its rim.
    BoundaryOptions rimOptions;
    rimOptions.minGapAngle = 90.0;
    const std::vector<char> rim = boundaryPoints(g.points, g.normals, N, rimOptions);
    releaseIdleThreads(); // the rest is serial
    constexpr double infinity = std::numeric_limits<double>::infinity();
    // Distance from the rim along the neighbourhood graph (Dijkstra from every rim point),
    // within the width.
    std::vector<double> distance(static_cast<size_t>(n), infinity);
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (rim[static_cast<size_t>(i)]) {
            distance[static_cast<size_t>(i)] = 0.0;
            queue.push({0.0, static_cast<int>(i)});
        }
    }
    std::vector<int> band;
    while (!queue.empty()) {
        const auto [d, p] = queue.top();
        queue.pop();
        if (d > distance[static_cast<size_t>(p)]) {
            continue;
        }
        band.push_back(p);
        for (int j = 0; j < N.k(); ++j) {
            const int q = N.indices(p, j);
            const double dq = d + std::sqrt(N.squaredDistances(p, j));
            if (dq < width && dq < distance[static_cast<size_t>(q)]) {
                distance[static_cast<size_t>(q)] = dq;
                queue.push({dq, q});
            }
        }
    }
    return band;
}

/// The curvature of a coarse region near its rim replaced by the values of its interior. At the
/// rim the fit and the smoothing see one side only, and their bias (the curvature of a
/// cylinder rises by half within a few spacings of a cut) spreads over a few coarse spacings,
/// a band many fine spacings wide that the sharp lines' band (SmoothRegionOptions::bandWidth)
/// no longer covers: its values would form a level of their own along every sharp edge. The
/// points within `width` (length unit, along the neighbourhoods) of a rim point (an empty
/// sector in its neighbourhood, boundaryPoints) take, from the innermost outwards, the mean of
/// their neighbours' values that are known: a fillet running into a sharp edge keeps its
/// level up to the edge. A region that is all rim keeps its values.
void fillRimFromInterior(RegionGeometry& g, double width)
{
    const Eigen::Index n = g.points.rows();
    const Neighbourhoods& N = g.neighbours;
    const std::vector<int> band = rimBand(g, width);
    if (band.size() == static_cast<size_t>(n)) {
        return;
    }
    // Innermost first: each takes what its neighbours farther in already hold.
    std::vector<char> known(static_cast<size_t>(n), 1);
    for (int p : band) {
        known[static_cast<size_t>(p)] = 0;
    }
    for (auto it = band.rbegin(); it != band.rend(); ++it) {
        const int p = *it;
        double sum = 0.0;
        int count = 0;
        for (int j = 0; j < N.k(); ++j) {
            const int q = N.indices(p, j);
            if (known[static_cast<size_t>(q)]) {
                sum += g.curvature[q];
                ++count;
            }
        }
        if (count > 0) {
            g.curvature[p] = sum / count;
            known[static_cast<size_t>(p)] = 1;
        }
    }
}

void requireScaleOptions(const CurvatureScaleOptions& so)
{
    if (!(so.maxScale >= 1.0) || !(so.carryWidth > 0.0) || !(so.rimWidth >= 0.0) ||
        so.minPoints < 0 || !(so.planeTolerance >= 0.0)) {
        throw std::invalid_argument("curvature scales: the coarsest scale must be at least 1 "
                                    "spacing, the carry width positive, the rim width, the "
                                    "plane tolerance and the least number of cells not "
                                    "negative");
    }
}

/// The largest fillet radius that stands minSeparation noise floors above a flat face, at a
/// curvature noise floor `floor`: |H| = 1 / 2r.
double largestVisibleRadius(double floor, const SmoothEdgeOptions& options)
{
    const double minSeparation = std::max(options.automatic.minSeparation, 1.0);
    return 1.0 / (2.0 * minSeparation * floor);
}

/// The options a coarse scale of a region is analysed with: no coarser scales of its own, and
/// no curvature averaging. The grid's averaging has already taken most of the noise; averaging
/// the curvature too would blur each transition over two more coarse neighbourhoods, and carry
/// the mean curvature through zero between a concave fillet and the convex face it meets (a band
/// that looks like a flat patch of its own).
SmoothEdgeOptions coarseScaleOptions(const SmoothEdgeOptions& options)
{
    SmoothEdgeOptions coarse = options;
    coarse.scales.maxScale = 1.0;
    coarse.curvatureAveragingPasses = 0;
    return coarse;
}

/// A scale's trial: the thresholds the automatic rule accepts on the geometry r.
RegionGeometry::ScaleTrial weighScale(const RegionGeometry& r, double regionSpacing,
                                      const SmoothEdgeOptions& coarseOptions)
{
    RegionGeometry::ScaleTrial trial;
    trial.scale = r.spacing / regionSpacing;
    trial.acceptedThresholds = 0;
    trial.points = static_cast<int>(r.points.rows());
    trial.noise = r.noise;
    for (const ThresholdDecision& d : automaticThresholds(r, coarseOptions)) {
        if (d.accepted) {
            trial.separation = trial.acceptedThresholds == 0
                                   ? d.separation
                                   : std::min(trial.separation, d.separation);
            ++trial.acceptedThresholds;
        }
    }
    return trial;
}

/// The coarse scale that accepts the most thresholds, with the grid its cells were averaged on.
struct CoarseScale
{
    std::shared_ptr<RegionGeometry> geometry;
    GridCentroids grid;
    int acceptedThresholds = 0;
};

/// The region's raw points averaged onto the grid of `scale` region spacings, analysed as a
/// region of their own, its rim filled from its interior.
std::shared_ptr<RegionGeometry> coarseGeometry(const GridCentroids& grid, const RegionGeometry& g,
                                               const SmoothEdgeOptions& coarseOptions,
                                               const ProgressSpan& progress)
{
    NeighbourOptions no;
    no.k = g.neighbours.k();
    Neighbourhoods cn = nearestNeighbours(grid.points, no, progress.part(0.0, 0.15));
    const double coarseSpacing = meanSpacing(cn);
    auto coarse = std::make_shared<RegionGeometry>(
        analyseRegion(grid.points, std::move(cn), NormalMatrix(), g.region, coarseSpacing,
                      coarseOptions, progress.part(0.15, 1.0)));
    fillRimFromInterior(*coarse, coarseOptions.scales.rimWidth * coarseSpacing);
    return coarse;
}

/// The coarse scales (2, 4, ... spacings) weighed in turn, each trial added to g.scaleTrials,
/// until the largest visible radius covers the region (extent) or too few cells are left.
/// Each scale has about a quarter of the points of the one before: the first is told as half
/// of `progress`, the next as half of the rest, and so on.
CoarseScale weighCoarseScales(const PointMatrix& raw, double extent, RegionGeometry& g,
                              const SmoothEdgeOptions& options, const ProgressSpan& progress)
{
    const CurvatureScaleOptions& so = options.scales;
    const SmoothEdgeOptions coarseOptions = coarseScaleOptions(options);
    CoarseScale best;
    double told = 0.0;
    for (double s = 2.0; s <= so.maxScale; s *= 2.0) {
        const ProgressSpan trial = progress.part(told, 0.5 * (1.0 + told));
        told = 0.5 * (1.0 + told);
        // A coarser scale is an offer, not a stage: one that cannot be analysed (too few or
        // degenerate cells) ends the trials and the region keeps what it has.
        try {
            GridCentroids grid = gridCentroids(raw, s * g.spacing);
            const Eigen::Index cells = grid.points.rows();
            if (cells < std::max<Eigen::Index>(so.minPoints, g.neighbours.k() + 1)) {
                break;
            }
            trial.report(0.1);
            const std::shared_ptr<RegionGeometry> coarse =
                coarseGeometry(grid, g, coarseOptions, trial.part(0.1, 0.8));
            g.scaleTrials.push_back(weighScale(*coarse, g.spacing, coarseOptions));
            trial.report(1.0);
            // The finer of two coarse scales on a tie.
            if (g.scaleTrials.back().acceptedThresholds > best.acceptedThresholds) {
                best.acceptedThresholds = g.scaleTrials.back().acceptedThresholds;
                best.geometry = coarse;
                best.grid = std::move(grid);
            }
            if (largestVisibleRadius(coarse->curvatureNoise, options) >= extent) {
                break;
            }
        } catch (const std::invalid_argument&) {
            break;
        }
    }
    return best;
}

/// Beyond the paper: the scale of a region's curvature. At the cloud's own sampling a fillet of
/// radius r stands minSeparation noise floors above a flat face only while r stays under
/// 1 / (2 minSeparation floor); when that radius is smaller than the region itself, larger
/// fillets could hide in the noise, and the region is averaged onto coarser grids (2, 4, ...
/// spacings, CurvatureScaleOptions) until the radius covers the region or too few cells are
/// left. At each scale the automatic rule weighs the region's thresholds on the coarse
/// geometry; the scale with the most accepted thresholds wins, the finer one on a tie (it
/// resolves smaller fillets and places the lines more closely). Its curvature is carried back
/// to the region's points, where the labels, clusters and lines are drawn as at scale 1.
void chooseCurvatureScale(const PointMatrix& P, const std::vector<int>& members, RegionGeometry& g,
                          const SmoothEdgeOptions& options, const ProgressSpan& progress)
{
    const CurvatureScaleOptions& so = options.scales;
    requireScaleOptions(so);
    if (!(so.maxScale >= 2.0) || !(g.curvatureNoise > 0.0)) {
        return;
    }
    const Eigen::Index m = g.points.rows();
    PointMatrix raw(m, 3);
    for (Eigen::Index i = 0; i < m; ++i) {
        raw.row(i) = P.row(members[static_cast<size_t>(i)]);
    }
    const double extent = 0.5 * (raw.colwise().maxCoeff() - raw.colwise().minCoeff()).norm();
    if (largestVisibleRadius(g.curvatureNoise, options) >= extent) {
        return;
    }
    // A face within noise of its plane (one in a thousand of its points may stray farther,
    // noise's own tail at 3.3 standard deviations) has no fillet to hide.
    if (m >= 3 && planeDeviation(raw, 0.001) <= so.planeTolerance * g.noise * g.spacing) {
        return;
    }
    // The coarse scales first: the region's own scale needs weighing (a labelling of all its
    // points per threshold searched) only when one of them accepts a threshold.
    RegionGeometry::ScaleTrial own;
    own.points = static_cast<int>(m);
    own.noise = g.noise;
    g.scaleTrials.push_back(own);
    CoarseScale chosen = weighCoarseScales(raw, extent, g, options, progress.part(0.0, 0.7));
    if (!chosen.geometry) {
        return;
    }
    g.scaleTrials.front() = weighScale(g, g.spacing, coarseScaleOptions(options));
    progress.report(0.9);
    if (g.scaleTrials.front().acceptedThresholds >= chosen.acceptedThresholds) {
        return;
    }
    g.curvatureScale = chosen.geometry->spacing / g.spacing;
    g.curvatureNoise = chosen.geometry->curvatureNoise;
    g.curvature =
        valuesAtPoints(raw, chosen.grid, chosen.geometry->neighbours, chosen.geometry->curvature,
                       so.carryWidth * chosen.geometry->spacing);
    g.coarse = std::move(chosen.geometry);
    g.coarseRowOf = std::move(chosen.grid.cellOf);
}

} // namespace

double estimateNoise(const PointMatrix& P, const NormalMatrix& normals, const Neighbourhoods& N,
                     double spacing, int maxSamples)
{
    const Eigen::Index n = P.rows();
    if (n == 0 || N.size() != n || normals.rows() != n || !(spacing > 0.0) || N.k() < 6) {
        throw std::invalid_argument("estimateNoise: empty or mismatched input");
    }
    const Eigen::Index stride =
        maxSamples > 0 ? std::max<Eigen::Index>(1, (n + maxSamples - 1) / maxSamples) : 1;
    const Eigen::Index samples = (n + stride - 1) / stride;
    std::vector<double> residuals(static_cast<size_t>(samples), 0.0);
#pragma omp parallel for schedule(static)
    for (Eigen::Index s = 0; s < samples; ++s) {
        // The point's height over the quadric fitted to its neighbours alone: its noise.
        const double height = quadricHeight(P, normals, N, s * stride);
        residuals[static_cast<size_t>(s)] = std::isfinite(height) ? std::abs(height) : 0.0;
    }
    return median(std::move(residuals)) / spacing;
}

namespace {

/// The options and the cloud's normals (none, or one per point of P) analyseRegion can use.
void requireRegionInputs(const PointMatrix& P, const NormalMatrix& normals,
                         const SmoothEdgeOptions& options)
{
    if (options.curvatureAveragingPasses < 0) {
        throw std::invalid_argument("curvature averaging passes must not be negative");
    }
    if (normals.rows() != 0 && normals.rows() != P.rows()) {
        throw std::invalid_argument("analyseRegion: the cloud's normals and points differ in "
                                    "number");
    }
}

/// The rest of analyseRegion once the region's points, neighbourhoods and normals are in g:
/// noise, smoothing, 1-rings, curvature, its noise floor and scale.
/// `progress` is told in shares measured on noisy clouds of a million points.
void analyseRegionGeometry(const PointMatrix& P, RegionGeometry& g,
                           const SmoothEdgeOptions& options, const ProgressSpan& progress)
{
    g.noise = estimateNoise(g.points, g.normals, g.neighbours, g.spacing, options.noiseSamples);
    progress.report(0.05);
    g.smoothed =
        options.smoothing == SmoothingMode::Always ||
        (options.smoothing == SmoothingMode::Automatic && g.noise > options.noiseThreshold);
    if (g.smoothed) {
        // Sec. 2.4: smoothing inside the region only, after the sharp edges are found, so it
        // cannot round them off.
        g.points = laplacianSmooth(g.points, g.neighbours, allIndices(g.points.rows()),
                                   options.smoothingOptions, progress.part(0.05, 0.25));
        g.normals = pcaNormals(g.points, g.neighbours, {}, progress.part(0.25, 0.3)).normals;
    }
    g.ring = ringNeighbourhoods(g.points, g.normals, g.neighbours, {}, progress.part(0.3, 0.35));
    g.curvature = regionCurvature(g.points, g.normals, g.neighbours,
                                  g.smoothed ? options.curvatureAveragingPasses : 0,
                                  options.curvature, progress.part(0.35, 0.45));
    g.curvatureNoise =
        curvatureNoiseFloor(g.noise, g.neighbours.k(), g.smoothed, options) / g.spacing;
    progress.report(0.47);
    chooseCurvatureScale(P, g.members, g, options, progress.part(0.47, 1.0));
}

} // namespace

RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options,
                             const ProgressSpan& progress)
{
    return analyseRegion(P, N, NormalMatrix(), region, members, regionId, spacing, options,
                         progress);
}

RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const NormalMatrix& normals, const std::vector<int>& region,
                             const std::vector<int>& members, int regionId, double spacing,
                             const SmoothEdgeOptions& options, const ProgressSpan& progress)
{
    requireRegionInputs(P, normals, options);
    if (members.size() <= static_cast<size_t>(N.k())) {
        throw std::invalid_argument("smooth region " + std::to_string(regionId) + " has " +
                                    std::to_string(members.size()) +
                                    " points, too few for its curvature");
    }
    RegionGeometry g;
    g.region = regionId;
    g.members = members;
    g.spacing = spacing;
    g.neighbours = regionNeighbourhoods(N, region, members, regionId);
    const Eigen::Index m = static_cast<Eigen::Index>(members.size());
    g.points.resize(m, 3);
    adviseHugePagesOf(g.points);
    for (Eigen::Index i = 0; i < m; ++i) {
        g.points.row(i) = P.row(members[static_cast<size_t>(i)]);
    }
    if (normals.rows() == 0) {
        g.normals = pcaNormals(g.points, g.neighbours, {}, progress.part(0.0, 0.1)).normals;
    } else {
        // A row of the region whose neighbours are all in the region is the cloud's row, its
        // fit the cloud's fit.
        g.normals.resize(m, 3);
        std::vector<char> cut(static_cast<size_t>(m), 0);
#pragma omp parallel for schedule(static, 4096)
        for (Eigen::Index i = 0; i < m; ++i) {
            const int p = members[static_cast<size_t>(i)];
            g.normals.row(i) = normals.row(p);
            for (int j = 0; j < N.k(); ++j) {
                cut[i] = cut[i] || region[N.indices(p, j)] != regionId;
            }
        }
        std::vector<int> cutRows;
        for (Eigen::Index i = 0; i < m; ++i) {
            if (cut[i]) {
                cutRows.push_back(static_cast<int>(i));
            }
        }
        pcaNormalsOfRows(g.points, g.neighbours, cutRows, g.normals);
    }
    progress.report(0.1);
    analyseRegionGeometry(P, g, options, progress.part(0.1, 1.0));
    return g;
}

RegionGeometry analyseRegion(const PointMatrix& P, Neighbourhoods&& N, const NormalMatrix& normals,
                             int regionId, double spacing, const SmoothEdgeOptions& options,
                             const ProgressSpan& progress)
{
    requireRegionInputs(P, normals, options);
    if (N.size() != P.rows() || P.rows() <= N.k()) {
        throw std::invalid_argument("smooth region " + std::to_string(regionId) + " has " +
                                    std::to_string(P.rows()) + " points and " +
                                    std::to_string(N.size()) +
                                    " neighbourhoods: too few, or not the same cloud");
    }
    RegionGeometry g;
    g.region = regionId;
    g.members = allIndices(P.rows());
    g.spacing = spacing;
    g.neighbours = std::move(N);
    g.points = P;
    // Every neighbour is in the region: the cloud's normals are the region's.
    g.normals = normals.rows() == 0
                    ? pcaNormals(g.points, g.neighbours, {}, progress.part(0.0, 0.1)).normals
                    : normals;
    analyseRegionGeometry(P, g, options, progress.part(0.1, 1.0));
    return g;
}

} // namespace featurelines
