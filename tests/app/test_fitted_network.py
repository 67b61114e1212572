# SPDX-License-Identifier: LGPL-2.1-or-later
"""The lines as CAD geometry (issue 18) on sampled shapes whose edges are known: a box's Shape is
12 straight edges on 8 shared corners and its 6 faces get closed border wires on those edges; a
capped cylinder's rims are two circles of its radius; STEP, IGES and BREP files of the Shape read
back with its edge count; a Surface::Filling built on one face's border wire lies on that face's
points; a patch left open by a deleted line is reported, not a failed recompute; CornerAngle cuts
a rounded cube's loops at their corners; featurelines-cad writes a BREP and a STEP that FreeCAD
reads back."""

import math
import os
import subprocess
import unittest

import FreeCAD
import Import
import Part

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5
RADIUS, HEIGHT = 8.0, 16.0


def corners(edge):
    h = edge / 2
    return [FreeCAD.Vector(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]


def nearest(point, candidates):
    return min((point - c).Length for c in candidates)


def edge_index(shape, edge):
    """The 1-based index of `edge` in shape.Edges (the same edge, not a copy)."""
    for i, e in enumerate(shape.Edges):
        if e.isSame(edge):
            return i + 1
    return 0


class BoxTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("FittedBox")
        cls.points = sampled_shapes.cube(EDGE, SPACING, 11)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, cls.points)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_twelve_straight_edges_on_eight_shared_corners(self):
        shape = self.lines.Shape
        self.assertEqual(support.error_message(self.lines), "")
        self.assertEqual(len(shape.Edges), 12)
        self.assertEqual(len(shape.Vertexes), 8, "one vertex per corner, shared by three edges")
        self.assertEqual(list(self.lines.CurveKinds), ["segment"] * 12)
        self.assertEqual(list(self.lines.CurveProblems), [])
        for edge in shape.Edges:
            self.assertIsInstance(edge.Curve, Part.Line)
            self.assertAlmostEqual(edge.Length, EDGE, delta=2 * SPACING)
        for vertex in shape.Vertexes:
            self.assertLess(nearest(vertex.Point, corners(EDGE)), SPACING)
            self.assertEqual(len(shape.ancestorsOfType(vertex, Part.Edge)), 3)
        # The 12 wires of SharpWires are the 12 edges of Shape, one line each.
        self.assertEqual(self.lines.SharpLineCount, 12)
        self.assertEqual(len(self.lines.SharpWires.Edges), 12)

    def test_the_polylines_stay_wire_for_wire(self):
        polylines = self.lines.Polylines
        self.assertEqual(len(polylines.Wires), len(self.lines.Shape.Wires))
        self.assertGreater(len(polylines.Edges), 10 * 12, "many short segments per line")
        for fitted, polyline in zip(self.lines.Shape.Wires, polylines.Wires):
            self.assertAlmostEqual(fitted.Length, polyline.Length, delta=2 * SPACING)

    def test_six_closed_face_wires_on_the_same_edges(self):
        borders = self.lines.PatchBorders
        self.assertEqual(len(self.lines.PatchBorderEdges), 6)
        self.assertEqual(list(self.lines.OpenPatches), [])
        self.assertEqual(len(borders.Wires), 6)
        self.assertEqual(len(set(self.lines.PatchBorderPatches)), 6)
        for wire in borders.Wires:
            self.assertTrue(wire.isClosed())
            self.assertEqual(len(wire.Edges), 4)
            self.assertAlmostEqual(wire.Length, 4 * EDGE, delta=4 * SPACING)
            for edge in wire.Edges:
                self.assertGreater(edge_index(self.lines.Shape, edge), 0,
                                   "a border edge is an edge of Shape, not a copy")
        # The object moved: the borders move with Shape and keep its edges.
        self.lines.Placement = FreeCAD.Placement(FreeCAD.Vector(5, 0, 0), FreeCAD.Rotation())
        try:
            moved = self.lines.PatchBorders.Wires[0]
            self.assertGreater(edge_index(self.lines.Shape, moved.Edges[0]), 0)
            self.assertAlmostEqual(self.lines.PatchBorders.BoundBox.XMax, EDGE / 2 + 5,
                                   delta=SPACING)
        finally:
            self.lines.Placement = FreeCAD.Placement()

    def test_patch_borders_give_each_face_its_points_and_wire(self):
        patches = FeatureLines.patchBorders(self.lines)
        self.assertEqual(len(patches), 6)
        for patch in patches:
            self.assertTrue(patch["closed"], patch["reason"])
            self.assertEqual(patch["reason"], "")
            self.assertEqual(len(patch["wires"]), 1, "a box face has no hole")
            faces = {support.face_of(p) for p in patch["points"]}
            self.assertEqual(len(faces), 1, "a patch is the points of one face")
            axis, positive = faces.pop()
            for v in patch["wires"][0].Vertexes:
                self.assertAlmostEqual(v.Point[axis], EDGE / 2 if positive else -EDGE / 2,
                                       delta=SPACING)

    def test_step_iges_and_brep_read_back_with_twelve_edges(self):
        folder = support.scratch_dir("fitted_box_export")
        shape = self.lines.Shape
        files = {}
        for ext, write in (("step", shape.exportStep), ("iges", shape.exportIges),
                           ("brep", shape.exportBrep)):
            files[ext] = os.path.join(folder, "box." + ext)
            write(files[ext])
        # FreeCAD's own export of the document object, as File > Export does.
        files["Import.step"] = os.path.join(folder, "box-object.step")
        Import.export([self.lines], files["Import.step"])
        files["Part.brep"] = os.path.join(folder, "box-object.brep")
        Part.export([self.lines], files["Part.brep"])
        for name, path in files.items():
            back = Part.read(path)
            self.assertEqual(len(back.Edges), 12, name)
            for edge in back.Edges:
                self.assertIsInstance(edge.Curve, Part.Line, name)
        # BREP keeps the shared corners; STEP and IGES write each curve with its own ends.
        self.assertEqual(len(Part.read(files["brep"]).Vertexes), 8)
        # The patch border wires: BREP keeps their 12 shared edges; STEP writes each wire's 4.
        borders = self.lines.PatchBorders
        borders.exportBrep(os.path.join(folder, "borders.brep"))
        back = Part.read(os.path.join(folder, "borders.brep"))
        self.assertEqual((len(back.Wires), len(back.Edges), len(back.Vertexes)), (6, 12, 8))
        borders.exportStep(os.path.join(folder, "borders.step"))
        back = Part.read(os.path.join(folder, "borders.step"))
        self.assertEqual(len(back.Edges), 6 * 4)

    def test_a_filling_on_a_face_wire_lies_on_that_face(self):
        import Surface  # noqa: F401  (registers Surface::Filling)

        patch = FeatureLines.patchBorders(self.lines)[0]
        names = patch["edge_names"][0]
        self.assertEqual(len(names), 4)
        for name, edge in zip(names, patch["wires"][0].Edges):
            self.assertTrue(self.lines.Shape.getElement(name).isSame(edge), name)
        filling = self.doc.addObject("Surface::Filling", "Filling")
        filling.BoundaryEdges = [(self.lines, name) for name in names]
        self.doc.recompute()
        self.assertEqual(support.error_message(filling), "")
        face = filling.Shape.Faces[0]
        worst = max(face.distToShape(Part.Vertex(p))[0] for p in patch["points"][::7])
        self.assertLess(worst, 0.5 * SPACING)


