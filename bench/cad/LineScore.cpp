// SPDX-License-Identifier: LGPL-2.1-or-later
#include "LineScore.h"

#include <cmath>
#include <limits>
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

/// Share of lines that are closed or end on a line at both ends (see LineScore::closedness);
/// with `only`, of the lines of that type (their ends may lie on a line of any type).
double closednessOf(const std::vector<TypedPolyline>& lines, double step, double tol,
                    const LineType* only = nullptr)
{
    if (lines.empty()) {
        return notDefined;
    }
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
    int good = 0;
    int counted = 0;
    for (size_t l = 0; l < lines.size(); ++l) {
        const TypedPolyline& line = lines[l];
        if (only && line.type != *only) {
            continue;
        }
        ++counted;
        if (line.closed) {
            ++good;
            continue;
        }
        if (line.points.rows() == 0) {
            continue;
        }
        const int id = static_cast<int>(l);
        const Eigen::Vector3d first = line.points.row(0).transpose();
        const Eigen::Vector3d last = line.points.row(line.points.rows() - 1).transpose();
        if (endJoined(id, first, 0.0) && endJoined(id, last, lengths[l])) {
            ++good;
        }
    }
    return counted > 0 ? static_cast<double>(good) / static_cast<double>(counted) : notDefined;
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
    result.closedness = closednessOf(detected, step, tol);
    const LineType sharp = LineType::Sharp;
    result.sharpClosedness = closednessOf(detected, step, tol, &sharp);
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

} // namespace featurelines::bench
