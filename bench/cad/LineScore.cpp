// SPDX-License-Identifier: LGPL-2.1-or-later
#include "LineScore.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "FeatureLines/Extraction.h"
#include "PointGrid.h"

namespace featurelines::bench {

namespace {

constexpr double notDefined = std::numeric_limits<double>::quiet_NaN();

/// The core's type of a line type: its name is the core's (featurelines::lineTypeName).
featurelines::LineType coreLineType(LineType type)
{
    switch (type) {
    case LineType::Sharp:
        return featurelines::LineType::Sharp;
    case LineType::Smooth:
        return featurelines::LineType::Smooth;
    case LineType::Boundary:
        return featurelines::LineType::Boundary;
    }
    return featurelines::LineType::Sharp;
}

void checkPositive(double value, const char* what)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument(std::string("Line scoring: ") + what +
                                    " must be a positive number.");
    }
}

void checkLine(const TypedPolyline& line, const char* side)
{
    if (!line.points.allFinite()) {
        throw std::invalid_argument(std::string("Line scoring: a ") + side +
                                    " line has a NaN or infinite coordinate.");
    }
}

/// Samples of every line of one type, resampled at `step`.
struct TypeSamples
{
    std::vector<Eigen::Vector3d> points;
};

std::array<TypeSamples, lineTypeCount> samplesByType(const std::vector<TypedPolyline>& lines,
                                                     double step, const char* side)
{
    std::array<TypeSamples, lineTypeCount> result;
    for (const TypedPolyline& line : lines) {
        checkLine(line, side);
        const PointMatrix s = resamplePolyline(line, step);
        auto& target = result[static_cast<int>(line.type)].points;
        for (Eigen::Index i = 0; i < s.rows(); ++i) {
            target.emplace_back(s.row(i).transpose());
        }
    }
    return result;
}

PointGrid gridOf(const std::vector<Eigen::Vector3d>& points, double cell)
{
    PointGrid grid(cell);
    for (size_t i = 0; i < points.size(); ++i) {
        grid.insert(points[i], static_cast<int>(i));
    }
    return grid;
}

long countNear(const std::vector<Eigen::Vector3d>& queries, const PointGrid& grid, double tol)
{
    long n = 0;
    for (const Eigen::Vector3d& q : queries) {
        n += grid.anyWithin(q, tol) ? 1 : 0;
    }
    return n;
}

void finish(TypeScore& s, long matchedDetected, long matchedTruth)
{
    s.precision = s.detectedSamples > 0 ? static_cast<double>(matchedDetected) /
                                              static_cast<double>(s.detectedSamples)
                                        : notDefined;
    if (s.truthSamples == 0) {
        s.recall = notDefined;
        s.f1 = notDefined;
        return;
    }
    s.recall = static_cast<double>(matchedTruth) / static_cast<double>(s.truthSamples);
    const double p = std::isnan(s.precision) ? 0.0 : s.precision;
    s.f1 = p + s.recall > 0.0 ? 2.0 * p * s.recall / (p + s.recall) : 0.0;
}

/// The ends of a set of lines: how many lines are closed or end on a line at both ends, of
/// how many counted, and how many open-line ends join nothing (see LineScore::closedness);
/// with `only`, the lines of that type (their ends may lie on a line of any type).
struct LineEnds
{
    int good = 0;
    int counted = 0;
    int freeEnds = 0;

    double closedness() const
    {
        return counted > 0 ? static_cast<double>(good) / static_cast<double>(counted) : notDefined;
    }
};

