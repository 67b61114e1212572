// SPDX-License-Identifier: LGPL-2.1-or-later
// Plane, sphere and cylinder fits (algebraic start, geometric refinement with Eigen's
// Levenberg-Marquardt) and the B-spline height field (regularised linear least squares).
#include "SurfaceFit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include "FeatureLines/neighbourhoods/Neighbours.h"
#include "FeatureLines/neighbourhoods/Normals.h"
#include "FeatureLines/smooth/RegionGeometry.h"

namespace featurelines::surfaces {

namespace {

/// Two unit vectors that make a right-handed frame with the unit n.
void frameOf(const Eigen::Vector3d& n, Eigen::Vector3d& e1, Eigen::Vector3d& e2)
{
    e1 = n.unitOrthogonal();
    e2 = n.cross(e1);
}

/// The points' distances to the surface: RMS and largest.
void measure(FittedSurface& s, const PointMatrix& P)
{
    double sum = 0.0;
    double largest = 0.0;
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const double d = surfaceDistance(s, P.row(i).transpose());
        sum += d * d;
        largest = std::max(largest, d);
    }
    s.rmsDeviation = P.rows() > 0 ? std::sqrt(sum / static_cast<double>(P.rows())) : 0.0;
    s.maxDeviation = largest;
}

/// Residuals for Eigen's Levenberg-Marquardt, differentiated numerically.
template <typename Residual>
struct Functor : Eigen::DenseFunctor<double>
{
    Functor(int parameters, int values, Residual residual)
        : Eigen::DenseFunctor<double>(parameters, values), residual_(std::move(residual))
    {
    }
    int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const
    {
        residual_(x, f);
        return 0;
    }
    Residual residual_;
};

template <typename Residual>
Eigen::VectorXd refine(Eigen::VectorXd x, int values, Residual residual)
{
    using F = Functor<Residual>;
    Eigen::NumericalDiff<F> diff(F(static_cast<int>(x.size()), values, std::move(residual)));
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<F>> lm(diff);
    lm.setMaxfev(200 * static_cast<int>(x.size()));
    lm.minimize(x);
    return x;
}

Eigen::Vector3d centroidOf(const PointMatrix& P)
{
    return P.colwise().mean().transpose();
}

/// The cubic B-spline basis functions that are non-zero at t in [0, 1] on `poles` control
/// points with uniform clamped knots: the first index and the four values.
int cubicBasis(double t, int poles, double values[4])
{
    const int spans = poles - 3;
    std::vector<double> knots(static_cast<size_t>(poles + 4));
    for (int i = 0; i < poles + 4; ++i) {
        knots[i] = std::clamp(static_cast<double>(i - 3) / spans, 0.0, 1.0);
    }
    const int span = std::min(static_cast<int>(t * spans), spans - 1) + 3;
    // de Boor-Cox for degree 3 at knot span [knots[span], knots[span + 1]).
    double left[4];
    double right[4];
    values[0] = 1.0;
    for (int j = 1; j <= 3; ++j) {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double denominator = right[r + 1] + left[j - r];
            const double temp = denominator != 0.0 ? values[r] / denominator : 0.0;
            values[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        values[j] = saved;
    }
    return span - 3;
}

double bsplineHeight(const FittedSurface& s, double u, double v)
{
    const double tu = std::clamp((u - s.uMin) / (s.uMax - s.uMin), 0.0, 1.0);
    const double tv = std::clamp((v - s.vMin) / (s.vMax - s.vMin), 0.0, 1.0);
    double bu[4];
    double bv[4];
    const int iu = cubicBasis(tu, s.uPoles, bu);
    const int iv = cubicBasis(tv, s.vPoles, bv);
    double h = 0.0;
    for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b) {
            h += bu[a] * bv[b] * s.heights[(iu + a) + (iv + b) * s.uPoles];
        }
    }
    return h;
}

