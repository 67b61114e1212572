// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/curves/CurveFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

using Vec3 = Eigen::Vector3d;

Vec3 row(const PointMatrix& P, Eigen::Index i)
{
    return P.row(i).transpose();
}

/// Distance from p to the segment a-b.
double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * d)).norm();
}

/// Whether a segment, arc or circle holds the tolerance: its RMS deviation within half of it
/// and no point beyond one and a half times it. A noisy line wobbles about its edge, a line
/// of another shape deviates from the model all along: the RMS tells them apart, where a
/// bound on the worst point alone would reject the right model for one wobble.
bool analyticHolds(const FittedCurve& c, double tolerance)
{
    return c.rmsDeviation <= 0.5 * tolerance && c.maxDeviation <= 1.5 * tolerance;
}

void setDeviations(FittedCurve& c, const Eigen::VectorXd& distances)
{
    c.maxDeviation = distances.size() ? distances.maxCoeff() : 0.0;
    c.rmsDeviation =
        distances.size() ? std::sqrt(distances.squaredNorm() / double(distances.size())) : 0.0;
}

/// The segment, arc or circle c with its deviations from the points P (`distance` of a point
/// to it), when it holds the tolerance (analyticHolds).
template <class Distance>
std::optional<FittedCurve> ifItHolds(FittedCurve c, const PointMatrix& P, double tolerance,
                                     Distance distance)
{
    Eigen::VectorXd d(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        d[i] = distance(row(P, i));
    }
    setDeviations(c, d);
    if (!analyticHolds(c, tolerance)) {
        return std::nullopt;
    }
    return c;
}

/// A unit vector perpendicular to the unit vector n.
Vec3 anyPerpendicular(const Vec3& n)
{
    const Vec3 a = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    return n.cross(a).normalized();
}

// ---- circles --------------------------------------------------------------------------------

/// The angle of p about the circle (centre c, axis n) counter-clockwise from the direction of
/// `from`, in [0, 2 pi).
double angleAbout(const Vec3& p, const Vec3& c, const Vec3& n, const Vec3& from)
{
    const Vec3 x = (from - c - n * n.dot(from - c)).normalized();
    const Vec3 y = n.cross(x);
    double a = std::atan2((p - c).dot(y), (p - c).dot(x));
    return a < 0 ? a + 2 * pi : a;
}

/// Distance of p to the full circle (centre c, unit axis n, radius r).
double distanceToCircle(const Vec3& p, const Vec3& c, const Vec3& n, double r)
{
    const Vec3 d = p - c;
    const double h = d.dot(n);
    const double rho = (d - h * n).norm();
    return std::sqrt(h * h + (rho - r) * (rho - r));
}

/// Distance of p to the arc of `c` (start, centre, axis, radius, counter-clockwise to end).
double distanceToArc(const Vec3& p, const FittedCurve& c)
{
    const double sweep = angleAbout(c.end, c.centre, c.axis, c.start);
    const double a = angleAbout(p, c.centre, c.axis, c.start);
    if (a <= sweep) {
        return distanceToCircle(p, c.centre, c.axis, c.radius);
    }
    return std::min((p - c.start).norm(), (p - c.end).norm());
}

/// The sense of travel of the points about the axis n through c: +1 counter-clockwise.
double turningSense(const PointMatrix& P, const Vec3& c, const Vec3& n)
{
    double s = 0.0;
    for (Eigen::Index i = 0; i + 1 < P.rows(); ++i) {
        s += (row(P, i) - c).cross(row(P, i + 1) - c).dot(n);
    }
    return s >= 0 ? 1.0 : -1.0;
}

// ---- B-splines ------------------------------------------------------------------------------

/// A cubic B-spline in the flat form of the textbooks (Piegl and Tiller, The NURBS Book,
/// Ch. 2): flat knots U (#poles + 4 values) and per flat pole the row of the curve's poles
/// (a periodic curve repeats its first three poles at the end, as OpenCASCADE unperiodizes).
struct FlatSpline
{
    std::vector<double> U;
    std::vector<int> pole;
    int degree = 3;
    double first() const { return U[static_cast<size_t>(degree)]; }
    double last() const { return U[U.size() - 1 - static_cast<size_t>(degree)]; }
};

