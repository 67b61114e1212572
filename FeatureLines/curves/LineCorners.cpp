// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curves/LineCorners.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "FeatureLines/curves/CurveFit.h"

namespace featurelines {

namespace {

using Vec3 = Eigen::Vector3d;

constexpr double pi = 3.14159265358979323846;

Vec3 row(const PointMatrix& P, Eigen::Index i)
{
    return P.row(i).transpose();
}

/// The line through points: their centroid and principal direction, and the sum of their
/// squared distances to it.
struct FittedLine
{
    Vec3 centre = Vec3::Zero();
    Vec3 direction = Vec3::UnitX();
    double squaredResidual = 0.0;
};

FittedLine fitLine(const std::vector<Vec3>& points)
{
    FittedLine f;
    for (const Vec3& p : points) {
        f.centre += p;
    }
    f.centre /= static_cast<double>(points.size());
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (const Vec3& p : points) {
        C += (p - f.centre) * (p - f.centre).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
    f.direction = eig.eigenvectors().col(2);
    f.squaredResidual = std::max(0.0, eig.eigenvalues()(0) + eig.eigenvalues()(1));
    return f;
}

/// The sum of the squared distances of points to the circle that fits them best
/// (bestFitCircle, CurveFit.h); infinite where none does.
double circleResidual(const std::vector<Vec3>& points)
{
    PointMatrix P(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) {
        P.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    }
    const std::optional<BestCircle> circle = bestFitCircle(P);
    if (!circle) {
        return std::numeric_limits<double>::infinity();
    }
    double sum = 0.0;
    for (const Vec3& p : points) {
        const Vec3 d = p - circle->centre;
        const double off = d.dot(circle->normal);
        const double radial = (d - off * circle->normal).norm() - circle->radius;
        sum += radial * radial + off * off;
    }
    return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
}

/// One side of a corner: its points, how far along the line they reach, their line and its
/// direction of travel (into the corner before it, out of it after it).
struct Side
{
    std::vector<Vec3> points;
    double reached = 0.0;
    FittedLine line;
    Vec3 travel = Vec3::UnitX();
};

/// The points of the line on one side of vertex i (backwards when `before`), from `from` to
/// `to` along the line; open lines stop at their ends, closed ones at half their length.
std::vector<Vec3> side(const PointMatrix& P, bool closed, Eigen::Index i, bool before, double from,
                       double to, double halfLength, double* reached)
{
    std::vector<Vec3> out;
    const Eigen::Index n = P.rows();
    double along = 0.0;
    *reached = 0.0;
    Eigen::Index at = i;
    for (Eigen::Index step = 1; step < n; ++step) {
        Eigen::Index next = before ? at - 1 : at + 1;
        if (next < 0 || next >= n) {
            if (!closed) {
                break;
            }
            next = (next + n) % n;
        }
        along += (row(P, next) - row(P, at)).norm();
        if (along > to || (closed && along > halfLength)) {
            break;
        }
        at = next;
        *reached = along;
        if (along >= from) {
            out.push_back(row(P, at));
        }
    }
    return out;
}

/// The side of the line before (or after) vertex i, from `from` to `to` along it.
Side makeSide(const PointMatrix& P, bool closed, Eigen::Index i, bool before, double from,
              double to, double halfLength)
{
    Side sd;
    sd.points = side(P, closed, i, before, from, to, halfLength, &sd.reached);
    if (sd.points.size() < 3) {
        return sd;
    }
    sd.line = fitLine(sd.points);
    // The points run away from the corner; travel runs along the line.
    const Vec3 away = sd.points.back() - sd.points.front();
    const Vec3 lineAway =
        sd.line.direction.dot(away) >= 0 ? sd.line.direction : Vec3(-sd.line.direction);
    sd.travel = before ? Vec3(-lineAway) : lineAway;
    return sd;
}

/// The sum of the squared distances of a side's points to its own curve: its line or, where
/// it fits better, an arc. Only for the vertices that pass the turn tests: a circle fit costs
/// far more than the lines.
double ownResidual(const Side& sd)
{
    return std::min(sd.line.squaredResidual, circleResidual(sd.points));
}

double turnDegrees(const Vec3& a, const Vec3& b)
{
    return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / pi;
}

struct Candidate
{
    LineCorner corner;
    double along = 0.0; // arc length from the line's first vertex
};

} // namespace

std::vector<LineCorner> findLineCorners(const PointMatrix& P, bool closed, double spacing,
                                        const LineCornerOptions& o)
{
    if (!(spacing > 0) || !(o.gap >= 0) || !(o.window > o.gap) || !(o.angle >= 0) ||
        !(o.growth >= 0) || !(o.arcRatio >= 0)) {
        throw std::invalid_argument("the line corner options must be positive, the window wider "
                                    "than the gap");
    }
    std::vector<LineCorner> corners;
    const Eigen::Index n = P.rows();
    if (n < 7 || o.angle >= 180.0) {
        return corners;
    }
    std::vector<double> along(static_cast<size_t>(n), 0.0);
    for (Eigen::Index i = 1; i < n; ++i) {
        along[static_cast<size_t>(i)] =
            along[static_cast<size_t>(i - 1)] + (row(P, i) - row(P, i - 1)).norm();
    }
    const double length = along.back() + (closed ? (row(P, 0) - row(P, n - 1)).norm() : 0.0);
    const double gap = o.gap * spacing, window = o.window * spacing;
    if (length < (closed ? 3.0 : 2.0) * window) {
        return corners;
    }
    const double halfLength = length / 2;
    const double wide = std::min(2 * window, length / 3);
    std::vector<Candidate> candidates;
    for (Eigen::Index i = 0; i < n; ++i) {
        const double s = along[static_cast<size_t>(i)];
        if (!closed && (s < window || length - s < window)) {
            continue;
        }
        // The sides' lines over the window turn by the angle: a quick test most vertices fail.
        const Side nearBefore = makeSide(P, closed, i, true, gap, window, halfLength);
        if (nearBefore.points.size() < 3 || nearBefore.reached < 0.75 * window) {
            continue;
        }
        const Side nearAfter = makeSide(P, closed, i, false, gap, window, halfLength);
        if (nearAfter.points.size() < 3 || nearAfter.reached < 0.75 * window) {
            continue;
        }
        const double turn = turnDegrees(nearBefore.travel, nearAfter.travel);
        if (turn < o.angle) {
            continue;
        }
        // Over twice the window the lines still turn by the angle (a slow excursion of a noisy
        // line turns back within it) and by hardly more: on an arc of curvature k the sides'
        // lines turn by k (2 gap + both reaches), nearly twice as much over twice the window,
        // where a corner's turn stays its angle. Twice the window also because the lines
        // round a corner of their edge off over a spacing or two.
        const Side before = makeSide(P, closed, i, true, gap, wide, halfLength);
        const Side after = makeSide(P, closed, i, false, gap, wide, halfLength);
        const double wideTurn = turnDegrees(before.travel, after.travel);
        const double arcGrowth = (2 * gap + before.reached + after.reached) /
                                 (2 * gap + nearBefore.reached + nearAfter.reached);
        if (wideTurn < o.angle || wideTurn > turn * (1 + o.growth * (arcGrowth - 1))) {
            continue;
        }
        // And the two sides, each a line or an arc of its own, fit their points better than
        // one circle through both: where noise makes a gentle arc's turn uncertain, its
        // points still lie on one circle.
        const double count = static_cast<double>(before.points.size() + after.points.size());
        const double sides = (ownResidual(before) + ownResidual(after)) / count;
        std::vector<Vec3> both = before.points;
        both.insert(both.end(), after.points.begin(), after.points.end());
        const double floor = 0.05 * spacing;
        if (circleResidual(both) / count <
            o.arcRatio * o.arcRatio * std::max(sides, floor * floor)) {
            continue;
        }
        Candidate c;
        c.corner.vertex = static_cast<int>(i);
        c.corner.turn = wideTurn;
        c.along = s;
        // The corner where the two sides' lines pass nearest each other.
        const Vec3 p = row(P, i);
        c.corner.position = p;
        // From three gaps out: the sides without the rounded-off corner.
        const Side placeBefore = makeSide(P, closed, i, true, 3 * gap, wide, halfLength);
        const Side placeAfter = makeSide(P, closed, i, false, 3 * gap, wide, halfLength);
        const FittedLine& fb = placeBefore.line;
        const FittedLine& fa = placeAfter.line;
        const Vec3 w0 = fb.centre - fa.centre;
        const double a = fb.direction.dot(fb.direction), b = fb.direction.dot(fa.direction);
        const double cc = fa.direction.dot(fa.direction), d = fb.direction.dot(w0),
                     e = fa.direction.dot(w0);
        const double denominator = a * cc - b * b;
        if (denominator > 1e-9 && placeBefore.points.size() >= 3 && placeAfter.points.size() >= 3) {
            const double t = (b * e - cc * d) / denominator, u = (a * e - b * d) / denominator;
            const Vec3 q0 = fb.centre + t * fb.direction, q1 = fa.centre + u * fa.direction;
            const Vec3 meet = (q0 + q1) / 2;
            // The line's vertex nearest the meeting point, a few either side of this one
            // (they see straight sides too).
            Eigen::Index nearestVertex = i;
            double nearest = (meet - p).norm();
            for (Eigen::Index k = -5; k <= 5; ++k) {
                Eigen::Index j = i + k;
                if (closed) {
                    j = (j % n + n) % n;
                } else if (j < 0 || j >= n) {
                    continue;
                }
                const double dj = (row(P, j) - meet).norm();
                if (dj < nearest) {
                    nearest = dj;
                    nearestVertex = j;
                }
            }
            // Where both sides are straight and their lines meet within a spacing and a half
            // of the line, the line only rounds the corner off: the corner is the meeting
            // point. Where a side is curved (a corner between arcs, or a straight run into a
            // tight round of the border) the lines' meeting point is no corner of the line's:
            // the corner stays on the line.
            // Straight: its line fits it within twice the RMS of its own arc (noise alone
            // fits both alike), or within a twentieth of a spacing.
            const auto straight = [&](const Side& sd) {
                const double floor =
                    0.05 * 0.05 * spacing * spacing * static_cast<double>(sd.points.size());
                return sd.line.squaredResidual <= std::max(4 * ownResidual(sd), floor);
            };
            if ((q0 - q1).norm() <= spacing && nearest <= 1.5 * spacing && straight(placeBefore) &&
                straight(placeAfter)) {
                c.corner.position = meet;
                c.corner.vertex = static_cast<int>(nearestVertex);
                c.along = along[static_cast<size_t>(nearestVertex)];
            }
        }
        candidates.push_back(c);
    }
    // Of the candidates about one corner, the one whose wide sides turn most, one per window.
    std::stable_sort(
        candidates.begin(), candidates.end(),
        [](const Candidate& a, const Candidate& b) { return a.corner.turn > b.corner.turn; });
    std::vector<Candidate> kept;
    for (const Candidate& c : candidates) {
        bool near = false;
        for (const Candidate& k : kept) {
            double d = std::abs(c.along - k.along);
            if (closed) {
                d = std::min(d, length - d);
            }
            near = near || d < window;
        }
        if (!near) {
            kept.push_back(c);
        }
    }
    std::sort(kept.begin(), kept.end(),
              [](const Candidate& a, const Candidate& b) { return a.along < b.along; });
    for (const Candidate& c : kept) {
        corners.push_back(c.corner);
    }
    return corners;
}

} // namespace featurelines
