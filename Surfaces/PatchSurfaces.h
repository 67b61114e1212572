// SPDX-License-Identifier: LGPL-2.1-or-later
// From lines to surfaces (issue 21): every patch with a closed border gets its fitted surface
// (SurfaceFit.h) as an OpenCASCADE face trimmed by the border's wires (the network's own edges,
// CadExport/CurveShapes.h); the faces are sewn along their shared edges into shells, a solid
// where they close. OpenCASCADE and the core, no FreeCAD. Design: docs/design/surfaces.md.
#pragma once

#include <Geom_Surface.hxx>
#include <Standard_Handle.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "CurveShapes.h"
#include "FeatureLines/Extraction.h"
#include "FeatureLines/curves/CurveNetwork.h"
#include "SurfaceFit.h"

namespace featurelines::surfaces {

/// How a patch that no plane, sphere, cylinder, cone or torus fits gets its B-spline face.
/// Measured on the benchmark's parts (docs/ACCURACY.md, "B-spline faces"): the plate lies
/// farther from the true faces wherever both are made, and makes no face the height field
/// does not; it stays for that comparison.
enum class BSplineFace
{
    /// The height field over the patch's plane trimmed by the border (fitSurface's).
    HeightField,
    /// OpenCASCADE's plate (BRepFill_Filling) through the border's edges and up to 300 of
    /// the points: a face on the network's own edges.
    Plate,
};

struct PatchSurfaceOptions
{
    SurfaceFitOptions fit;
    BSplineFace bspline = BSplineFace::HeightField;
    /// Sewing tolerance, x spacing: edges of two faces this close are one (1).
    double sewingTolerance = 1.0;
};

/// One patch's surface and face.
struct PatchFace
{
    int patch = -1;
    int points = 0;
    FittedSurface surface;
    /// Null when the patch got no face; `problem` says why. After sewPatchFaces(), the face as
    /// it is in the sewn shape (its orientation there).
    TopoDS_Face face;
    std::string problem;
    /// A B-spline face made as OpenCASCADE's plate (BSplineFace::Plate), not the height field
    /// `surface` describes; its RMS and largest deviations are then the plate's (the points'
    /// distances along its normal, by projection).
    bool plate = false;
    /// Per point of the patch, in the order given: its signed distance from the surface
    /// along the surface's normal (a B-spline's by projection; surface.rmsDeviation and
    /// maxDeviation then the same measure's), positive on the side the face's normal points to
    /// (out of the solid where the faces close into one); empty without a face.
    std::vector<double> deviations;
};

struct PatchSurfaces
{
    /// One per patch border handed in, in the same order.
    std::vector<PatchFace> faces;
    /// The sewn faces: a solid where they close, else a shell or a compound of shells and faces.
    TopoDS_Shape shape;
    /// The shape is one closed, valid solid (BRepCheck_Analyzer).
    bool solid = false;
    bool valid = false;
    /// The largest tolerance of the shape's edges and vertices after sewing (model units).
    double tolerance = 0.0;
    /// One line per patch left out, and per sewing problem.
    std::vector<std::string> problems;
};

/// The OpenCASCADE surface of a fitted one (a B-spline height field as a Geom_BSplineSurface
/// with the same poles). Throws std::invalid_argument for a surface that makes none.
Handle(Geom_Surface) makeSurface(const FittedSurface& surface);

/// One patch's face: its surface fitted to `points` (at least 6), placed (seam) and trimmed by
/// its closed border `wires` (the outer first, then the holes; a band all round a cylinder,
/// cone or torus between two loops on its circles is made on those circles). `spacing` is the
/// cloud's sampling spacing, `noise` the points' scatter about their surface (model units;
/// negative: estimated from the points, estimatePatchNoise).
/// Never throws for a bad patch: the face is then null and `problem` says why.
PatchFace fitPatchFace(int patch, const PointMatrix& points, const std::vector<TopoDS_Wire>& wires,
                       double spacing, double noise, const PatchSurfaceOptions& options = {});

/// The faces sewn at `tolerance` (model units) into a shell, a solid where it closes; the faces
/// without a shape are listed in `problems`.
PatchSurfaces sewPatchFaces(std::vector<PatchFace> faces, double tolerance);

/// The surfaces of the patches of `borders` (patchBorders() of the network whose shapes are
/// `shapes`), each fitted to its points (rows of P with result.patch equal to its id) and
/// trimmed by its border wires (fitPatchFace), then sewn at options.sewingTolerance spacings.
/// `noise` is the scatter of the points about their surfaces (model units), e.g. medianNoise.
/// A patch whose border is open, whose points make no surface or whose face OpenCASCADE cannot
/// build is left out and listed in `problems`.
PatchSurfaces fitPatchSurfaces(const PointMatrix& P, const ExtractionResult& result,
                               const std::vector<PatchBorder>& borders,
                               const cad::NetworkShapes& shapes, double noise,
                               const PatchSurfaceOptions& options = {});

/// The scatter of an extraction's points about their surfaces, in model units: the median of its
/// regions' noise estimates (RegionReport::noise, in spacings) times the spacing; 0 without
/// regions.
double medianNoise(const ExtractionResult& result);

/// The whole step from an extraction of P: its lines fitted as curves (fitCurveNetwork), the
/// network's shapes (a curve straying more than 2 spacings from its points drawn as its
/// polyline, as the FreeCAD module and featurelines-cad do), the patches' borders, then
/// fitPatchSurfaces() with the extraction's median noise.
PatchSurfaces surfacesOfExtraction(const PointMatrix& P, const ExtractionResult& result,
                                   const CurveFitOptions& fit = {},
                                   const PatchSurfaceOptions& options = {});

} // namespace featurelines::surfaces
