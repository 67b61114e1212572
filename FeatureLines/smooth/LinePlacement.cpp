// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/LinePlacement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "FeatureLines/neighbourhoods/MortonOrder.h"

namespace featurelines {

namespace {

/// The points of P hashed into cubic cells `cell` wide: the points within `cell` of a query
/// along every axis lie in its cell and the 26 around it.
class CellIndex
{
public:
    CellIndex(const PointMatrix& P, double cell) : cell_(cell)
    {
        low_ =
            P.rows() > 0 ? Eigen::RowVector3d(P.colwise().minCoeff()) : Eigen::RowVector3d::Zero();
        const Eigen::RowVector3d span = P.rows() > 0
                                            ? Eigen::RowVector3d(P.colwise().maxCoeff() - low_)
                                            : Eigen::RowVector3d::Zero();
        if (!((span / cell).maxCoeff() < static_cast<double>((1 << mortonBitsPerAxis) - 2))) {
            throw std::invalid_argument(
                "line placement: the region spans too many strip widths to be indexed");
        }
        keyed_.resize(static_cast<size_t>(P.rows()));
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            std::uint64_t c[3];
            for (int d = 0; d < 3; ++d) {
                c[d] = static_cast<std::uint64_t>(std::floor((P(i, d) - low_[d]) / cell_));
            }
            keyed_[static_cast<size_t>(i)] = {mortonKey(c[0], c[1], c[2]), static_cast<int>(i)};
        }
        sortByMortonKey(keyed_);
    }

    /// Appends to `out` the points in q's cell and the cells around it.
    void near(const Eigen::RowVector3d& q, std::vector<int>& out) const
    {
        std::int64_t c[3];
        for (int d = 0; d < 3; ++d) {
            c[d] = static_cast<std::int64_t>(std::floor((q[d] - low_[d]) / cell_));
        }
        const std::int64_t top = (std::int64_t{1} << mortonBitsPerAxis) - 1;
        for (std::int64_t x = c[0] - 1; x <= c[0] + 1; ++x) {
            for (std::int64_t y = c[1] - 1; y <= c[1] + 1; ++y) {
                for (std::int64_t z = c[2] - 1; z <= c[2] + 1; ++z) {
                    if (x < 0 || y < 0 || z < 0 || x > top || y > top || z > top) {
                        continue;
                    }
                    const std::uint64_t key =
                        mortonKey(static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y),
                                  static_cast<std::uint64_t>(z));
                    auto it = std::lower_bound(keyed_.begin(), keyed_.end(), key,
                                               [](const std::pair<std::uint64_t, int>& e,
                                                  std::uint64_t k) { return e.first < k; });
                    for (; it != keyed_.end() && it->first == key; ++it) {
                        out.push_back(it->second);
                    }
                }
            }
        }
    }

private:
    double cell_;
    Eigen::RowVector3d low_;
    std::vector<std::pair<std::uint64_t, int>> keyed_;
};