class OpenPatchTest(unittest.TestCase):
    def test_a_deleted_line_leaves_two_faces_open_and_says_so(self):
        doc = support.new_document("OpenBox")
        try:
            _, lines = support.add_extraction(doc, sampled_shapes.cube(EDGE, SPACING, 11))
            FeatureLines.cleanLines(lines, remove=[0])
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(len(lines.Shape.Edges), 11)
            self.assertEqual(len(lines.OpenPatches), 2, "the two faces beside the deleted edge")
            self.assertEqual(len(lines.PatchBorders.Wires), 4)
            for reason in lines.OpenPatchReasons:
                self.assertIn("border is open", reason)
            patches = FeatureLines.patchBorders(lines)
            open_ones = [p for p in patches if not p["closed"]]
            self.assertEqual(sorted(p["patch"] for p in open_ones), sorted(lines.OpenPatches))
            for p in open_ones:
                self.assertEqual(p["wires"], [])
                self.assertTrue(p["reason"].startswith("patch %d: " % p["patch"]), p["reason"])
        finally:
            support.close_document(doc)


class CylinderTest(unittest.TestCase):
    def test_the_rims_are_two_circles_of_the_radius(self):
        doc = support.new_document("FittedCylinder")
        try:
            _, lines = support.add_extraction(
                doc, sampled_shapes.capped_cylinder(RADIUS, HEIGHT, SPACING, 3))
            self.assertEqual(support.error_message(lines), "")
            circles = [e for e in lines.SharpWires.Edges if isinstance(e.Curve, Part.Circle)]
            self.assertEqual(len(circles), 2)
            self.assertEqual(len(lines.SharpWires.Edges), 2)
            heights = sorted(c.Curve.Center.z for c in circles)
            for circle, z in zip(sorted(circles, key=lambda c: c.Curve.Center.z),
                                 (-HEIGHT / 2, HEIGHT / 2)):
                self.assertAlmostEqual(circle.Curve.Radius, RADIUS, delta=0.5 * SPACING)
                self.assertAlmostEqual(circle.Curve.Center.z, z, delta=0.5 * SPACING)
                self.assertLess(math.hypot(circle.Curve.Center.x, circle.Curve.Center.y),
                                0.5 * SPACING)
                self.assertAlmostEqual(abs(circle.Curve.Axis.z), 1.0, delta=0.01)
                self.assertTrue(circle.isClosed())
            self.assertLess(heights[0], heights[1])
        finally:
            support.close_document(doc)


