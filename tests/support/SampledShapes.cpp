// SPDX-License-Identifier: LGPL-2.1-or-later
#include "SampledShapes.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace featurelines::shapes {

namespace {

constexpr double pi = 3.14159265358979323846;
/// Jitter of a sample inside its grid cell, as a fraction of the cell: +-0.2 as a scanner's
/// slightly irregular pattern, small enough that no two samples come close to coinciding.
constexpr double jitter = 0.2;

void requirePositive(double value, const char* name)
{
    if (!(value > 0.0) || !std::isfinite(value)) {
        throw std::invalid_argument(std::string("shape sampler: ") + name +
                                    " must be a positive length");
    }
}

/// Collects samples, then packs them into a Sample.
class Builder
{
public:
    explicit Builder(unsigned seed) : rng_(seed), offset_(-jitter, jitter) {}

    /// Number of grid cells along a parameter line of the given length (at least one).
    static int cells(double length, double spacing)
    {
        return std::max(1, static_cast<int>(std::lround(length / spacing)));
    }

    /// Position of sample i of n cells on [0, 1], jittered inside its cell.
    double cellPosition(int i, int n) { return (i + 0.5 + offset_(rng_)) / n; }

    void add(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double curvature,
             int part)
    {
        points_.push_back(point);
        normals_.push_back(normal.normalized());
        curvature_.push_back(curvature);
        part_.push_back(part);
    }

