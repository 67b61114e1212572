// SPDX-License-Identifier: LGPL-2.1-or-later
// Seeded point samplings of shapes whose normals and mean curvature are known exactly, for the
// tests and the benchmarks. Every sampler lays a grid of the given spacing over each face's
// parameter domain and jitters every sample by up to +-0.2 spacing (uniform, std::mt19937 with
// the given seed), which looks like a scan: roughly uniform density, no exact lattice. Every
// shape is centred at the origin. Lengths are in any one unit; spacing is measured on the
// surface.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "FeatureLines/PointCloud.h"

namespace featurelines::shapes {

struct Sample
{
    /// P  #P by 3 positions.
    PointMatrix points;
    /// N  #P by 3 true outward unit normals.
    NormalMatrix normals;
    /// H  #P true unsigned mean curvature |H| (1 / length unit).
    Eigen::VectorXd meanCurvature;
    /// #P which face or patch type a point was sampled from (meaning given per shape).
    std::vector<int> part;

    Eigen::Index size() const { return points.rows(); }
};

/// The square [-size/2, size/2]^2 of the plane z = 0; normals +z, |H| = 0, part 0.
Sample plane(double size, double spacing, unsigned seed);

/// Sphere of the given radius; radial normals, |H| = 1/radius, part 0. Sampled along circles of
/// latitude spaced `spacing` apart, each holding as many points as its length allows.
Sample sphere(double radius, double spacing, unsigned seed);

/// Open cylinder (no caps) around the z axis, z in [-height/2, height/2]; radial normals,
/// |H| = 1/(2 radius), part 0.
Sample cylinder(double radius, double height, double spacing, unsigned seed);

/// Surface of the cube [-edge/2, edge/2]^3; |H| = 0. part is the face: 0 +x, 1 -x, 2 +y, 3 -y,
/// 4 +z, 5 -z. No sample lies on an edge (the grid is of cell centres), so every point has
/// the normal of its face.
Sample cube(double edge, double spacing, unsigned seed);

/// The cube [-edge/2, edge/2]^3 with every edge and corner rounded to `radius`
/// (0 < radius < edge/2): six flat squares of side edge - 2 radius, twelve quarter cylinders
/// (fillets) and eight eighth spheres (corners), all tangent-continuous. part: 0 flat
/// (|H| = 0), 1 cylindrical fillet (|H| = 1/(2 radius)), 2 spherical corner (|H| = 1/radius).
Sample roundedCube(double edge, double radius, double spacing, unsigned seed);

/// Surface of the convex polyhedron {x : n . x <= d for every plane (n, d)} (rows n_x, n_y,
/// n_z, d; n need not be unit): each plane that bounds it gives one face, sampled on a jittered
/// grid laid in its plane; |H| = 0, part is the plane's index. A plane that does not touch the
/// polyhedron gives no sample. Not centred: the planes place it.
Sample convexPolyhedron(const std::vector<Eigen::Vector4d>& planes, double spacing, unsigned seed);

/// The cube [-edge/2, edge/2]^3 with all twelve edges chamfered, each face cut back by
/// `chamfer` (0 < chamfer < edge/2), and every corner cut by the triangle through the ends of
/// its three chamfers (what an equal-distance chamfer of all edges gives in a CAD system).
/// Sharp edges only: 24 of 45 degrees between faces and chamfers, 24 of 35.26 degrees between
/// chamfers and corner triangles. part: 0-5 faces (+x, -x, +y, -y, +z, -z), 6-17 chamfers,
/// 18-25 corners.
Sample chamferedCube(double edge, double chamfer, double spacing, unsigned seed);

/// Right prism over the convex polygon `section` (vertices counter-clockwise in the xy plane),
/// z in [-height/2, height/2]. part k is the side from vertex k to k + 1; then the top (+z) and
/// bottom caps.
Sample prism(const std::vector<Eigen::Vector2d>& section, double height, double spacing,
             unsigned seed);

/// Moves every point along its true normal by a Gaussian offset of standard deviation sigma
/// (scanner noise across the surface). Normals and curvature stay the true ones.
void addNormalNoise(Sample& s, double sigma, unsigned seed);

} // namespace featurelines::shapes