FlatSpline flatSpline(const std::vector<double>& knots, const std::vector<int>& multiplicities,
                      int degree, bool periodic, int poleCount)
{
    FlatSpline f;
    f.degree = degree;
    if (!periodic) {
        for (size_t i = 0; i < knots.size(); ++i) {
            f.U.insert(f.U.end(), static_cast<size_t>(multiplicities[i]), knots[i]);
        }
        for (int j = 0; j < poleCount; ++j) {
            f.pole.push_back(j);
        }
        return f;
    }
    // Periodic, simple knots k_0..k_m, m poles: the knots before k_0 and after k_m repeat by
    // the period (OpenCASCADE's BSplCLib convention, checked against Geom_BSplineCurve).
    const int m = static_cast<int>(knots.size()) - 1;
    const double period = knots.back() - knots.front();
    for (int i = m - degree; i < m; ++i) {
        f.U.push_back(knots[static_cast<size_t>(i)] - period);
    }
    f.U.insert(f.U.end(), knots.begin(), knots.end());
    for (int i = 1; i <= degree; ++i) {
        f.U.push_back(knots[static_cast<size_t>(i)] + period);
    }
    for (int j = 0; j < m + degree; ++j) {
        f.pole.push_back(j % poleCount);
    }
    return f;
}

FlatSpline flatSpline(const FittedCurve& c)
{
    return flatSpline(c.knots, c.multiplicities, c.degree, c.periodic,
                      static_cast<int>(c.poles.rows()));
}

/// The span index s with U[s] <= u < U[s+1] among the curve's domain spans.
int findSpan(const FlatSpline& f, double u)
{
    const int p = f.degree;
    const int n = static_cast<int>(f.pole.size()) - 1;
    if (u >= f.U[static_cast<size_t>(n + 1)]) {
        return n;
    }
    if (u <= f.U[static_cast<size_t>(p)]) {
        return p;
    }
    const auto it = std::upper_bound(f.U.begin() + p, f.U.begin() + n + 1, u);
    return static_cast<int>(it - f.U.begin()) - 1;
}

