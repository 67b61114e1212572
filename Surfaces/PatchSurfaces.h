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

struct PatchSurfaceOptions
{
    SurfaceFitOptions fit;
    /// Sewing tolerance, x spacing: edges of two faces this close are one (1).
    double sewingTolerance = 1.0;
};

/// One patch's surface and face.
struct PatchFace
{
    int patch = -1;
    int points = 0;
    FittedSurface surface;
    /// Null when the patch got no face; `problem` says why.
    TopoDS_Face face;
    std::string problem;
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

/// The surfaces of the patches of `borders` (patchBorders() of `network`, whose shapes are
/// `shapes`), each fitted to its
/// points (rows of P with result.patch equal to its id), trimmed by its border wires, then
/// sewn. `noise` is the scatter of the points about their surfaces (model units), e.g. the
/// median RegionReport::noise. A patch whose border is open, whose points make no surface or
/// whose face OpenCASCADE cannot build is left out and listed in `problems`.
PatchSurfaces fitPatchSurfaces(const PointMatrix& P, const ExtractionResult& result,
                               const CurveNetwork& network,
                               const std::vector<PatchBorder>& borders,
                               const cad::NetworkShapes& shapes, double noise,
                               const PatchSurfaceOptions& options = {});

/// The scatter of an extraction's points about their surfaces: the median of its regions'
/// noise estimates (RegionReport::noise), 0 without regions.
double medianNoise(const ExtractionResult& result);

/// The whole step from an extraction of P: its lines fitted as curves (fitCurveNetwork), the
/// network's shapes (a curve straying more than 2 spacings from its points drawn as its
/// polyline, as the FreeCAD module and featurelines-cad do), the patches' borders, then
/// fitPatchSurfaces() with the extraction's median noise.
PatchSurfaces surfacesOfExtraction(const PointMatrix& P, const ExtractionResult& result,
                                   const CurveFitOptions& fit = {},
                                   const PatchSurfaceOptions& options = {});

} // namespace featurelines::surfaces
