// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/SmoothEdges.h"

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

#include <Eigen/Geometry>

#include "FeatureLines/boundary/Boundary.h"
#include "FeatureLines/support/DisjointSets.h"
#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/support/IdleThreads.h"
#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/LineBand.h"
#include "FeatureLines/smooth/RegionNeighbourhoods.h"

namespace featurelines {

namespace {

std::vector<int> allIndices(Eigen::Index n)
{
    std::vector<int> all(static_cast<size_t>(n));
    std::iota(all.begin(), all.end(), 0);
    return all;
}

/// The smallest piece of one level that counts as a patch, in the region's points, when the
/// curvature was computed at a coarser scale: a patch's worth of its samples
/// (AutomaticThresholdOptions::minInnerPoints), each standing for curvatureScale^2 of the
/// region's points. A smaller piece of the smooth carried-back field is a blob of the coarse
/// samples' noise. At the region's own scale there is no such size: a piece of a few points can
/// be a real patch's end (a fillet border running into a corner), and noise islands there are
/// told by their values (islandMargin).
int minIslandPoints(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    if (!(region.curvatureScale > 1.0)) {
        return 0;
    }
    const int inner = options.automatic.minInnerPoints > 0 ? options.automatic.minInnerPoints
                                                           : 2 * region.neighbours.k();
    return static_cast<int>(std::lround(inner * region.curvatureScale * region.curvatureScale));
}

ThresholdOptions histogramOptions(const RegionGeometry& region, const SmoothEdgeOptions& options)
{
    ThresholdOptions h = options.histogram;
    if (h.outlierPercent < 0.0) {
        // Sec. 2.4: outliers of the curvature come with noise; a clean region keeps them all.
        h.outlierPercent = region.smoothed ? 1.0 : 0.0;
    }
    return h;
}

std::vector<double> valuesOf(const RegionGeometry& region, const std::vector<int>& subset)
{
    std::vector<double> values;
    if (subset.empty()) {
        values.assign(region.curvature.data(), region.curvature.data() + region.curvature.size());
    } else {
        values.reserve(subset.size());
        for (int i : subset) {
            values.push_back(region.curvature[i]);
        }
    }
    return values;
}

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

double median(std::vector<double> v)
{
    if (v.empty()) {
        return 0.0;
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

/// The middle of the valley that starts at a threshold: Sec. 2.2 puts tau right after the peak
/// b1 (the end of its run of k bins), where the valley starts; the valley ends where the
/// histogram rises to the next peak: k bins holding twice the valley's floor so far (the least
/// k bins from b2 on; b2 itself may still lie on the lower peak's slope) and at least
/// minPeakPercent of the values (the least peak Sec. 2.2 may follow). Where no such rise
/// follows (a noisy valley whose next level is a low plateau, or the top of the histogram),
/// tau stays: there the lower peak's noise tail already reaches to the middle. The
/// quadric fit blurs a curvature step symmetrically, so the middle of the values between the
/// two levels crosses on the tangent line, while the valley's start can lie up to a
/// neighbourhood radius off it, onto the flatter side (a clean plane's values are one spike
/// at 0, and the valley starts one bin above it).
double valleyMiddle(const ThresholdResult& t, double minPeakPercent)
{
    const Histogram& h = t.histogram;
    const int L = h.bins();
    const int k = std::max(1, t.joinedBins);
    if (L == 0 || !(h.binWidth > 0.0)) {
        return t.threshold;
    }
    const int first = static_cast<int>(std::lround((t.threshold - h.minimum) / h.binWidth));
    const double values =
        static_cast<double>(std::accumulate(h.counts.begin(), h.counts.end(), 0L));
    const double minPeak = std::max(minPeakPercent / 100.0 * values, 1.0);
    // The valley's floor so far: the least of its windows of k bins, from b2 at its start on.
    double floor = static_cast<double>(t.valleyCount);
    double end = t.threshold;
    for (int j = std::max(first, 0); j < L; ++j) {
        const int last = std::min(L, j + k);
        double count = 0.0;
        for (int b = j; b < last; ++b) {
            count += static_cast<double>(h.counts[b]);
        }
        count *= static_cast<double>(k) / (last - j);
        if (count > std::max(2.0 * floor, minPeak)) {
            end = h.minimum + j * h.binWidth;
            break;
        }
        floor = std::min(floor, count);
    }
    return 0.5 * (t.threshold + std::max(end, t.threshold));
}

/// The share of the border points of a labelling (at most `samples` of them, evenly strided)
/// that have a point of curvature at most `low` or above `high` within `reach` fit radii
/// (the k-th neighbour's distance; found breadth first over the neighbourhoods).
double straddleShare(const RegionGeometry& g, const std::vector<PointLabel>& labels, int samples,
                     double low, double high, double reach)
{
    std::vector<int> border;
    for (size_t i = 0; i < labels.size(); ++i) {
        if (labels[i] == PointLabel::Border) {
            border.push_back(static_cast<int>(i));
        }
    }
    if (border.empty() || (std::isinf(low) && std::isinf(high))) {
        return 0.0;
    }
    const size_t stride =
        samples > 0 ? std::max<size_t>(1, (border.size() + samples - 1) / samples) : 1;
    const long count = static_cast<long>((border.size() + stride - 1) / stride);
    const Neighbourhoods& N = g.neighbours;
    long straddling = 0;
#pragma omp parallel reduction(+ : straddling)
    {
        // The sample that last queued each point: the queue's membership test in O(1).
        std::vector<long> queuedBy(labels.size(), -1);
        std::vector<int> queue;
#pragma omp for schedule(dynamic, 16)
        for (long s = 0; s < count; ++s) {
            const int p = border[static_cast<size_t>(s) * stride];
            const double reach2 = reach * reach * N.squaredDistances(p, N.k() - 1);
            // Breadth first over the neighbourhoods, within the reach.
            queue.assign(1, p);
            queuedBy[static_cast<size_t>(p)] = s;
            bool outside = false;
            for (size_t head = 0; head < queue.size() && !outside; ++head) {
                const int q = queue[head];
                for (int j = 0; j < N.k() && !outside; ++j) {
                    const int r = N.indices(q, j);
                    if (queuedBy[static_cast<size_t>(r)] == s ||
                        (g.points.row(r) - g.points.row(p)).squaredNorm() > reach2) {
                        continue;
                    }
                    const double v = g.curvature[r];
                    outside = v <= low || v > high;
                    queue.push_back(r);
                    queuedBy[static_cast<size_t>(r)] = s;
                }
            }
            straddling += outside ? 1 : 0;
        }
    }
    return static_cast<double>(straddling) / static_cast<double>(count);
}

/// The curvature with the noise islands of threshold tau levelled: connected pieces (over the
/// 1-rings) of points above tau whose 90th percentile stays below tau + margin, or that hold
/// fewer than minPoints points, are set to tau (low); pieces at or below tau whose 10th
/// percentile stays above tau - margin, or that hold fewer than minPoints, are set just above
/// it (high). Only the points of `points` are looked at.
Eigen::VectorXd withoutNoiseIslands(const Eigen::VectorXd& curvature, double tau,
                                    const RingNeighbourhoods& ring, const std::vector<int>& points,
                                    double margin, int minPoints)
{
    Eigen::VectorXd result = curvature;
    if (!(margin > 0.0) && minPoints <= 1) {
        return result;
    }
    const Eigen::Index n = curvature.size();
    std::vector<char> inSet(static_cast<size_t>(n), 0);
    for (int i : points) {
        inSet[static_cast<size_t>(i)] = 1;
    }
    std::vector<char> seen(static_cast<size_t>(n), 0);
    std::vector<int> piece, stack;
    std::vector<double> values;
    const double above = std::nextafter(tau, std::numeric_limits<double>::infinity());
    for (int s : points) {
        if (seen[static_cast<size_t>(s)]) {
            continue;
        }
        const bool high = curvature[s] > tau;
        piece.assign(1, s);
        stack.assign(1, s);
        seen[static_cast<size_t>(s)] = 1;
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            for (const int* q = ring.begin(p); q != ring.end(p); ++q) {
                if (inSet[static_cast<size_t>(*q)] && !seen[static_cast<size_t>(*q)] &&
                    (curvature[*q] > tau) == high) {
                    seen[static_cast<size_t>(*q)] = 1;
                    piece.push_back(*q);
                    stack.push_back(*q);
                }
            }
        }
        values.clear();
        for (int p : piece) {
            values.push_back(curvature[p]);
        }
        const size_t at = high ? values.size() * 9 / 10 : values.size() / 10;
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at),
                         values.end());
        const double extreme = values[at];
        if (static_cast<int>(piece.size()) < minPoints ||
            (margin > 0.0 && (high ? extreme < tau + margin : extreme > tau - margin))) {
            for (int p : piece) {
                result[p] = high ? tau : above;
            }
        }
    }
    return result;
}

/// The local contrast across threshold tau at point p of the geometry g: among the points
/// within two fit radii (two hops of the neighbourhoods), the median curvature of those above
/// tau minus that of those at or below it; NaN when they lie on one side only.
double localContrast(const RegionGeometry& g, const Eigen::VectorXd& curvature, double tau, int p)
{
    const Neighbourhoods& N = g.neighbours;
    const double reach2 = 4.0 * N.squaredDistances(p, N.k() - 1);
    std::vector<int> near{p};
    for (int j = 0; j < N.k(); ++j) {
        const int q = N.indices(p, j);
        near.push_back(q);
        for (int l = 0; l < N.k(); ++l) {
            near.push_back(N.indices(q, l));
        }
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::vector<double> high, low;
    for (int q : near) {
        if ((g.points.row(q) - g.points.row(p)).squaredNorm() <= reach2) {
            (curvature[q] > tau ? high : low).push_back(curvature[q]);
        }
    }
    if (high.empty() || low.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return median(std::move(high)) - median(std::move(low));
}

/// The largest patches of the curvature levels (low, tau] and (tau, high]: points with values
/// in the level whose whole 1-ring is in it too (the inner points of Sec. 3 for that level),
/// connected through the 1-rings; returns their numbers of points, {above, below}. Both levels
/// are searched in one sweep: a patch never leaves its level.
std::pair<int, int> largestPatches(const Eigen::VectorXd& curvature, double low, double tau,
                                   double high, const RingNeighbourhoods& ring)
{
    const Eigen::Index n = curvature.size();
    constexpr char outside = 0, above = 1, below = 2;
    const auto levelOf = [&](int i) {
        const double c = curvature[i];
        return c > tau && c <= high ? above : (c > low && c <= tau ? below : outside);
    };
    // Per point: its level, then the level it is an interior point of, or outside.
    std::vector<char> levels(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        levels[i] = levelOf(static_cast<int>(i));
    }
    std::vector<char> state(static_cast<size_t>(n), outside);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        const char level = levels[i];
        if (level == outside || ring.size(i) == 0) {
            continue;
        }
        bool interior = true;
        for (const int* q = ring.begin(i); q != ring.end(i) && interior; ++q) {
            interior = levels[*q] == level;
        }
        state[i] = interior ? level : outside;
    }
    // The patches: interior points of one level joined through the 1-rings (both ways).
    DisjointSets sets(static_cast<int>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (state[i] == outside) {
            continue;
        }
        int root = static_cast<int>(i);
        for (const int* q = ring.begin(i); q != ring.end(i); ++q) {
            if (state[*q] == state[i]) {
                root = sets.join(root, *q);
            }
        }
    }
    // Sizes per set, counted in runs of points of one set (rows in Morton order: long runs).
    const std::vector<int> root = sets.representatives();
    std::vector<int> size(static_cast<size_t>(n), 0);
#pragma omp parallel
    {
        int current = -1, run = 0;
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            const int r = state[i] == outside ? -1 : root[i];
            if (r != current) {
                if (run > 0) {
#pragma omp atomic
                    size[current] += run;
                }
                current = r;
                run = 0;
            }
            run += r >= 0 ? 1 : 0;
        }
        if (run > 0) {
#pragma omp atomic
            size[current] += run;
        }
    }
    int largestAbove = 0, largestBelow = 0;
#pragma omp parallel for schedule(static, 4096) reduction(max : largestAbove, largestBelow)
    for (Eigen::Index i = 0; i < n; ++i) {
        if (root[i] == i && state[i] == above) {
            largestAbove = std::max(largestAbove, size[i]);
        } else if (root[i] == i && state[i] == below) {
            largestBelow = std::max(largestBelow, size[i]);
        }
    }
    return {largestAbove, largestBelow};
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
                                const CurvatureOptions& options)
{
    if (averagingPasses == 0) {
        return meanCurvature(P, normals, N, options);
    }
    CurvatureOptions signedOptions = options;
    signedOptions.signedCurvature = true;
    Eigen::VectorXd H = meanCurvature(P, orientedNormals(normals, N), N, signedOptions);
    for (int pass = 0; pass < averagingPasses; ++pass) {
        H = averageOverNeighbours(H, N);
    }
    return options.signedCurvature ? H : Eigen::VectorXd(H.cwiseAbs());
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
        // The grid's mean spacing, then heights of `level` spacings over the estimate's
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
            std::vector<int> all(static_cast<size_t>(P.rows()));
            std::iota(all.begin(), all.end(), 0);
            P = laplacianSmooth(P, N, all, so);
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
        perNoise = estimated > 0.0 ? median(std::move(interior)) / 0.6745 / estimated : 0.0;
        std::lock_guard<std::mutex> lock(mutex);
        cache[key] = perNoise;
    }
    return noise * perNoise;
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
                          const SmoothEdgeOptions& options)
{
    const CurvatureScaleOptions& so = options.scales;
    if (!(so.maxScale >= 1.0) || !(so.carryWidth > 0.0) || !(so.rimWidth >= 0.0) ||
        so.minPoints < 0 || !(so.planeTolerance >= 0.0)) {
        throw std::invalid_argument("curvature scales: the coarsest scale must be at least 1 "
                                    "spacing, the carry width positive, the rim width, the "
                                    "plane tolerance and the least number of cells not "
                                    "negative");
    }
    if (!(so.maxScale >= 2.0) || !(g.curvatureNoise > 0.0)) {
        return;
    }
    const double minSeparation = std::max(options.automatic.minSeparation, 1.0);
    const auto largestRadius = [&](double floor) { return 1.0 / (2.0 * minSeparation * floor); };
    const Eigen::Index m = g.points.rows();
    PointMatrix raw(m, 3);
    for (Eigen::Index i = 0; i < m; ++i) {
        raw.row(i) = P.row(members[static_cast<size_t>(i)]);
    }
    const double extent = 0.5 * (raw.colwise().maxCoeff() - raw.colwise().minCoeff()).norm();
    if (largestRadius(g.curvatureNoise) >= extent) {
        return;
    }
    // A face within noise of its plane (one in a thousand of its points may stray farther,
    // noise's own tail at 3.3 standard deviations) has no fillet to hide.
    if (m >= 3 && planeDeviation(raw, 0.001) <= so.planeTolerance * g.noise * g.spacing) {
        return;
    }
    SmoothEdgeOptions coarseOptions = options;
    coarseOptions.scales.maxScale = 1.0;
    // The grid's averaging has already taken most of the noise; averaging the curvature
    // too would blur each transition over two more coarse neighbourhoods, and carry the mean
    // curvature through zero between a concave fillet and the convex face it meets (a band
    // that looks like a flat patch of its own).
    coarseOptions.curvatureAveragingPasses = 0;
    const auto weigh = [&](const RegionGeometry& r) {
        RegionGeometry::ScaleTrial trial;
        trial.scale = r.spacing / g.spacing;
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
    };
    // The coarse scales first: the region's own scale needs weighing (a labelling of all its
    // points per threshold searched) only when one of them accepts a threshold.
    RegionGeometry::ScaleTrial own;
    own.points = static_cast<int>(m);
    own.noise = g.noise;
    g.scaleTrials.push_back(own);
    int best = 0;
    std::shared_ptr<RegionGeometry> chosen;
    GridCentroids chosenGrid;
    for (double s = 2.0; s <= so.maxScale; s *= 2.0) {
        // A coarser scale is an offer, not a stage: one that cannot be analysed (too few or
        // degenerate cells) ends the trials and the region keeps what it has.
        try {
            GridCentroids grid = gridCentroids(raw, s * g.spacing);
            const Eigen::Index cells = grid.points.rows();
            if (cells < std::max<Eigen::Index>(so.minPoints, g.neighbours.k() + 1)) {
                break;
            }
            NeighbourOptions no;
            no.k = g.neighbours.k();
            Neighbourhoods cn = nearestNeighbours(grid.points, no);
            const double coarseSpacing = meanSpacing(cn);
            auto coarse = std::make_shared<RegionGeometry>(
                analyseRegion(grid.points, std::move(cn), NormalMatrix(), g.region,
                              coarseSpacing, coarseOptions));
            fillRimFromInterior(*coarse, so.rimWidth * coarseSpacing);
            g.scaleTrials.push_back(weigh(*coarse));
            // The finer of two coarse scales on a tie.
            if (g.scaleTrials.back().acceptedThresholds > best) {
                best = g.scaleTrials.back().acceptedThresholds;
                chosen = coarse;
                chosenGrid = std::move(grid);
            }
            if (largestRadius(coarse->curvatureNoise) >= extent) {
                break;
            }
        } catch (const std::invalid_argument&) {
            break;
        }
    }
    if (!chosen) {
        return;
    }
    g.scaleTrials.front() = weigh(g);
    if (g.scaleTrials.front().acceptedThresholds >= best) {
        return;
    }
    g.curvatureScale = chosen->spacing / g.spacing;
    g.curvatureNoise = chosen->curvatureNoise;
    g.curvature = valuesAtPoints(raw, chosenGrid, chosen->neighbours, chosen->curvature,
                                 so.carryWidth * chosen->spacing);
    g.coarse = std::move(chosen);
    g.coarseRowOf = std::move(chosenGrid.cellOf);
}

