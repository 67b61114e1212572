// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/LinePlacement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/smooth/StripFit.h"

namespace featurelines {

namespace {

/// The points of P hashed into cubic cells `cell` wide: the points within `cell` of a query
/// along every axis lie in its cell and the 26 around it. Only the cells within `margin` of a
/// cell holding a vertex of `network` are kept (all of them when `margin` is over 3): a
/// strip's centre moves from its vertex by at most its re-centrings, and its queries reach one
/// cell around the centre. Hashing the whole region instead cost ten times the fits on a
/// million points.
class CellIndex
{
public:
    CellIndex(const PointMatrix& P, double cell, const LineNetwork& network, int margin)
        : cell_(cell)
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
        const bool all = margin > 3;
        const std::vector<std::uint64_t> wanted =
            all ? std::vector<std::uint64_t>{} : cellsNearLines(network, margin);
        const Eigen::Index n = P.rows();
        std::vector<std::uint64_t> keyOf(static_cast<size_t>(n));
        std::vector<char> kept(static_cast<size_t>(n), 0);
#pragma omp parallel for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            std::int64_t c[3];
            cellOf(P.row(i), c);
            const std::uint64_t key =
                mortonKey(static_cast<std::uint64_t>(c[0]), static_cast<std::uint64_t>(c[1]),
                          static_cast<std::uint64_t>(c[2]));
            keyOf[static_cast<size_t>(i)] = key;
            kept[static_cast<size_t>(i)] =
                all || std::binary_search(wanted.begin(), wanted.end(), key);
        }
        for (Eigen::Index i = 0; i < n; ++i) {
            if (kept[static_cast<size_t>(i)]) {
                keyed_.emplace_back(keyOf[static_cast<size_t>(i)], static_cast<int>(i));
            }
        }
        // Stable: the pairs come in index order, so this is their order by (key, index).
        sortByMortonKey(keyed_);
    }

