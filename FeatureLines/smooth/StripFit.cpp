// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/StripFit.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace featurelines {

namespace {

constexpr size_t terms = 11;
/// Sums over points of u^0..u^4, a^2 u^0..u^2, z u^0..u^2.
using Sums = std::array<double, terms>;

/// The sums the normal equations of every border position are made of.
struct StripSums
{
    /// From each sorted point on (#strip + 1 entries); the prefix sums are the whole minus them.
    std::vector<Sums> suffix;
    /// Over the whole strip: z^2, z a^2 and a^4.
    double zz = 0.0, za = 0.0, aaaa = 0.0;
};

/// The sums of `s`, sorted by u.
StripSums stripSums(const std::vector<StripPoint>& s)
{
    const size_t n = s.size();
    StripSums sums;
    sums.suffix.resize(n + 1);
    sums.suffix[n].fill(0.0);
    for (size_t j = n; j-- > 0;) {
        const StripPoint& p = s[j];
        const double u2 = p.u * p.u, a2 = p.a * p.a;
        const Sums v = {1.0,      p.u,     u2,  u2 * p.u,  u2 * u2, a2,
                        a2 * p.u, a2 * u2, p.z, p.z * p.u, p.z * u2};
        for (size_t t = 0; t < terms; ++t) {
            sums.suffix[j][t] = sums.suffix[j + 1][t] + v[t];
        }
        sums.zz += p.z * p.z;
        sums.za += p.z * p.a * p.a;
        sums.aaaa += a2 * a2;
    }
    return sums;
}

/// The residual sum of squares of a least-squares fit from its factorised normal equations and
/// right-hand side; infinite when the factorisation failed or the sum is not finite.
template <class Fit, class Rhs> double residual(double zz, const Fit& fit, const Rhs& rhs)
{
    if (fit.info() != Eigen::Success) {
        return std::numeric_limits<double>::infinity();
    }
    const double sse = zz - fit.solve(rhs).dot(rhs);
    return std::isfinite(sse) ? sse : std::numeric_limits<double>::infinity();
}

/// The normal equations of the model: columns 1, u, a^2 (the straight side) and the hinge.
struct NormalEquations
{
    Eigen::Matrix4d M;
    Eigen::Vector4d r;
};

/// The straight side's block (columns 1, u, a^2) of the normal equations.
NormalEquations straightSide(const StripSums& sums)
{
    const Sums& all = sums.suffix[0];
    NormalEquations eq;
    eq.M.setZero(); // the hinge's row and column are set per position
    eq.r.setZero();
    eq.M.topLeftCorner<3, 3>() << all[0], all[1], all[5], //
        all[1], all[2], all[6],                           //
        all[5], all[6], sums.aaaa;
    eq.r.head<3>() << all[8], all[9], sums.za;
    return eq;
}

/// The hinge's row and column of the normal equations from the sums S over the hinge's side:
/// h = u^2 - 2 u0 u + u0^2 times 1, u, a^2, h and z.
void setHinge(NormalEquations& eq, const Sums& S, double u0)
{
    const double u02 = u0 * u0;
    Eigen::Matrix4d& M = eq.M;
    M(3, 0) = M(0, 3) = S[2] - 2 * u0 * S[1] + u02 * S[0];
    M(3, 1) = M(1, 3) = S[3] - 2 * u0 * S[2] + u02 * S[1];
    M(3, 2) = M(2, 3) = S[7] - 2 * u0 * S[6] + u02 * S[5];
    M(3, 3) = S[4] - 4 * u0 * S[3] + 6 * u02 * S[2] - 4 * u02 * u0 * S[1] + u02 * u02 * S[0];
    eq.r(3) = S[10] - 2 * u0 * S[9] + u02 * S[8];
}

/// The best hinge over the positions k step, |k| <= positions, on either side of each.
struct Hinge
{
    double sse = std::numeric_limits<double>::infinity();
    double u = std::numeric_limits<double>::quiet_NaN();
};

Hinge bestHinge(const std::vector<StripPoint>& s, const StripSums& sums, NormalEquations eq,
                int positions, double step, size_t minSide)
{
    const size_t n = s.size();
    const Sums& all = sums.suffix[0];
    Hinge best;
    size_t j0 = 0;
    for (int k = -positions; k <= positions; ++k) {
        const double u0 = k * step;
        while (j0 < n && s[j0].u <= u0) {
            ++j0;
        }
        if (j0 < minSide || n - j0 < minSide) {
            continue;
        }
        for (int side = 0; side < 2; ++side) {
            // The hinge's side: u > u0, or u <= u0.
            Sums S = sums.suffix[j0];
            if (side == 1) {
                for (size_t t = 0; t < terms; ++t) {
                    S[t] = all[t] - S[t];
                }
            }
            setHinge(eq, S, u0);
            const double sse = residual(sums.zz, Eigen::LDLT<Eigen::Matrix4d>(eq.M), eq.r);
            if (sse < best.sse) {
                best.sse = sse;
                best.u = u0;
            }
        }
    }
    return best;
}

} // namespace

StepFit curvatureStep(std::vector<StripPoint>& s, const StepSearch& search)
{
    StepFit none;
    const size_t n = s.size();
    const size_t minSide = static_cast<size_t>(std::max(search.minPointsPerSide, 1));
    if (n < std::max<size_t>(2 * minSide, 8)) {
        return none;
    }
    std::sort(s.begin(), s.end(),
              [](const StripPoint& x, const StripPoint& y) { return x.u < y.u; });
    const StripSums sums = stripSums(s);
    const NormalEquations eq = straightSide(sums);
    // No step: the straight side alone.
    const double straight =
        residual(sums.zz, Eigen::LDLT<Eigen::Matrix3d>(eq.M.topLeftCorner<3, 3>()),
                 Eigen::Vector3d(eq.r.head<3>()));
    if (!std::isfinite(straight)) {
        return none;
    }
    const int positions = static_cast<int>(std::floor(search.maxShift / search.step));
    const Hinge best = bestHinge(s, sums, eq, positions, search.step, minSide);
    if (!std::isfinite(best.u)) {
        return none;
    }
    if (std::abs(best.u) > (positions - 0.5) * search.step) {
        none.edge = best.u > 0.0 ? 1 : -1;
        return none;
    }
    const double variance = std::max(best.sse, 0.0) / static_cast<double>(n - 4);
    if (!(variance > 0.0) || !(straight - best.sse >= search.minEvidence * variance)) {
        return none;
    }
    StepFit found;
    found.u = best.u;
    return found;
}

} // namespace featurelines
