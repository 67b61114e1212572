// SPDX-License-Identifier: LGPL-2.1-or-later
// Scan-like point clouds of a B-rep, and the B-rep's edges as typed ground-truth polylines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <Eigen/Core>

#include "FeatureLines/PointCloud.h"
#include "LineScore.h"

namespace featurelines::bench {

struct SamplingOptions
{
    /// Poisson-disk radius r (model units, > 0): no two samples are closer than r. The mean
    /// nearest-neighbour spacing comes out near 1.1 to 1.3 r.
    double radius = 1.0;
    /// Uniform random candidates drawn per expected sample before the Poisson-disk thinning;
    /// 10 leaves few holes larger than r (a near-maximal sampling, as a scanner's even grid).
    double oversampling = 10.0;
    /// Chordal deflection of the triangulation used to draw candidates by area, as a multiple
    /// of r. Candidates are moved onto the exact surface afterwards, so this only biases the
    /// density, by about the relative area error.
    double meshDeflectionFactor = 0.1;
    /// Seed of the candidate draws.
    std::uint32_t seed = 1;
};

struct SampledCloud
{
    /// P  #P by 3 points on the faces of the shape.
    PointMatrix points;
    /// N  #P by 3 outward unit normals of the surface at the points (face orientation
    /// respected).
    NormalMatrix normals;
};

/// A fine triangulation of a shape's faces whose nodes carry their face's (u, v): points are
/// drawn on its triangles (by area, or where a ray meets them) and then placed exactly on the
/// face's surface at the interpolated (u, v). Used by sampleShape and by the scanner models
/// (ScanSampling.h). Meshing stores the triangulation in the shape, as BRepMesh does.
class SurfaceTriangulation
{
public:
    struct Triangle
    {
        int face;              // index of the face, for place()
        Eigen::Vector3d p[3];  // corners in space (location applied)
        Eigen::Vector2d uv[3]; // corners in the face's (u, v)
    };

    /// Triangulates every face of `shape` with chordal deflection `deflection` (model units).
    /// Throws std::runtime_error when the triangulation fails or is empty.
    SurfaceTriangulation(const TopoDS_Shape& shape, double deflection);

    /// The triangles of positive area, every face's in turn.
    const std::vector<Triangle>& triangles() const { return triangleList; }
    /// Total area of the triangles (model units squared).
    double area() const { return cumulativeArea.back(); }
    /// Index of the triangle in which the cumulative area of the triangles reaches `a` (0 to
    /// area()): a uniform `a` picks triangles by area.
    std::size_t triangleAtArea(double a) const;
    /// Point and outward normal (face orientation respected) of the exact surface at the
    /// (u, v) interpolated with barycentric weights (b0, b1, b2) in triangle t; false where the
    /// normal is undefined (a pole of a sphere, the apex of a cone).
    bool place(std::size_t t, double b0, double b1, double b2, Eigen::Vector3d& point,
               Eigen::Vector3d& normal) const;

private:
    std::vector<TopoDS_Face> faces;
    std::vector<BRepAdaptor_Surface> surfaces;
    std::vector<Triangle> triangleList;
    std::vector<double> cumulativeArea;
};

/// Total area of the faces of `shape` (model units squared).
double shapeArea(const TopoDS_Shape& shape);

/// Length of the diagonal of the axis-aligned box around `shape`.
double boundingDiagonal(const TopoDS_Shape& shape);

/// The Poisson-disk radius that gives about `points` samples on a surface of `area` with the
/// default oversampling (about 0.57 / r^2 samples per unit area).
double radiusForPointCount(double area, double points);

/// Samples every face of `shape`: candidates uniform by area on a fine triangulation,
/// thinned greedily to a Poisson-disk set of radius options.radius (hash grid), then each kept
/// candidate is placed exactly on its face's surface by evaluating the surface at the
/// candidate's interpolated (u, v), with the surface normal there. Same options, same cloud.
/// Throws std::invalid_argument when the shape has no face or the radius is not positive, and
/// std::runtime_error when the triangulation fails.
SampledCloud sampleShape(const TopoDS_Shape& shape, const SamplingOptions& options);

/// Moves every point along its normal by a Gaussian offset of standard deviation `sigma`
/// (model units, >= 0), as scanner noise along the line of sight. Seeded.
void addNormalNoise(SampledCloud& cloud, double sigma, std::uint32_t seed);

/// Mean distance from each point to its nearest other point at a distance above zero, the
/// definition of the core library's meanSpacing (FeatureLines/neighbourhoods/Neighbours.h).
double meanNearestSpacing(const PointMatrix& P);

struct TruthOptions
{
    /// Arc-length step of the samples along each edge (model units, > 0); the benchmark uses
    /// half the point spacing.
    double step = 0.5;
    /// An edge between two faces is sharp when the angle between the face normals across it
    /// exceeds this (degrees), at the median of the samples along the edge. Demarsin 2008,
    /// Sec. 1: a sharp edge is a tangent discontinuity; 5 degrees keeps the tessellation-level
    /// tangency errors of fillets well below and any designed crease above.
    double sharpAngleDegrees = 5.0;
    /// A tangent edge is smooth when the principal curvatures on its two sides differ by more
    /// than this share of the largest of them (a curvature discontinuity, Sec. 1), and flat
    /// on both sides it is no edge at all.
    double curvatureRelativeTolerance = 0.05;
    /// Samples along each edge used to decide its type.
    int classificationSamples = 15;
};

/// Every feature edge of the shape's B-rep as a typed polyline sampled at options.step:
/// an edge with one adjacent face is "boundary"; seam and degenerate edges are skipped; an
/// edge between two faces is "sharp" (normals differ), "smooth" (tangent, curvature differs)
/// or skipped (same surface continued); an edge of more than two faces is "sharp".
std::vector<TypedPolyline> truthEdges(const TopoDS_Shape& shape, const TruthOptions& options);

} // namespace featurelines::bench