FittedSurface fitHeightField(const PointMatrix& P, double spacing, const SurfaceFitOptions& options)
{
    FittedSurface s = fitPlane(P);
    s.kind = SurfaceKind::BSpline;
    Eigen::Vector3d e1;
    Eigen::Vector3d e2;
    frameOf(s.axis, e1, e2);
    // u along the patch's longest extent.
    const Eigen::Matrix3d cov = (P.rowwise() - s.origin.transpose()).transpose() *
                                (P.rowwise() - s.origin.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
    e1 = solver.eigenvectors().col(2);
    e1 = (e1 - e1.dot(s.axis) * s.axis).normalized();
    e2 = s.axis.cross(e1);
    s.uDirection = e1;
    const Eigen::Index n = P.rows();
    Eigen::VectorXd u(n);
    Eigen::VectorXd v(n);
    Eigen::VectorXd h(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d x = P.row(i).transpose() - s.origin;
        u[i] = x.dot(e1);
        v[i] = x.dot(e2);
        h[i] = x.dot(s.axis);
    }
    const double margin = spacing;
    s.uMin = u.minCoeff() - margin;
    s.uMax = u.maxCoeff() + margin;
    s.vMin = v.minCoeff() - margin;
    s.vMax = v.maxCoeff() + margin;
    auto poles = [&](double extent) {
        return std::clamp(static_cast<int>(extent / (options.spacingsPerPole * spacing)) + 3, 4,
                          std::max(4, options.maxPoles));
    };
    s.uPoles = poles(s.uMax - s.uMin);
    s.vPoles = poles(s.vMax - s.vMin);
    const int m = s.uPoles * s.vPoles;
    // Normal equations of the points' residuals plus the smoothness of the poles (second
    // differences in u and in v), scaled to the number of points.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
    for (Eigen::Index i = 0; i < n; ++i) {
        double bu[4];
        double bv[4];
        const int iu = cubicBasis((u[i] - s.uMin) / (s.uMax - s.uMin), s.uPoles, bu);
        const int iv = cubicBasis((v[i] - s.vMin) / (s.vMax - s.vMin), s.vPoles, bv);
        int index[16];
        double weight[16];
        for (int a = 0; a < 4; ++a) {
            for (int c = 0; c < 4; ++c) {
                index[a * 4 + c] = (iu + a) + (iv + c) * s.uPoles;
                weight[a * 4 + c] = bu[a] * bv[c];
            }
        }
        for (int p = 0; p < 16; ++p) {
            b[index[p]] += weight[p] * h[i];
            for (int q = 0; q < 16; ++q) {
                A(index[p], index[q]) += weight[p] * weight[q];
            }
        }
    }
    const double lambda = options.smoothing * static_cast<double>(n);
    auto penalise = [&](int p0, int p1, int p2) {
        const int idx[3] = {p0, p1, p2};
        const double c[3] = {1.0, -2.0, 1.0};
        for (int a = 0; a < 3; ++a) {
            for (int d = 0; d < 3; ++d) {
                A(idx[a], idx[d]) += lambda * c[a] * c[d];
            }
        }
    };
    for (int j = 0; j < s.vPoles; ++j) {
        for (int i = 1; i + 1 < s.uPoles; ++i) {
            penalise((i - 1) + j * s.uPoles, i + j * s.uPoles, (i + 1) + j * s.uPoles);
        }
    }
    for (int i = 0; i < s.uPoles; ++i) {
        for (int j = 1; j + 1 < s.vPoles; ++j) {
            penalise(i + (j - 1) * s.uPoles, i + j * s.uPoles, i + (j + 1) * s.uPoles);
        }
    }
    // A small ridge keeps poles no point reaches at the smooth continuation.
    A.diagonal().array() += 1e-9 * std::max(1.0, A.diagonal().maxCoeff());
    s.heights = A.ldlt().solve(b);
    return s;
}

/// The PCA normals of the points over their 12 nearest.
NormalMatrix patchNormals(const PointMatrix& P)
{
    NeighbourOptions no;
    no.k = static_cast<int>(std::min<Eigen::Index>(12, P.rows() - 1));
    return pcaNormals(P, nearestNeighbours(P, no)).normals;
}

/// The axis every normal line meets best: a line (point, unit direction) with Pluecker
/// coordinates (a, b = point x a) meets the normal line through p along n when
/// a . (p x n) + b . n = 0; the least squares with |a| = 1 is the generalised eigenproblem
/// M x = lambda D x, D = diag(1, 1, 1, 0, 0, 0), solved through the Schur complement in b.
/// False when the normals do not fix an axis (a plane's, or a sphere's, all meeting at one
/// point).
bool revolutionAxis(const PointMatrix& P, const NormalMatrix& N, Eigen::Vector3d& point,
                    Eigen::Vector3d& axis)
{
    Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
    const Eigen::Vector3d c0 = centroidOf(P);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        const Eigen::Vector3d p = P.row(i).transpose() - c0;
        const Eigen::Vector3d n = N.row(i).transpose();
        Eigen::Matrix<double, 6, 1> row;
        row << p.cross(n), n;
        M += row * row.transpose();
    }
    const Eigen::Matrix3d A = M.topLeftCorner<3, 3>();
    const Eigen::Matrix3d B = M.topRightCorner<3, 3>();
    const Eigen::Matrix3d C = M.bottomRightCorner<3, 3>();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> cSolver(C);
    if (!(cSolver.eigenvalues()[0] > 1e-9 * std::max(1.0, cSolver.eigenvalues()[2]))) {
        return false;
    }
    // Minimising over b for a fixed a: b = -C^-1 B^T a, leaving a^T (A - B C^-1 B^T) a.
    const Eigen::Matrix3d S = A - B * C.ldlt().solve(B.transpose());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(S);
    const Eigen::Vector3d a = solver.eigenvectors().col(0);
    const Eigen::Vector3d b = -C.ldlt().solve(B.transpose() * a);
    // A sphere's normals all meet at its centre: any axis through it fits as well.
    if (!(solver.eigenvalues()[1] > 4.0 * solver.eigenvalues()[0])) {
        return false;
    }
    axis = a.normalized();
    point = c0 + a.cross(b) / a.squaredNorm();
    return true;
}

