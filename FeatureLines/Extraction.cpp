// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/Extraction.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numeric>
#include <vector>

#include <omp.h>

#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/neighbourhoods/BalancedNeighbourhoods.h"
#include "FeatureLines/neighbourhoods/SheetNeighbourhoods.h"
#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/BlendRadius.h"
#include "FeatureLines/smooth/PointValues.h"
#include "FeatureLines/smooth/RegionNeighbourhoods.h"
#include "FeatureLines/smooth/SmoothEdgeLevel.h"
#include "FeatureLines/support/DisjointSets.h"
#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

/// Where each stage starts in the run's share (0..1), so that the share grows about as the time
/// does where runs are long, on noisy clouds of a million points: the neighbours take about
/// 15 % of the time, the normals 5 %, the sharp edges 10 %, the smooth regions 5 %, the
/// regions' curvature (smoothing, fits, coarser scales) 50 % and their smooth edges 15 %.
namespace stageStart {
constexpr double neighbours = 0.0;
constexpr double normals = 0.15;
constexpr double sharpEdges = 0.2;
constexpr double smoothRegions = 0.3;
constexpr double curvature = 0.35;
constexpr double smoothEdges = 0.85;
} // namespace stageStart

/// Sorts `keyed` by key, then each run of equal keys by `less`.
template <class Less>
void sortByKey(std::vector<std::pair<std::uint64_t, int>>& keyed, const Less& less)
{
    sortByMortonKey(keyed);
    const std::size_t n = keyed.size();
    for (std::size_t first = 0; first < n;) {
        std::size_t last = first + 1;
        while (last < n && keyed[last].first == keyed[first].first) {
            ++last;
        }
        if (last - first > 1) {
            std::sort(keyed.begin() + static_cast<std::ptrdiff_t>(first),
                      keyed.begin() + static_cast<std::ptrdiff_t>(last), less);
        }
        first = last;
    }
}

/// The distinct points of P in one canonical spatial order, and per input row its distinct
/// point. The rows are sorted by the Morton (Z-order) key of their coordinates quantised to
/// 2^21 steps over the bounding box, points of one key by their coordinates. Every stage then
/// finds the neighbours of a point in nearby rows (the cache holds them even when the input is
/// stored in random order), and, since the order depends on the points' positions only, the
/// extraction gives the same result whatever the input order. Exact duplicates carry no
/// geometry and make a neighbourhood of one repeated point: the sort puts them side by side,
/// where they are merged.
PointMatrix orderedDistinctPoints(const PointMatrix& P, std::vector<int>& inputToPoint)
{
    const Eigen::Index n = P.rows();
    const MortonGrid grid(P);
    auto keyed = hugePageVector<std::pair<std::uint64_t, int>>(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        keyed[static_cast<size_t>(i)] = {grid.key(P, i), static_cast<int>(i)};
    }
    // Coordinates compare as numbers: -0.0 equals 0.0, and duplicates compare equal, so which of
    // them comes first does not matter.
    const auto less = [&](const std::pair<std::uint64_t, int>& a,
                          const std::pair<std::uint64_t, int>& b) {
        if (a.first != b.first) {
            return a.first < b.first;
        }
        const auto pa = P.row(a.second), pb = P.row(b.second);
        return std::lexicographical_compare(pa.begin(), pa.end(), pb.begin(), pb.end());
    };
    sortByKey(keyed, less);
    inputToPoint.resize(static_cast<size_t>(n));
    std::vector<int> firstOf; // distinct point -> an input row holding it
    firstOf.reserve(static_cast<size_t>(n));
    for (size_t r = 0; r < keyed.size(); ++r) {
        const int i = keyed[r].second;
        if (firstOf.empty() || P.row(firstOf.back()) != P.row(i)) {
            firstOf.push_back(i);
        }
        inputToPoint[static_cast<size_t>(i)] = static_cast<int>(firstOf.size()) - 1;
    }
    PointMatrix distinct(static_cast<Eigen::Index>(firstOf.size()), 3);
    adviseHugePagesOf(distinct);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index r = 0; r < distinct.rows(); ++r) {
        distinct.row(r) = P.row(firstOf[static_cast<size_t>(r)]);
    }
    return distinct;
}

