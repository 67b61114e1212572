// SPDX-License-Identifier: LGPL-2.1-or-later
// How the fitted patch surfaces (Surfaces/PatchSurfaces.h) sit on the true B-rep (issue 21):
// distances from the sewn shape to the truth and back, the true faces recovered with their
// kind, and whether the faces close into a valid solid.
#pragma once

#include <TopoDS_Shape.hxx>

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "PatchSurfaces.h"

namespace featurelines::bench {

struct SurfaceQuality
{
    /// Patches handed in, and those that got a face; faces of each SurfaceKind.
    int patches = 0;
    int faces = 0;
    std::array<int, 6> kinds{};
    /// Of the B-spline faces, those made as OpenCASCADE's plate (PatchFace::plate).
    int plates = 0;
    /// The faces closed into one solid, and BRepCheck finds it valid.
    bool solid = false;
    bool valid = false;
    /// Spacings: from points on the fitted faces to the true shape (mean, 95th percentile),
    /// and from points on the true faces that the cloud saw to the fitted faces. NaN without
    /// faces.
    double toTruthMean = 0.0;
    double toTruthP95 = 0.0;
    double fromTruthMean = 0.0;
    double fromTruthP95 = 0.0;
    /// True faces the cloud saw (a point within 2 spacings of their sample), and those whose
    /// samples lie mostly within a spacing of fitted faces of their own kind (a B-spline, or
    /// any kind OpenCASCADE does not name, counts as "bspline").
    int trueFaces = 0;
    int rightKind = 0;
    /// Seconds to fit and sew the surfaces.
    double seconds = 0.0;
};

/// A run's surfaces over its parts: what the surfaces' floors (--surface-floor) judge.
struct SurfaceTotals
{
    int parts = 0;
    /// Parts whose faces closed into one valid solid.
    int validSolids = 0;
    int trueFaces = 0;
    int rightKind = 0;
    /// The mean over the parts with faces of their mean distance to the truth (spacings);
    /// NaN without faces.
    double toTruthMean = std::numeric_limits<double>::quiet_NaN();

    /// rightKind / trueFaces; NaN without true faces.
    double rightKindShare() const;
};
SurfaceTotals surfaceTotals(const std::vector<SurfaceQuality>& parts);

/// The least acceptable share of true faces of their kind and count of valid solids, and the
/// largest acceptable mean distance to the truth (spacings); NaN: not judged.
struct SurfaceFloors
{
    double kinds = std::numeric_limits<double>::quiet_NaN();
    double solids = std::numeric_limits<double>::quiet_NaN();
    double toTruth = std::numeric_limits<double>::quiet_NaN();
};

/// "kinds=0.49,solids=5,truth=0.07" (any subset). Throws std::invalid_argument otherwise.
SurfaceFloors parseSurfaceFloors(const std::string& text);

/// One sentence per measure past its floor (a NaN measure is past it), empty when all pass.
std::vector<std::string> surfaceFloorFailures(const SurfaceTotals& totals,
                                              const SurfaceFloors& floors);

/// Scores `surfaces` (fitted to `cloud`, a sampling of `truth`, whose mean spacing is `spacing`)
/// against the true shape: up to `samples` points each way.
SurfaceQuality measureSurfaces(const surfaces::PatchSurfaces& surfaces, const TopoDS_Shape& truth,
                               const PointMatrix& cloud, double spacing, int samples = 400);

} // namespace featurelines::bench