LineEnds lineEndsOf(const std::vector<TypedPolyline>& lines, double step, double tol,
                    const LineType* only = nullptr)
{
    // Every sample remembers its line and its arc length, so that an end can be tested
    // against the other lines and against the far parts of its own line.
    struct Sample
    {
        int line;
        double arc;
    };
    std::vector<Sample> samples;
    std::vector<double> lengths(lines.size(), 0.0);
    PointGrid grid(tol);
    for (size_t l = 0; l < lines.size(); ++l) {
        const PointMatrix s = resamplePolyline(lines[l], step);
        double arc = 0.0;
        for (Eigen::Index i = 0; i < s.rows(); ++i) {
            if (i > 0) {
                arc += (s.row(i) - s.row(i - 1)).norm();
            }
            grid.insert(s.row(i).transpose(), static_cast<int>(samples.size()));
            samples.push_back({static_cast<int>(l), arc});
        }
        lengths[l] = arc;
    }
    const auto endJoined = [&](int line, const Eigen::Vector3d& end, double endArc) {
        bool joined = false;
        grid.forEachWithin(end, tol, [&](int id, double) {
            const Sample& s = samples[static_cast<size_t>(id)];
            joined = s.line != line || std::abs(s.arc - endArc) > 2.0 * tol;
            return !joined;
        });
        return joined;
    };
    LineEnds ends;
    for (size_t l = 0; l < lines.size(); ++l) {
        const TypedPolyline& line = lines[l];
        if (only && line.type != *only) {
            continue;
        }
        ++ends.counted;
        if (line.closed) {
            ++ends.good;
            continue;
        }
        if (line.points.rows() == 0) {
            continue;
        }
        const int id = static_cast<int>(l);
        const bool first = endJoined(id, line.points.row(0).transpose(), 0.0);
        const bool last =
            endJoined(id, line.points.row(line.points.rows() - 1).transpose(), lengths[l]);
        ends.good += first && last ? 1 : 0;
        ends.freeEnds += (first ? 0 : 1) + (last ? 0 : 1);
    }
    return ends;
}

/// Distance from q to the segment [a, b].
double segmentDistance(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return (a + t * ab - q).norm();
}

/// The true edges resampled, with a grid over their samples, answering the exact distance
/// from a point to the nearest edge within a radius (through the segments next to the
/// samples within it).
class EdgeDistance
{
public:
    EdgeDistance(const std::vector<TypedPolyline>& edges, double step, double radius) : grid(radius)
    {
        for (const TypedPolyline& e : edges) {
            checkLine(e, "true");
            lines.push_back({resamplePolyline(e, step), e.closed});
            const PointMatrix& s = lines.back().samples;
            for (Eigen::Index i = 0; i < s.rows(); ++i) {
                grid.insert(s.row(i).transpose(), static_cast<int>(where.size()));
                where.push_back({static_cast<int>(lines.size() - 1), static_cast<int>(i)});
            }
        }
    }

    /// The distance from q to the nearest edge, when an edge sample lies within the radius.
    std::optional<double> nearest(const Eigen::Vector3d& q) const
    {
        std::optional<double> best;
        grid.forEachWithin(q, grid.cellSize(), [&](int id, double) {
            const Sample& w = where[static_cast<size_t>(id)];
            const Line& line = lines[static_cast<size_t>(w.line)];
            const Eigen::Index n = line.samples.rows();
            const Eigen::Vector3d p = line.samples.row(w.index).transpose();
            double d = (p - q).norm();
            for (const Eigen::Index j : {w.index - 1, w.index + 1}) {
                const bool inside = j >= 0 && j < n;
                if (inside || (line.closed && n > 2)) {
                    const Eigen::Index k = (j + n) % n;
                    d = std::min(d, segmentDistance(q, p, line.samples.row(k).transpose()));
                }
            }
            best = best ? std::min(*best, d) : d;
            return true;
        });
        return best;
    }

private:
    struct Line
    {
        PointMatrix samples;
        bool closed;
    };
    struct Sample
    {
        int line;
        Eigen::Index index;
    };
    std::vector<Line> lines;
    std::vector<Sample> where;
    PointGrid grid;
};

/// The value below which `share` of the values lie (nearest rank), NaN for none.
double quantile(std::vector<double> values, double share)
{
    if (values.empty()) {
        return notDefined;
    }
    const size_t rank = static_cast<size_t>(std::ceil(share * static_cast<double>(values.size())));
    const size_t k = std::min(values.size() - 1, rank > 0 ? rank - 1 : 0);
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

} // namespace

