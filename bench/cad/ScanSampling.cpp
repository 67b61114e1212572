// SPDX-License-Identifier: LGPL-2.1-or-later
#include "ScanSampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <Eigen/Geometry>

#include "PointGrid.h"
#include "ShapeSampling.h"

namespace featurelines::bench {

namespace {

constexpr double pi = 3.14159265358979323846;

/// Uniform and normal draws made from std::mt19937's integers, whose sequence the standard
/// fixes, so that a cloud does not depend on the standard library's distributions.
class Draws
{
public:
    explicit Draws(std::uint32_t seed) : engine(seed) {}

    /// Uniform in [0, 1) with 53 random bits.
    double uniform()
    {
        const std::uint64_t high = engine() >> 5;
        const std::uint64_t low = engine() >> 6;
        return (static_cast<double>(high) * 67108864.0 + static_cast<double>(low)) /
               9007199254740992.0;
    }

    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

    /// Uniform integer in [lo, hi].
    int integer(int lo, int hi)
    {
        const int n = hi - lo + 1;
        return lo + std::min(n - 1, static_cast<int>(uniform() * n));
    }

    /// Standard normal (Box-Muller, one value per pair of uniforms).
    double normal()
    {
        const double u1 = 1.0 - uniform(); // in (0, 1]
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * pi * u2);
    }

    /// Uniform on the unit sphere.
    Eigen::Vector3d direction()
    {
        const double z = uniform(-1.0, 1.0);
        const double phi = uniform(0.0, 2.0 * pi);
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

    /// Uniform among the unit vectors perpendicular to unit d.
    Eigen::Vector3d perpendicular(const Eigen::Vector3d& d)
    {
        const Eigen::Vector3d u = d.unitOrthogonal();
        const Eigen::Vector3d v = d.cross(u);
        const double phi = uniform(0.0, 2.0 * pi);
        return std::cos(phi) * u + std::sin(phi) * v;
    }

private:
    std::mt19937 engine;
};

/// An independent seed per stage, so that switching one add-on on leaves the others' draws.
std::uint32_t stageSeed(std::uint32_t seed, std::uint32_t stage)
{
    std::uint32_t x = seed * 0x9E3779B9u + stage * 0x85EBCA6Bu + 0x6A09E667u;
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return x;
}

enum Stage : std::uint32_t
{
    SampleStage = 1,
    ViewStage,
    MisregistrationStage,
    HoleStage,
    NoiseStage,
    OutlierStage,
    DrawStage,
    CloudSeedStage
};

/// Points with their normals and the view that saw each.
struct Samples
{
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> normals;
    std::vector<int> view;