/// The degree + 1 basis functions non-zero on span s at u (The NURBS Book, A2.2).
void basisFunctions(const FlatSpline& f, int s, double u, double* N)
{
    const int p = f.degree;
    double left[8], right[8];
    N[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - f.U[static_cast<size_t>(s + 1 - j)];
        right[j] = f.U[static_cast<size_t>(s + j)] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double denom = right[r + 1] + left[j - r];
            const double temp = denom != 0.0 ? N[r] / denom : 0.0;
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

Vec3 splinePoint(const FlatSpline& f, const PointMatrix& poles, double u)
{
    const int s = findSpan(f, u);
    double N[4];
    basisFunctions(f, s, u, N);
    Vec3 p = Vec3::Zero();
    for (int k = 0; k <= f.degree; ++k) {
        p += N[k] * row(poles, f.pole[static_cast<size_t>(s - f.degree + k)]);
    }
    return p;
}

/// How a flat pole enters the least squares: fixed at a point, free (three unknowns), or on a
/// fixed tangent line through a point (one unknown, the distance along it).
struct PoleUnknown
{
    enum Kind
    {
        Fixed,
        Free,
        OnTangent
    } kind = Free;
    Vec3 point = Vec3::Zero();
    Vec3 direction = Vec3::Zero();
    int column = -1;
};

struct SplineFit
{
    FittedCurve curve;
    /// Per point its curve parameter and distance to the curve.
    Eigen::VectorXd u;
    Eigen::VectorXd distance;
};

/// Chord-length parameters of the points in [0, 1]; a closed run includes its closing chord
/// (the first point is at 0, the loop closes at 1).
Eigen::VectorXd chordParameters(const PointMatrix& P, bool closed)
{
    const Eigen::Index n = P.rows();
    Eigen::VectorXd u(n);
    u[0] = 0.0;
    for (Eigen::Index i = 1; i < n; ++i) {
        u[i] = u[i - 1] + (P.row(i) - P.row(i - 1)).norm();
    }
    const double total = closed ? u[n - 1] + (P.row(0) - P.row(n - 1)).norm() : u[n - 1];
    return total > 0 ? Eigen::VectorXd(u / total) : Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
}

/// The least-squares poles of the spline with the given knots through the points at their
/// parameters u, with the unknowns of each pole as `unknowns` says (rows of the curve's poles).
PointMatrix solvePoles(const FlatSpline& f, const std::vector<PoleUnknown>& unknowns, int columns,
                       const PointMatrix& P, const Eigen::VectorXd& u)
{
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(columns, columns);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(columns);
    const int p = f.degree;
    // One row of the design per coordinate: sparse entries (column, coefficient).
    std::vector<std::pair<int, double>> entries;
    auto accumulate = [&](double target) {
        for (const auto& [ci, vi] : entries) {
            b[ci] += vi * target;
            for (const auto& [cj, vj] : entries) {
                A(ci, cj) += vi * vj;
            }
        }
    };
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const int s = findSpan(f, u[i]);
        double N[4];
        basisFunctions(f, s, u[i], N);
        for (int d = 0; d < 3; ++d) {
            entries.clear();
            double target = P(i, d);
            for (int k = 0; k <= p; ++k) {
                const PoleUnknown& q =
                    unknowns[static_cast<size_t>(f.pole[static_cast<size_t>(s - p + k)])];
                target -= N[k] * q.point[d];
                if (q.kind == PoleUnknown::Free) {
                    entries.emplace_back(q.column + d, N[k]);
                } else if (q.kind == PoleUnknown::OnTangent) {
                    entries.emplace_back(q.column, N[k] * q.direction[d]);
                }
            }
            accumulate(target);
        }
    }
    // A light pull of every pole towards the middle of its neighbours keeps the system regular
    // where a knot span holds few points; its weight is small beside the points'.
    const double weight = 1e-6 * std::max<Eigen::Index>(P.rows(), 1);
    const int flat = static_cast<int>(f.pole.size());
    for (int j = 1; j + 1 < flat; ++j) {
        for (int d = 0; d < 3; ++d) {
            entries.clear();
            double target = 0.0;
            const double coefficient[3] = {1.0, -2.0, 1.0};
            for (int k = 0; k < 3; ++k) {
                const PoleUnknown& q = unknowns[static_cast<size_t>(f.pole[j - 1 + k])];
                const double c = coefficient[k] * std::sqrt(weight);
                target -= c * q.point[d];
                if (q.kind == PoleUnknown::Free) {
                    entries.emplace_back(q.column + d, c);
                } else if (q.kind == PoleUnknown::OnTangent) {
                    entries.emplace_back(q.column, c * q.direction[d]);
                }
            }
            accumulate(target);
        }
    }
    const Eigen::VectorXd x = A.ldlt().solve(b);
    PointMatrix poles(static_cast<Eigen::Index>(unknowns.size()), 3);
    for (size_t j = 0; j < unknowns.size(); ++j) {
        const PoleUnknown& q = unknowns[j];
        Vec3 pole = q.point;
        if (q.kind == PoleUnknown::Free) {
            pole = x.segment<3>(q.column);
        } else if (q.kind == PoleUnknown::OnTangent) {
            pole += x[q.column] * q.direction;
        }
        poles.row(static_cast<Eigen::Index>(j)) = pole.transpose();
    }
    return poles;
}

/// One least-squares fit with fixed knots (distinct knots in [0, 1]), then two rounds of
/// parameter correction (each point's parameter moved to its nearest curve point, Hoschek's
/// step) and refit.
SplineFit fitWithKnots(const CurveFitInput& in, const PointMatrix& P, Eigen::VectorXd u,
                       const std::vector<double>& knots)
{
    const bool periodic = in.closed && in.freeVertex;
    FittedCurve c;
    c.kind = CurveKind::BSpline;
    c.degree = 3;
    c.periodic = periodic;
    c.knots = knots;
    c.multiplicities.assign(knots.size(), 1);
    int poleCount;
    if (periodic) {
        poleCount = static_cast<int>(knots.size()) - 1;
    } else {
        c.multiplicities.front() = c.multiplicities.back() = 4;
        poleCount = static_cast<int>(knots.size()) + 2;
    }
    const FlatSpline f = flatSpline(knots, c.multiplicities, 3, periodic, poleCount);

    std::vector<PoleUnknown> unknowns(static_cast<size_t>(poleCount));
    int columns = 0;
    for (PoleUnknown& q : unknowns) {
        q.kind = PoleUnknown::Free;
        q.column = columns;
        columns += 3;
    }
    if (!periodic) {
        // Clamped: the end poles are the end vertices; a given tangent puts the next pole on
        // the tangent line.
        const Vec3 first = row(P, 0);
        const Vec3 last = row(P, P.rows() - 1);
        columns = 0;
        for (int j = 0; j < poleCount; ++j) {
            PoleUnknown& q = unknowns[static_cast<size_t>(j)];
            if (j == 0 || j == poleCount - 1) {
                q.kind = PoleUnknown::Fixed;
                q.point = j == 0 ? first : last;
            } else if (j == 1 && in.startTangent) {
                q.kind = PoleUnknown::OnTangent;
                q.point = first;
                q.direction = *in.startTangent;
            } else if (j == poleCount - 2 && in.endTangent) {
                q.kind = PoleUnknown::OnTangent;
                q.point = last;
                q.direction = -*in.endTangent;
            } else {
                q.kind = PoleUnknown::Free;
            }
            if (q.kind != PoleUnknown::Fixed) {
                q.column = columns;
                columns += q.kind == PoleUnknown::Free ? 3 : 1;
            }
        }
    }

    SplineFit fit;
    for (int round = 0; round < 3; ++round) {
        c.poles = solvePoles(f, unknowns, columns, P, u);
        if (round == 2) {
            break;
        }
        // Hoschek's parameter correction: u += (p - C(u)) . C'(u) / |C'(u)|^2, C' by central
        // differences; the first point stays at the start (and an open run's last at the end).
        const double h = 1e-6;
        for (Eigen::Index i = 1; i < P.rows() - (in.closed ? 0 : 1); ++i) {
            const Vec3 q = splinePoint(f, c.poles, u[i]);
            const double ua = std::max(0.0, u[i] - h), ub = std::min(1.0, u[i] + h);
            const Vec3 d = (splinePoint(f, c.poles, ub) - splinePoint(f, c.poles, ua)) / (ub - ua);
            if (d.squaredNorm() > 0) {
                const double moved = u[i] + (row(P, i) - q).dot(d) / d.squaredNorm();
                // A periodic curve's parameter runs round: a point near the seam that moves
                // past 1 or below 0 continues on the other side (clamped, it was stuck at the
                // seam and drew knot after knot towards it).
                u[i] = periodic ? moved - std::floor(moved) : std::clamp(moved, 0.0, 1.0);
            }
        }
    }
    fit.distance.resize(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        fit.distance[i] = (row(P, i) - splinePoint(f, c.poles, u[i])).norm();
    }
    c.start = splinePoint(f, c.poles, 0.0);
    c.end = periodic ? c.start : splinePoint(f, c.poles, 1.0);
    if (!periodic) {
        // Exactly the vertices (the fixed end poles).
        c.start = row(P, 0);
        c.end = in.closed ? c.start : row(P, P.rows() - 1);
    }
    setDeviations(c, fit.distance);
    fit.curve = std::move(c);
    fit.u = std::move(u);
    return fit;
}

/// The run to fit: a closed run on a fixed vertex gets its vertex again at the end (a clamped
/// loop); a periodic one stays as it is.
PointMatrix fitPoints(const CurveFitInput& in)
{
    if (!in.closed || in.freeVertex) {
        return in.points;
    }
    PointMatrix P(in.points.rows() + 1, 3);
    P.topRows(in.points.rows()) = in.points;
    P.row(in.points.rows()) = in.points.row(0);
    return P;
}

} // namespace