    /// Jittered grid on a flat rectangle: origin + s * du + t * dv, s and t in [0, 1].
    void rectangle(const Eigen::Vector3d& origin, const Eigen::Vector3d& du,
                   const Eigen::Vector3d& dv, double spacing, int part)
    {
        const Eigen::Vector3d normal = du.cross(dv);
        const int nu = cells(du.norm(), spacing);
        const int nv = cells(dv.norm(), spacing);
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                add(origin + cellPosition(i, nu) * du + cellPosition(j, nv) * dv, normal, 0.0,
                    part);
            }
        }
    }

    /// A zone of the sphere of the given centre and radius, in the orthonormal frame (ex, ey,
    /// ez): polar angle theta in [0, thetaMax] from ez, azimuth phi in [0, phiSpan] from ex.
    /// Circles of latitude are one spacing apart and each holds as many samples as its length
    /// allows, so the density stays uniform up to the pole.
    void sphereZone(const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& ex,
                    const Eigen::Vector3d& ey, const Eigen::Vector3d& ez, double thetaMax,
                    double phiSpan, double spacing, int part)
    {
        const int rings = cells(radius * thetaMax, spacing);
        for (int j = 0; j < rings; ++j) {
            const double ringTheta = (j + 0.5) / rings * thetaMax;
            const int around = cells(radius * std::sin(ringTheta) * phiSpan, spacing);
            for (int i = 0; i < around; ++i) {
                const double theta = cellPosition(j, rings) * thetaMax;
                const double phi = cellPosition(i, around) * phiSpan;
                const Eigen::Vector3d direction =
                    std::sin(theta) * (std::cos(phi) * ex + std::sin(phi) * ey) +
                    std::cos(theta) * ez;
                add(centre + radius * direction, direction, 1.0 / radius, part);
            }
        }
    }

    /// A cylinder sector around the axis through `centre` along ez: angle alpha in
    /// [0, alphaSpan] from ex towards ey, axial position in [-length/2, length/2].
    void cylinderSector(const Eigen::Vector3d& centre, double radius, double length,
                        const Eigen::Vector3d& ex, const Eigen::Vector3d& ey,
                        const Eigen::Vector3d& ez, double alphaSpan, double spacing, int part)
    {
        const int na = cells(radius * alphaSpan, spacing);
        const int nz = cells(length, spacing);
        for (int i = 0; i < na; ++i) {
            for (int j = 0; j < nz; ++j) {
                const double alpha = cellPosition(i, na) * alphaSpan;
                const double z = (cellPosition(j, nz) - 0.5) * length;
                const Eigen::Vector3d radial = std::cos(alpha) * ex + std::sin(alpha) * ey;
                add(centre + radius * radial + z * ez, radial, 0.5 / radius, part);
            }
        }
    }

    /// Jittered grid of cell centres over the face of the convex polyhedron {x : n_j . x <=
    /// d_j} that lies in plane `face`: laid in the plane over the face's bounding rectangle,
    /// samples outside the polyhedron dropped.
    void convexFace(const std::vector<Eigen::Vector4d>& planes, std::size_t face, double spacing,
                    int part)
    {
        const Eigen::Vector3d n = planes[face].head<3>().normalized();
        const double d = planes[face][3] / planes[face].head<3>().norm();
        const Eigen::Vector3d u = n.unitOrthogonal();
        const Eigen::Vector3d v = n.cross(u);
        // The face polygon: a square larger than the polyhedron, clipped by every other plane
        // (Sutherland-Hodgman), in the plane's (u, v) coordinates.
        double extent = spacing;
        for (const Eigen::Vector4d& p : planes) {
            extent += std::abs(p[3] / p.head<3>().norm());
        }
        extent *= 4.0;
        std::vector<Eigen::Vector2d> polygon = {
            {-extent, -extent}, {extent, -extent}, {extent, extent}, {-extent, extent}};
        const Eigen::Vector3d origin = d * n;
        auto at = [&](const Eigen::Vector2d& q) {
            return Eigen::Vector3d(origin + q.x() * u + q.y() * v);
        };
        for (std::size_t j = 0; j < planes.size() && !polygon.empty(); ++j) {
            if (j == face) {
                continue;
            }
            const Eigen::Vector3d nj = planes[j].head<3>();
            auto inside = [&](const Eigen::Vector2d& q) { return planes[j][3] - nj.dot(at(q)); };
            std::vector<Eigen::Vector2d> clipped;
            for (std::size_t i = 0; i < polygon.size(); ++i) {
                const Eigen::Vector2d& a = polygon[i];
                const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
                const double fa = inside(a), fb = inside(b);
                if (fa >= 0.0) {
                    clipped.push_back(a);
                }
                if ((fa >= 0.0) != (fb >= 0.0)) {
                    clipped.push_back(a + fa / (fa - fb) * (b - a));
                }
            }
            polygon = std::move(clipped);
        }
        if (polygon.size() < 3) {
            return;
        }
        Eigen::Vector2d low = polygon[0], high = polygon[0];
        for (const Eigen::Vector2d& q : polygon) {
            low = low.cwiseMin(q);
            high = high.cwiseMax(q);
        }
        const int nu = cells(high.x() - low.x(), spacing);
        const int nv = cells(high.y() - low.y(), spacing);
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                const Eigen::Vector2d q(low.x() + cellPosition(i, nu) * (high.x() - low.x()),
                                        low.y() + cellPosition(j, nv) * (high.y() - low.y()));
                const Eigen::Vector3d x = at(q);
                bool inside = true;
                for (std::size_t k = 0; k < planes.size() && inside; ++k) {
                    inside = k == face || planes[k].head<3>().dot(x) <= planes[k][3];
                }
                if (inside) {
                    add(x, n, 0.0, part);
                }
            }
        }
    }

    Sample finish()
    {
        Sample s;
        const Eigen::Index n = static_cast<Eigen::Index>(points_.size());
        s.points.resize(n, 3);
        s.normals.resize(n, 3);
        s.meanCurvature.resize(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            s.points.row(i) = points_[i].transpose();
            s.normals.row(i) = normals_[i].transpose();
            s.meanCurvature(i) = curvature_[i];
        }
        s.part = std::move(part_);
        return s;
    }

private:
    std::mt19937 rng_;
    std::uniform_real_distribution<double> offset_;
    std::vector<Eigen::Vector3d> points_;
    std::vector<Eigen::Vector3d> normals_;
    std::vector<double> curvature_;
    std::vector<int> part_;
};