/// Direction of a line at one end (pointing out of the line), from the end vertex and the
/// vertex about `length` back along it.
Eigen::RowVector3d endDirection(const PointMatrix& V, bool atEnd, double length)
{
    const Eigen::Index n = V.rows();
    const Eigen::Index tip = atEnd ? n - 1 : 0;
    const Eigen::Index step = atEnd ? -1 : 1;
    Eigen::Index back = tip;
    double walked = 0.0;
    while (back + step >= 0 && back + step < n && walked < length) {
        walked += (V.row(back + step) - V.row(back)).norm();
        back += step;
    }
    const Eigen::RowVector3d d = V.row(tip) - V.row(back);
    const double norm = d.norm();
    return norm > 0.0 ? Eigen::RowVector3d(d / norm) : Eigen::RowVector3d::Zero();
}

/// Closest point to p on the polylines; false when there is none.
bool closestOnLines(const std::vector<Polyline>& lines, const Eigen::RowVector3d& p,
                    Eigen::RowVector3d& closest)
{
    double best = std::numeric_limits<double>::infinity();
    for (const Polyline& line : lines) {
        const Eigen::Index n = line.points.rows();
        const Eigen::Index segments = line.closed ? n : n - 1;
        if (n == 1) {
            const double d = (line.points.row(0) - p).squaredNorm();
            if (d < best) {
                best = d;
                closest = line.points.row(0);
            }
        }
        for (Eigen::Index s = 0; s < segments; ++s) {
            const Eigen::RowVector3d a = line.points.row(s);
            const Eigen::RowVector3d ab = line.points.row((s + 1) % n) - a;
            const double len2 = ab.squaredNorm();
            const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
            const Eigen::RowVector3d q = a + t * ab;
            const double d = (q - p).squaredNorm();
            if (d < best) {
                best = d;
                closest = q;
            }
        }
    }
    return std::isfinite(best);
}

} // namespace