double polylineScatter(const PointMatrix& P, bool closed)
{
    const Eigen::Index n = P.rows();
    if (n < 3) {
        return 0.0;
    }
    double sum = 0.0;
    long count = 0;
    for (Eigen::Index i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i) {
        const Vec3 a = row(P, (i + n - 1) % n), b = row(P, i), c = row(P, (i + 1) % n);
        Vec3 offset = b - 0.5 * (a + c);
        const Vec3 chord = c - a;
        if (chord.squaredNorm() > 0) {
            offset -= chord * offset.dot(chord) / chord.squaredNorm();
        }
        sum += offset.squaredNorm();
        ++count;
    }
    return std::sqrt(sum / double(count) / 1.5);
}

std::optional<FittedCurve> fitSegment(const CurveFitInput& in)
{
    const PointMatrix& P = in.points;
    if (in.closed || P.rows() < 2) {
        return std::nullopt;
    }
    FittedCurve c;
    c.kind = CurveKind::Segment;
    c.start = row(P, 0);
    c.end = row(P, P.rows() - 1);
    if (c.end == c.start) {
        return std::nullopt;
    }
    return ifItHolds(c, P, in.tolerance,
                     [&](const Vec3& p) { return distanceToSegment(p, c.start, c.end); });
}

std::optional<FittedCurve> fitArc(const CurveFitInput& in)
{
    const PointMatrix& P = in.points;
    if (in.closed || P.rows() < 3) {
        return std::nullopt;
    }
    const Vec3 a = row(P, 0), b = row(P, P.rows() - 1);
    const Vec3 mid = 0.5 * (a + b);
    const double half = 0.5 * (b - a).norm();
    if (half <= in.tolerance) {
        return std::nullopt;
    }
    // The plane through the chord that holds the points best: its normal is the direction
    // across the chord in which the points spread least.
    const Vec3 x = (b - a).normalized();
    const Vec3 e1 = anyPerpendicular(x), e2 = x.cross(e1);
    Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const Eigen::Vector2d q((row(P, i) - mid).dot(e1), (row(P, i) - mid).dot(e2));
        C += q * q.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(C);
    const Vec3 n = (eig.eigenvectors()(0, 0) * e1 + eig.eigenvectors()(1, 0) * e2).normalized();
    const Vec3 y = n.cross(x);
    // In the plane (chord along x, centred), the circle through both ends has its centre at
    // (0, t): x^2 + y^2 - 2 y t - half^2 = 0 is linear in t (algebraic fit), refined by
    // Gauss-Newton on the geometric distances.
    Eigen::ArrayXd px(P.rows()), py(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        px[i] = (row(P, i) - mid).dot(x);
        py[i] = (row(P, i) - mid).dot(y);
    }
    const double syy = (py * py).sum();
    if (syy <= 0) {
        return std::nullopt;
    }
    double t = (py * (px * px + py * py - half * half)).sum() / (2 * syy);
    for (int iteration = 0; iteration < 10 && std::isfinite(t); ++iteration) {
        const double r = std::sqrt(half * half + t * t);
        const Eigen::ArrayXd rho = (px * px + (py - t) * (py - t)).sqrt().max(1e-300);
        const Eigen::ArrayXd residual = rho - r;
        const Eigen::ArrayXd jacobian = -(py - t) / rho - t / r;
        const double jj = (jacobian * jacobian).sum();
        if (jj <= 0) {
            break;
        }
        t -= (jacobian * residual).sum() / jj;
    }
    if (!std::isfinite(t)) {
        return std::nullopt;
    }
    FittedCurve c;
    c.kind = CurveKind::Arc;
    c.start = a;
    c.end = b;
    c.centre = mid + t * y;
    c.radius = std::sqrt(half * half + t * t);
    c.axis = n;
    c.axis *= turningSense(P, c.centre, c.axis);
    return ifItHolds(c, P, in.tolerance, [&](const Vec3& p) { return distanceToArc(p, c); });
}