/// The axis tilted by (q[0], q[1]) in the frame (e1, e2) of a0 and moved by (q[2], q[3]).
struct AxisParameters
{
    Eigen::Vector3d a0;
    Eigen::Vector3d e1;
    Eigen::Vector3d e2;
    Eigen::Vector3d p0;
    Eigen::Vector3d axis(const Eigen::VectorXd& q) const
    {
        return (a0 + q[0] * e1 + q[1] * e2).normalized();
    }
    Eigen::Vector3d point(const Eigen::VectorXd& q) const { return p0 + q[2] * e1 + q[3] * e2; }
};

AxisParameters axisParameters(const Eigen::Vector3d& point, const Eigen::Vector3d& axis)
{
    AxisParameters ap;
    ap.a0 = axis;
    frameOf(axis, ap.e1, ap.e2);
    ap.p0 = point;
    return ap;
}

/// A point's height along the axis and distance from it.
Eigen::Vector2d meridian(const Eigen::Vector3d& x, const Eigen::Vector3d& point,
                         const Eigen::Vector3d& axis)
{
    const Eigen::Vector3d d = x - point;
    const double h = d.dot(axis);
    return Eigen::Vector2d(h, (d - h * axis).norm());
}

FittedSurface failedFit(SurfaceKind kind)
{
    FittedSurface s;
    s.kind = kind;
    s.rmsDeviation = s.maxDeviation = std::numeric_limits<double>::infinity();
    return s;
}

} // namespace

const char* surfaceKindName(SurfaceKind kind)
{
    switch (kind) {
    case SurfaceKind::Plane:
        return "plane";
    case SurfaceKind::Sphere:
        return "sphere";
    case SurfaceKind::Cylinder:
        return "cylinder";
    case SurfaceKind::Cone:
        return "cone";
    case SurfaceKind::Torus:
        return "torus";
    case SurfaceKind::BSpline:
        return "bspline";
    }
    return "unknown";
}