    void add(const Eigen::Vector3d& p, const Eigen::Vector3d& n, int v)
    {
        points.push_back(p);
        normals.push_back(n);
        view.push_back(v);
    }
};

void requireIn(double value, double lo, double hi, const char* message)
{
    if (!(value >= lo && value <= hi)) {
        throw std::invalid_argument(message);
    }
}

void validate(const ScanOptions& o)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (!(o.points > 1.0) || !std::isfinite(o.points)) {
        throw std::invalid_argument("A scan needs more than one point.");
    }
    requireIn(o.rowSpacingRatio, 1.0, 1e3, "The row spacing ratio must be at least 1.");
    if (o.viewCount < 1) {
        throw std::invalid_argument("A merged scan needs at least one view.");
    }
    requireIn(o.minViewTurnDegrees, 0.0, 180.0, "View turns are angles of 0 to 180 degrees.");
    requireIn(o.maxViewTurnDegrees, o.minViewTurnDegrees, 180.0,
              "View turns are angles of 0 to 180 degrees, the largest last.");
    requireIn(o.grazingLimitDegrees, 1e-9, 90.0, "The grazing limit is an angle up to 90 degrees.");
    requireIn(o.misregistration, 0.0, inf, "The misregistration cannot be negative.");
    requireIn(o.densityRatio, 1.0, 1e6, "The density ratio must be at least 1.");
    requireIn(o.oversampling, 1.0, 1e3, "The oversampling must be at least 1.");
    if (o.occlusionHoles < 0) {
        throw std::invalid_argument("The number of occlusion holes cannot be negative.");
    }
    requireIn(o.holeRadius, 1e-12, inf, "The hole radius must be positive.");
    requireIn(o.outlierShare, 0.0, 1.0, "The outlier share lies between 0 and 1.");
    requireIn(o.outlierMinDistance, 0.0, inf, "Outlier distances cannot be negative.");
    requireIn(o.outlierMaxDistance, o.outlierMinDistance, inf,
              "The largest outlier distance cannot be below the smallest.");
    requireIn(o.normalNoise, 0.0, inf, "The normal noise cannot be negative.");
    requireIn(o.tangentialJitter, 0.0, inf, "The tangential jitter cannot be negative.");
    requireIn(o.meshDeflectionFactor, 1e-6, 1e3, "The mesh deflection factor must be positive.");
}

/// The views given, made orthonormal, or `count` views drawn: the first from any direction,
/// each next turned from the previous about an axis perpendicular to it.
std::vector<ScanView> viewsFor(const ScanOptions& o, int count)
{
    std::vector<ScanView> views;
    if (!o.views.empty()) {
        for (const ScanView& given : o.views) {
            ScanView v;
            v.direction = given.direction.normalized();
            const Eigen::Vector3d row =
                given.rowDirection - given.rowDirection.dot(v.direction) * v.direction;
            if (!v.direction.allFinite() || !(row.norm() > 1e-9)) {
                throw std::invalid_argument("A scan view needs a direction and a row direction "
                                            "across it.");
            }
            v.rowDirection = row.normalized();
            views.push_back(v);
        }
        return views;
    }
    Draws draws(stageSeed(o.seed, ViewStage));
    ScanView v;
    v.direction = draws.direction();
    v.rowDirection = draws.perpendicular(v.direction);
    views.push_back(v);
    for (int k = 1; k < count; ++k) {
        const Eigen::Vector3d axis = draws.perpendicular(views.back().direction);
        const double turn = draws.uniform(o.minViewTurnDegrees, o.maxViewTurnDegrees) * pi / 180.0;
        ScanView next;
        next.direction = Eigen::AngleAxisd(turn, axis) * views.back().direction;
        next.rowDirection = draws.perpendicular(next.direction);
        views.push_back(next);
    }
    return views;
}

/// Corners of the triangulation's axis-aligned box.
Eigen::AlignedBox3d boxOf(const SurfaceTriangulation& mesh)
{
    Eigen::AlignedBox3d box;
    for (const SurfaceTriangulation::Triangle& t : mesh.triangles()) {
        for (const Eigen::Vector3d& p : t.p) {
            box.extend(p);
        }
    }
    return box;
}

/// A point uniform by area on the triangulation: its triangle and barycentric weights.
struct TrianglePoint
{
    std::size_t triangle;
    double b0, b1, b2;