void requireSurface(const PointMatrix& P)
{
    const Eigen::Matrix3d covariance = covarianceOf(P);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d lambda = solver.eigenvalues(); // ascending
    if (!(lambda[2] > 0.0) || lambda[1] <= 1e-12 * lambda[2]) {
        throw std::invalid_argument("point cloud: the points lie on a line (or on one point); "
                                    "feature lines need a surface");
    }
}

FeatureLine toFeatureLine(const Polyline& line, LineType type, int junctionOffset)
{
    FeatureLine f;
    f.type = type;
    f.closed = line.closed;
    f.points = line.points;
    f.startJunction = line.startJunction >= 0 ? line.startJunction + junctionOffset : -1;
    f.endJunction = line.endJunction >= 0 ? line.endJunction + junctionOffset : -1;
    return f;
}

void appendJunctions(PointMatrix& all, const PointMatrix& more)
{
    if (more.rows() == 0) {
        return;
    }
    const Eigen::Index before = all.rows();
    all.conservativeResize(before + more.rows(), 3);
    all.bottomRows(more.rows()) = more;
}

std::vector<double> regionThresholdList(const RegionGeometry& g, const ExtractionOptions& options,
                                        RegionReport& report)
{
    std::vector<double> thresholds;
    switch (options.thresholdMode) {
    case ThresholdMode::Explicit: {
        auto it = options.regionThresholds.find(g.region);
        thresholds = it != options.regionThresholds.end() ? it->second : options.thresholds;
        break;
    }
    case ThresholdMode::First:
        try {
            thresholds.push_back(regionThreshold(g, options.smooth).threshold);
        } catch (const std::invalid_argument&) {
            // A region of one curvature value (a plane) has no threshold: no smooth edges.
        }
        break;
    case ThresholdMode::Automatic:
        report.decisions = automaticThresholds(g, options.smooth);
        for (const ThresholdDecision& d : report.decisions) {
            if (d.accepted) {
                thresholds.push_back(d.applied);
            }
        }
        break;
    }
    for (double t : thresholds) {
        if (!std::isfinite(t) || t < 0.0) {
            throw std::invalid_argument("curvature thresholds must be finite and not negative");
        }
    }
    std::sort(thresholds.begin(), thresholds.end(), std::greater<double>());
    thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
    return thresholds;
}

} // namespace

int labelPatches(const RegionGeometry& g, const std::vector<double>& thresholds, int firstId,
                 std::vector<int>& patchOfRegionPoint)
{
    const Eigen::Index n = g.points.rows();
    std::vector<int> level(static_cast<size_t>(n), 0);
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        for (double t : thresholds) {
            level[i] += g.curvature[i] > t ? 1 : 0;
        }
    }
    // Pieces: the points joined with the ring members of their level (either way), each
    // numbered in the order of its first point.
    DisjointSets sets(static_cast<int>(n));
#pragma omp parallel for schedule(static, 4096)
    for (Eigen::Index i = 0; i < n; ++i) {
        int root = static_cast<int>(i);
        for (const int* q = g.ring.begin(i); q != g.ring.end(i); ++q) {
            if (level[*q] == level[i]) {
                root = sets.join(root, *q);
            }
        }
    }
    const std::vector<int> root = sets.representatives();
    patchOfRegionPoint.assign(static_cast<size_t>(n), -1);
    int next = firstId;
    for (Eigen::Index i = 0; i < n; ++i) {
        patchOfRegionPoint[i] = root[i] == i ? next++ : patchOfRegionPoint[root[i]];
    }
    return next;
}

const char* lineTypeName(LineType type)
{
    switch (type) {
    case LineType::Sharp:
        return "sharp";
    case LineType::Smooth:
        return "smooth";
    case LineType::Boundary:
        return "boundary";
    }
    return "unknown";
}

int ExtractionResult::countLines(LineType type) const
{
    return static_cast<int>(std::count_if(lines.begin(), lines.end(),
                                          [type](const FeatureLine& l) { return l.type == type; }));
}