double signedSurfaceDistance(const FittedSurface& s, const Eigen::Vector3d& x)
{
    const Eigen::Vector3d d = x - s.origin;
    switch (s.kind) {
    case SurfaceKind::Plane:
        return d.dot(s.axis);
    case SurfaceKind::Sphere:
        return d.norm() - s.radius;
    case SurfaceKind::Cylinder:
        return (d - d.dot(s.axis) * s.axis).norm() - s.radius;
    case SurfaceKind::Cone: {
        const double h = d.dot(s.axis);
        const double rho = (d - h * s.axis).norm();
        return (rho - (s.radius + h * std::tan(s.halfAngle))) * std::cos(s.halfAngle);
    }
    case SurfaceKind::Torus: {
        const double h = d.dot(s.axis);
        const double rho = (d - h * s.axis).norm();
        return std::hypot(rho - s.radius, h) - s.minorRadius;
    }
    case SurfaceKind::BSpline: {
        const Eigen::Vector3d e2 = s.axis.cross(s.uDirection);
        return d.dot(s.axis) - bsplineHeight(s, d.dot(s.uDirection), d.dot(e2));
    }
    }
    return 0.0;
}

double surfaceDistance(const FittedSurface& s, const Eigen::Vector3d& x)
{
    return std::abs(signedSurfaceDistance(s, x));
}

FittedSurface fitPlane(const PointMatrix& P)
{
    FittedSurface s;
    s.kind = SurfaceKind::Plane;
    s.origin = centroidOf(P);
    const Eigen::MatrixXd centred = P.rowwise() - s.origin.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
    s.axis = solver.eigenvectors().col(0);
    measure(s, P);
    return s;
}

FittedSurface fitSphere(const PointMatrix& P)
{
    // Algebraic: |x|^2 + a.x + d = 0, linear in (a, d); then the geometric distances.
    const Eigen::Index n = P.rows();
    const Eigen::Vector3d c0 = centroidOf(P);
    Eigen::MatrixXd A(n, 4);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d x = P.row(i).transpose() - c0;
        A.row(i) << x.transpose(), 1.0;
        b[i] = -x.squaredNorm();
    }
    const Eigen::Vector4d sol = A.colPivHouseholderQr().solve(b);
    Eigen::Vector3d centre = -0.5 * sol.head<3>();
    double r2 = centre.squaredNorm() - sol[3];
    FittedSurface s;
    s.kind = SurfaceKind::Sphere;
    Eigen::VectorXd x(4);
    x << centre, std::sqrt(std::max(r2, 0.0));
    x = refine(x, static_cast<int>(n), [&P, c0](const Eigen::VectorXd& q, Eigen::VectorXd& f) {
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            f[i] = (P.row(i).transpose() - c0 - q.head<3>()).norm() - q[3];
        }
    });
    s.origin = c0 + x.head<3>();
    s.radius = std::abs(x[3]);
    measure(s, P);
    return s;
}

namespace {

FittedSurface cylinderWith(const PointMatrix& P, const NormalMatrix& normals)
{
    const Eigen::Index n = P.rows();
    const Eigen::Vector3d c0 = centroidOf(P);
    // The axis: the direction the points' normals are most nearly all perpendicular to.
    const Eigen::Matrix3d nn = normals.transpose() * normals;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(nn);
    const Eigen::Vector3d a0 = solver.eigenvectors().col(0);
    Eigen::Vector3d e1;
    Eigen::Vector3d e2;
    frameOf(a0, e1, e2);
    // The circle of the points projected along the axis (algebraic), then all five parameters:
    // the axis tilted by (p, q) in the frame, its point moved by (s, t), the radius.
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d x = P.row(i).transpose() - c0;
        const double u = x.dot(e1);
        const double v = x.dot(e2);
        A.row(i) << u, v, 1.0;
        b[i] = -(u * u + v * v);
    }
    const Eigen::Vector3d sol = A.colPivHouseholderQr().solve(b);
    const double cu = -0.5 * sol[0];
    const double cv = -0.5 * sol[1];
    const double r0 = std::sqrt(std::max(cu * cu + cv * cv - sol[2], 0.0));
    Eigen::VectorXd x(5);
    x << 0.0, 0.0, cu, cv, r0;
    auto axisOf = [a0, e1, e2](const Eigen::VectorXd& q) {
        return Eigen::Vector3d((a0 + q[0] * e1 + q[1] * e2).normalized());
    };
    x = refine(x, static_cast<int>(n),
               [&P, c0, e1, e2, axisOf](const Eigen::VectorXd& q, Eigen::VectorXd& f) {
                   const Eigen::Vector3d a = axisOf(q);
                   const Eigen::Vector3d p = c0 + q[2] * e1 + q[3] * e2;
                   for (Eigen::Index i = 0; i < P.rows(); ++i) {
                       const Eigen::Vector3d d = P.row(i).transpose() - p;
                       f[i] = (d - d.dot(a) * a).norm() - q[4];
                   }
               });
    FittedSurface s;
    s.kind = SurfaceKind::Cylinder;
    s.axis = axisOf(x);
    const Eigen::Vector3d p = c0 + x[2] * e1 + x[3] * e2;
    s.origin = p + (c0 - p).dot(s.axis) * s.axis;
    s.radius = std::abs(x[4]);
    measure(s, P);
    return s;
}