/// One point of a strip in the vertex's frame, in fit spacings: across the line (u), along it
/// (a), along the normal (z).
struct StripPoint
{
    double u, a, z;
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

/// The border across a strip: the position u0 (fit spacings) at which the model
///   z = c0 + c1 u + c2 a^2 + c3 [u > u0] (u - u0)^2     (or [u < u0] (u0 - u)^2)
/// fits best. The first three terms are the surface on the straight side (a plane across the
/// line, bending along it); the hinge adds a curvature step at u0 with value and slope
/// continuous: a fillet meeting a face, or a face that is straight across the border (a
/// cylinder along its axis, a fillet's spine). A curved side as well would leave the step
/// nearly unplaceable: on a strip, a quadric plus a one-sided parabola reproduces a hinge
/// moved by several of its widths to within a few percent. Returns NaN unless the best
/// position beats the straight side alone (c3 = 0: no step) by minEvidence residual
/// variances, or when it lies on the edge of [-maxShift, maxShift] (then `edge` says which):
/// one curvature across the whole strip (a cylinder across, a sphere) is fitted best by a
/// hinge at the strip's edge, and so is a border beyond the range.
StepFit curvatureStep(std::vector<StripPoint>& s, double maxShift, double step,
                      const LinePlacementOptions& options)
{
    StepFit none;
    const size_t n = s.size();
    const size_t minSide = static_cast<size_t>(std::max(options.minPointsPerSide, 1));
    if (n < std::max<size_t>(2 * minSide, 8)) {
        return none;
    }
    std::sort(s.begin(), s.end(),
              [](const StripPoint& x, const StripPoint& y) { return x.u < y.u; });
    // Suffix sums from each sorted point on of u^0..u^4, a^2 u^0..u^2, z u^0..u^2; the prefix
    // sums are the whole minus them.
    constexpr size_t terms = 11;
    using Sums = std::array<double, terms>;
    std::vector<Sums> suffix(n + 1);
    suffix[n].fill(0.0);
    double zz = 0.0, za = 0.0, aaaa = 0.0;
    for (size_t j = n; j-- > 0;) {
        const StripPoint& p = s[j];
        const double u2 = p.u * p.u, a2 = p.a * p.a;
        const Sums v = {1.0,      p.u,     u2,  u2 * p.u,  u2 * u2, a2,
                        a2 * p.u, a2 * u2, p.z, p.z * p.u, p.z * u2};
        for (size_t t = 0; t < terms; ++t) {
            suffix[j][t] = suffix[j + 1][t] + v[t];
        }
        zz += p.z * p.z;
        za += p.z * p.a * p.a;
        aaaa += a2 * a2;
    }
    const Sums& all = suffix[0];
    // The straight side: columns 1, u, a^2.
    Eigen::Matrix4d M;
    Eigen::Vector4d r;
    M.topLeftCorner<3, 3>() << all[0], all[1], all[5], //
        all[1], all[2], all[6],                        //
        all[5], all[6], aaaa;
    r.head<3>() << all[8], all[9], za;
    const auto residual = [&](auto fit, auto rhs) {
        if (fit.info() != Eigen::Success) {
            return std::numeric_limits<double>::infinity();
        }
        const double sse = zz - fit.solve(rhs).dot(rhs);
        return std::isfinite(sse) ? sse : std::numeric_limits<double>::infinity();
    };
    // No step: the straight side alone.
    const double straight = residual(Eigen::LDLT<Eigen::Matrix3d>(M.topLeftCorner<3, 3>()),
                                     Eigen::Vector3d(r.head<3>()));
    if (!std::isfinite(straight)) {
        return none;
    }

    double bestSse = std::numeric_limits<double>::infinity();
    double bestU = std::numeric_limits<double>::quiet_NaN();
    size_t j0 = 0;
    const int positions = static_cast<int>(std::floor(maxShift / step));
    for (int k = -positions; k <= positions; ++k) {
        const double u0 = k * step;
        while (j0 < n && s[j0].u <= u0) {
            ++j0;
        }
        if (j0 < minSide || n - j0 < minSide) {
            continue;
        }
        const double u02 = u0 * u0;
        for (int side = 0; side < 2; ++side) {
            // Sums over the hinge's side (u > u0, or u <= u0) of the hinge
            // h = u^2 - 2 u0 u + u0^2 times 1, u, a^2, h and z.
            Sums S = suffix[j0];
            if (side == 1) {
                for (size_t t = 0; t < terms; ++t) {
                    S[t] = all[t] - S[t];
                }
            }
            M(3, 0) = M(0, 3) = S[2] - 2 * u0 * S[1] + u02 * S[0];
            M(3, 1) = M(1, 3) = S[3] - 2 * u0 * S[2] + u02 * S[1];
            M(3, 2) = M(2, 3) = S[7] - 2 * u0 * S[6] + u02 * S[5];
            M(3, 3) =
                S[4] - 4 * u0 * S[3] + 6 * u02 * S[2] - 4 * u02 * u0 * S[1] + u02 * u02 * S[0];
            r(3) = S[10] - 2 * u0 * S[9] + u02 * S[8];
            const double sse = residual(Eigen::LDLT<Eigen::Matrix4d>(M), r);
            if (sse < bestSse) {
                bestSse = sse;
                bestU = u0;
            }
        }
    }
    if (!std::isfinite(bestU)) {
        return none;
    }
    if (std::abs(bestU) > (positions - 0.5) * step) {
        none.edge = bestU > 0.0 ? 1 : -1;
        return none;
    }
    const double variance = std::max(bestSse, 0.0) / static_cast<double>(n - 4);
    if (!(variance > 0.0) || !(straight - bestSse >= options.minEvidence * variance)) {
        return none;
    }
    StepFit found;
    found.u = bestU;
    return found;
}

double median(std::vector<double>& v)
{
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    const double upper = v[mid];
    if (v.size() % 2 == 1) {
        return upper;
    }
    return 0.5 *
           (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)));
}

} // namespace