    Eigen::Vector3d position(const SurfaceTriangulation& mesh) const
    {
        const SurfaceTriangulation::Triangle& t = mesh.triangles()[triangle];
        return b0 * t.p[0] + b1 * t.p[1] + b2 * t.p[2];
    }
    bool place(const SurfaceTriangulation& mesh, Eigen::Vector3d& p, Eigen::Vector3d& n) const
    {
        return mesh.place(triangle, b0, b1, b2, p, n);
    }
};

TrianglePoint drawByArea(const SurfaceTriangulation& mesh, Draws& draws)
{
    const std::size_t t = mesh.triangleAtArea(draws.uniform() * mesh.area());
    // Uniform barycentric coordinates (square-root warp of two uniforms).
    const double s = std::sqrt(draws.uniform());
    const double w2 = draws.uniform();
    return {t, 1.0 - s, s * (1.0 - w2), s * w2};
}

Samples uniformRandom(const SurfaceTriangulation& mesh, const ScanOptions& o)
{
    Draws draws(stageSeed(o.seed, SampleStage));
    Samples s;
    const long count = std::lround(o.points);
    Eigen::Vector3d p, n;
    for (long i = 0; i < count; ++i) {
        if (drawByArea(mesh, draws).place(mesh, p, n)) {
            s.add(p, n, -1);
        }
    }
    return s;
}

Samples poissonDisk(const TopoDS_Shape& shape, const ScanOptions& o)
{
    SamplingOptions sampling;
    sampling.radius = radiusForPointCount(shapeArea(shape), o.points);
    sampling.oversampling = o.oversampling;
    sampling.meshDeflectionFactor = o.meshDeflectionFactor;
    sampling.seed = stageSeed(o.seed, SampleStage);
    const SampledCloud cloud = sampleShape(shape, sampling);
    Samples s;
    for (Eigen::Index i = 0; i < cloud.points.rows(); ++i) {
        s.add(cloud.points.row(i).transpose(), cloud.normals.row(i).transpose(), -1);
    }
    return s;
}

/// Greedy Poisson-disk thinning whose radius shrinks across the part, so that the density
/// grows linearly from 1 to densityRatio along the gradient direction over the part's extent.
Samples densityGradient(const SurfaceTriangulation& mesh, const ScanOptions& o)
{
    Draws draws(stageSeed(o.seed, SampleStage));
    Eigen::Vector3d g = o.gradientDirection;
    if (g.isZero()) {
        g = draws.direction();
    }
    g.normalize();
    if (!g.allFinite()) {
        throw std::invalid_argument("The density gradient's direction must be finite.");
    }
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const SurfaceTriangulation::Triangle& t : mesh.triangles()) {
        for (const Eigen::Vector3d& p : t.p) {
            lo = std::min(lo, p.dot(g));
            hi = std::max(hi, p.dot(g));
        }
    }
    const double extent = std::max(hi - lo, 1e-300);
    // Density relative to the dense end, 1 / densityRatio to 1.
    const auto relativeDensity = [&](const Eigen::Vector3d& p) {
        const double t = std::clamp((p.dot(g) - lo) / extent, 0.0, 1.0);
        return (1.0 + (o.densityRatio - 1.0) * t) / o.densityRatio;
    };
    double weighted = 0.0;
    for (const SurfaceTriangulation::Triangle& t : mesh.triangles()) {
        const double a = 0.5 * (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).norm();
        weighted += a * relativeDensity((t.p[0] + t.p[1] + t.p[2]) / 3.0);
    }
    // The dense end's radius gives o.points over the density-weighted area.
    const double rDense = radiusForPointCount(weighted, o.points);
    const double rSparse = rDense * std::sqrt(o.densityRatio);
    const long candidates =
        static_cast<long>(std::ceil(o.oversampling * o.points * mesh.area() / weighted));
    PointGrid grid(rSparse);
    Samples s;
    Eigen::Vector3d p, n;
    for (long c = 0; c < candidates; ++c) {
        const TrianglePoint candidate = drawByArea(mesh, draws);
        const Eigen::Vector3d approx = candidate.position(mesh);
        if (grid.anyWithin(approx, rDense / std::sqrt(relativeDensity(approx))) ||
            !candidate.place(mesh, p, n)) {
            continue;
        }
        grid.insert(p, static_cast<int>(s.points.size()));
        s.add(p, n, -1);
    }
    return s;
}

/// One ray's nearest hit so far.
struct RayHit
{
    double depth = std::numeric_limits<double>::infinity();
    int triangle = -1;
    double b1 = 0.0;
    double b2 = 0.0;
};

/// The projection of the triangulation onto a view's plane: x along the rows, y across.
struct ViewFrame
{
    Eigen::Vector3d d, x, y;
    double xMin, xMax, yMin, yMax;

    ViewFrame(const SurfaceTriangulation& mesh, const ScanView& view)
        : d(view.direction), x(view.rowDirection), y(view.direction.cross(view.rowDirection))
    {
        xMin = yMin = std::numeric_limits<double>::infinity();
        xMax = yMax = -xMin;
        for (const SurfaceTriangulation::Triangle& t : mesh.triangles()) {
            for (const Eigen::Vector3d& p : t.p) {
                xMin = std::min(xMin, p.dot(x));
                xMax = std::max(xMax, p.dot(x));
                yMin = std::min(yMin, p.dot(y));
                yMax = std::max(yMax, p.dot(y));
            }
        }
    }
    double rectangleArea() const { return (xMax - xMin) * (yMax - yMin); }
};