std::string lineTypeName(LineType type)
{
    return featurelines::lineTypeName(coreLineType(type));
}

LineType lineTypeFromName(const std::string& name)
{
    for (int t = 0; t < lineTypeCount; ++t) {
        if (name == lineTypeName(static_cast<LineType>(t))) {
            return static_cast<LineType>(t);
        }
    }
    throw std::invalid_argument(
        "Unknown feature line type \"" + name + "\" (expected " + lineTypeName(LineType::Sharp) +
        ", " + lineTypeName(LineType::Smooth) + " or " + lineTypeName(LineType::Boundary) + ").");
}

PointMatrix resamplePolyline(const TypedPolyline& line, double step)
{
    checkPositive(step, "the resampling step");
    const PointMatrix& P = line.points;
    const Eigen::Index n = P.rows();
    if (n <= 1) {
        return P;
    }
    std::vector<Eigen::Vector3d> out;
    out.emplace_back(P.row(0).transpose());
    const Eigen::Index segments = line.closed ? n : n - 1;
    double carried = 0.0; // arc length walked since the last emitted sample
    for (Eigen::Index i = 0; i < segments; ++i) {
        const Eigen::Vector3d a = P.row(i).transpose();
        const Eigen::Vector3d b = P.row((i + 1) % n).transpose();
        const double length = (b - a).norm();
        double t = step - carried; // position of the next sample along this segment
        while (t < length) {
            out.push_back(a + (b - a) * (t / length));
            t += step;
        }
        carried = length - (t - step);
    }
    // The last vertex (open line) is always a sample so both ends are represented; a closed
    // line ends where it started.
    if (!line.closed) {
        const Eigen::Vector3d last = P.row(n - 1).transpose();
        if ((out.back() - last).norm() > 1e-12 * step) {
            out.push_back(last);
        }
    }
    PointMatrix S(static_cast<Eigen::Index>(out.size()), 3);
    for (size_t i = 0; i < out.size(); ++i) {
        S.row(static_cast<Eigen::Index>(i)) = out[i].transpose();
    }
    return S;
}

LineScore scoreLines(const std::vector<TypedPolyline>& detected,
                     const std::vector<TypedPolyline>& truth, const LineScoreOptions& options)
{
    checkPositive(options.spacing, "the point spacing");
    checkPositive(options.toleranceFactor, "the tolerance factor");
    checkPositive(options.resampleFactor, "the resampling factor");
    const double tol = options.toleranceFactor * options.spacing;
    const double step = options.resampleFactor * options.spacing;

    const auto det = samplesByType(detected, step, "detected");
    const auto tru = samplesByType(truth, step, "true");
    LineScore result;
    for (int t = 0; t < lineTypeCount; ++t) {
        TypeScore& s = result.types[static_cast<size_t>(t)];
        s.detectedSamples = static_cast<long>(det[t].points.size());
        s.truthSamples = static_cast<long>(tru[t].points.size());
        const long matchedDetected = countNear(det[t].points, gridOf(tru[t].points, tol), tol);
        const long matchedTruth = countNear(tru[t].points, gridOf(det[t].points, tol), tol);
        finish(s, matchedDetected, matchedTruth);
    }
    result.closedness = lineEndsOf(detected, step, tol).closedness();
    const LineType sharp = LineType::Sharp;
    result.sharpClosedness = lineEndsOf(detected, step, tol, &sharp).closedness();
    result.lineCount = static_cast<int>(detected.size());
    return result;
}

