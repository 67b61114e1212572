// SPDX-License-Identifier: LGPL-2.1-or-later
// What the CadExport tests count in a shape.
#pragma once

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

/// The distinct sub-shapes of one kind (an edge shared by two wires counts once).
inline int countOf(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind)
{
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, kind, map);
    return map.Extent();
}