std::optional<BestCircle> bestFitCircle(const PointMatrix& P)
{
    if (P.rows() < 3) {
        return std::nullopt;
    }
    const Vec3 mean = P.colwise().mean().transpose();
    const PointMatrix centred = P.rowwise() - mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(centred.transpose() * centred);
    const Vec3 n = eig.eigenvectors().col(0).normalized();
    const Vec3 x = eig.eigenvectors().col(2).normalized(), y = n.cross(x);
    // Kasa's algebraic fit in the plane, x^2 + y^2 = 2 a x + 2 b y + c, then Gauss-Newton on
    // the geometric distances (centre and radius).
    Eigen::MatrixXd A(P.rows(), 3);
    Eigen::VectorXd rhs(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const double qx = centred.row(i).dot(x), qy = centred.row(i).dot(y);
        A.row(i) << 2 * qx, 2 * qy, 1.0;
        rhs[i] = qx * qx + qy * qy;
    }
    const Eigen::Vector3d abc = A.colPivHouseholderQr().solve(rhs);
    Eigen::Vector3d g(abc[0], abc[1],
                      std::sqrt(std::max(0.0, abc[2] + abc[0] * abc[0] + abc[1] * abc[1])));
    for (int iteration = 0; iteration < 10; ++iteration) {
        Eigen::MatrixXd J(P.rows(), 3);
        Eigen::VectorXd r(P.rows());
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            const double dx = A(i, 0) / 2 - g[0], dy = A(i, 1) / 2 - g[1];
            const double rho = std::max(std::hypot(dx, dy), 1e-300);
            r[i] = rho - g[2];
            J.row(i) << -dx / rho, -dy / rho, -1.0;
        }
        const Eigen::Vector3d step = J.colPivHouseholderQr().solve(r);
        g -= step;
        if (step.norm() < 1e-12 * g[2]) {
            break;
        }
    }
    if (!g.allFinite() || g[2] <= 0) {
        return std::nullopt;
    }
    return BestCircle{mean + g[0] * x + g[1] * y, n, g[2]};
}

