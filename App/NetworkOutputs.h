// SPDX-License-Identifier: LGPL-2.1-or-later
// The fitted line network (FeatureLines/curves/CurveNetwork.h) of a result, made into what
// FreeCAD shows (NetworkOutputs, ExtractionOutputs.h): one wire per cleaned line on the
// network's edges (lines, arcs, circles, B-splines) that share one vertex per junction, every
// patch's closed border wires on those same edges, and in words what could not be fitted or
// closed. The shapes come from CadExport/CurveShapes.h, which featurelines-cad writes too.
#pragma once

#include <Base/Matrix.h>
#include <gp_Trsf.hxx>

#include <vector>

#include "ExtractionOutputs.h"

namespace FeatureLines {

/// The placement `toWorld` (a rigid motion) as OpenCASCADE's transformation.
gp_Trsf toTrsf(const Base::Matrix4D& toWorld);

/// The network of the cleaned lines (the edges of the lines `lines` keeps), in world
/// coordinates, and the patches' borders on it. P  #P by 3 the cloud `result` came from, in its
/// own coordinates (the patch ids are per row). When the core cannot fit the network at all,
/// every line is its polyline, said in curveProblems. cornerAngle: CurveFitOptions::cornerAngle.
NetworkOutputs makeNetworkOutputs(const featurelines::ExtractionResult& result,
                                  const featurelines::PointMatrix& P,
                                  const std::vector<CleanedLine>& lines,
                                  const Base::Matrix4D& toWorld, double cornerAngle = 180.0);

} // namespace FeatureLines