/// Unit vector along axis a (0 x, 1 y, 2 z) with the given sign.
Eigen::Vector3d axis(int a, double sign = 1.0)
{
    return sign * Eigen::Vector3d::Unit(a);
}

} // namespace

Sample plane(double size, double spacing, unsigned seed)
{
    requirePositive(size, "size");
    requirePositive(spacing, "spacing");
    Builder b(seed);
    b.rectangle(Eigen::Vector3d(-size / 2, -size / 2, 0), axis(0, size), axis(1, size), spacing, 0);
    return b.finish();
}

Sample sphere(double radius, double spacing, unsigned seed)
{
    requirePositive(radius, "radius");
    requirePositive(spacing, "spacing");
    Builder b(seed);
    b.sphereZone(Eigen::Vector3d::Zero(), radius, axis(0), axis(1), axis(2), pi, 2 * pi, spacing,
                 0);
    return b.finish();
}

Sample cylinder(double radius, double height, double spacing, unsigned seed)
{
    requirePositive(radius, "radius");
    requirePositive(height, "height");
    requirePositive(spacing, "spacing");
    Builder b(seed);
    b.cylinderSector(Eigen::Vector3d::Zero(), radius, height, axis(0), axis(1), axis(2), 2 * pi,
                     spacing, 0);
    return b.finish();
}

Sample cube(double edge, double spacing, unsigned seed)
{
    requirePositive(edge, "edge");
    requirePositive(spacing, "spacing");
    Builder b(seed);
    const double h = edge / 2;
    for (int face = 0; face < 6; ++face) {
        const int a = face / 2;
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        // du x dv must point outwards: (a+1, a+2) is right-handed for +, swapped for -.
        Eigen::Vector3d du = axis((a + 1) % 3, edge);
        Eigen::Vector3d dv = axis((a + 2) % 3, edge);
        if (sign < 0) {
            std::swap(du, dv);
        }
        const Eigen::Vector3d origin = sign * h * axis(a) - (du + dv) / 2;
        b.rectangle(origin, du, dv, spacing, face);
    }
    return b.finish();
}

Sample roundedCube(double edge, double radius, double spacing, unsigned seed)
{
    requirePositive(edge, "edge");
    requirePositive(radius, "radius");
    requirePositive(spacing, "spacing");
    if (!(radius < edge / 2)) {
        throw std::invalid_argument("shape sampler: the rounding radius must be below half the "
                                    "cube's edge");
    }
    Builder b(seed);
    // The rounded cube is the set of points at distance `radius` from the inner box
    // [-inner, inner]^3: its faces, edges and corners become flats, fillets and corners.
    const double inner = edge / 2 - radius;
    const double side = 2 * inner;
    for (int face = 0; face < 6; ++face) {
        const int a = face / 2;
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        Eigen::Vector3d du = axis((a + 1) % 3, side);
        Eigen::Vector3d dv = axis((a + 2) % 3, side);
        if (sign < 0) {
            std::swap(du, dv);
        }
        b.rectangle(sign * (edge / 2) * axis(a) - (du + dv) / 2, du, dv, spacing, 0);
    }
    for (int a = 0; a < 3; ++a) { // fillet axis
        for (int corner = 0; corner < 4; ++corner) {
            const double su = corner & 1 ? -1.0 : 1.0;
            const double sv = corner & 2 ? -1.0 : 1.0;
            const Eigen::Vector3d ex = axis((a + 1) % 3, su);
            const Eigen::Vector3d ey = axis((a + 2) % 3, sv);
            b.cylinderSector(inner * (ex + ey), radius, side, ex, ey, axis(a), pi / 2, spacing, 1);
        }
    }
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d s(corner & 1 ? -1.0 : 1.0, corner & 2 ? -1.0 : 1.0,
                                corner & 4 ? -1.0 : 1.0);
        b.sphereZone(inner * s, radius, axis(0, s.x()), axis(1, s.y()), axis(2, s.z()), pi / 2,
                     pi / 2, spacing, 2);
    }
    return b.finish();
}