std::optional<FittedCurve> fitCircle(const CurveFitInput& in)
{
    const PointMatrix& P = in.points;
    if (!in.closed || !in.freeVertex || P.rows() < 4) {
        return std::nullopt;
    }
    const std::optional<BestCircle> best = bestFitCircle(P);
    if (!best) {
        return std::nullopt;
    }
    const Vec3 n = best->normal;
    FittedCurve c;
    c.kind = CurveKind::Circle;
    c.centre = best->centre;
    c.radius = best->radius;
    c.axis = n * turningSense(P, c.centre, n);
    // The vertex slides onto the circle: the circle's point nearest the first point.
    Vec3 radial = row(P, 0) - c.centre;
    radial -= c.axis * c.axis.dot(radial);
    if (radial.norm() <= 0) {
        return std::nullopt;
    }
    c.start = c.end = c.centre + c.radius * radial.normalized();
    return ifItHolds(c, P, in.tolerance, [&](const Vec3& p) {
        return distanceToCircle(p, c.centre, c.axis, c.radius);
    });
}

FittedCurve fitBSpline(const CurveFitInput& in)
{
    if (!(in.tolerance > 0)) {
        throw std::invalid_argument("the curve fitting tolerance must be positive");
    }
    const PointMatrix P = fitPoints(in);
    if (P.rows() < 2) {
        throw std::invalid_argument("a curve needs at least two points");
    }
    const bool periodic = in.closed && in.freeVertex;
    Eigen::VectorXd u = chordParameters(P, periodic);
    // As few poles as hold the tolerance: start with the fewest (a Bezier arc; a periodic
    // curve of four poles) and split every knot span whose worst point is out of tolerance
    // at that point, until the tolerance holds or the poles would outnumber half the points.
    std::vector<double> knots =
        periodic ? std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0} : std::vector<double>{0.0, 1.0};
    const int poleLimit = std::max(periodic ? 4 : 4, static_cast<int>(P.rows()) / 2);
    SplineFit fit = fitWithKnots(in, P, u, knots);
    constexpr int minPointsToSplit = 4;
    while (fit.curve.maxDeviation > in.tolerance) {
        // The spans whose worst point is out of tolerance and at least half as far out as the
        // worst of all: a knot each (more than one per round keeps long lines quick).
        const double splitFrom = std::max(in.tolerance, 0.5 * fit.curve.maxDeviation);
        std::vector<double> added;
        for (size_t k = 0; k + 1 < knots.size(); ++k) {
            const double a = knots[k], b = knots[k + 1];
            Eigen::Index worst = -1;
            int inSpan = 0;
            for (Eigen::Index i = 0; i < P.rows(); ++i) {
                if (fit.u[i] >= a && fit.u[i] < b) {
                    ++inSpan;
                    if (fit.distance[i] > splitFrom &&
                        (worst < 0 || fit.distance[i] > fit.distance[worst])) {
                        worst = i;
                    }
                }
            }
            // A span is split only where both halves keep points to fit: a knot between too
            // few points adds a pole that nothing holds in place.
            if (worst < 0 || inSpan < minPointsToSplit) {
                continue;
            }
            // At the worst point, unless that is close to a knot: then mid-span.
            double knot = fit.u[worst];
            if (knot - a < 0.2 * (b - a) || b - knot < 0.2 * (b - a)) {
                knot = 0.5 * (a + b);
            }
            added.push_back(knot);
        }
        const int poles = static_cast<int>(fit.curve.poles.rows() + added.size());
        if (added.empty() || poles > poleLimit) {
            break;
        }
        knots.insert(knots.end(), added.begin(), added.end());
        std::sort(knots.begin(), knots.end());
        fit = fitWithKnots(in, P, fit.u, knots);
    }
    FittedCurve c = std::move(fit.curve);
    if (!periodic) {
        // The report covers the input points (a clamped loop's repeated vertex is one of them).
        Eigen::VectorXd d = fit.distance.head(in.points.rows());
        setDeviations(c, d);
    }
    return c;
}

