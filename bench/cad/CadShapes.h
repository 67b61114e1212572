// SPDX-License-Identifier: LGPL-2.1-or-later
// The CAD parts of the accuracy benchmark, built with OpenCASCADE so that every feature line
// is known exactly from the B-rep (docs/ACCURACY.md describes each part).
#pragma once

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

namespace featurelines::bench {

struct CadShape
{
    std::string name;
    /// One sentence: what the part is and which edges it tests.
    std::string description;
    /// A solid, or a shell for the open parts. Lengths in millimetres.
    TopoDS_Shape shape;
    /// The smallest fillet radius of the part (0 without fillet), in millimetres: the point
    /// spacing must stay well below it for the fillet to be resolvable.
    double smallestRadius = 0.0;
};

/// The names of the parts the method is measured (and was tuned) on, in the benchmark's
/// order: box_fillets, box_chamfers, variable_fillet, boss_blend, plate_holes, open_sheet,
/// close_fillets.
std::vector<std::string> cadShapeNames();

/// Held-out parts, never used to tune the method, reported apart: wedge (a 30 degree knife
/// edge and a 150 degree shallow crease), chamfered_cylinder (sharp and smooth circles).
std::vector<std::string> heldOutShapeNames();

/// Builds the part called `name`. Throws std::invalid_argument for an unknown name (listing
/// the known ones) and std::runtime_error when OpenCASCADE fails to build it.
CadShape makeCadShape(const std::string& name);

} // namespace featurelines::bench