FittedSurface coneWith(const PointMatrix& P, const NormalMatrix& normals)
{
    Eigen::Vector3d point;
    Eigen::Vector3d axis;
    if (!revolutionAxis(P, normals, point, axis)) {
        return failedFit(SurfaceKind::Cone);
    }
    // The profile: rho = r0 + k h, a line in the half-plane (total least squares).
    const Eigen::Index n = P.rows();
    Eigen::MatrixXd m(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        m.row(i) = meridian(P.row(i).transpose(), point, axis).transpose();
    }
    const Eigen::RowVector2d mean = m.colwise().mean();
    const Eigen::MatrixXd centred = m.rowwise() - mean;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> line(centred.transpose() * centred);
    const Eigen::Vector2d along = line.eigenvectors().col(1);
    if (std::abs(along.x()) < 1e-6) {
        return failedFit(SurfaceKind::Cone);
    }
    const double k0 = along.y() / along.x();
    const double r00 = mean.y() - k0 * mean.x();
    const AxisParameters ap = axisParameters(point, axis);
    Eigen::VectorXd x(6);
    x << 0.0, 0.0, 0.0, 0.0, r00, k0;
    x = refine(x, static_cast<int>(n), [&P, ap](const Eigen::VectorXd& q, Eigen::VectorXd& f) {
        const Eigen::Vector3d a = ap.axis(q);
        const Eigen::Vector3d p = ap.point(q);
        const double c = 1.0 / std::sqrt(1.0 + q[5] * q[5]);
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            const Eigen::Vector2d hr = meridian(P.row(i).transpose(), p, a);
            f[i] = (hr.y() - (q[4] + q[5] * hr.x())) * c;
        }
    });
    FittedSurface s;
    s.kind = SurfaceKind::Cone;
    s.axis = ap.axis(x);
    const Eigen::Vector3d p = ap.point(x);
    // The reference point: the axis point level with the points' centroid.
    const double h = (centroidOf(P) - p).dot(s.axis);
    s.origin = p + h * s.axis;
    s.radius = x[4] + x[5] * h;
    s.halfAngle = std::atan(x[5]);
    if (!(s.radius > 0.0)) {
        return failedFit(SurfaceKind::Cone);
    }
    measure(s, P);
    return s;
}

