// SPDX-License-Identifier: LGPL-2.1-or-later
// Edits of a line network after the cluster graph: free ends anchored on other lines, lines
// dropped (their junctions mended), dangling spurs pruned, short open pieces dropped.
// Design: docs/design/smooth-edges.md, "Editing the line network".
#pragma once

#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

/// Sec. 1.2: every free end (no junction) of an open line that lies within `reach` of an anchor
/// line, and points towards it (within maxAngleDegrees of the line's direction at that end), is
/// extended to the closest point of the anchor lines. Returns per line two flags, start and end:
/// anchored.
std::vector<char> anchorLineEnds(LineNetwork& network, const std::vector<Polyline>& anchors,
                                 double reach, double maxAngleDegrees);

/// Removes the lines flagged in `drop`; a junction left with two line ends joins them into one
/// line (a loop when both are the same line's), left with one, that end is on nothing.
/// Junctions are renumbered; `anchored` (two flags per line, see anchorLineEnds; empty: none)
/// follows the lines.
void dropLines(LineNetwork& network, std::vector<char>& anchored, const std::vector<char>& drop);

/// Removes the lines shorter than minLength that run from a junction to an end on nothing
/// (neither a junction nor, by the `anchored` flags, an anchor line): spurs noise grows off a
/// feature line. A junction left with two line ends joins them into one line (a loop when
/// both are the same line's); left with one, that end is on nothing. Repeated until no such
/// spur is left. `anchored` follows the lines. Returns the number of lines removed.
int pruneDanglingLines(LineNetwork& network, std::vector<char>& anchored, double minLength);

/// Drops the pieces of lines (lines joined through junctions) that have no cycle, are shorter
/// than minLength in total and keep an end on nothing (neither a junction nor, by the
/// `anchored` flags of anchorLineEnds, an anchor line): noise gathered along a surface rather
/// than a feature. Junctions are renumbered. Returns the number of lines dropped.
int dropOpenPieces(LineNetwork& network, const std::vector<char>& anchored, double minLength);

} // namespace featurelines