int placeOnCurvatureSteps(LineNetwork& network, const PointMatrix& P, const NormalMatrix& N,
                          const Eigen::VectorXd& curvature, double spacing, double fitSpacing,
                          double threshold, const LinePlacementOptions& options)
{
    if (P.rows() != N.rows()) {
        throw std::invalid_argument("line placement: every point needs a normal");
    }
    if (curvature.size() != 0 && curvature.size() != P.rows()) {
        throw std::invalid_argument(
            "line placement: the curvature must be given for every point or for none");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing) || !(fitSpacing >= spacing) ||
        !std::isfinite(fitSpacing) || !(threshold >= 0.0) || !std::isfinite(threshold)) {
        throw std::invalid_argument(
            "line placement: the spacings must be positive, the fit's at least the region's, "
            "the threshold a number not below zero");
    }
    if (!(options.halfWidth > 0.0) || !(options.halfLength > 0.0) || !(options.maxShift > 0.0) ||
        !(options.step > 0.0) || !(options.minEvidence >= 0.0) || !(options.radiusShare >= 0.0) ||
        options.minPointsPerSide < 1 || options.medianHalfWindow < 0 || options.recentres < 0 ||
        !(options.fitStride >= 0.0) ||
        !std::isfinite(options.halfWidth + options.halfLength + options.maxShift + options.step)) {
        throw std::invalid_argument("line placement: the strip's half width and length, the "
                                    "largest shift and the step must be positive numbers, the "
                                    "evidence not negative, a side at least one point");
    }
    if (P.rows() == 0 || network.lines.empty()) {
        return 0;
    }
    // The strip's half width and length in fit spacings.
    double W = options.halfWidth;
    if (threshold > 0.0) {
        W = std::max(W, options.radiusShare / (4.0 * threshold) / fitSpacing);
    }
    const double L = std::max(options.halfLength, W);
    const double reach = std::sqrt(2 * W * W + L * L) * fitSpacing;
    const double step = options.step * spacing / fitSpacing;
    const CellIndex index(P, reach);

    // The vertices fitted: along each line, inner vertices (an open line's ends sit on
    // junctions or anchors) about fitStride strip half lengths apart; the strips of the
    // vertices between them would hold nearly the same points.
    const double stride = options.fitStride * L * fitSpacing;
    std::vector<std::pair<int, int>> fitted;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        const PointMatrix& V = network.lines[l].points;
        const int m = static_cast<int>(V.rows());
        if (m < 3) {
            continue;
        }
        const int firstInner = network.lines[l].closed ? 0 : 1;
        const int lastInner = network.lines[l].closed ? m - 1 : m - 2;
        double run = stride;
        for (int i = firstInner; i <= lastInner; ++i) {
            if (i > firstInner) {
                run += (V.row(i) - V.row(i - 1)).norm();
            }
            if (run >= stride || i == lastInner) {
                fitted.emplace_back(static_cast<int>(l), i);
                run = 0.0;
            }
        }
    }
    // Per fitted vertex: the shift found (fit spacings, NaN: none) and the direction across.
    std::vector<double> shift(fitted.size(), std::numeric_limits<double>::quiet_NaN());
    std::vector<Eigen::RowVector3d> across(fitted.size(), Eigen::RowVector3d::Zero());