FittedSurface torusWith(const PointMatrix& P, const NormalMatrix& normals)
{
    Eigen::Vector3d point;
    Eigen::Vector3d axis;
    if (!revolutionAxis(P, normals, point, axis)) {
        return failedFit(SurfaceKind::Torus);
    }
    // The profile: a circle about (h0, R) of radius r in the half-plane (algebraic).
    const Eigen::Index n = P.rows();
    Eigen::MatrixXd A(n, 3);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector2d hr = meridian(P.row(i).transpose(), point, axis);
        A.row(i) << hr.x(), hr.y(), 1.0;
        b[i] = -hr.squaredNorm();
    }
    const Eigen::Vector3d sol = A.colPivHouseholderQr().solve(b);
    const double h0 = -0.5 * sol[0];
    const double major = -0.5 * sol[1];
    const double minor = std::sqrt(std::max(h0 * h0 + major * major - sol[2], 0.0));
    if (!(major > 0.0) || !(minor > 0.0)) {
        return failedFit(SurfaceKind::Torus);
    }
    const AxisParameters ap = axisParameters(point + h0 * axis, axis);
    Eigen::VectorXd x(7);
    x << 0.0, 0.0, 0.0, 0.0, 0.0, major, minor;
    x = refine(x, static_cast<int>(n), [&P, ap](const Eigen::VectorXd& q, Eigen::VectorXd& f) {
        const Eigen::Vector3d a = ap.axis(q);
        const Eigen::Vector3d c = ap.point(q) + q[4] * a;
        for (Eigen::Index i = 0; i < P.rows(); ++i) {
            const Eigen::Vector2d hr = meridian(P.row(i).transpose(), c, a);
            f[i] = std::hypot(hr.y() - q[5], hr.x()) - q[6];
        }
    });
    FittedSurface s;
    s.kind = SurfaceKind::Torus;
    s.axis = ap.axis(x);
    s.origin = ap.point(x) + x[4] * s.axis;
    s.radius = x[5];
    s.minorRadius = std::abs(x[6]);
    if (!(s.radius > 0.0) || !(s.minorRadius > 0.0)) {
        return failedFit(SurfaceKind::Torus);
    }
    measure(s, P);
    return s;
}

} // namespace

double estimatePatchNoise(const PointMatrix& P, double spacing)
{
    if (P.rows() < 8 || !(spacing > 0.0)) {
        return 0.0;
    }
    NeighbourOptions no;
    no.k = static_cast<int>(std::min<Eigen::Index>(16, P.rows() - 1));
    const Neighbourhoods N = nearestNeighbours(P, no);
    const NormalEstimate normals = pcaNormals(P, N);
    return estimateNoise(P, normals.normals, N, spacing, 2000) * spacing / 0.9;
}

FittedSurface fitCylinder(const PointMatrix& P)
{
    return cylinderWith(P, patchNormals(P));
}

FittedSurface fitCone(const PointMatrix& P)
{
    return coneWith(P, patchNormals(P));
}

FittedSurface fitTorus(const PointMatrix& P)
{
    return torusWith(P, patchNormals(P));
}

namespace {

/// Up to `most` rows of P, evenly picked, and each one's nearest (k) among them.
struct PatchSample
{
    PointMatrix points;
    Neighbourhoods neighbours;
};

PatchSample samplePatch(const PointMatrix& P, Eigen::Index most, int k)
{
    PatchSample s;
    const Eigen::Index step = std::max<Eigen::Index>(1, (P.rows() + most - 1) / most);
    s.points.resize((P.rows() + step - 1) / step, 3);
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
        s.points.row(i) = P.row(i * step);
    }
    NeighbourOptions no;
    no.k = static_cast<int>(std::min<Eigen::Index>(k, s.points.rows() - 1));
    s.neighbours = nearestNeighbours(s.points, no);
    return s;
}

/// The part of the points' deviation from `s` that follows the surface, not the noise: the RMS
/// over the sample of each point's signed distance averaged with its nearest's. Noise of
/// deviation sigma leaves about sigma / sqrt(k + 1) of it; a surface of the wrong kind, which
/// the points leave by the same amount over a stretch, all of its deviation there.
double systematicDeviation(const FittedSurface& s, const PatchSample& sample)
{
    const Eigen::Index n = sample.points.rows();
    std::vector<double> d(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        d[static_cast<size_t>(i)] = signedSurfaceDistance(s, sample.points.row(i).transpose());
    }
    double sum = 0.0;
    const int k = sample.neighbours.k();
    for (Eigen::Index i = 0; i < n; ++i) {
        double local = d[static_cast<size_t>(i)];
        for (int j = 0; j < k; ++j) {
            local += d[static_cast<size_t>(sample.neighbours.indices(i, j))];
        }
        local /= (k + 1);
        sum += local * local;
    }
    return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

} // namespace

