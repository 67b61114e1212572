// SPDX-License-Identifier: LGPL-2.1-or-later
// The surface of one patch (issue 21): a plane, sphere, cylinder, cone or torus where the patch's
// points fit one within a noise-aware tolerance (CAD parts are mostly such faces), else a cubic B-spline
// height field over the patch's plane. Plain data and Eigen: the OpenCASCADE surfaces are made
// from it in PatchSurfaces.h. Design: docs/design/surfaces.md.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "FeatureLines/PointCloud.h"

namespace featurelines::surfaces {

enum class SurfaceKind
{
    Plane,
    Sphere,
    Cylinder,
    Cone,
    Torus,
    BSpline,
};

/// "plane", "sphere", "cylinder", "cone", "torus", "bspline".
const char* surfaceKindName(SurfaceKind kind);

struct FittedSurface
{
    SurfaceKind kind = SurfaceKind::Plane;
    /// Plane: a point on it (the points' centroid) and its unit normal. Sphere: the centre.
    /// Cylinder: a point on the axis (the points' centroid projected onto it) and the unit axis.
    /// BSpline: the origin and unit normal of the plane it is a height field over.
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    /// Sphere, Cylinder: the radius. Cone: the radius at `origin` (a point on the axis), growing
    /// by tan(halfAngle) per unit along `axis`. Torus: the major radius (centre to the tube's
    /// centre line) about `origin`, the centre.
    double radius = 0.0;
    /// Cone: radians, the angle between the axis and the cone's lines (negative: narrowing
    /// along `axis`).
    double halfAngle = 0.0;
    /// Torus: the tube's radius.
    double minorRadius = 0.0;
    /// Sphere, Cylinder, Cone, Torus: where the parametrisation starts (its seam), a direction from the
    /// axis; zero: any. fitPatchSurfaces() puts the seam through a vertex of the border.
    Eigen::Vector3d seam = Eigen::Vector3d::Zero();
    /// BSpline: the height h(u, v) along `axis` over the plane, u along `uDirection` and v along
    /// axis x uDirection, both in [uMin, uMax] x [vMin, vMax]: a clamped cubic tensor B-spline
    /// with uniform knots, poles heights[i + j * uPoles] at the Greville abscissae.
    Eigen::Vector3d uDirection = Eigen::Vector3d::UnitX();
    double uMin = 0.0;
    double uMax = 0.0;
    double vMin = 0.0;
    double vMax = 0.0;
    int uPoles = 0;
    int vPoles = 0;
    Eigen::VectorXd heights;
    /// The points' distances to the surface: root mean square and largest (model units).
    double rmsDeviation = 0.0;
    double maxDeviation = 0.0;
    /// The tolerance the kind was accepted at (model units).
    double tolerance = 0.0;
};

struct SurfaceFitOptions
{
    /// A kind is accepted when the points' RMS distance to it is within this many spacings ...
    double tolerance = 0.2;
    /// ... or, where larger, this multiple of the noise (the points' scatter about the surface
    /// the caller measured, e.g. RegionReport::noise) (1.5).
    double noiseFactor = 1.5;
    /// A sphere or cylinder wider than this multiple of the patch's extent is a plane's
    /// approximation, not a surface of its own (20).
    double maxRadiusRatio = 20.0;
    /// The sphere, cylinder, cone and torus are fitted to at most this many of the points,
    /// evenly picked, and measured on all (20000).
    int maxFitPoints = 20000;
    /// A plane, sphere, cylinder, cone or torus is also refused when the points' deviation
    /// averaged over each one's systematicK nearest (on at most systematicPoints of them)
    /// has an RMS above this many spacings, with the share of the noise such an average
    /// leaves added (0.1; 0: no such test): a small patch of several surfaces fits one sphere
    /// within the noise, but leaves it by a like amount over whole stretches.
    double systematicTolerance = 0.1;
    int systematicK = 16;
    Eigen::Index systematicPoints = 4000;
    /// BSpline: control points per direction, at most (12), and about one per this many
    /// spacings of the patch's extent (4).
    int maxPoles = 12;
    double spacingsPerPole = 4.0;
    /// BSpline: weight of the smoothness term (second differences of the poles) against the
    /// points' residuals (1e-3).
    double smoothing = 1e-3;
};

/// The surface of a patch: points P  #P by 3 (at least 6, not all on a line), `spacing` the
/// cloud's sampling spacing, `noise` the scatter of the points about their surface (model
/// units; 0 when unknown). A plane when its RMS deviation is within the tolerance; else of the
/// sphere, cylinder, cone and torus within it, the first (the fewest parameters) whose RMS
/// deviation is within 1.5 times the least of theirs; else the B-spline height field. Throws
/// std::invalid_argument naming the problem for too few points, non-finite input or a
/// non-positive spacing.
FittedSurface fitSurface(const PointMatrix& P, double spacing, double noise = 0.0,
                         const SurfaceFitOptions& options = {});

/// The scatter of the points about their surface (model units): the core's estimateNoise (the
/// median distance of a point from the quadric of its 16 nearest, about 0.9 sigma of normal
/// noise) over at most 2000 of them, divided by 0.9; 0 for fewer than 8 points.
double estimatePatchNoise(const PointMatrix& P, double spacing);

/// The distance from x to the fitted surface (the B-spline's: along its axis, the height
/// field's vertical distance).
double surfaceDistance(const FittedSurface& surface, const Eigen::Vector3d& x);

/// surfaceDistance with a sign: positive on the side the normal of makeSurface()'s surface
/// points to (a plane's and a height field's `axis`; away from a sphere's centre, a cylinder's
/// or cone's axis, a torus's centre line).
double signedSurfaceDistance(const FittedSurface& surface, const Eigen::Vector3d& x);

/// Each kind fitted alone (no B-spline), for tests and the report. The surfaces of revolution
/// start from the axis the points' normals (PCA over their 12 nearest) meet best: every normal
/// of such a surface meets its axis (Pottmann and Randrup 1998), a linear condition on the
/// axis's Pluecker coordinates; their profile in the half-plane through the axis is then a
/// line (cylinder, cone) or a circle (torus); all is refined by Levenberg-Marquardt on the
/// points' distances.
FittedSurface fitPlane(const PointMatrix& P);
FittedSurface fitSphere(const PointMatrix& P);
FittedSurface fitCylinder(const PointMatrix& P);
FittedSurface fitCone(const PointMatrix& P);
FittedSurface fitTorus(const PointMatrix& P);

} // namespace featurelines::surfaces