std::vector<char> anchorLineEnds(LineNetwork& network, const std::vector<Polyline>& anchors,
                                 double reach, double maxAngleDegrees)
{
    std::vector<char> anchored(2 * network.lines.size(), 0);
    if (anchors.empty() || !(reach > 0.0)) {
        return anchored;
    }
    const double cosMax = std::cos(maxAngleDegrees * 3.14159265358979323846 / 180.0);
    for (size_t l = 0; l < network.lines.size(); ++l) {
        Polyline& line = network.lines[l];
        if (line.closed || line.points.rows() < 2) {
            continue;
        }
        for (int end = 0; end < 2; ++end) {
            const bool atEnd = end == 1;
            if ((atEnd ? line.endJunction : line.startJunction) >= 0) {
                continue;
            }
            const Eigen::Index tip = atEnd ? line.points.rows() - 1 : 0;
            const Eigen::RowVector3d p = line.points.row(tip);
            Eigen::RowVector3d q;
            if (!closestOnLines(anchors, p, q)) {
                continue;
            }
            const double distance = (q - p).norm();
            if (distance > reach) {
                continue;
            }
            // Ahead of the end: the line runs on towards the anchor line, not along it.
            const Eigen::RowVector3d direction = endDirection(line.points, atEnd, reach);
            if (distance > 0.0 && direction.dot((q - p) / distance) < cosMax) {
                continue;
            }
            PointMatrix extended(line.points.rows() + 1, 3);
            if (atEnd) {
                extended << line.points, q;
            } else {
                extended << q, line.points;
            }
            line.points = std::move(extended);
            anchored[2 * l + static_cast<size_t>(end)] = 1;
        }
    }
    return anchored;
}

