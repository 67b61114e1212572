// SPDX-License-Identifier: LGPL-2.1-or-later
// The curvature step across a strip of points: where a straight side meets a parabola with the
// same value and slope (beyond the paper; docs/design/line-placement.md, "The strip fit").
#pragma once

#include <limits>
#include <vector>

namespace featurelines {

/// One point of a strip in its vertex's frame, in fit spacings: across the line (u), along it
/// (a), along the normal (z).
struct StripPoint
{
    double u, a, z;
};

/// Where curvatureStep looks for the border and what it asks of it.
struct StepSearch
{
    /// The largest |u0| tried (fit spacings).
    double maxShift;
    /// The step between the positions u0 tried (fit spacings).
    double step;
    /// The drop in the residual sum of squares a border must bring, in residual variances.
    double minEvidence;
    /// Least number of points on each side of a border position (at least 1 is used).
    int minPointsPerSide;
};

/// What curvatureStep found across a strip.
struct StepFit
{
    /// The border's position across the strip (fit spacings), NaN when none was found.
    double u = std::numeric_limits<double>::quiet_NaN();
    /// The best position lay on the edge of the range searched, on the side of `edge` (-1 or
    /// +1; 0 when it did not): the border may lie beyond it.
    int edge = 0;
};

/// The border across a strip: the position u0 (fit spacings, a multiple of search.step within
/// search.maxShift) at which
///   z = c0 + c1 u + c2 a^2 + c3 [u > u0] (u - u0)^2     (or [u < u0] (u0 - u)^2)
/// fits best by least squares. NaN unless that beats the straight side alone (c3 = 0) by
/// minEvidence residual variances; NaN with `edge` set when the best u0 lies on the edge of the
/// range. Sorts `strip` by u.
StepFit curvatureStep(std::vector<StripPoint>& strip, const StepSearch& search);

} // namespace featurelines