namespace {

/// The distinct points of a cloud of `inputRows` points are more than k and not on one line.
void requireDistinctSurface(const PointMatrix& distinct, Eigen::Index inputRows, int k)
{
    if (distinct.rows() <= k) {
        throw std::invalid_argument(
            "point cloud: " + std::to_string(distinct.rows()) + " distinct points (" +
            std::to_string(inputRows - distinct.rows()) + " duplicates merged); at least " +
            std::to_string(k + 1) + " are needed for " + std::to_string(k) +
            " neighbours per point");
    }
    requireSurface(distinct);
}

} // namespace

void requireSurfaceCloud(const PointMatrix& P, int k)
{
    checkFinite(P, "point cloud");
    std::vector<int> inputToPoint;
    requireDistinctSurface(orderedDistinctPoints(P, inputToPoint), P.rows(), k);
}

CloudGeometry analyseCloud(const PointMatrix& P, const NeighbourOptions& options,
                           const ProgressCallback& progress, double progressInterval)
{
    checkFinite(P, "point cloud");
    ProgressReporter reporter(progress, progressInterval);
    CloudGeometry g;
    g.points = orderedDistinctPoints(P, g.inputToPoint);
    requireDistinctSurface(g.points, P.rows(), options.k);
    reporter.stage(stageStart::neighbours, "neighbours");
    g.neighbours = nearestNeighbours(
        g.points, options, ProgressSpan(reporter, stageStart::neighbours, stageStart::normals));
    reporter.stage(stageStart::normals, "normals");
    g.normals = pcaNormals(g.points, g.neighbours, {},
                           ProgressSpan(reporter, stageStart::normals, stageStart::sharpEdges));
    // Scan rows too far apart for k neighbours to leave their own row: such neighbourhoods
    // reach across the rows, and their normals are estimated again.
    const std::vector<int> rebuilt =
        balanceCollinearNeighbourhoods(g.points, g.neighbours, g.normals.spread);
    if (!rebuilt.empty()) {
        pcaNormalsOfRows(g.points, g.neighbours, rebuilt, g.normals.normals);
    }
    releaseIdleThreads(); // samplingSpacing is serial
    g.spacing = samplingSpacing(g.neighbours);
    // Thin walls: neighbours on the wall's other side are exchanged for points of the own
    // sheet, and those normals are estimated again.
    const std::vector<int> separated =
        separateSheets(g.points, g.neighbours, g.spacing, options.sheets, options.threads);
    if (!separated.empty()) {
        pcaNormalsOfRows(g.points, g.neighbours, separated, g.normals.normals);
    }
    return g;
}