LineScore scoreFlaggedPoints(const PointMatrix& flagged, const std::vector<TypedPolyline>& truth,
                             const LineScoreOptions& options)
{
    checkPositive(options.spacing, "the point spacing");
    checkPositive(options.toleranceFactor, "the tolerance factor");
    checkPositive(options.resampleFactor, "the resampling factor");
    if (!flagged.allFinite()) {
        throw std::invalid_argument("Line scoring: a flagged point has a NaN coordinate.");
    }
    const double tol = options.toleranceFactor * options.spacing;
    const double step = options.resampleFactor * options.spacing;

    const auto tru = samplesByType(truth, step, "true");
    std::vector<Eigen::Vector3d> points;
    points.reserve(static_cast<size_t>(flagged.rows()));
    for (Eigen::Index i = 0; i < flagged.rows(); ++i) {
        points.emplace_back(flagged.row(i).transpose());
    }
    const PointGrid flaggedGrid = gridOf(points, tol);

    // near[t][i]: flagged point i lies within the tolerance of a true edge of type t.
    std::array<std::vector<char>, lineTypeCount> near;
    for (int t = 0; t < lineTypeCount; ++t) {
        const PointGrid truthGrid = gridOf(tru[t].points, tol);
        near[t].resize(points.size());
        for (size_t i = 0; i < points.size(); ++i) {
            near[t][i] = truthGrid.anyWithin(points[i], tol) ? 1 : 0;
        }
    }
    LineScore result;
    for (int t = 0; t < lineTypeCount; ++t) {
        long counted = 0;
        long matched = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            bool nearOther = false;
            for (int o = 0; o < lineTypeCount; ++o) {
                nearOther = nearOther || (o != t && near[o][i]);
            }
            if (near[t][i]) {
                ++counted;
                ++matched;
            } else if (!nearOther) {
                ++counted;
            }
        }
        TypeScore& s = result.types[static_cast<size_t>(t)];
        s.detectedSamples = counted;
        s.truthSamples = static_cast<long>(tru[t].points.size());
        finish(s, matched, countNear(tru[t].points, flaggedGrid, tol));
    }
    result.closedness = notDefined;
    result.sharpClosedness = notDefined;
    result.lineCount = 0;
    return result;
}

double LineQuality::confusionShare(LineType truth, LineType found) const
{
    const auto& row = confusion[static_cast<size_t>(truth)];
    long total = missed[static_cast<size_t>(truth)];
    for (const long n : row) {
        total += n;
    }
    return total > 0
               ? static_cast<double>(row[static_cast<size_t>(found)]) / static_cast<double>(total)
               : notDefined;
}

/// LineQuality's estimate errors: each detected sharp or smooth sample against the nearest true
/// sample of any type within `tol` (the true edges resampled at `step`).
void measureEstimates(const std::vector<TypedPolyline>& detected,
                      const std::vector<TypedPolyline>& truth, double step, double tol,
                      LineQuality& q)
{
    // The true samples, each with its line.
    std::vector<int> lineOf;
    PointGrid grid(tol);
    for (size_t l = 0; l < truth.size(); ++l) {
        const PointMatrix s = resamplePolyline(truth[l], step);
        for (Eigen::Index i = 0; i < s.rows(); ++i) {
            grid.insert(s.row(i).transpose(), static_cast<int>(lineOf.size()));
            lineOf.push_back(static_cast<int>(l));
        }
    }
    std::vector<double> angleErrors, radiusErrors;
    long sharpOnSharp = 0, smoothOnSmooth = 0;
    for (const TypedPolyline& line : detected) {
        if (line.type != LineType::Sharp && line.type != LineType::Smooth) {
            continue;
        }
        const bool sharp = line.type == LineType::Sharp;
        const double estimate = sharp ? line.angle : line.radius;
        const PointMatrix s = resamplePolyline(line, step);
        for (Eigen::Index i = 0; i < s.rows(); ++i) {
            int nearest = -1;
            double best = std::numeric_limits<double>::infinity();
            grid.forEachWithin(s.row(i).transpose(), tol, [&](int id, double d2) {
                if (d2 < best) {
                    best = d2;
                    nearest = id;
                }
                return true;
            });
            if (nearest < 0) {
                continue;
            }
            const TypedPolyline& edge = truth[static_cast<size_t>(lineOf[static_cast<size_t>(nearest)])];
            if (edge.type != line.type) {
                continue;
            }
            (sharp ? sharpOnSharp : smoothOnSmooth) += 1;
            const double truthValue = sharp ? edge.angle : edge.radius;
            if (!std::isfinite(estimate) || !std::isfinite(truthValue)) {
                continue;
            }
            if (sharp) {
                angleErrors.push_back(std::abs(estimate - truthValue));
            } else if (truthValue > 0.0) {
                radiusErrors.push_back(std::abs(estimate / truthValue - 1.0));
            }
        }
    }
    q.medianAngleError = quantile(angleErrors, 0.5);
    q.medianRadiusError = quantile(radiusErrors, 0.5);
    q.angleEstimatedShare = sharpOnSharp > 0 ? static_cast<double>(angleErrors.size()) /
                                                   static_cast<double>(sharpOnSharp)
                                             : notDefined;
    q.radiusEstimatedShare = smoothOnSmooth > 0 ? static_cast<double>(radiusErrors.size()) /
                                                      static_cast<double>(smoothOnSmooth)
                                                : notDefined;
}