void dropLines(LineNetwork& network, std::vector<char>& anchored, const std::vector<char>& drop)
{
    std::vector<Polyline>& lines = network.lines;
    anchored.resize(2 * lines.size(), 0);
    std::vector<char> removed = drop;
    removed.resize(lines.size(), 0);
    // Junctions left with fewer than three line ends: one end becomes an end on nothing (it
    // ended on lines that are gone), two ends are one line through the point (a loop when
    // both are the same line's). Merges can leave a line with both ends at one junction,
    // hence the passes.
    for (bool changed = true; changed;) {
        changed = false;
        std::map<int, std::vector<std::pair<size_t, int>>> ends; // junction -> (line, 0|1)
        for (size_t l = 0; l < lines.size(); ++l) {
            if (removed[l] || lines[l].closed) {
                continue;
            }
            if (lines[l].startJunction >= 0) {
                ends[lines[l].startJunction].emplace_back(l, 0);
            }
            if (lines[l].endJunction >= 0) {
                ends[lines[l].endJunction].emplace_back(l, 1);
            }
        }
        for (const auto& [junction, at] : ends) {
            if (at.size() >= 3) {
                continue;
            }
            if (at.size() == 1) {
                Polyline& line = lines[at[0].first];
                (at[0].second == 0 ? line.startJunction : line.endJunction) = -1;
                anchored[2 * at[0].first + static_cast<size_t>(at[0].second)] = 0;
                continue;
            }
            auto [a, aEnd] = at[0];
            auto [b, bEnd] = at[1];
            if (removed[a] || removed[b]) {
                continue; // touched by a merge of this pass
            }
            changed = true;
            if (a == b) {
                Polyline& line = lines[a];
                if (line.points.rows() > 2) {
                    line.points.conservativeResize(line.points.rows() - 1, 3);
                }
                line.closed = true;
                line.startJunction = line.endJunction = -1;
                continue;
            }
            // a ends at the junction, b starts there: a + b.
            auto reverse = [&](size_t l) {
                Polyline& line = lines[l];
                line.points = line.points.colwise().reverse().eval();
                std::swap(line.startJunction, line.endJunction);
                std::swap(anchored[2 * l], anchored[2 * l + 1]);
            };
            if (aEnd == 0) {
                reverse(a);
            }
            if (bEnd == 1) {
                reverse(b);
            }
            Polyline& first = lines[a];
            const Polyline& second = lines[b];
            PointMatrix joined(first.points.rows() + second.points.rows() - 1, 3);
            joined << first.points, second.points.bottomRows(second.points.rows() - 1);
            first.points = std::move(joined);
            first.endJunction = second.endJunction;
            anchored[2 * a + 1] = anchored[2 * b + 1];
            removed[b] = 1;
        }
    }
    std::vector<Polyline> kept;
    std::vector<char> keptAnchored;
    std::map<int, int> newJunction;
    for (size_t l = 0; l < lines.size(); ++l) {
        if (removed[l]) {
            continue;
        }
        Polyline line = std::move(lines[l]);
        for (int* j : {&line.startJunction, &line.endJunction}) {
            if (*j >= 0) {
                *j = newJunction.emplace(*j, static_cast<int>(newJunction.size())).first->second;
            }
        }
        kept.push_back(std::move(line));
        keptAnchored.push_back(anchored[2 * l]);
        keptAnchored.push_back(anchored[2 * l + 1]);
    }
    PointMatrix junctions(static_cast<Eigen::Index>(newJunction.size()), 3);
    for (const auto& [old, now] : newJunction) {
        junctions.row(now) = network.junctions.row(old);
    }
    lines = std::move(kept);
    anchored = std::move(keptAnchored);
    network.junctions = std::move(junctions);
}