/// A line scanner's view: rays along the view direction on a grid of `along` by `across`
/// (rows along the view's row direction), the grid shifted by (phaseX, phaseY) steps. Each
/// ray keeps its nearest triangle (a depth buffer: occluded surfaces and back faces get no
/// ray), and its hit is placed on the exact surface; a hit seen more obliquely than the
/// grazing limit is dropped. Returns the number of points added.
long scanView(const SurfaceTriangulation& mesh, const ViewFrame& f, double along, double across,
              double phaseX, double phaseY, double cosGrazing, int viewIndex, Samples* out)
{
    const double x0 = f.xMin - phaseX * along;
    const double y0 = f.yMin - phaseY * across;
    const long nx = static_cast<long>(std::floor((f.xMax - x0) / along)) + 1;
    const long ny = static_cast<long>(std::floor((f.yMax - y0) / across)) + 1;
    if (static_cast<double>(nx) * static_cast<double>(ny) > 4e8) {
        throw std::invalid_argument("A scan view would need more than 400 million rays.");
    }
    std::vector<RayHit> buffer(static_cast<std::size_t>(nx * ny));
    const auto& triangles = mesh.triangles();
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const SurfaceTriangulation::Triangle& tri = triangles[t];
        double px[3], py[3], pz[3];
        for (int c = 0; c < 3; ++c) {
            px[c] = tri.p[c].dot(f.x);
            py[c] = tri.p[c].dot(f.y);
            pz[c] = tri.p[c].dot(f.d);
        }
        const double det = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
        if (std::abs(det) < 1e-300) {
            continue; // seen edge-on
        }
        const long i0 = std::max(
            0L, static_cast<long>(std::ceil((std::min({px[0], px[1], px[2]}) - x0) / along)));
        const long i1 = std::min(
            nx - 1, static_cast<long>(std::floor((std::max({px[0], px[1], px[2]}) - x0) / along)));
        const long j0 = std::max(
            0L, static_cast<long>(std::ceil((std::min({py[0], py[1], py[2]}) - y0) / across)));
        const long j1 = std::min(
            ny - 1, static_cast<long>(std::floor((std::max({py[0], py[1], py[2]}) - y0) / across)));
        for (long j = j0; j <= j1; ++j) {
            const double Y = y0 + static_cast<double>(j) * across - py[0];
            for (long i = i0; i <= i1; ++i) {
                const double X = x0 + static_cast<double>(i) * along - px[0];
                const double b1 = (X * (py[2] - py[0]) - (px[2] - px[0]) * Y) / det;
                const double b2 = ((px[1] - px[0]) * Y - X * (py[1] - py[0])) / det;
                const double b0 = 1.0 - b1 - b2;
                constexpr double inside = -1e-12;
                if (b0 < inside || b1 < inside || b2 < inside) {
                    continue;
                }
                const double depth = b0 * pz[0] + b1 * pz[1] + b2 * pz[2];
                RayHit& hit = buffer[static_cast<std::size_t>(j * nx + i)];
                if (depth < hit.depth) {
                    hit = {depth, static_cast<int>(t), b1, b2};
                }
            }
        }
    }
    long added = 0;
    Eigen::Vector3d p, n;
    for (const RayHit& hit : buffer) {
        if (hit.triangle < 0) {
            continue;
        }
        const double b1 = std::clamp(hit.b1, 0.0, 1.0);
        const double b2 = std::clamp(hit.b2, 0.0, 1.0 - b1);
        if (!mesh.place(static_cast<std::size_t>(hit.triangle), 1.0 - b1 - b2, b1, b2, p, n)) {
            continue;
        }
        // Either side of a face is seen (an open shell's inside); a solid's back faces lie
        // behind its front ones.
        if (std::abs(n.dot(f.d)) < cosGrazing) {
            continue;
        }
        ++added;
        if (out) {
            out->add(p, n, viewIndex);
        }
    }
    return added;
}