    /// Appends to `out` the points in q's cell and the cells around it.
    void near(const Eigen::RowVector3d& q, std::vector<int>& out) const
    {
        std::int64_t c[3];
        cellOf(q, c);
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
    /// q's cell, counted from low_ (negative or beyond the Morton range off the region).
    void cellOf(const Eigen::RowVector3d& q, std::int64_t c[3]) const
    {
        for (int d = 0; d < 3; ++d) {
            c[d] = static_cast<std::int64_t>(std::floor((q[d] - low_[d]) / cell_));
        }
    }

    /// The Morton keys of the cells within `margin` of a cell holding a vertex of the network,
    /// sorted, each once.
    std::vector<std::uint64_t> cellsNearLines(const LineNetwork& network, int margin) const
    {
        std::vector<std::array<std::int64_t, 3>> holding;
        for (const Polyline& line : network.lines) {
            for (Eigen::Index i = 0; i < line.points.rows(); ++i) {
                std::array<std::int64_t, 3> c;
                cellOf(line.points.row(i), c.data());
                holding.push_back(c);
            }
        }
        std::sort(holding.begin(), holding.end());
        holding.erase(std::unique(holding.begin(), holding.end()), holding.end());
        const std::int64_t top = (std::int64_t{1} << mortonBitsPerAxis) - 1;
        std::vector<std::uint64_t> keys;
        for (const auto& c : holding) {
            for (std::int64_t x = c[0] - margin; x <= c[0] + margin; ++x) {
                for (std::int64_t y = c[1] - margin; y <= c[1] + margin; ++y) {
                    for (std::int64_t z = c[2] - margin; z <= c[2] + margin; ++z) {
                        if (x < 0 || y < 0 || z < 0 || x > top || y > top || z > top) {
                            continue;
                        }
                        keys.push_back(mortonKey(static_cast<std::uint64_t>(x),
                                                 static_cast<std::uint64_t>(y),
                                                 static_cast<std::uint64_t>(z)));
                    }
                }
            }
        }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        return keys;
    }

    double cell_;
    Eigen::RowVector3d low_;
    std::vector<std::pair<std::uint64_t, int>> keyed_;
};

void checkInput(const LinePlacementInput& in, const LinePlacementOptions& options)
{
    if (in.points.rows() != in.normals.rows()) {
        throw std::invalid_argument("line placement: every point needs a normal");
    }
    if (in.curvature.size() != 0 && in.curvature.size() != in.points.rows()) {
        throw std::invalid_argument(
            "line placement: the curvature must be given for every point or for none");
    }
    if (!(in.spacing > 0.0) || !std::isfinite(in.spacing) || !(in.fitSpacing >= in.spacing) ||
        !std::isfinite(in.fitSpacing) || !(in.threshold >= 0.0) || !std::isfinite(in.threshold)) {
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
}

/// The strip's size in fit spacings, derived from the options and the threshold.
struct StripSize
{
    /// The widest half width across (W): halfWidth, or radiusShare of the threshold's fillet.
    double halfWidth;
    /// The half length along (L): halfLength, at least W.
    double halfLength;
    /// The step of the border positions tried.
    double step;
};

StripSize stripSize(const LinePlacementInput& in, const LinePlacementOptions& options)
{
    double W = options.halfWidth;
    if (in.threshold > 0.0) {
        W = std::max(W, options.radiusShare / (4.0 * in.threshold) / in.fitSpacing);
    }
    const double L = std::max(options.halfLength, W);
    return {W, L, options.step * in.spacing / in.fitSpacing};
}

/// What every vertex's fit reads.
struct PlacementContext
{
    const LinePlacementInput& in;
    const LinePlacementOptions& options;
    StripSize size;
    /// The region's points in cells as wide as a strip's half diagonal.
    CellIndex index;
};

/// A thread's buffers, reused from vertex to vertex.
struct Scratch
{
    std::vector<int> near;
    std::vector<StripPoint> strip;
    std::vector<double> high;
};

/// A fitted vertex on its line.
struct LineAt
{
    Eigen::RowVector3d vertex;
    /// The line's direction over the strip's length.
    Eigen::RowVector3d tangent;
    /// The first strip's direction across (zero before it is known).
    Eigen::RowVector3d across;
};

/// A strip's frame: the surface normal (n), the line's direction in the tangent plane (a) and
/// across it (c).
struct StripFrame
{
    Eigen::RowVector3d n, a, c;
};

/// The line's direction at vertex i over `length`: from the vertex that far back to the one that
/// far ahead (the line's own vertices zigzag by a coarse spacing; their neighbours' chord can be
/// tens of degrees off).
Eigen::RowVector3d lineDirection(const Polyline& line, Eigen::Index i, double length)
{
    const PointMatrix& V = line.points;
    const Eigen::Index m = V.rows();
    const auto reachAlong = [&](Eigen::Index step) {
        Eigen::Index j = i;
        double walked = 0.0;
        for (Eigen::Index s = 0; s + 1 < m && walked < length; ++s) {
            const Eigen::Index next = line.closed ? (j + step + m) % m : j + step;
            if (next < 0 || next >= m) {
                break;
            }
            walked += (V.row(next) - V.row(j)).norm();
            j = next;
        }
        return j;
    };
    return V.row(reachAlong(1)) - V.row(reachAlong(-1));
}

/// The strip's frame at `centre`: the surface normal from the points within a fit spacing
/// (their normals turned alike), the line's direction in the tangent plane, and across it on
/// the side of the first frame's (a re-centred strip continues the search in the same
/// direction). Leaves the points near `centre` in `near`. None where the points do not give one.
std::optional<StripFrame> frameAt(const PlacementContext& ctx, const LineAt& at,
                                  const Eigen::RowVector3d& centre, std::vector<int>& near)
{
    const PointMatrix& P = ctx.in.points;
    const NormalMatrix& N = ctx.in.normals;
    const double fitSpacing = ctx.in.fitSpacing;
    near.clear();
    ctx.index.near(centre, near);
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
        return std::nullopt;
    }
    StripFrame f;
    f.n = normal.normalized();
    const Eigen::RowVector3d along = at.tangent - at.tangent.dot(f.n) * f.n;
    if (!(along.norm() > 0.0)) {
        return std::nullopt;
    }
    f.a = along.normalized();
    const Eigen::RowVector3d cross = f.n.cross(f.a);
    f.c = at.across.norm() > 0.0 && cross.dot(at.across) < 0.0 ? -cross : cross;
    return f;
}

/// The vertex's strip half width: narrowed to radiusShare of the radius of the fillet the
/// points on the line's high side show (1 / (2 |H|), |H| their lower quartile), where that is
/// smaller than the threshold's. Reads the points near the vertex in scratch.near.
double stripHalfWidth(const PlacementContext& ctx, const Eigen::RowVector3d& v, const StripFrame& f,
                      Scratch& scratch)
{
    const double W = ctx.size.halfWidth, L = ctx.size.halfLength;
    const double threshold = ctx.in.threshold, fitSpacing = ctx.in.fitSpacing;
    const Eigen::VectorXd& curvature = ctx.in.curvature;
    if (curvature.size() == 0 || !(threshold > 0.0)) {
        return W;
    }
    std::vector<double>& high = scratch.high;
    high.clear();
    for (int p : scratch.near) {
        const Eigen::RowVector3d d = (ctx.in.points.row(p) - v) / fitSpacing;
        const double value = std::abs(curvature[p]);
        if (value > threshold && std::abs(d.dot(f.c)) <= W && std::abs(d.dot(f.a)) <= L) {
            high.push_back(value);
        }
    }
    if (high.empty()) {
        return W;
    }
    // The lower quartile: where a corner's sphere (|H| of a cylinder of half its radius) shares
    // the high side with the fillet, the fillet's values.
    const size_t quartile = high.size() / 4;
    std::nth_element(high.begin(), high.begin() + static_cast<std::ptrdiff_t>(quartile),
                     high.end());
    const double radius = 1.0 / (2.0 * high[quartile]);
    return std::max(ctx.options.halfWidth,
                    std::min(W, ctx.options.radiusShare * radius / fitSpacing));
}

/// Fills scratch.strip with the points near `centre` in its strip `width` wide, in its frame.
void collectStrip(const PlacementContext& ctx, const Eigen::RowVector3d& centre,
                  const StripFrame& f, double width, Scratch& scratch)
{
    scratch.strip.clear();
    for (int p : scratch.near) {
        const Eigen::RowVector3d d = (ctx.in.points.row(p) - centre) / ctx.in.fitSpacing;
        const StripPoint sp{d.dot(f.c), d.dot(f.a), d.dot(f.n)};
        if (std::abs(sp.u) <= width && std::abs(sp.a) <= ctx.size.halfLength &&
            std::abs(sp.z) <= width) {
            scratch.strip.push_back(sp);
        }
    }
}

/// One fitted vertex's result.
struct VertexShift
{
    /// Across the line (fit spacings), NaN where no step was found.
    double shift = std::numeric_limits<double>::quiet_NaN();
    /// The direction across of its first strip; zero where it had none.
    Eigen::RowVector3d across = Eigen::RowVector3d::Zero();
};

/// The step under vertex i of `line`: the strip centred on it, and re-centred on the edge of
/// the range searched while the best border lies there, up to `recentres` times.
VertexShift fitVertex(const PlacementContext& ctx, const Polyline& line, Eigen::Index i,
                      Scratch& scratch)
{
    const double fitSpacing = ctx.in.fitSpacing;
    const LinePlacementOptions& options = ctx.options;
    LineAt at{line.points.row(i), lineDirection(line, i, ctx.size.halfLength * fitSpacing),
              Eigen::RowVector3d::Zero()};
    Eigen::RowVector3d centre = at.vertex;
    double width = ctx.size.halfWidth; // this vertex's strip half width
    VertexShift result;
    for (int attempt = 0; attempt <= options.recentres; ++attempt) {
        const std::optional<StripFrame> frame = frameAt(ctx, at, centre, scratch.near);
        if (!frame) {
            break;
        }
        if (attempt == 0) {
            at.across = frame->c;
            width = stripHalfWidth(ctx, at.vertex, *frame, scratch);
        }
        collectStrip(ctx, centre, *frame, width, scratch);
        const StepFit fit =
            curvatureStep(scratch.strip, {options.maxShift * width, ctx.size.step,
                                          options.minEvidence, options.minPointsPerSide});
        if (std::isfinite(fit.u)) {
            result.shift =
                (centre + fit.u * fitSpacing * frame->c - at.vertex).dot(at.across) / fitSpacing;
            break;
        }
        if (fit.edge == 0) {
            break;
        }
        // The border lies beyond the range: the next strip is centred on its edge.
        centre += fit.edge * options.maxShift * width * fitSpacing * frame->c;
    }
    result.across = at.across;
    return result;
}

/// The fitted vertices, in line order, and what was found at each.
struct FittedVertices
{
    /// (line, vertex).
    std::vector<std::pair<int, int>> at;
    /// Per fitted vertex: the shift found (fit spacings, NaN: none) and the direction across.
    std::vector<double> shift;
    std::vector<Eigen::RowVector3d> across;
    /// Per fitted vertex: the displacement it moves by (length unit), where placed is nonzero.
    std::vector<Eigen::RowVector3d> displacement;
    std::vector<char> placed;
};

/// The vertices fitted: along each line, inner vertices (an open line's ends sit on junctions
/// or anchors) about `stride` apart, and the last inner one.
std::vector<std::pair<int, int>> verticesToFit(const LineNetwork& network, double stride)
{
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
    return fitted;
}

void fitShifts(const PlacementContext& ctx, const LineNetwork& network, FittedVertices& fitted)
{
    fitted.shift.assign(fitted.at.size(), std::numeric_limits<double>::quiet_NaN());
    fitted.across.assign(fitted.at.size(), Eigen::RowVector3d::Zero());
#pragma omp parallel
    {
        Scratch scratch;
#pragma omp for schedule(dynamic, 4)
        for (size_t t = 0; t < fitted.at.size(); ++t) {
            const Polyline& line = network.lines[static_cast<size_t>(fitted.at[t].first)];
            const VertexShift found = fitVertex(ctx, line, fitted.at[t].second, scratch);
            fitted.shift[t] = found.shift;
            fitted.across[t] = found.across;
        }
    }
}

/// Calls f(line, first, last) for each line's run [first, last) of fitted vertices.
template <class F> void forEachLineRun(const std::vector<std::pair<int, int>>& at, F f)
{
    for (size_t first = 0; first < at.size();) {
        const int l = at[first].first;
        size_t last = first;
        while (last < at.size() && at[last].first == l) {
            ++last;
        }
        f(l, first, last);
        first = last;
    }
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

/// A fitted vertex moves by the median of the shifts found around it along its line (h fitted
/// vertices on each side), when most of them found one: a lone fit does not bend the line. The
/// normals' signs are each vertex's own, so a neighbour's shift counts along this vertex's
/// direction across.
void takeMedianShifts(FittedVertices& fitted, const LineNetwork& network, int h, double fitSpacing)
{
    fitted.displacement.assign(fitted.at.size(), Eigen::RowVector3d::Zero());
    fitted.placed.assign(fitted.at.size(), 0);
    std::vector<double> window;
    forEachLineRun(fitted.at, [&](int l, size_t first, size_t last) {
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
                if (std::isfinite(fitted.shift[k])) {
                    window.push_back(fitted.across[k].dot(fitted.across[at]) < 0.0
                                         ? -fitted.shift[k]
                                         : fitted.shift[k]);
                }
            }
            if (static_cast<int>(window.size()) >= std::min(h + 1, count) &&
                fitted.across[at].norm() > 0.0) {
                fitted.displacement[at] = median(window) * fitSpacing * fitted.across[at];
                fitted.placed[at] = 1;
            }
        }
    });
}

