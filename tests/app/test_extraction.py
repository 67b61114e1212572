# SPDX-License-Identifier: LGPL-2.1-or-later
"""FeatureLines::Extraction on sampled shapes whose feature lines are known: a cube's twelve
sharp edges, a rounded cube's fillet borders (Demarsin et al. 2008, Fig. 7 b), an open sheet's
boundary; recompute after a parameter or cloud change, and the cache that makes a threshold
change cheap."""

import math
import unittest

import FreeCAD

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5
ROUNDED_EDGE, RADIUS = 40.0, 6.0


def on_cube_edge(p, half, tolerance):
    """Two coordinates at +-half: the point lies on one of the cube's twelve edges."""
    a = sorted(abs(c) for c in (p.x, p.y, p.z))
    return abs(a[1] - half) < tolerance and abs(a[2] - half) < tolerance and a[0] <= half


class CubeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("Cube")
        cls.points = sampled_shapes.cube(EDGE, SPACING, 11)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, cls.points)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_twelve_sharp_wires_on_the_edges(self):
        lines = self.lines
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 12)
        self.assertEqual(lines.SmoothLineCount, 0, "flat faces have no curvature valley")
        self.assertEqual(lines.BoundaryLineCount, 0, "a closed surface has no boundary")
        self.assertEqual(len(lines.SharpWires.Wires), 12)
        self.assertEqual(len(lines.Shape.Wires), 12)
        for p in support.vertex_points(lines.Shape):
            self.assertTrue(on_cube_edge(p, EDGE / 2, 2 * SPACING), p)

    def test_each_sharp_wire_has_its_angle_and_no_blend_radius(self):
        # Per wire of SharpWires its faces' angle: a cube's edges are right angles, where one
        # was estimated (NaN where not); no smooth wire, so no blend radius.
        angles = list(self.lines.SharpAngles)
        self.assertEqual(len(angles), self.lines.SharpLineCount)
        self.assertEqual(support.estimates_outside(angles, 0.0, 180.0), [])
        self.assertEqual(support.estimates_outside(angles, 75.0, 105.0), [], "a box edge is 90")
        self.assertEqual(list(self.lines.SmoothBlendRadii), [])

    def test_the_network_is_closed_at_the_eight_corners(self):
        # Sec. 1.2: closed feature lines; on a cube every edge ends on two corner junctions.
        junctions = self.lines.Junctions
        self.assertEqual(len(junctions), 8)
        for j in junctions:
            # Near a corner (the core places a junction within a few spacings of it).
            for c in (j.x, j.y, j.z):
                self.assertAlmostEqual(abs(c), EDGE / 2, delta=3 * SPACING)
        for wire in self.lines.Shape.Wires:
            self.assertFalse(wire.isClosed())
            for end in support.wire_ends(wire):
                nearest = min(end.distanceToPoint(j) for j in junctions)
                self.assertLess(nearest, 1e-6, "a line end sits on a junction")

    def test_every_face_is_one_region(self):
        self.assertEqual(self.lines.RegionCount, 6)
        region = self.lines.PointRegion
        self.assertEqual(len(region), len(self.points))
        faces = {}
        for p, r in zip(self.points, region):
            if r >= 0:
                axis = max(range(3), key=lambda a: abs(p[a]))
                faces.setdefault(r, set()).add((axis, p[axis] > 0))
        self.assertEqual(len(faces), 6)
        for r, face in faces.items():
            self.assertEqual(len(face), 1, "region %d spans faces %s" % (r, face))

    def test_wires_follow_the_cloud_placement_without_new_analysis(self):
        doc = support.new_document("MovedCube")
        try:
            cloud, lines = support.add_extraction(doc, self.points)
            before = FeatureLines.cacheStatistics()
            shift = FreeCAD.Vector(100, -50, 7)
            cloud.Placement = FreeCAD.Placement(shift, FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 30))
            doc.recompute()
            after = FeatureLines.cacheStatistics()
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.SharpLineCount, 12)
            # The analysis is of the cloud's own coordinates: moving it is a cache hit.
            self.assertEqual(after["geometry_misses"], before["geometry_misses"])
            self.assertEqual(after["analysis_misses"], before["analysis_misses"])
            inverse = cloud.Placement.inverse()
            for p in support.vertex_points(lines.Shape):
                self.assertTrue(on_cube_edge(inverse.multVec(p), EDGE / 2, 2 * SPACING), p)
            self.assertLess(lines.Shape.BoundBox.Center.distanceToPoint(shift), 2 * SPACING)
        finally:
            support.close_document(doc)


class RoundedCubeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("Rounded")
        cls.points = sampled_shapes.rounded_cube(ROUNDED_EDGE, RADIUS, SPACING, 6)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, cls.points)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def setUp(self):
        for name in ("ThresholdMode", "NoiseThreshold"):
            setattr(self.lines, name, support.default_value(name))
        self.lines.Thresholds = []
        self.doc.recompute()

    def test_fillet_borders_are_fourteen_closed_wires_at_two_thresholds(self):
        lines = self.lines
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 0, "fillets of radius 12 spacings are smooth")
        self.assertEqual(lines.RegionCount, 1)
        # Sec. 2.3: planes | fillets | corners, two thresholds, each between two levels.
        self.assertEqual(list(lines.UsedThresholdRegions), [0, 0])
        tau1, tau2 = lines.UsedThresholds
        self.assertTrue(1 / (2 * RADIUS) < tau1 < 1 / RADIUS, tau1)
        self.assertTrue(0 < tau2 < 1 / (2 * RADIUS), tau2)
        # tau1: a loop around each of the 8 corners; tau2: a loop around each of the 6 faces.
        self.assertEqual(lines.SmoothLineCount, 14)
        self.assertEqual(sorted(lines.SmoothLineThresholds), sorted([tau1] * 8 + [tau2] * 6))
        self.assertEqual(lines.ClosedLineCount, 14)
        self.assertEqual(len(lines.SmoothWires.Wires), 14)
        for wire in lines.SmoothWires.Wires:
            self.assertTrue(wire.isClosed())
        self.assertEqual(len(lines.Shape.Wires), 14)

    def test_each_smooth_wire_has_its_blend_radius_and_no_angle(self):
        # Per wire of SmoothWires the radius of the blend it borders: every blend of the part
        # has radius RADIUS, where one was estimated (NaN where not); no sharp wire, no angle.
        radii = list(self.lines.SmoothBlendRadii)
        self.assertEqual(len(radii), self.lines.SmoothLineCount)
        self.assertEqual(support.estimates_outside(radii, 0.0, math.inf), [])
        self.assertEqual(support.estimates_outside(radii, RADIUS / 2, 2 * RADIUS), [])
        self.assertEqual(list(self.lines.SharpAngles), [])

    def test_flat_face_patches_are_patch_clouds(self):
        doc = support.new_document("Patches")
        try:
            cloud, lines = support.add_extraction(doc, self.points)
            clouds = FeatureLines.makePatchClouds(lines)
            half, inner = ROUNDED_EDGE / 2, ROUNDED_EDGE / 2 - RADIUS
            flat = []
            for patch in clouds:
                pts = patch.Points.Points
                self.assertGreaterEqual(len(pts), 2 * lines.NeighbourCount)
                faces = {support.face_of(p) for p in pts}
                if all(abs(max(abs(p.x), abs(p.y), abs(p.z)) - half) < 1e-3 for p in pts):
                    self.assertEqual(len(faces), 1, "a flat patch is one face")
                    flat.append(patch)
            self.assertEqual(len(flat), 6, "one patch per flat face")
            for patch in flat:
                # The patch stops at the face's border with its fillets (+- the sampling).
                for p in patch.Points.Points:
                    a = sorted(abs(c) for c in (p.x, p.y, p.z))
                    self.assertLess(a[1], inner + 3 * SPACING)
            group = doc.getObjectsByLabel("FeatureLines patches")
            self.assertEqual(len(group), 1)
            self.assertEqual(len(group[0].Group), len(clouds))
        finally:
            support.close_document(doc)

    def test_a_threshold_change_reuses_neighbours_normals_and_curvature(self):
        before = FeatureLines.cacheStatistics()
        self.lines.ThresholdMode = "Explicit"
        self.lines.Thresholds = [0.75 / RADIUS]  # between the fillet and the corner curvature
        self.doc.recompute()
        after = FeatureLines.cacheStatistics()
        self.assertEqual(support.error_message(self.lines), "")
        self.assertEqual(after["geometry_misses"], before["geometry_misses"])
        self.assertEqual(after["analysis_misses"], before["analysis_misses"])
        self.assertEqual(after["geometry_hits"], before["geometry_hits"] + 1)
        self.assertEqual(after["analysis_hits"], before["analysis_hits"] + 1)
        self.assertEqual(list(self.lines.UsedThresholds), [0.75 / RADIUS])
        self.assertEqual(self.lines.SmoothLineCount, 8, "one loop per corner")
        self.assertEqual(self.lines.ClosedLineCount, 8)

    def test_a_region_stage_change_reuses_neighbours_only(self):
        before = FeatureLines.cacheStatistics()
        self.lines.NoiseThreshold = 5.0  # no smoothing: the region's curvature is recomputed
        self.doc.recompute()
        after = FeatureLines.cacheStatistics()
        self.assertEqual(after["geometry_misses"], before["geometry_misses"])
        self.assertEqual(after["analysis_misses"], before["analysis_misses"] + 1)