LineQuality measureLineQuality(const std::vector<TypedPolyline>& detected,
                               const std::vector<TypedPolyline>& truth,
                               const LineScoreOptions& options)
{
    checkPositive(options.spacing, "the point spacing");
    checkPositive(options.toleranceFactor, "the tolerance factor");
    checkPositive(options.resampleFactor, "the resampling factor");
    const double tol = options.toleranceFactor * options.spacing;
    const double step = options.resampleFactor * options.spacing;
    LineQuality q;

    // Distances of the detected samples to the true edges.
    const EdgeDistance edges(truth, step, tol);
    std::vector<double> distances;
    long samples = 0;
    for (const TypedPolyline& line : detected) {
        checkLine(line, "detected");
        const PointMatrix s = resamplePolyline(line, step);
        for (Eigen::Index i = 0; i < s.rows(); ++i, ++samples) {
            if (const std::optional<double> d = edges.nearest(s.row(i).transpose())) {
                distances.push_back(*d / options.spacing);
            }
        }
        if (line.type == LineType::Boundary) {
            for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
                q.boundaryLength += (line.points.row(i) - line.points.row(i - 1)).norm();
            }
            if (line.closed && line.points.rows() > 2) {
                q.boundaryLength +=
                    (line.points.row(0) - line.points.row(line.points.rows() - 1)).norm();
            }
        }
    }
    q.boundaryLength /= options.spacing;
    q.matchedShare = samples > 0
                         ? static_cast<double>(distances.size()) / static_cast<double>(samples)
                         : notDefined;
    q.medianDistance = quantile(distances, 0.5);
    q.p95Distance = quantile(distances, 0.95);

    // The type each true sample is found as: that of the nearest detected sample.
    const auto det = samplesByType(detected, step, "detected");
    std::vector<PointGrid> grids;
    for (int t = 0; t < lineTypeCount; ++t) {
        grids.push_back(gridOf(det[t].points, tol));
    }
    const auto tru = samplesByType(truth, step, "true");
    for (int t = 0; t < lineTypeCount; ++t) {
        for (const Eigen::Vector3d& p : tru[t].points) {
            int found = -1;
            double best = std::numeric_limits<double>::infinity();
            for (int u = 0; u < lineTypeCount; ++u) {
                grids[static_cast<size_t>(u)].forEachWithin(p, tol, [&](int, double d2) {
                    if (d2 < best) {
                        best = d2;
                        found = u;
                    }
                    return true;
                });
            }
            if (found < 0) {
                ++q.missed[static_cast<size_t>(t)];
            } else {
                ++q.confusion[static_cast<size_t>(t)][static_cast<size_t>(found)];
            }
        }
    }

    measureEstimates(detected, truth, step, tol, q);
    q.linesPerTrueEdge =
        truth.empty() ? notDefined
                      : static_cast<double>(detected.size()) / static_cast<double>(truth.size());
    q.freeEnds = lineEndsOf(detected, step, tol).freeEnds;
    return q;
}

} // namespace featurelines::bench
