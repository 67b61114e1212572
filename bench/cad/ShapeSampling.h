// SPDX-License-Identifier: LGPL-2.1-or-later
// Scan-like point clouds of a B-rep, and the B-rep's edges as typed ground-truth polylines.
#pragma once

#include <cstdint>
#include <vector>

#include <TopoDS_Shape.hxx>

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