class RecomputeTest(unittest.TestCase):
    def test_changing_the_cloud_recomputes_the_lines(self):
        doc = support.new_document("Change")
        try:
            cloud, lines = support.add_extraction(doc, sampled_shapes.cube(EDGE, SPACING, 3))
            self.assertEqual(lines.SharpLineCount, 12)
            misses = FeatureLines.cacheStatistics()["geometry_misses"]
            bigger = 2 * EDGE
            cloud.Points = support.add_cloud(doc, sampled_shapes.cube(bigger, 2 * SPACING, 4),
                                             "Other").Points
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(FeatureLines.cacheStatistics()["geometry_misses"], misses + 1)
            self.assertEqual(lines.SharpLineCount, 12)
            for p in support.vertex_points(lines.Shape):
                self.assertTrue(on_cube_edge(p, bigger / 2, 4 * SPACING), p)
        finally:
            support.close_document(doc)

    def test_an_open_sheet_gives_its_closed_boundary_only(self):
        doc = support.new_document("Sheet")
        try:
            cloud, lines = support.add_extraction(doc, sampled_shapes.plane(EDGE, SPACING, 3))
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.SharpLineCount, 0)
            self.assertEqual(lines.SmoothLineCount, 0)
            self.assertEqual(lines.BoundaryLineCount, 1)
            wire = lines.BoundaryWires.Wires[0]
            self.assertTrue(wire.isClosed())
            for p in support.vertex_points(wire):
                rim = max(abs(p.x), abs(p.y))
                self.assertAlmostEqual(rim, EDGE / 2, delta=3 * SPACING)
            self.assertEqual(len(lines.Shape.Wires), 1)
        finally:
            support.close_document(doc)

    def test_without_sharp_edges_the_sheet_is_one_region_with_its_boundary(self):
        doc = support.new_document("NoSharp")
        try:
            points = sampled_shapes.plane(EDGE, SPACING, 5)
            cloud, lines = support.add_extraction(doc, points, SharpEdges=False)
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.BoundaryLineCount, 1)
            self.assertEqual(lines.RegionCount, 1)
            # The spacing is the mean nearest-neighbour distance of a grid jittered by 0.2.
            self.assertAlmostEqual(lines.Spacing.Value, SPACING, delta=0.3 * SPACING)
            self.assertEqual(lines.Spacing.Unit, FreeCAD.Units.Length)
            curvature = [c for c in lines.PointCurvature if not math.isnan(c)]
            self.assertEqual(len(lines.PointCurvature), len(points))
            self.assertLess(max(curvature), 0.05 / SPACING, "a plane has no curvature")
        finally:
            support.close_document(doc)


if __name__ == "__main__":
    unittest.main()