/// The segment between an arc's ends when the arc turns by less than flatArcDegrees and the
/// segment holds twice the tolerance (RMS within it, no point beyond three times it). A long
/// straight edge whose line is placed a fraction of a spacing off at its ends bows by that much
/// between its vertices, and the arc through them then holds where the segment just fails: a
/// radius of thousands of spacings, never a designed arc.
std::optional<FittedCurve> straightInstead(const FittedCurve& arc, const CurveFitInput& in)
{
    constexpr double flatArcDegrees = 10.0;
    const Vec3 a = arc.start - arc.centre, b = arc.end - arc.centre;
    double turn = std::atan2(a.cross(b).norm(), a.dot(b));
    if (a.cross(b).dot(arc.axis) < 0.0) {
        turn = 2.0 * M_PI - turn;
    }
    if (turn * 180.0 / M_PI >= flatArcDegrees) {
        return std::nullopt;
    }
    CurveFitInput relaxed = in;
    relaxed.tolerance = 2.0 * in.tolerance;
    return fitSegment(relaxed);
}

FittedCurve fitCurve(const CurveFitInput& in)
{
    if (!(in.tolerance > 0)) {
        throw std::invalid_argument("the curve fitting tolerance must be positive");
    }
    if (auto segment = fitSegment(in)) {
        return *segment;
    }
    if (auto arc = fitArc(in)) {
        if (auto straight = straightInstead(*arc, in)) {
            return *straight;
        }
        return *arc;
    }
    if (auto circle = fitCircle(in)) {
        return *circle;
    }
    return fitBSpline(in);
}