/// Arc length from the first vertex to each, and (last entry) once around the closed polygon.
std::vector<double> arcLengths(const PointMatrix& V)
{
    const Eigen::Index m = V.rows();
    std::vector<double> arc(static_cast<size_t>(m) + 1, 0.0);
    for (Eigen::Index i = 1; i <= m; ++i) {
        arc[static_cast<size_t>(i)] =
            arc[static_cast<size_t>(i - 1)] + (V.row(i % m) - V.row(i - 1)).norm();
    }
    return arc;
}

/// Moves the vertices of `line`, whose fitted vertices are fitted[first, last): those between
/// two fitted ones by the displacements of the two, weighed by arc length; next to a fitted
/// vertex that found no step, by the other's over its half. An open line's ends sit on
/// junctions or anchors and stay: the displacement tapers to none over one stride from each
/// end, so the line keeps its direction there. Returns the number of vertices moved.
int moveLine(Polyline& line, const FittedVertices& fitted, size_t first, size_t last, double stride)
{
    const Eigen::Index m = line.points.rows();
    const std::vector<double> arc = arcLengths(line.points);
    const double length = arc[static_cast<size_t>(m)];
    PointMatrix placed = line.points;
    int moved = 0;
    // (The first and last inner vertices of an open line are fitted, so every inner vertex lies
    // between two.)
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
    const std::vector<Eigen::RowVector3d>& displacement = fitted.displacement;
    const std::vector<char>& placedFit = fitted.placed;
    const int count = static_cast<int>(last - first);
    // Pairs of consecutive fitted vertices; a closed line's last pairs with its first.
    for (int j = 0; j + 1 < count + (line.closed ? 1 : 0); ++j) {
        const size_t f0 = first + static_cast<size_t>(j);
        const size_t f1 = first + static_cast<size_t>((j + 1) % count);
        const Eigen::Index i0 = fitted.at[f0].second, i1 = fitted.at[f1].second;
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
        move(fitted.at[first].second, displacement[first]);
    }
    line.points = std::move(placed);
    return moved;
}

} // namespace