Sample convexPolyhedron(const std::vector<Eigen::Vector4d>& planes, double spacing, unsigned seed)
{
    requirePositive(spacing, "spacing");
    for (const Eigen::Vector4d& p : planes) {
        if (!p.allFinite() || !(p.head<3>().norm() > 0.0)) {
            throw std::invalid_argument("shape sampler: a plane needs a finite, nonzero normal");
        }
    }
    Builder b(seed);
    for (std::size_t face = 0; face < planes.size(); ++face) {
        b.convexFace(planes, face, spacing, static_cast<int>(face));
    }
    return b.finish();
}

Sample chamferedCube(double edge, double chamfer, double spacing, unsigned seed)
{
    requirePositive(edge, "edge");
    requirePositive(chamfer, "chamfer");
    if (!(chamfer < edge / 2)) {
        throw std::invalid_argument("shape sampler: the chamfer must be below half the cube's "
                                    "edge");
    }
    const double h = edge / 2;
    std::vector<Eigen::Vector4d> planes;
    for (int a = 0; a < 3; ++a) {
        for (double sign : {1.0, -1.0}) {
            planes.emplace_back(sign * (a == 0), sign * (a == 1), sign * (a == 2), h);
        }
    }
    // The chamfer of the edge where faces a and b meet cuts both back by `chamfer`:
    // x_a + x_b <= 2 h - chamfer (signs per edge), normal at 45 degrees to either face.
    const double r = 1.0 / std::sqrt(2.0);
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3;
        for (double sa : {1.0, -1.0}) {
            for (double sb : {1.0, -1.0}) {
                Eigen::Vector4d p = Eigen::Vector4d::Zero();
                p[a] = sa * r;
                p[b] = sb * r;
                p[3] = (2 * h - chamfer) * r;
                planes.push_back(p);
            }
        }
    }
    // The corner triangle through the three chamfers' ends: x + y + z <= 3 h - 2 chamfer.
    const double c = 1.0 / std::sqrt(3.0);
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d s(corner & 1 ? -1.0 : 1.0, corner & 2 ? -1.0 : 1.0,
                                corner & 4 ? -1.0 : 1.0);
        planes.emplace_back(s.x() * c, s.y() * c, s.z() * c, (3 * h - 2 * chamfer) * c);
    }
    return convexPolyhedron(planes, spacing, seed);
}

Sample prism(const std::vector<Eigen::Vector2d>& section, double height, double spacing,
             unsigned seed)
{
    requirePositive(height, "height");
    if (section.size() < 3) {
        throw std::invalid_argument("shape sampler: a prism's section needs three vertices");
    }
    std::vector<Eigen::Vector4d> planes;
    const std::size_t m = section.size();
    for (std::size_t k = 0; k < m; ++k) {
        const Eigen::Vector2d a = section[k], b = section[(k + 1) % m];
        // Counter-clockwise: the outward normal is the edge turned clockwise.
        const Eigen::Vector2d n = Eigen::Vector2d(b.y() - a.y(), a.x() - b.x()).normalized();
        planes.emplace_back(n.x(), n.y(), 0.0, n.dot(a));
    }
    planes.emplace_back(0.0, 0.0, 1.0, height / 2);
    planes.emplace_back(0.0, 0.0, -1.0, height / 2);
    return convexPolyhedron(planes, spacing, seed);
}

void addNormalNoise(Sample& s, double sigma, unsigned seed)
{
    if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
        throw std::invalid_argument("shape sampler: the noise sigma must be zero or positive");
    }
    std::mt19937 rng(seed);
    std::normal_distribution<double> offset(0.0, sigma);
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
        s.points.row(i) += offset(rng) * s.normals.row(i);
    }
}

} // namespace featurelines::shapes