/// The views' scans at the along-row step that gives about o.points points in all: a trial
/// pass on a coarse grid counts the hits, which scale with 1 / step^2.
Samples scanLines(const SurfaceTriangulation& mesh, const std::vector<ScanView>& views,
                  const ScanOptions& o, double& rowStep)
{
    Draws draws(stageSeed(o.seed, SampleStage));
    std::vector<ViewFrame> frames;
    std::vector<std::pair<double, double>> phases;
    double rectangles = 0.0;
    for (const ScanView& v : views) {
        frames.emplace_back(mesh, v);
        rectangles += frames.back().rectangleArea();
        const double px = draws.uniform();
        phases.emplace_back(px, draws.uniform());
    }
    const double ratio = o.rowSpacingRatio;
    const double cosGrazing = std::cos(o.grazingLimitDegrees * pi / 180.0);
    const double trialRays = std::max(4000.0, 0.25 * o.points);
    const double trialStep = std::sqrt(rectangles / (trialRays * ratio));
    long trialHits = 0;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        trialHits += scanView(mesh, frames[k], trialStep, ratio * trialStep, phases[k].first,
                              phases[k].second, cosGrazing, static_cast<int>(k), nullptr);
    }
    if (trialHits == 0) {
        throw std::runtime_error("No view of the scan sees the shape.");
    }
    rowStep = trialStep * std::sqrt(static_cast<double>(trialHits) / o.points);
    Samples s;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        scanView(mesh, frames[k], rowStep, ratio * rowStep, phases[k].first, phases[k].second,
                 cosGrazing, static_cast<int>(k), &s);
    }
    return s;
}

/// Moves each view's points by a small rigid motion: a translation of half the
/// misregistration and a rotation about the box's centre that moves no point of the box by
/// more than the other half.
void misregister(Samples& s, int viewCount, const Eigen::AlignedBox3d& box, double largest,
                 std::uint32_t seed)
{
    Draws draws(seed);
    const Eigen::Vector3d centre = box.center();
    const double radius = std::max(0.5 * box.diagonal().norm(), 1e-300);
    std::vector<Eigen::Matrix3d> rotations;
    std::vector<Eigen::Vector3d> shifts;
    for (int k = 0; k < viewCount; ++k) {
        const Eigen::Vector3d axis = draws.direction();
        const double angle = 0.5 * largest / radius;
        rotations.push_back(Eigen::AngleAxisd(angle, axis).toRotationMatrix());
        shifts.push_back(0.5 * largest * draws.direction());
    }
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const std::size_t k = static_cast<std::size_t>(s.view[i]);
        s.points[i] = centre + rotations[k] * (s.points[i] - centre) + shifts[k];
        s.normals[i] = rotations[k] * s.normals[i];
    }
}

/// Cuts `count` cylindrical holes centred on random points of the cloud.
std::vector<OcclusionHole> cutHoles(Samples& s, const ScanOptions& o,
                                    const std::vector<ScanView>& views, double spacing)
{
    Draws draws(stageSeed(o.seed, HoleStage));
    std::vector<OcclusionHole> holes;
    for (int h = 0; h < o.occlusionHoles && !s.points.empty(); ++h) {
        OcclusionHole hole;
        hole.point = s.points[static_cast<std::size_t>(
            draws.integer(0, static_cast<int>(s.points.size()) - 1))];
        hole.direction = views.empty() ? draws.direction()
                                       : views[static_cast<std::size_t>(draws.integer(
                                                   0, static_cast<int>(views.size()) - 1))]
                                             .direction;
        hole.radius = o.holeRadius * spacing;
        holes.push_back(hole);
        Samples kept;
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            const Eigen::Vector3d q = s.points[i] - hole.point;
            const Eigen::Vector3d across = q - q.dot(hole.direction) * hole.direction;
            if (across.norm() >= hole.radius) {
                kept.add(s.points[i], s.normals[i], s.view[i]);
            }
        }
        s = std::move(kept);
    }
    return holes;
}

/// Gaussian jitter in the tangent plane and along the normal.
void addNoise(Samples& s, double tangential, double normal, std::uint32_t seed)
{
    if (tangential == 0.0 && normal == 0.0) {
        return;
    }
    Draws draws(seed);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const Eigen::Vector3d& n = s.normals[i];
        const Eigen::Vector3d u = n.unitOrthogonal();
        const Eigen::Vector3d v = n.cross(u);
        const double gu = draws.normal();
        const double gv = draws.normal();
        const double gn = draws.normal();
        s.points[i] += tangential * (gu * u + gv * v) + normal * gn * n;
    }
}