class RoundedCubeTest(unittest.TestCase):
    def test_fillet_borders_are_closed_curves_on_the_part(self):
        edge, radius = 40.0, 6.0
        doc = support.new_document("FittedRoundedCube")
        try:
            _, lines = support.add_extraction(
                doc, sampled_shapes.rounded_cube(edge, radius, SPACING, 6))
            self.assertEqual(support.error_message(lines), "")
            wires = lines.SmoothWires.Wires
            self.assertEqual(len(wires), 14, "8 corner loops and 6 face loops")
            inner = edge / 2 - radius
            for wire in wires:
                self.assertTrue(wire.isClosed())
                # A loop meeting no other line is one closed edge on one vertex.
                self.assertEqual(len(wire.Edges), 1)
                self.assertEqual(len(wire.Vertexes), 1)
                # On the rounded cube's border between face and fillet or fillet and corner.
                for p in wire.discretize(400):
                    a = sorted(abs(c) for c in (p.x, p.y, p.z))
                    self.assertLess(a[2], edge / 2 + SPACING)
                    self.assertGreater(a[2], inner - SPACING)
            # Every loop is a fitted curve: none strays from its points so that it has to be
            # drawn as its polyline (a periodic B-spline once gathered knots at its seam here,
            # down to 1e-34 apart, and swung 26 units off the part).
            kinds = list(lines.CurveKinds)
            self.assertEqual(list(lines.CurveProblems), [])
            self.assertEqual(kinds.count("polyline"), 0, kinds)
            self.assertGreaterEqual(kinds.count("bspline"), 12, kinds)
        finally:
            support.close_document(doc)


class CornerTest(unittest.TestCase):
    def test_corner_angle_cuts_the_rounded_cubes_loops_at_their_corners(self):
        """CornerAngle 30: each face loop of a rounded cube is its four edges between the
        square's corners, each corner blend's loop is cut at its corners, every patch still
        closed; back at 180 each loop is one closed edge again."""
        edge, radius = 40.0, 6.0
        doc = support.new_document("RoundedCubeCorners")
        try:
            _, lines = support.add_extraction(
                doc, sampled_shapes.rounded_cube(edge, radius, SPACING, 6))
            self.assertEqual(lines.CornerAngle.Value, 180.0, "off by default")
            lines.CornerAngle = 30
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            wires = lines.SmoothWires.Wires
            self.assertEqual(len(wires), 14)
            inner = edge / 2 - radius
            faces, blends = [], []
            for wire in wires:
                self.assertTrue(wire.isClosed())
                # A face loop lies in its face's plane: one coordinate is +-edge/2 throughout.
                on_face = any(all(abs(abs(v.Point[k]) - edge / 2) < SPACING for v in wire.Vertexes)
                              for k in range(3))
                (faces if on_face else blends).append(wire)
            self.assertEqual((len(faces), len(blends)), (6, 8))
            for wire in faces:
                self.assertEqual(len(wire.Edges), 4)
                for v in wire.Vertexes:  # at the square's corners, within 3.5 spacings
                    a = sorted(abs(c) for c in v.Point)
                    self.assertLess(math.dist(a, (inner, inner, edge / 2)), 3.5 * SPACING, v.Point)
            # A corner blend's loop turns through a right angle between arcs of its radius;
            # each is cut at two or three of its three corners (between strongly curved arcs a
            # corner can look like the arcs' own bend: docs/design/curves.md, "Corners").
            for wire in blends:
                self.assertIn(len(wire.Edges), (2, 3))
            self.assertGreaterEqual(sum(len(w.Edges) for w in blends), 20)
            self.assertEqual(list(lines.OpenPatches), [])
            self.assertEqual(list(lines.CurveProblems), [])
            lines.CornerAngle = 180
            doc.recompute()
            self.assertEqual([len(w.Edges) for w in lines.SmoothWires.Wires], [1] * 14)
        finally:
            support.close_document(doc)


class CommandLineToolTest(unittest.TestCase):
    """featurelines-cad (FEATURELINES_CAD_TOOL) on the box's cloud, its files read by Part."""

    def test_brep_and_step_of_the_box(self):
        tool = os.environ.get("FEATURELINES_CAD_TOOL")
        self.assertTrue(tool and os.path.isfile(tool), "FEATURELINES_CAD_TOOL: %r" % tool)
        folder = support.scratch_dir("featurelines_cad")
        cloud = os.path.join(folder, "box.xyz")
        with open(cloud, "w") as f:
            for p in sampled_shapes.cube(EDGE, SPACING, 11):
                f.write("%.17g %.17g %.17g\n" % p)
        for ext, vertices in (("brep", 8), ("step", None)):
            out = os.path.join(folder, "box." + ext)
            run = subprocess.run([tool, "extract", cloud, "-o", out], capture_output=True,
                                 text=True)
            self.assertEqual(run.returncode, 0, run.stderr)
            back = Part.read(out)
            self.assertEqual(len(back.Edges), 12, ext)
            if vertices:
                self.assertEqual(len(back.Vertexes), vertices, ext)


if __name__ == "__main__":
    unittest.main()