FittedSurface fitSurface(const PointMatrix& P, double spacing, double noise,
                         const SurfaceFitOptions& options)
{
    if (P.rows() < 6) {
        throw std::invalid_argument("a patch needs at least 6 points for a surface, it has " +
                                    std::to_string(P.rows()));
    }
    if (!P.allFinite()) {
        throw std::invalid_argument("a patch point has a coordinate that is not finite");
    }
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        throw std::invalid_argument("the spacing must be positive and finite");
    }
    if (!(noise >= 0.0) || !std::isfinite(noise)) {
        throw std::invalid_argument("the noise must be zero or positive and finite");
    }
    const Eigen::Vector3d c = centroidOf(P);
    const Eigen::MatrixXd centred = P.rowwise() - c.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
    if (!(solver.eigenvalues()[1] > 1e-12 * solver.eigenvalues()[2])) {
        throw std::invalid_argument("the patch's points lie on one line: no surface");
    }
    const double tolerance = std::max(options.tolerance * spacing, options.noiseFactor * noise);
    const double extent = (P.colwise().maxCoeff() - P.colwise().minCoeff()).norm();
    // A kind is also held to its systematic deviation: the points' averaged over their nearest,
    // within systematicTolerance spacings and what such an average leaves of the noise.
    const PatchSample sample = samplePatch(P, options.systematicPoints, options.systematicK);
    const double systematicTolerance =
        std::hypot(options.systematicTolerance * spacing,
                   options.noiseFactor * noise / std::sqrt(sample.neighbours.k() + 1.0));
    const auto systematicOk = [&](const FittedSurface& s) {
        return options.systematicTolerance <= 0.0 ||
               systematicDeviation(s, sample) <= systematicTolerance;
    };
    FittedSurface plane = fitPlane(P);
    plane.tolerance = tolerance;
    if (plane.rmsDeviation <= tolerance && systematicOk(plane)) {
        return plane;
    }
    // Of the sphere, cylinder, cone and torus within the tolerance, the first (the fewest
    // parameters) whose deviation is within 1.5 times the least: a cylinder is also a cone of
    // angle near 0 and a torus of a large tube, closer by a hair.
    // Fitted to at most maxFitPoints of the points, evenly picked (the normals once, over their
    // own neighbours), then measured on all.
    const Eigen::Index step =
        std::max<Eigen::Index>(1, (P.rows() + options.maxFitPoints - 1) /
                                      std::max(1, options.maxFitPoints));
    PointMatrix S((P.rows() + step - 1) / step, 3);
    for (Eigen::Index i = 0; i < S.rows(); ++i) {
        S.row(i) = P.row(i * step);
    }
    const NormalMatrix normals = patchNormals(S);
    FittedSurface candidates[4] = {fitSphere(S), cylinderWith(S, normals), coneWith(S, normals),
                                   torusWith(S, normals)};
    if (step > 1) {
        for (FittedSurface& c : candidates) {
            if (std::isfinite(c.rmsDeviation)) {
                measure(c, P);
            }
        }
    }
    auto accepted = [&](const FittedSurface& s) {
        return s.rmsDeviation <= tolerance && s.radius > 0.0 &&
               s.radius <= options.maxRadiusRatio * extent &&
               (s.kind != SurfaceKind::Torus || s.minorRadius <= options.maxRadiusRatio * extent);
    };
    double least = std::numeric_limits<double>::infinity();
    for (const FittedSurface& s : candidates) {
        if (accepted(s)) {
            least = std::min(least, s.rmsDeviation);
        }
    }
    for (const FittedSurface& s : candidates) {
        if (accepted(s) && s.rmsDeviation <= 1.5 * least && systematicOk(s)) {
            FittedSurface out = s;
            out.tolerance = tolerance;
            return out;
        }
    }
    FittedSurface field = fitHeightField(P, spacing, options);
    measure(field, P);
    field.tolerance = tolerance;
    return field;
}

} // namespace featurelines::surfaces
