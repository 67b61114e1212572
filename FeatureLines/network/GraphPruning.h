// SPDX-License-Identifier: LGPL-2.1-or-later
// The steps that cut the node graph: short branches (G_pruned_branches), bubbles, close
// junctions, short pieces, and the free ends no join reached. Internal to the network stage;
// each returns how many it cut (docs/design/network.md).
#pragma once

#include "FeatureLines/network/NodeGraph.h"

namespace featurelines::clustergraph {

/// G_pruned_branches: branches from a junction to a free end shorter than minLength are cut,
/// repeatedly, but a junction always keeps two branches.
int pruneShortBranches(Graph& g, double minLength);

/// Of two chains joining the same two junctions the longer is dropped when shorter than
/// maxLength, and so is a loop shorter than maxLength hanging at one junction.
int removeBubbles(Graph& g, double maxLength);

/// Junctions joined by a chain shorter than maxLength become one junction.
int mergeCloseJunctions(Graph& g, double maxLength);

/// Connected pieces shorter than minLength are dropped, and pieces without a cycle shorter
/// than minOpenLength.
int dropShortComponents(Graph& g, double minLength, double minOpenLength);

/// Free ends are removed with their branch up to the first junction (an open piece ending in
/// nothing on both sides goes whole) when the branch or piece is no longer than maxLength.
int removeFreeEnds(Graph& g, double maxLength);

} // namespace featurelines::clustergraph