namespace {

/// The run's share [from, to] split among the regions by their numbers of points (a region's
/// work grows with its points): one span per region.
std::vector<ProgressSpan> regionSpans(ProgressReporter& reporter, double from, double to,
                                      const std::vector<size_t>& points)
{
    const double total =
        std::max(1.0, static_cast<double>(std::accumulate(points.begin(), points.end(), 0.0)));
    std::vector<ProgressSpan> spans;
    double before = 0.0;
    for (size_t count : points) {
        const double after = before + static_cast<double>(count);
        spans.emplace_back(reporter, from + (to - from) * before / total,
                           from + (to - from) * after / total);
        before = after;
    }
    return spans;
}

/// analyseRegions; a region of every point takes over `spare` when given (the cloud's own
/// neighbourhoods, which it then holds as its own) instead of a copy of them.
RegionAnalysis analyseRegionsOf(const CloudGeometry& cloud, Neighbourhoods* spare,
                                const ExtractionOptions& options)
{
    RegionAnalysis a;
    const Eigen::Index n = cloud.points.rows();
    ProgressReporter reporter(options.progress, options.progressInterval);
    reporter.stage(stageStart::sharpEdges, "sharp edges");
    if (options.sharpEdges) {
        a.sharp = extractSharpEdges(cloud.points, cloud.normals.normals, cloud.neighbours,
                                    cloud.spacing, options.sharp);
    } else {
        a.sharp.isSharpCandidate.assign(static_cast<size_t>(n), 0);
        a.sharp.isBoundary.assign(static_cast<size_t>(n), 0);
        if (options.sharp.includeBoundary) {
            const Boundary b =
                extractBoundary(cloud.points, cloud.normals.normals, cloud.neighbours,
                                cloud.spacing, options.sharp.boundary);
            a.sharp.network = b.network;
            for (Polyline& line : a.sharp.network.lines) {
                line.label = boundaryLineLabel;
            }
            a.sharp.isBoundary = b.isBoundary;
        }
    }
    std::vector<Polyline> sharpLines;
    for (const Polyline& line : a.sharp.network.lines) {
        // A blend's borders divide the regions as its sharp line did.
        if (line.label == sharpLineLabel || line.label == blendBorderLabel) {
            sharpLines.push_back(line);
        }
    }
    reporter.stage(stageStart::smoothRegions, "smooth regions");
    a.regions = divideSmoothRegions(
        {cloud.points, cloud.neighbours, sharpLines, a.sharp.isSharpCandidate, cloud.spacing},
        options.regions);
    if (options.smoothEdges) {
        std::vector<size_t> points;
        for (const std::vector<int>& members : a.regions.members) {
            points.push_back(members.size());
        }
        const std::vector<ProgressSpan> spans =
            regionSpans(reporter, stageStart::curvature, stageStart::smoothEdges, points);
        for (int r = 0; r < a.regions.count(); ++r) {
            reporter.stage(spans[r].at(0.0), "curvature of smooth region " + std::to_string(r + 1));
            const std::vector<int>& members = a.regions.members[r];
            if (spare != nullptr && holdsEveryPoint(a.regions.region, members, r)) {
                a.geometry.push_back(analyseRegion(cloud.points, std::move(*spare),
                                                   cloud.normals.normals, r, cloud.spacing,
                                                   options.smooth, spans[r]));
            } else {
                a.geometry.push_back(analyseRegion(cloud.points, cloud.neighbours,
                                                   cloud.normals.normals, a.regions.region, members,
                                                   r, cloud.spacing, options.smooth, spans[r]));
            }
        }
    }
    return a;
}

} // namespace

RegionAnalysis analyseRegions(const CloudGeometry& cloud, const ExtractionOptions& options)
{
    return analyseRegionsOf(cloud, nullptr, options);
}

namespace {

/// The per-point results on the distinct points (CloudGeometry::points), before they are
/// copied to the input points.
struct DistinctPointResults
{
    std::vector<int> region;
    std::vector<int> patch;
    std::vector<PointLabel> label;
    Eigen::VectorXd curvature;

    explicit DistinctPointResults(Eigen::Index n)
        : region(static_cast<size_t>(n), -1), patch(static_cast<size_t>(n), -1),
          label(static_cast<size_t>(n), PointLabel::Outside),
          curvature(Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN()))
    {
    }
};

/// The sharp and boundary lines, and their junctions, as the result's first lines.
void addSharpLines(const SharpEdges& sharp, ExtractionResult& result)
{
    for (size_t l = 0; l < sharp.network.lines.size(); ++l) {
        const Polyline& line = sharp.network.lines[l];
        const LineType type = line.label == boundaryLineLabel  ? LineType::Boundary
                              : line.label == blendBorderLabel ? LineType::Smooth
                                                               : LineType::Sharp;
        FeatureLine out = toFeatureLine(line, type, 0);
        if (l < sharp.profiles.size()) {
            if (type == LineType::Sharp) {
                out.angle = sharp.profiles[l].angle;
            } else if (type == LineType::Smooth) {
                out.blendRadius = sharp.profiles[l].radius;
            }
        }
        result.lines.push_back(std::move(out));
    }
    result.junctions = sharp.network.junctions;
}

/// The report of region g: its geometry's facts, its thresholds (regionThresholdList) and the
/// histogram of its first threshold search.
RegionReport regionReport(const RegionGeometry& g, const ExtractionOptions& options)
{
    RegionReport rr;
    rr.region = g.region;
    rr.points = static_cast<int>(g.members.size());
    rr.noise = g.noise;
    rr.smoothed = g.smoothed;
    rr.curvatureScale = g.curvatureScale;
    rr.scaleTrials = g.scaleTrials;
    rr.thresholds = regionThresholdList(g, options, rr);
    if (!rr.decisions.empty()) {
        // The automatic search starts with this very search, on all the region's values.
        rr.histogram = rr.decisions.front().result.histogram;
    } else {
        try {
            rr.histogram = regionThreshold(g, options.smooth).histogram;
        } catch (const std::invalid_argument&) {
            // One curvature value only: an empty histogram tells the user there is no
            // valley.
        }
    }
    return rr;
}

