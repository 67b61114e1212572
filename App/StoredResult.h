// SPDX-License-Identifier: LGPL-2.1-or-later
// What an extraction holds from its last run, checked before anything trusts it: the per-point
// lists (PointRegion, PointPatch, PointLabel, PointCurvature) have one value per point of the
// source cloud, the line counts match the wires, the paired lists are paired. A document read
// back from a damaged or hand-edited file, or restored while an embedded file failed to read,
// can break any of these; a failed or pending recompute leaves results of an earlier run.
#pragma once

#include <string>

namespace FeatureLines {

class Extraction;

/// The first way the stored result contradicts itself, or its source cloud's point count when
/// `againstSource` (and the Source is a Points object); "" when it is consistent. The message
/// names the property, e.g. "PointRegion holds 990 values but PointPatch 1000".
std::string storedResultMismatch(const Extraction& extraction, bool againstSource = true);

/// Throws std::invalid_argument (a ValueError in Python) naming `function`, the object and the
/// problem when the stored result cannot be used: the last recompute failed, the object or its
/// source changed since, the source is gone, nothing was computed yet, or storedResultMismatch.
void requireCurrentResult(const Extraction& extraction, const std::string& function);

} // namespace FeatureLines