/// Displaces a share of the points (chosen without repetition) outwards, in a direction
/// within 45 degrees of the normal, by a distance uniform in [minDistance, maxDistance].
std::vector<std::uint8_t> addOutliers(Samples& s, double share, double minDistance,
                                      double maxDistance, std::uint32_t seed)
{
    std::vector<std::uint8_t> outlier(s.points.size(), 0);
    const long count = std::lround(share * static_cast<double>(s.points.size()));
    if (count == 0) {
        return outlier;
    }
    Draws draws(seed);
    std::vector<int> order(s.points.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = static_cast<int>(i);
    }
    const int n = static_cast<int>(order.size());
    for (int k = 0; k < count; ++k) {
        // A partial Fisher-Yates shuffle: order[k] is drawn from the rest.
        std::swap(order[static_cast<std::size_t>(k)],
                  order[static_cast<std::size_t>(draws.integer(k, n - 1))]);
        const std::size_t i = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
        const Eigen::Vector3d& normal = s.normals[i];
        // A point uniform in the unit disc across the normal tilts it by at most 45 degrees.
        const double radius = std::sqrt(draws.uniform());
        const Eigen::Vector3d tilt = radius * draws.perpendicular(normal);
        const Eigen::Vector3d direction = (normal + tilt).normalized();
        s.points[i] += draws.uniform(minDistance, maxDistance) * direction;
        outlier[i] = 1;
    }
    return outlier;
}

} // namespace

std::string scanModelName(ScanModel model)
{
    switch (model) {
    case ScanModel::UniformRandom:
        return "uniform_random";
    case ScanModel::PoissonDisk:
        return "poisson_disk";
    case ScanModel::ScanLines:
        return "scan_lines";
    case ScanModel::MergedViews:
        return "merged_views";
    case ScanModel::DensityGradient:
        return "density_gradient";
    }
    throw std::invalid_argument("Unknown scan model.");
}

ScannedCloud sampleLikeAScanner(const TopoDS_Shape& shape, const ScanOptions& options)
{
    validate(options);
    const double area = shapeArea(shape);
    if (!(area > 0.0)) {
        throw std::invalid_argument("The shape to scan has no face.");
    }
    ScannedCloud result;
    Samples s;
    const bool scanned =
        options.model == ScanModel::ScanLines || options.model == ScanModel::MergedViews;
    if (options.model == ScanModel::PoissonDisk) {
        s = poissonDisk(shape, options);
    } else {
        // The sampling step: the mean spacing for the area models, a rough along-row step
        // (a part's views see about half its area) for the scan models.
        const double step = scanned
                                ? std::sqrt(0.5 * area / (options.points * options.rowSpacingRatio))
                                : std::sqrt(area / options.points);
        const SurfaceTriangulation mesh(shape, options.meshDeflectionFactor * step);
        if (options.model == ScanModel::UniformRandom) {
            s = uniformRandom(mesh, options);
        } else if (options.model == ScanModel::DensityGradient) {
            s = densityGradient(mesh, options);
        } else {
            result.views =
                viewsFor(options, options.model == ScanModel::ScanLines ? 1 : options.viewCount);
            if (options.model == ScanModel::ScanLines) {
                result.views.resize(1);
            }
            s = scanLines(mesh, result.views, options, result.rowStep);
            if (options.model == ScanModel::MergedViews && options.misregistration > 0.0) {
                misregister(s, static_cast<int>(result.views.size()), boxOf(mesh),
                            options.misregistration * result.rowStep,
                            stageSeed(options.seed, MisregistrationStage));
            }
        }
    }
    if (s.points.size() < 2) {
        throw std::runtime_error("The scan of the shape gave fewer than two points.");
    }
    PointMatrix clean(static_cast<Eigen::Index>(s.points.size()), 3);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        clean.row(static_cast<Eigen::Index>(i)) = s.points[i].transpose();
    }
    result.spacing = meanNearestSpacing(clean);

    result.holes = cutHoles(s, options, result.views, result.spacing);
    addNoise(s, options.tangentialJitter * result.spacing, options.normalNoise * result.spacing,
             stageSeed(options.seed, NoiseStage));
    result.outlier = addOutliers(
        s, options.outlierShare, options.outlierMinDistance * result.spacing,
        options.outlierMaxDistance * result.spacing, stageSeed(options.seed, OutlierStage));

    const Eigen::Index rows = static_cast<Eigen::Index>(s.points.size());
    result.points.resize(rows, 3);
    result.normals.resize(rows, 3);
    for (Eigen::Index i = 0; i < rows; ++i) {
        result.points.row(i) = s.points[static_cast<std::size_t>(i)].transpose();
        result.normals.row(i) = s.normals[static_cast<std::size_t>(i)].transpose();
    }
    result.view = std::move(s.view);
    return result;
}

