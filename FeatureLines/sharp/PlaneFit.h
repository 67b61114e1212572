// SPDX-License-Identifier: LGPL-2.1-or-later
// Planes fitted to the points of one face, and where two of them meet: shared by the crease
// placement and the typing by profile of the sharp stage.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace featurelines {

struct Plane
{
    Eigen::Vector3d normal;
    double offset; // normal . x = offset
};

/// Least-squares plane through `points` (principal component analysis), refitted once
/// without the points farther than 2.5 times the RMS distance (points of the other face that
/// the segmentation gave to this one) when at least minPoints remain.
Plane fitPlane(const std::vector<Eigen::Vector3d>& points, int minPoints);

/// The plane of one face read from its points' normals, where noise makes the points' own
/// least-squares plane tilt: the normal is the dominant direction of the points' (unoriented)
/// normals, again over those within maxTurnDegrees of it (the points of another face that the
/// segmentation gave to this one turn by the crease), and the offset the median of the kept
/// points' offsets along it. fitPlane(points) when fewer than minPoints are kept, and where the
/// points' RMS distance to their own plane is under tan(3 degrees) of their spread across its
/// smaller axis: there noise cannot tilt that plane, and it is exact on a clean face, whose
/// normals near the edge still lean a little.
Plane fitPlaneByNormals(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<Eigen::Vector3d>& normals, int minPoints,
                        double maxTurnDegrees = 10.0);

/// The point of the line {x : a.x = a.offset, b.x = b.offset} closest to c; the planes must not
/// be parallel.
Eigen::Vector3d closestOnIntersection(const Plane& a, const Plane& b, const Eigen::Vector3d& c);

} // namespace featurelines