#pragma omp parallel
    {
        std::vector<int> near;
        std::vector<StripPoint> strip;
        std::vector<double> high;
#pragma omp for schedule(dynamic, 4)
        for (size_t t = 0; t < fitted.size(); ++t) {
            const PointMatrix& V = network.lines[static_cast<size_t>(fitted[t].first)].points;
            const Eigen::Index m = V.rows(), i = fitted[t].second;
            const Eigen::RowVector3d v = V.row(i);
            // The line's direction over the strip's length: from the vertex half a strip
            // length back to the one half a strip length ahead (the line's own vertices zigzag
            // by a coarse spacing; their neighbours' chord can be tens of degrees off).
            const bool closed = network.lines[static_cast<size_t>(fitted[t].first)].closed;
            const auto reachAlong = [&](Eigen::Index step) {
                Eigen::Index j = i;
                double walked = 0.0;
                for (Eigen::Index s = 0; s + 1 < m && walked < L * fitSpacing; ++s) {
                    const Eigen::Index next = closed ? (j + step + m) % m : j + step;
                    if (next < 0 || next >= m) {
                        break;
                    }
                    walked += (V.row(next) - V.row(j)).norm();
                    j = next;
                }
                return j;
            };
            const Eigen::RowVector3d tangent = V.row(reachAlong(1)) - V.row(reachAlong(-1));
            // The strip's frame at `centre`: the surface normal from the points within a fit
            // spacing (their normals turned alike), the line's direction in the tangent plane,
            // and across it. False where the points do not give one.
            Eigen::RowVector3d n, a, c;
            const auto frameAt = [&](const Eigen::RowVector3d& centre) {
                near.clear();
                index.near(centre, near);
                Eigen::RowVector3d normal = Eigen::RowVector3d::Zero();
                int reference = -1;
                for (int p : near) {
                    if ((P.row(p) - centre).squaredNorm() <= fitSpacing * fitSpacing) {
                        if (reference < 0) {
                            reference = p;
                        }
                        const double sign = N.row(p).dot(N.row(reference)) < 0.0 ? -1.0 : 1.0;
                        normal += sign * N.row(p);
                    }
                }
                if (!(normal.norm() > 0.0)) {
                    return false;
                }
                n = normal.normalized();
                const Eigen::RowVector3d along = tangent - tangent.dot(n) * n;
                if (!(along.norm() > 0.0)) {
                    return false;
                }
                a = along.normalized();
                // Across keeps the side of the first frame's: a re-centred strip continues
                // the search in the same direction.
                const Eigen::RowVector3d cross = n.cross(a);
                c = across[t].norm() > 0.0 && cross.dot(across[t]) < 0.0 ? -cross : cross;
                return true;
            };
            // The strip is narrowed to the fillet the points on the line's high side show, where
            // it is smaller than the threshold implies (a fillet whose radius varies along it,
            // a threshold low in its valley): 0.4 of the radius of the cylinder with their
            // lower quartile of |H|, r = 1 / (2 |H|). Needs the frame at v (n, a, c) and the
            // points near it.
            const auto stripWidth = [&]() {
                if (curvature.size() == 0 || !(threshold > 0.0)) {
                    return W;
                }
                high.clear();
                for (int p : near) {
                    const Eigen::RowVector3d d = (P.row(p) - v) / fitSpacing;
                    const double value = std::abs(curvature[p]);
                    if (value > threshold && std::abs(d.dot(c)) <= W && std::abs(d.dot(a)) <= L) {
                        high.push_back(value);
                    }
                }
                if (high.empty()) {
                    return W;
                }
                // The lower quartile: where a corner's sphere (|H| of a cylinder of half its
                // radius) shares the high side with the fillet, the fillet's values.
                const size_t quartile = high.size() / 4;
                std::nth_element(high.begin(), high.begin() + static_cast<std::ptrdiff_t>(quartile),
                                 high.end());
                const double radius = 1.0 / (2.0 * high[quartile]);
                return std::max(options.halfWidth,
                                std::min(W, options.radiusShare * radius / fitSpacing));
            };
            Eigen::RowVector3d centre = v;
            double width = W; // this vertex's strip half width
            for (int attempt = 0; attempt <= options.recentres; ++attempt) {
                if (!frameAt(centre)) {
                    break;
                }
                if (attempt == 0) {
                    across[t] = c;
                    width = stripWidth();
                }
                strip.clear();
                for (int p : near) {
                    const Eigen::RowVector3d d = (P.row(p) - centre) / fitSpacing;
                    const StripPoint sp{d.dot(c), d.dot(a), d.dot(n)};
                    if (std::abs(sp.u) <= width && std::abs(sp.a) <= L && std::abs(sp.z) <= width) {
                        strip.push_back(sp);
                    }
                }
                const StepFit fit = curvatureStep(strip, options.maxShift * width, step, options);
                if (std::isfinite(fit.u)) {
                    shift[t] = (centre + fit.u * fitSpacing * c - v).dot(across[t]) / fitSpacing;
                    break;
                }
                if (fit.edge == 0) {
                    break;
                }
                // The border lies beyond the range: the next strip is centred on its edge.
                centre += fit.edge * options.maxShift * width * fitSpacing * c;
            }
        }
    }

    // A fitted vertex moves by the median of the shifts found around it along its line, when
    // most of them found one: a lone fit does not bend the line. The normals' signs are each
    // vertex's own, so a neighbour's shift counts along this vertex's direction across.
    const int h = options.medianHalfWindow;
    std::vector<Eigen::RowVector3d> displacement(fitted.size(), Eigen::RowVector3d::Zero());
    std::vector<char> placedFit(fitted.size(), 0);
    std::vector<double> window;
    for (size_t first = 0; first < fitted.size();) {
        const int l = fitted[first].first;
        size_t last = first;
        while (last < fitted.size() && fitted[last].first == l) {
            ++last;
        }
        const bool closed = network.lines[static_cast<size_t>(l)].closed;
        const int count = static_cast<int>(last - first);
        for (int j = 0; j < count; ++j) {
            const size_t at = first + static_cast<size_t>(j);
            window.clear();
            for (int o = -h; o <= h; ++o) {
                int q = j + o;
                if (closed) {
                    q = ((q % count) + count) % count;
                } else if (q < 0 || q >= count) {
                    continue;
                }
                const size_t k = first + static_cast<size_t>(q);
                if (std::isfinite(shift[k])) {
                    window.push_back(across[k].dot(across[at]) < 0.0 ? -shift[k] : shift[k]);
                }
            }
            if (static_cast<int>(window.size()) >= std::min(h + 1, count) &&
                across[at].norm() > 0.0) {
                displacement[at] = median(window) * fitSpacing * across[at];
                placedFit[at] = 1;
            }
        }
        first = last;
    }

    // The vertices between two fitted ones move by the displacements of the two, weighed by
    // arc length; next to a fitted vertex that found no step, by the other's over its half.
    int moved = 0;
    for (size_t first = 0; first < fitted.size();) {
        const int l = fitted[first].first;
        size_t last = first;
        while (last < fitted.size() && fitted[last].first == l) {
            ++last;
        }
        Polyline& line = network.lines[static_cast<size_t>(l)];
        const Eigen::Index m = line.points.rows();
        std::vector<double> arc(static_cast<size_t>(m) + 1, 0.0);
        for (Eigen::Index i = 1; i <= m; ++i) {
            arc[static_cast<size_t>(i)] = arc[static_cast<size_t>(i - 1)] +
                                          (line.points.row(i % m) - line.points.row(i - 1)).norm();
        }
        const double length = arc[static_cast<size_t>(m)];
        PointMatrix placed = line.points;
        // An open line's ends sit on junctions or anchors and stay: the displacement tapers to
        // none over one stride from each end, so the line keeps its direction there. (Its
        // first and last inner vertices are fitted, so every inner vertex lies between two.)
        const auto move = [&](Eigen::Index i, const Eigen::RowVector3d& d) {
            double taper = 1.0;
            if (!line.closed && stride > 0.0) {
                const double fromEnd =
                    std::min(arc[static_cast<size_t>(i)],
                             arc[static_cast<size_t>(m - 1)] - arc[static_cast<size_t>(i)]);
                taper = std::min(1.0, fromEnd / stride);
            }
            if (taper * d.squaredNorm() > 0.0) {
                placed.row(i) += taper * d;
                ++moved;
            }
        };
        const int count = static_cast<int>(last - first);
        // Pairs of consecutive fitted vertices; a closed line's last pairs with its first.
        for (int j = 0; j + 1 < count + (line.closed ? 1 : 0); ++j) {
            const size_t f0 = first + static_cast<size_t>(j);
            const size_t f1 = first + static_cast<size_t>((j + 1) % count);
            const Eigen::Index i0 = fitted[f0].second, i1 = fitted[f1].second;
            const Eigen::Index span = ((i1 - i0) % m + m) % m;
            double gap = arc[static_cast<size_t>(i1)] - arc[static_cast<size_t>(i0)];
            if (gap <= 0.0) {
                gap += length;
            }
            for (Eigen::Index o = (j == 0 ? 0 : 1); o <= span; ++o) {
                const Eigen::Index i = (i0 + o) % m;
                if (o == span && line.closed && j + 1 == count) {
                    break; // the first fitted vertex, placed with the first pair
                }
                double along = arc[static_cast<size_t>(i)] - arc[static_cast<size_t>(i0)];
                if (along < 0.0) {
                    along += length;
                }
                const double t = gap > 0.0 ? along / gap : 0.0;
                if (placedFit[f0] && placedFit[f1]) {
                    move(i, (1.0 - t) * displacement[f0] + t * displacement[f1]);
                } else if (placedFit[f0] && t <= 0.5) {
                    move(i, displacement[f0]);
                } else if (placedFit[f1] && t > 0.5) {
                    move(i, displacement[f1]);
                }
            }
        }
        if (count == 1 && placedFit[first]) {
            move(fitted[first].second, displacement[first]);
        }
        line.points = std::move(placed);
        first = last;
    }
    return moved;
}

} // namespace featurelines