int pruneDanglingLines(LineNetwork& network, std::vector<char>& anchored, double minLength)
{
    if (!(minLength > 0.0)) {
        return 0;
    }
    anchored.resize(2 * network.lines.size(), 0);
    int pruned = 0;
    for (;;) {
        // Short lines from a junction to an end on nothing.
        std::vector<char> drop(network.lines.size(), 0);
        int found = 0;
        for (size_t l = 0; l < network.lines.size(); ++l) {
            const Polyline& line = network.lines[l];
            if (line.closed) {
                continue;
            }
            const bool startFree = line.startJunction < 0 && !anchored[2 * l];
            const bool endFree = line.endJunction < 0 && !anchored[2 * l + 1];
            const bool dangling =
                (startFree && line.endJunction >= 0) || (endFree && line.startJunction >= 0);
            double length = 0.0;
            for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
                length += (line.points.row(i) - line.points.row(i - 1)).norm();
            }
            if (dangling && length < minLength) {
                drop[l] = 1;
                ++found;
            }
        }
        if (found == 0) {
            return pruned;
        }
        pruned += found;
        dropLines(network, anchored, drop);
    }
}

int dropOpenPieces(LineNetwork& network, const std::vector<char>& anchored, double minLength)
{
    const size_t lineCount = network.lines.size();
    if (!(minLength > 0.0) || lineCount == 0) {
        return 0;
    }
    // Pieces: lines joined through shared junctions.
    DisjointSets sets(static_cast<int>(lineCount));
    std::map<int, int> lineAtJunction;
    for (size_t l = 0; l < lineCount; ++l) {
        for (int j : {network.lines[l].startJunction, network.lines[l].endJunction}) {
            if (j < 0) {
                continue;
            }
            auto [it, inserted] = lineAtJunction.emplace(j, static_cast<int>(l));
            if (!inserted) {
                sets.join(static_cast<int>(l), it->second);
            }
        }
    }
    struct Piece
    {
        double length = 0.0;
        int openLines = 0;
        int looseEnds = 0; // ends on no junction, anchored or not
        int freeEnds = 0;  // ends on nothing at all
        std::vector<int> junctions;
        bool closedLine = false;
    };
    std::map<int, Piece> pieces;
    for (size_t l = 0; l < lineCount; ++l) {
        const Polyline& line = network.lines[l];
        Piece& p = pieces[sets.find(static_cast<int>(l))];
        for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
            p.length += (line.points.row(i) - line.points.row(i - 1)).norm();
        }
        if (line.closed) {
            p.closedLine = true;
            continue;
        }
        ++p.openLines;
        const int ends[2] = {line.startJunction, line.endJunction};
        for (int e = 0; e < 2; ++e) {
            if (ends[e] >= 0) {
                p.junctions.push_back(ends[e]);
                continue;
            }
            ++p.looseEnds;
            if (!anchored[2 * l + static_cast<size_t>(e)]) {
                ++p.freeEnds;
            }
        }
    }
    std::vector<char> keepPiece(lineCount, 0);
    for (auto& [id, p] : pieces) {
        std::sort(p.junctions.begin(), p.junctions.end());
        const auto junctions =
            std::unique(p.junctions.begin(), p.junctions.end()) - p.junctions.begin();
        // A tree of E lines has E + 1 end nodes (junctions and loose ends); more lines than
        // that close a cycle.
        const bool cycle = p.closedLine || p.openLines >= junctions + p.looseEnds;
        keepPiece[static_cast<size_t>(id)] = cycle || p.freeEnds == 0 || p.length >= minLength;
    }
    std::vector<Polyline> kept;
    std::map<int, int> newJunction;
    int dropped = 0;
    for (size_t l = 0; l < lineCount; ++l) {
        if (!keepPiece[static_cast<size_t>(sets.find(static_cast<int>(l)))]) {
            ++dropped;
            continue;
        }
        Polyline line = network.lines[l];
        for (int* j : {&line.startJunction, &line.endJunction}) {
            if (*j >= 0) {
                *j = newJunction.emplace(*j, static_cast<int>(newJunction.size())).first->second;
            }
        }
        kept.push_back(std::move(line));
    }
    PointMatrix junctions(static_cast<Eigen::Index>(newJunction.size()), 3);
    for (const auto& [old, now] : newJunction) {
        junctions.row(now) = network.junctions.row(old);
    }
    network.lines = std::move(kept);
    network.junctions = std::move(junctions);
    return dropped;
}

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
void analyseRegionGeometry(const PointMatrix& P, RegionGeometry& g,
                           const SmoothEdgeOptions& options)
{
    g.noise = estimateNoise(g.points, g.normals, g.neighbours, g.spacing, options.noiseSamples);
    g.smoothed =
        options.smoothing == SmoothingMode::Always ||
        (options.smoothing == SmoothingMode::Automatic && g.noise > options.noiseThreshold);
    if (g.smoothed) {
        // Sec. 2.4: smoothing inside the region only, after the sharp edges are found, so it
        // cannot round them off.
        g.points = laplacianSmooth(g.points, g.neighbours, allIndices(g.points.rows()),
                                   options.smoothingOptions);
        g.normals = pcaNormals(g.points, g.neighbours).normals;
    }
    g.ring = ringNeighbourhoods(g.points, g.normals, g.neighbours);
    g.curvature =
        regionCurvature(g.points, g.normals, g.neighbours,
                        g.smoothed ? options.curvatureAveragingPasses : 0, options.curvature);
    g.curvatureNoise =
        curvatureNoiseFloor(g.noise, g.neighbours.k(), g.smoothed, options) / g.spacing;
    chooseCurvatureScale(P, g.members, g, options);
}

} // namespace

RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const std::vector<int>& region, const std::vector<int>& members,
                             int regionId, double spacing, const SmoothEdgeOptions& options)
{
    return analyseRegion(P, N, NormalMatrix(), region, members, regionId, spacing, options);
}

RegionGeometry analyseRegion(const PointMatrix& P, const Neighbourhoods& N,
                             const NormalMatrix& normals, const std::vector<int>& region,
                             const std::vector<int>& members, int regionId, double spacing,
                             const SmoothEdgeOptions& options)
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
        g.normals = pcaNormals(g.points, g.neighbours).normals;
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
    analyseRegionGeometry(P, g, options);
    return g;
}

RegionGeometry analyseRegion(const PointMatrix& P, Neighbourhoods&& N, const NormalMatrix& normals,
                             int regionId, double spacing, const SmoothEdgeOptions& options)
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
    g.normals = normals.rows() == 0 ? pcaNormals(g.points, g.neighbours).normals : normals;
    analyseRegionGeometry(P, g, options);
    return g;
}

ThresholdResult regionThreshold(const RegionGeometry& region, const SmoothEdgeOptions& options,
                                const std::vector<int>& subset)
{
    return findThreshold(valuesOf(region, subset), histogramOptions(region, options));
}

ThresholdResult regionLowerThreshold(const RegionGeometry& region, double threshold,
                                     const SmoothEdgeOptions& options)
{
    return findLowerThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

ThresholdResult regionHigherThreshold(const RegionGeometry& region, double threshold,
                                      const SmoothEdgeOptions& options)
{
    return findHigherThreshold(valuesOf(region, {}), threshold, histogramOptions(region, options));
}

double lineContrast(const RegionGeometry& g, const Eigen::VectorXd& curvature, double tau,
                    const std::vector<int>& points)
{
    const bool coarse = g.coarse && g.coarseRowOf.size() == static_cast<size_t>(g.points.rows());
    std::vector<int> at;
    if (coarse) {
        for (int p : points) {
            at.push_back(g.coarseRowOf[static_cast<size_t>(p)]);
        }
        std::sort(at.begin(), at.end());
        at.erase(std::unique(at.begin(), at.end()), at.end());
    }
    const std::vector<int>& where = coarse ? at : points;
    std::vector<double> contrasts(where.size(), std::numeric_limits<double>::quiet_NaN());
#pragma omp parallel for schedule(dynamic, 16)
    for (long s = 0; s < static_cast<long>(where.size()); ++s) {
        const int p = where[static_cast<size_t>(s)];
        contrasts[static_cast<size_t>(s)] =
            coarse ? localContrast(*g.coarse, g.coarse->curvature, tau, p)
                   : localContrast(g, curvature, tau, p);
    }
    contrasts.erase(
        std::remove_if(contrasts.begin(), contrasts.end(), [](double c) { return std::isnan(c); }),
        contrasts.end());
    return contrasts.empty() ? 0.0 : median(std::move(contrasts));
}

SmoothEdgeLevel smoothEdgesAtThreshold(const RegionGeometry& region, double threshold,
                                       const SmoothEdgeOptions& options,
                                       const std::vector<int>& subset,
                                       const std::vector<Polyline>& anchors)
{
    if (!std::isfinite(threshold)) {
        throw std::invalid_argument("the curvature threshold must be a finite number");
    }
    if (options.maxCandidateClusterSize < 1) {
        throw std::invalid_argument("the largest candidate cluster must hold at least one point");
    }
    if (!(options.anchorReach >= 0.0) || !(options.anchorAngle >= 0.0) ||
        !(options.anchorBand >= 0.0)) {
        throw std::invalid_argument("the anchoring reach and angle must not be negative");
    }
    const std::vector<int> points = subset.empty() ? allIndices(region.points.rows()) : subset;
    SmoothEdgeLevel level;
    level.threshold = threshold;
    // Islands of one side whose values stay within a few noise floors of tau are noise of
    // the level around them, not patches: they join that level before the labels are drawn.
    const Eigen::VectorXd curvature = withoutNoiseIslands(
        region.curvature, threshold, region.ring, points,
        options.islandMargin * region.curvatureNoise, minIslandPoints(region, options));
    level.labels = labelPoints(curvature, threshold, region.ring, points, options.labels);
    level.clusters = growLabelClusters(level.labels, region.ring, points, options.seed);

    // Sec. 3: the small clusters ring the patches; the graph of neighbouring small clusters
    // is processed as for the sharp edges [4].
    std::vector<char> candidate(level.clusters.size.size(), 0);
    for (size_t c = 0; c < candidate.size(); ++c) {
        candidate[c] = level.clusters.size[c] <= options.maxCandidateClusterSize;
    }
    // Next to the lines that bound the region (an open cloud's boundary runs through it) the
    // neighbourhoods are one-sided: no candidates there; the lines are anchored across.
    if (!anchors.empty() && options.anchorBand > 0.0) {
        std::vector<int> candidatePoints;
        for (int i : points) {
            const int c = level.clusters.cluster[i];
            if (c >= 0 && candidate[c]) {
                candidatePoints.push_back(i);
            }
        }
        const std::vector<char> near = pointsNearLines(region.points, candidatePoints, anchors,
                                                       options.anchorBand * region.spacing);
        for (size_t j = 0; j < candidatePoints.size(); ++j) {
            if (near[j]) {
                candidate[level.clusters.cluster[candidatePoints[j]]] = 0;
            }
        }
    }
    // Open pieces are judged after their ends are anchored on the lines that bound the region
    // (a fillet border running from one sharp edge to another is short but complete).
    ClusterGraphOptions graphOptions = options.graph;
    graphOptions.minOpenComponentLength = 0.0;
    const ClusterGraph graph = buildClusterGraph(
        {region.points, region.neighbours, level.clusters.cluster, candidate, region.spacing},
        graphOptions);
    level.network = graph.network;
    level.counts = graph.counts;
    // A line must part two levels where it runs: across it, within two fit radii, the
    // curvature on its high side must exceed that on its low side by minLineContrast noise
    // floors (the median over the line's candidate points). The edge of a noise island, or a
    // drifting curvature crossing tau, has about one floor across it.
    std::vector<char> anchored;
    if (options.minLineContrast > 0.0 && region.curvatureNoise > 0.0) {
        std::vector<std::vector<int>> pointsOfNode(static_cast<size_t>(graph.nodes.rows()));
        for (size_t i = 0; i < graph.nodeOfPoint.size(); ++i) {
            if (graph.nodeOfPoint[i] >= 0) {
                pointsOfNode[static_cast<size_t>(graph.nodeOfPoint[i])].push_back(
                    static_cast<int>(i));
            }
        }
        std::vector<char> weak(level.network.lines.size(), 0);
        for (size_t l = 0; l < graph.lineNodes.size() && l < weak.size(); ++l) {
            std::vector<int> linePoints;
            for (int v : graph.lineNodes[l]) {
                if (v >= 0 && v < static_cast<int>(pointsOfNode.size())) {
                    const auto& ps = pointsOfNode[static_cast<size_t>(v)];
                    linePoints.insert(linePoints.end(), ps.begin(), ps.end());
                }
            }
            const double contrast = lineContrast(region, curvature, threshold, linePoints);
            weak[l] = contrast < options.minLineContrast * region.curvatureNoise;
        }
        level.counts.droppedComponents += static_cast<int>(std::count(weak.begin(), weak.end(), 1));
        dropLines(level.network, anchored, weak);
    }
    if (options.placeCoarseLines && region.curvatureScale > 1.0) {
        placeOnCurvatureSteps(level.network,
                              {region.points, region.normals, region.curvature, region.spacing,
                               region.curvatureScale * region.spacing, threshold},
                              options.placement);
    }
    anchored = anchorLineEnds(level.network, anchors, options.anchorReach * region.spacing,
                              options.anchorAngle);
    const double minOpen = options.graph.minOpenComponentLength * region.spacing;
    level.counts.prunedBranches += pruneDanglingLines(level.network, anchored, minOpen);
    level.counts.droppedComponents += dropOpenPieces(level.network, anchored, minOpen);
    return level;
}

std::vector<ThresholdDecision> automaticThresholds(const RegionGeometry& region,
                                                   const SmoothEdgeOptions& options)
{
    if (region.coarse) {
        // Decided at the region's curvature scale, where its patches and reaches are counted
        // in its own sampling; the values are the region's carried-back curvature's.
        return automaticThresholds(*region.coarse, options);
    }
    const AutomaticThresholdOptions& a = options.automatic;
    if (a.maxThresholds < 0 || a.maxSearches < 0 || a.maxMisses < 0 || a.minRatio < 1.0 ||
        a.minInnerPoints < 0 || a.minContrast < 1.0 || !(a.flatRadius > 0.0) ||
        !(a.minSeparation >= 0.0) || !(a.maxStraddle >= 0.0) || a.straddleSamples < 0) {
        throw std::invalid_argument("automatic thresholds: the limits are out of range");
    }
    const int minInner = a.minInnerPoints > 0 ? a.minInnerPoints : 2 * region.neighbours.k();
    const double flat = 1.0 / (a.flatRadius * region.spacing);
    const ThresholdOptions histogram = histogramOptions(region, options);
    const std::vector<double> all = valuesOf(region, {});
    const std::vector<int> everyPoint = allIndices(region.points.rows());
    constexpr double infinity = std::numeric_limits<double>::infinity();

    std::vector<ThresholdDecision> decisions;
    int accepted = 0;
    // Ranges of values (low, high] still to search, depth first. The first is the whole
    // histogram with its outliers (Sec. 2.4); an accepted tau opens the ranges below and above
    // it (the paper's "lower" and "higher" steps, Sec. 2.3). A threshold is weighed against the
    // patches it separates: the values between the nearest accepted thresholds on either side
    // (patchLow, patchHigh], not only the values of the range searched.
    struct Range
    {
        double low, high;
        double patchLow, patchHigh;
        bool first;
        int misses; // thresholds refused on the way to this range
    };
    std::vector<Range> ranges{{-infinity, infinity, -infinity, infinity, true, 0}};
    while (!ranges.empty() && accepted < a.maxThresholds &&
           static_cast<int>(decisions.size()) < a.maxSearches) {
        const Range range = ranges.back();
        ranges.pop_back();
        std::vector<double> values;
        for (double v : all) {
            if (v > range.low && v <= range.high) {
                values.push_back(v);
            }
        }
        if (values.empty()) {
            continue;
        }
        if (!range.first) {
            // A range whose values cannot hold two levels (contrast, separation) is not split.
            const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
            if ((*hi + flat) / (*lo + flat) < a.minContrast ||
                *hi - *lo < a.minSeparation * region.curvatureNoise) {
                continue;
            }
        }
        ThresholdOptions h = histogram;
        if (!range.first) {
            h.outlierPercent = 0.0;
        }
        ThresholdDecision d;
        try {
            d.result = findThreshold(values, h);
        } catch (const std::invalid_argument&) {
            continue; // too few distinct values in this range: nothing to split
        }
        const double tau =
            a.centreThresholds ? valleyMiddle(d.result, h.minPeakPercent) : d.result.threshold;
        d.applied = tau;
        // Sec. 2.4: the outliers leave the histogram, not the patches.
        const double searchHigh = range.first ? d.result.outlierCut : range.high;
        std::tie(d.largestPatch, d.largestPatchBelow) =
            largestPatches(region.curvature, range.patchLow, tau, range.patchHigh, region.ring);
        std::vector<double> below, above;
        for (double v : all) {
            if (v > range.patchLow && v <= range.patchHigh) {
                (v <= tau ? below : above).push_back(v);
            }
        }
        d.medianBelow = median(std::move(below));
        d.medianAbove = median(std::move(above));
        const std::vector<PointLabel> labels =
            labelPoints(region.curvature, tau, region.ring, everyPoint, options.labels);
        d.innerPoints =
            static_cast<int>(std::count(labels.begin(), labels.end(), PointLabel::Inner));
        d.straddle = straddleShare(region, labels, a.straddleSamples, range.patchLow,
                                   range.patchHigh, a.straddleReach);
        d.contrast = (d.medianAbove + flat) / (d.medianBelow + flat);
        d.separation = region.curvatureNoise > 0.0
                           ? (d.medianAbove - d.medianBelow) / region.curvatureNoise
                           : infinity;
        const bool patch = d.largestPatch >= minInner;
        const bool patchBelow = d.largestPatchBelow >= minInner;
        const bool levels = d.contrast >= a.minContrast && d.separation >= a.minSeparation &&
                            d.straddle <= a.maxStraddle;
        // The valley must follow a peak of a patch's worth of values: e = b1 / b2 of a few
        // stray values before an empty bin (b2 = 0) is no valley.
        const bool valley =
            d.result.ratio >= a.minRatio && d.result.peakCount >= static_cast<long>(minInner);
        d.accepted = valley && patch && patchBelow && levels;
        decisions.push_back(d);
        if (d.accepted) {
            ++accepted;
            // Searched next: the higher values first, then the lower (Sec. 2.3 offers both).
            ranges.push_back({range.patchLow, tau, range.patchLow, tau, false, 0});
            ranges.push_back({tau, searchHigh, tau, range.patchHigh, false, 0});
        } else if (range.misses >= a.maxMisses) {
            continue;
        } else if (!patch) {
            // No patch above tau: the valley found lies above the highest patch of the range
            // (e.g. after a fillet peak at the top of the histogram); the patches' own valley
            // is lower down (Sec. 2.3, "lower threshold").
            ranges.push_back({range.low, d.result.threshold, range.patchLow, range.patchHigh, false,
                              range.misses + 1});
        } else if (!levels || !patchBelow) {
            // tau splits one curvature level in two (a peak and its own noise tail), or cuts
            // the transition between two levels short of the lower one; a second level, if
            // any, lies higher up (Sec. 4, Fig. 9 a: "the desired threshold is located after
            // the second peak").
            ranges.push_back({d.result.threshold, searchHigh, range.patchLow, range.patchHigh,
                              false, range.misses + 1});
        }
    }
    return decisions;
}

SmoothEdgeLevel refineInCluster(const RegionGeometry& region, const SmoothEdgeLevel& level,
                                int cluster, const SmoothEdgeOptions& options)
{
    if (cluster < 0 || cluster >= static_cast<int>(level.clusters.size.size()) ||
        level.clusters.size[cluster] <= options.maxCandidateClusterSize) {
        throw std::invalid_argument("cluster " + std::to_string(cluster) +
                                    " is not a large cluster of this threshold");
    }
    std::vector<int> subset;
    subset.reserve(static_cast<size_t>(level.clusters.size[cluster]));
    for (size_t i = 0; i < level.clusters.cluster.size(); ++i) {
        if (level.clusters.cluster[i] == cluster) {
            subset.push_back(static_cast<int>(i));
        }
    }
    const ThresholdResult t = regionThreshold(region, options, subset);
    return smoothEdgesAtThreshold(region, t.threshold, options, subset);
}

} // namespace featurelines