std::vector<TypedPolyline> truthCoveredBy(const std::vector<TypedPolyline>& truth,
                                          const PointMatrix& P, double distance)
{
    if (!(distance > 0.0) || !std::isfinite(distance)) {
        throw std::invalid_argument("The covering distance must be a positive length.");
    }
    PointGrid grid(distance);
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
        grid.insert(P.row(i).transpose(), static_cast<int>(i));
    }
    std::vector<TypedPolyline> covered;
    for (const TypedPolyline& line : truth) {
        const Eigen::Index n = line.points.rows();
        std::vector<char> seen(static_cast<std::size_t>(n));
        Eigen::Index firstUnseen = -1;
        for (Eigen::Index k = 0; k < n; ++k) {
            seen[static_cast<std::size_t>(k)] =
                grid.anyWithin(line.points.row(k).transpose(), distance) ? 1 : 0;
            if (!seen[static_cast<std::size_t>(k)] && firstUnseen < 0) {
                firstUnseen = k;
            }
        }
        if (firstUnseen < 0) {
            covered.push_back(line);
            continue;
        }
        // A closed line is walked from an unseen vertex round to it again, so that no run
        // of seen vertices wraps round its start.
        const Eigen::Index start = line.closed ? firstUnseen : 0;
        const Eigen::Index steps = line.closed ? n + 1 : n;
        std::vector<Eigen::Index> run;
        const auto flush = [&]() {
            if (run.size() >= 2) {
                TypedPolyline piece;
                piece.type = line.type;
                piece.angle = line.angle;
                piece.radius = line.radius;
                piece.points.resize(static_cast<Eigen::Index>(run.size()), 3);
                for (std::size_t r = 0; r < run.size(); ++r) {
                    piece.points.row(static_cast<Eigen::Index>(r)) = line.points.row(run[r]);
                }
                covered.push_back(std::move(piece));
            }
            run.clear();
        };
        for (Eigen::Index s = 0; s < steps; ++s) {
            const Eigen::Index k = (start + s) % n;
            if (seen[static_cast<std::size_t>(k)]) {
                run.push_back(k);
            } else {
                flush();
            }
        }
        flush();
    }
    return covered;
}

ScanOptions drawScanOptions(std::uint32_t seed, const ScanDrawRanges& r)
{
    if (!(r.minPoints > 1.0 && r.maxPoints >= r.minPoints) || r.noiseLevels.empty() ||
        r.maxViews < 2) {
        throw std::invalid_argument("The scan draw ranges need points above 1 (the largest "
                                    "last), a noise level and at least two views.");
    }
    Draws draws(stageSeed(seed, DrawStage));
    ScanOptions o;
    // Every value is drawn whatever the model, so that each has the same place in the stream.
    o.model = static_cast<ScanModel>(draws.integer(0, 4));
    o.points = std::round(std::exp(draws.uniform(std::log(r.minPoints), std::log(r.maxPoints))));
    o.normalNoise = r.noiseLevels[static_cast<std::size_t>(
        draws.integer(0, static_cast<int>(r.noiseLevels.size()) - 1))];
    o.tangentialJitter = draws.uniform(0.0, r.maxTangentialJitter);
    o.rowSpacingRatio = draws.uniform(r.minRowSpacingRatio, r.maxRowSpacingRatio);
    o.viewCount = draws.integer(2, r.maxViews);
    o.misregistration = draws.uniform(r.minMisregistration, r.maxMisregistration);
    o.densityRatio = r.densityRatio;
    const bool holes = draws.uniform() < r.holeProbability;
    const int holeCount = draws.integer(1, std::max(1, r.maxHoles));
    o.occlusionHoles = holes ? holeCount : 0;
    o.holeRadius = draws.uniform(r.minHoleRadius, r.maxHoleRadius);
    o.outlierShare = draws.uniform(0.0, r.maxOutlierShare);
    o.seed = stageSeed(seed, CloudSeedStage);
    return o;
}

} // namespace featurelines::bench