/// The smooth edges of one region at each of its thresholds, and its patches.
struct RegionEdges
{
    std::vector<SmoothEdgeLevel> levels;
    std::vector<int> patchOf;
    /// The next free patch number after the region's.
    int nextPatch = 0;
};

/// The level beneath thresholds[item] in region g, from which a line of that threshold must
/// rise (SmoothEdgeOptions::minRelativeContrast): 0, a plane's curvature, beneath the region's
/// lowest threshold; beneath a higher one, the median curvature of the region's points between
/// the next lower threshold and it (a fillet's own level under a corner blend's).
double levelBelow(const RegionGeometry& g, const std::vector<double>& thresholds, int item)
{
    const double tau = thresholds[static_cast<size_t>(item)];
    double lower = -1.0;
    for (double t : thresholds) {
        if (t < tau) {
            lower = std::max(lower, t);
        }
    }
    if (lower < 0.0) {
        return 0.0;
    }
    std::vector<double> level;
    for (Eigen::Index i = 0; i < g.curvature.size(); ++i) {
        if (g.curvature[i] <= tau && g.curvature[i] > lower) {
            level.push_back(g.curvature[i]);
        }
    }
    return level.empty() ? lower : detail::median(std::move(level));
}

/// The smooth edges of region g at each threshold and its patches, numbered from firstPatch.
/// The levels and the patches are independent of each other: each level runs on a thread of
/// its own (most of its work walks the 1-rings one point after another). The patches run
/// beside them when the levels leave a thread idle, else after them on every thread.
/// `progress` is told as the levels start.
RegionEdges smoothEdgesAndPatches(const RegionGeometry& g, const std::vector<double>& thresholds,
                                  const SharpEdges& sharp, const ExtractionOptions& options,
                                  int firstPatch, const ProgressSpan& progress)
{
    const int levels = static_cast<int>(thresholds.size());
    const bool patchesBeside = levels % std::max(1, omp_get_max_threads()) != 0;
    const int items = levels + (patchesBeside ? 1 : 0);
    RegionEdges edges;
    edges.levels.resize(thresholds.size());
    int nextPatch = firstPatch;
    std::vector<std::exception_ptr> failure(static_cast<size_t>(items));
    LoopProgress loop(progress, items);
#pragma omp parallel for schedule(dynamic, 1) if (items > 1)
    for (int item = 0; item < items; ++item) {
        if (!loop.next(item)) {
            continue;
        }
        try {
            if (item < levels) {
                // Sec. 1.2: smooth edges end on the sharp edges and the boundary around the
                // region.
                edges.levels[item] = smoothEdgesAtThreshold(g, thresholds[item], options.smooth, {},
                                                            sharp.network.lines,
                                                            levelBelow(g, thresholds, item));
            } else {
                nextPatch = labelPatches(g, thresholds, firstPatch, edges.patchOf);
            }
        } catch (...) {
            failure[item] = std::current_exception();
        }
    }
    loop.finish();
    for (const std::exception_ptr& e : failure) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
    edges.nextPatch =
        patchesBeside ? nextPatch : labelPatches(g, thresholds, firstPatch, edges.patchOf);
    return edges;
}

/// Appends the smooth lines of region g (its report rr) and their junctions to the result;
/// returns the labels at its first threshold (empty when it has none).
std::vector<PointLabel> addSmoothLines(const RegionGeometry& g, const RegionReport& rr,
                                       const RegionEdges& edges, ExtractionResult& result)
{
    std::vector<PointLabel> firstLabels;
    for (size_t level = 0; level < rr.thresholds.size(); ++level) {
        const SmoothEdgeLevel& atLevel = edges.levels[level];
        const int offset = static_cast<int>(result.junctions.rows());
        const std::vector<double> radii = blendRadii(g, atLevel);
        for (size_t l = 0; l < atLevel.network.lines.size(); ++l) {
            FeatureLine f = toFeatureLine(atLevel.network.lines[l], LineType::Smooth, offset);
            f.region = g.region;
            f.level = static_cast<int>(level);
            f.threshold = rr.thresholds[level];
            f.blendRadius = radii[l];
            result.lines.push_back(std::move(f));
        }
        appendJunctions(result.junctions, atLevel.network.junctions);
        if (level == 0) {
            firstLabels = atLevel.labels;
        }
    }
    return firstLabels;
}