Vec3 curvePoint(const FittedCurve& c, double s)
{
    s = std::clamp(s, 0.0, 1.0);
    switch (c.kind) {
    case CurveKind::Segment:
        return c.start + s * (c.end - c.start);
    case CurveKind::Arc:
    case CurveKind::Circle: {
        const double sweep =
            c.kind == CurveKind::Circle ? 2 * pi : angleAbout(c.end, c.centre, c.axis, c.start);
        const Vec3 x = (c.start - c.centre).normalized();
        const Vec3 y = c.axis.cross(x);
        const double a = s * sweep;
        if (s == 1.0 && c.kind == CurveKind::Arc) {
            return c.end;
        }
        if (s == 0.0 || (s == 1.0 && c.kind == CurveKind::Circle)) {
            return c.start;
        }
        return c.centre + c.radius * (std::cos(a) * x + std::sin(a) * y);
    }
    case CurveKind::BSpline: {
        if (s == 0.0) {
            return c.start;
        }
        if (s == 1.0) {
            return c.end;
        }
        const FlatSpline f = flatSpline(c);
        return splinePoint(f, c.poles, f.first() + s * (f.last() - f.first()));
    }
    }
    return c.start;
}

Vec3 curveTangent(const FittedCurve& c, double s)
{
    const double h = 1e-5;
    const double a = std::max(0.0, s - h), b = std::min(1.0, s + h);
    if (c.kind == CurveKind::BSpline) {
        // Without the exact end points, whose snapping would spoil a one-sided difference.
        const FlatSpline f = flatSpline(c);
        const double ua = f.first() + a * (f.last() - f.first());
        const double ub = f.first() + b * (f.last() - f.first());
        return (splinePoint(f, c.poles, ub) - splinePoint(f, c.poles, ua)).normalized();
    }
    return (curvePoint(c, b) - curvePoint(c, a)).normalized();
}

namespace {

/// The length of the polygon through the curve's points at n equal parameter steps.
double polygonLength(const FittedCurve& c, int n)
{
    double length = 0.0;
    Vec3 previous = curvePoint(c, 0.0);
    for (int i = 1; i <= n; ++i) {
        const Vec3 q = curvePoint(c, double(i) / n);
        length += (q - previous).norm();
        previous = q;
    }
    return length;
}

} // namespace

PointMatrix sampleCurve(const FittedCurve& c, double step)
{
    if (!(step > 0)) {
        throw std::invalid_argument("the sampling step must be positive");
    }
    if (c.kind == CurveKind::Segment) {
        PointMatrix S(2, 3);
        S.row(0) = c.start.transpose();
        S.row(1) = c.end.transpose();
        return S;
    }
    // The length from a fine sampling, then as many equal parameter steps as the step asks.
    const double length = polygonLength(
        c, c.kind == CurveKind::BSpline ? std::max<int>(64, 16 * static_cast<int>(c.poles.rows()))
                                        : 256);
    const int segments = std::clamp(static_cast<int>(std::ceil(length / step)), 1, 1000000);
    PointMatrix S(segments + 1, 3);
    for (int i = 0; i <= segments; ++i) {
        S.row(i) = curvePoint(c, double(i) / segments).transpose();
    }
    return S;
}

double curveLength(const FittedCurve& c)
{
    if (c.kind == CurveKind::Segment) {
        return (c.end - c.start).norm();
    }
    return polygonLength(c, c.kind == CurveKind::BSpline
                                ? std::max<int>(1024, 64 * static_cast<int>(c.poles.rows()))
                                : 1024);
}

Eigen::VectorXd distancesToCurve(const FittedCurve& c, const PointMatrix& P, double step)
{
    const PointMatrix S = sampleCurve(c, step);
    Eigen::VectorXd d(P.rows());
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        double best = std::numeric_limits<double>::infinity();
        for (Eigen::Index j = 0; j + 1 < S.rows(); ++j) {
            best = std::min(best, distanceToSegment(row(P, i), row(S, j), row(S, j + 1)));
        }
        if (S.rows() == 1) {
            best = (row(P, i) - row(S, 0)).norm();
        }
        d[i] = best;
    }
    return d;
}

} // namespace featurelines