int placeOnCurvatureSteps(LineNetwork& network, const LinePlacementInput& input,
                          const LinePlacementOptions& options)
{
    checkInput(input, options);
    if (input.points.rows() == 0 || network.lines.empty()) {
        return 0;
    }
    const StripSize size = stripSize(input, options);
    const double W = size.halfWidth, L = size.halfLength, fitSpacing = input.fitSpacing;
    const double reach = std::sqrt(2 * W * W + L * L) * fitSpacing;
    // The farthest a strip's centre moves from its vertex: its re-centrings, each by at most
    // maxShift of the widest strip; the index keeps the cells it and one cell around can reach.
    const double recentring = options.recentres * options.maxShift * W * fitSpacing;
    const int margin = 1 + static_cast<int>(std::ceil(recentring / reach));
    const PlacementContext ctx{input, options, size,
                               CellIndex(input.points, reach, network, margin)};

    // Fitted vertices about fitStride strip half lengths apart: the strips of the vertices
    // between them would hold nearly the same points.
    const double stride = options.fitStride * L * fitSpacing;
    FittedVertices fitted;
    fitted.at = verticesToFit(network, stride);
    fitShifts(ctx, network, fitted);
    takeMedianShifts(fitted, network, options.medianHalfWindow, fitSpacing);
    int moved = 0;
    forEachLineRun(fitted.at, [&](int l, size_t first, size_t last) {
        moved += moveLine(network.lines[static_cast<size_t>(l)], fitted, first, last, stride);
    });
    return moved;
}

} // namespace featurelines