/// Region, patch, label and curvature of the members of region g.
void setRegionPoints(const RegionGeometry& g, const std::vector<int>& patchOf,
                     const std::vector<PointLabel>& firstLabels, DistinctPointResults& points)
{
    for (size_t i = 0; i < g.members.size(); ++i) {
        const int p = g.members[i];
        points.region[p] = g.region;
        points.patch[p] = patchOf[i];
        points.label[p] = firstLabels.empty() ? PointLabel::Low : firstLabels[i];
        points.curvature[p] = g.curvature[static_cast<Eigen::Index>(i)];
    }
}

/// The per-point results for every input point, through the merge of duplicates (serial
/// copies).
void copyToInputPoints(const CloudGeometry& cloud, const DistinctPointResults& points,
                       ExtractionResult& result)
{
    releaseIdleThreads();
    const size_t inputs = cloud.inputToPoint.size();
    result.region.resize(inputs);
    result.patch.resize(inputs);
    result.label.resize(inputs);
    result.curvature.resize(static_cast<Eigen::Index>(inputs));
    for (size_t i = 0; i < inputs; ++i) {
        const int p = cloud.inputToPoint[i];
        result.region[i] = points.region[p];
        result.patch[i] = points.patch[p];
        result.label[i] = points.label[p];
        result.curvature[static_cast<Eigen::Index>(i)] = points.curvature[p];
    }
}

} // namespace

ExtractionResult extractFeatureLines(const CloudGeometry& cloud, const RegionAnalysis& analysis,
                                     const ExtractionOptions& options)
{
    ExtractionResult result;
    result.spacing = cloud.spacing;
    const Eigen::Index n = cloud.points.rows();
    addSharpLines(analysis.sharp, result);
    DistinctPointResults points(n);
    int patches = 0;
    ProgressReporter reporter(options.progress, options.progressInterval);
    std::vector<size_t> regionPoints;
    for (const RegionGeometry& g : analysis.geometry) {
        regionPoints.push_back(g.members.size());
    }
    const std::vector<ProgressSpan> spans =
        regionSpans(reporter, stageStart::smoothEdges, 1.0, regionPoints);
    for (size_t r = 0; r < analysis.geometry.size(); ++r) {
        const RegionGeometry& g = analysis.geometry[r];
        reporter.stage(spans[r].at(0.0), "smooth edges of region " + std::to_string(r + 1));
        RegionReport rr = regionReport(g, options);
        // About half of a region's time goes to its thresholds, half to its lines.
        spans[r].report(0.5);
        const RegionEdges edges = smoothEdgesAndPatches(g, rr.thresholds, analysis.sharp, options,
                                                        patches, spans[r].part(0.5, 1.0));
        patches = edges.nextPatch;
        setRegionPoints(g, edges.patchOf, addSmoothLines(g, rr, edges, result), points);
        result.regions.push_back(std::move(rr));
    }
    if (!options.smoothEdges) {
        for (Eigen::Index p = 0; p < n; ++p) {
            points.region[p] = analysis.regions.region[p];
        }
    }
    copyToInputPoints(cloud, points, result);
    reporter.stage(1.0, "done");
    return result;
}

ExtractionResult extractFeatureLines(const PointMatrix& P, const ExtractionOptions& options)
{
    CloudGeometry cloud =
        analyseCloud(P, options.neighbours, options.progress, options.progressInterval);
    // Nothing after the regions reads the cloud's neighbourhoods: a region of every point may
    // take them over.
    const RegionAnalysis analysis = analyseRegionsOf(cloud, &cloud.neighbours, options);
    return extractFeatureLines(cloud, analysis, options);
}

} // namespace featurelines
