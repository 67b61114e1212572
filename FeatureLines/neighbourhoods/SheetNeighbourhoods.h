// SPDX-License-Identifier: LGPL-2.1-or-later
// Neighbourhoods kept to one sheet of a thin wall: where a point's k nearest neighbours reach
// the wall's other side, those neighbours are exchanged for the nearest points of its own
// sheet. Design: docs/design/neighbourhoods.md ("Thin walls").
#pragma once

#include <vector>

#include "FeatureLines/neighbourhoods/Neighbours.h"

namespace featurelines {

/// The rows of N whose neighbourhood reached another sheet and was rebuilt, ascending; their
/// normals are to be estimated again (pcaNormalsOfRows).
///
/// Every point gets a local plane: first the least-squares plane of it and its
/// options.fitPoints nearest neighbours, fitted again without the points whose distance to the
/// first plane is an outlier (over 3 x 1.48 their median, and over half the least gap); then,
/// as the other sheet can tilt or turn that plane, the plane read again wherever the first
/// planes about the point disagree or a neighbour lies off the point's: its normal the dominant
/// one of the first planes' normals of the point and its k neighbours, through the mean of the
/// point's own group of offsets along it (the offsets of the point and its k neighbours split in
/// two where their means lie options.minWall x spacing and 3.5 pooled deviations apart). Its gap
/// is the larger of options.minGap x spacing and options.noiseGap x its group's deviation, the
/// lower quartile over the point and its fitPoints nearest. Two points p and q are on opposite
/// sheets when their planes turn by at most options.maxTurnDegrees and each lies at least the
/// other's gap from the other's plane. Across a crease the planes turn; on a shallow crease the
/// offsets stay below the gap; along one noisy sheet the gap grows with the noise. A row with
/// options.minAcross neighbours on another sheet, all on one side, takes the k nearest points
/// among its neighbours and their neighbours that are on its own sheet (the k nearest of the
/// row's own when fewer are found), sorted by distance.
///   P        #P by 3 points; N their k nearest neighbours, changed in place
///   spacing  the cloud's sampling spacing (samplingSpacing)
/// Throws std::invalid_argument when N does not match P or the options are out of range.
std::vector<int> separateSheets(const PointMatrix& P, Neighbourhoods& N, double spacing,
                                const SheetOptions& options = {}, int threads = 0);

} // namespace featurelines
