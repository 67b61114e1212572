// SPDX-License-Identifier: LGPL-2.1-or-later
// Smoothing and resampling along a polyline.
#include "FeatureLines/network/Polyline.h"

#include <algorithm>
#include <cmath>

namespace featurelines {

PointMatrix smoothPolyline(const PointMatrix& points, bool closed, double length)
{
    if (!(length > 0.0) || points.rows() < 3) {
        return points;
    }
    // Each pass of (1/4, 1/2, 1/4) adds a variance of half a step squared: eight passes at a
    // step of length / 2 give a variance of length^2.
    const double step = 0.5 * length;
    const int passes = 8;
    PointMatrix smoothed = resamplePolyline(points, closed, step);
    const Eigen::Index m = smoothed.rows();
    for (int pass = 0; pass < passes && m >= 3; ++pass) {
        const PointMatrix old = smoothed;
        for (Eigen::Index i = 0; i < m; ++i) {
            if (!closed && (i == 0 || i == m - 1)) {
                continue;
            }
            smoothed.row(i) =
                0.25 * old.row((i + m - 1) % m) + 0.5 * old.row(i) + 0.25 * old.row((i + 1) % m);
        }
    }
    return smoothed;
}

PointMatrix resamplePolyline(const PointMatrix& points, bool closed, double step)
{
    const Eigen::Index m = points.rows();
    if (m < 2 || !(step > 0.0) || !std::isfinite(step)) {
        return points;
    }
    const Eigen::Index segments = closed ? m : m - 1;
    std::vector<double> arc(segments + 1, 0.0);
    for (Eigen::Index s = 0; s < segments; ++s) {
        arc[s + 1] = arc[s] + (points.row((s + 1) % m) - points.row(s)).norm();
    }
    const double total = arc.back();
    if (!(total > 0.0)) {
        return points.topRows(1);
    }
    Eigen::Index count = std::max<Eigen::Index>(1, std::llround(total / step));
    if (closed) {
        count = std::max<Eigen::Index>(3, count);
    }
    const Eigen::Index rows = closed ? count : count + 1;
    PointMatrix out(rows, 3);
    Eigen::Index s = 0;
    for (Eigen::Index i = 0; i < rows; ++i) {
        const double t = total * static_cast<double>(i) / static_cast<double>(count);
        while (s + 1 < segments && arc[s + 1] < t) {
            ++s;
        }
        const double span = arc[s + 1] - arc[s];
        const double f = span > 0.0 ? std::clamp((t - arc[s]) / span, 0.0, 1.0) : 0.0;
        out.row(i) = (1.0 - f) * points.row(s) + f * points.row((s + 1) % m);
    }
    if (!closed) {
        out.row(rows - 1) = points.row(m - 1);
    }
    return out;
}

} // namespace featurelines
