# SPDX-License-Identifier: LGPL-2.1-or-later
"""From lines to surfaces in FreeCAD (issue 21, first step): FeatureLines.fitSurfaces on a
recomputed extraction, and its parametric object FeatureLines.makeSurfaces, which follows the
lines when they recompute, keeps its faces when a recompute fails, and is saved with them;
its PointDeviations give each point's signed distance from its face (a box's points moved
along the outward normal by a known offset are that offset from their faces). A sampled box gives 6 planes sewn into a valid solid of the box's volume;
the demo cloud gives the demo part's 7 planes, 6 cylinders and 1 torus, a valid solid, each face
within a fraction of a spacing of its patch's points; a patch the lines leave open is reported
with its reason, not a failure; a stale extraction is refused with a ValueError."""

import math
import os
import unittest

import FreeCAD
import Part

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5


class BoxTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("SurfacesBox")
        cls.points = sampled_shapes.cube(EDGE, SPACING, 12)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, cls.points)
        cls.result = FeatureLines.fitSurfaces(cls.lines)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_six_planes_sewn_into_a_solid_of_the_boxs_volume(self):
        faces = self.result["faces"]
        self.assertEqual([f["kind"] for f in faces], ["plane"] * 6, [f["problem"] for f in faces])
        self.assertTrue(self.result["solid"])
        self.assertTrue(self.result["valid"])
        shape = self.result["shape"]
        self.assertEqual(len(shape.Solids), 1)
        self.assertAlmostEqual(shape.Volume, EDGE ** 3, delta=0.01 * EDGE ** 3)
        for f in faces:
            self.assertEqual(f["problem"], "")
            self.assertLess(f["rms_deviation"], 0.1 * SPACING)
            self.assertIsInstance(f["face"], Part.Face)

    def test_the_shape_can_be_shown_and_saved(self):
        feature = Part.show(self.result["shape"], "Surfaces")
        self.doc.recompute()
        self.assertTrue(feature.Shape.isValid())
        self.assertAlmostEqual(feature.Shape.Volume, EDGE ** 3, delta=0.01 * EDGE ** 3)


class DemoTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("SurfacesDemo")
        cls.cloud = cls.doc.addObject("Points::Feature", "Cloud")
        cls.cloud.Points = FeatureLines.readCloud(
            os.path.join(os.environ["FEATURELINES_SAMPLES"], "boss_blend.xyz"))
        cls.lines = FeatureLines.makeExtraction(cls.cloud)
        cls.doc.recompute()
        cls.result = FeatureLines.fitSurfaces(cls.lines)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_planes_cylinders_and_a_torus_sewn_into_a_valid_solid(self):
        kinds = [f["kind"] for f in self.result["faces"]]
        problems = [f["problem"] for f in self.result["faces"] if f["problem"]]
        self.assertEqual(problems, [])
        self.assertEqual(kinds.count("plane"), 7, kinds)
        self.assertEqual(kinds.count("cylinder"), 6, kinds)
        self.assertEqual(kinds.count("torus"), 1, kinds)
        self.assertTrue(self.result["solid"] and self.result["valid"])
        spacing = self.lines.Spacing.Value
        self.assertLess(self.result["tolerance"], spacing)
        for f in self.result["faces"]:
            self.assertLess(f["rms_deviation"], 0.2 * spacing, f)

    def test_a_moved_cloud_moves_its_surfaces(self):
        # The faces are in world coordinates, as the lines: a cloud placed elsewhere gives the
        # same solid placed there.
        doc = support.new_document("SurfacesMoved")
        try:
            cloud = doc.addObject("Points::Feature", "Cloud")
            cloud.Points = self.cloud.Points
            shift = FreeCAD.Vector(100, -50, 20)
            cloud.Placement = FreeCAD.Placement(shift, FreeCAD.Rotation())
            lines = FeatureLines.makeExtraction(cloud)
            doc.recompute()
            moved = FeatureLines.fitSurfaces(lines)["shape"]
            here = self.result["shape"]
            # The extraction of the moved cloud rounds differently: the same within 0.1 %.
            self.assertAlmostEqual(moved.Volume, here.Volume, delta=1e-3 * here.Volume)
            spacing = self.lines.Spacing.Value
            self.assertLess((moved.BoundBox.Center - here.BoundBox.Center - shift).Length,
                            0.1 * spacing)
        finally:
            support.close_document(doc)


class ParametricTest(unittest.TestCase):
    def test_the_surfaces_follow_the_lines_and_a_failed_recompute_keeps_them(self):
        doc = support.new_document("SurfacesParametric")
        try:
            points = sampled_shapes.cube(EDGE, SPACING, 14)
            cloud, lines = support.add_extraction(doc, points)
            surfaces = FeatureLines.makeSurfaces(lines)
            doc.recompute()
            self.assertEqual(support.error_message(surfaces), "")
            self.assertEqual(list(surfaces.FaceKinds), ["plane"] * 6)
            self.assertTrue(surfaces.IsSolid and surfaces.IsValid)
            self.assertEqual(list(surfaces.Problems), [])
            self.assertAlmostEqual(surfaces.Shape.Volume, EDGE ** 3, delta=0.01 * EDGE ** 3)
            self.assertEqual(len(surfaces.FaceRmsDeviations), 6)
            # The cloud moved: the extraction and then the surfaces follow.
            shift = FreeCAD.Vector(0, 0, 40)
            cloud.Placement = FreeCAD.Placement(shift, FreeCAD.Rotation())
            doc.recompute()
            self.assertEqual(support.error_message(surfaces), "")
            self.assertAlmostEqual(surfaces.Shape.BoundBox.Center.z, 40.0, delta=0.1 * SPACING)
            # No sharp lines: no patch is closed, the recompute fails with the reason and the
            # faces of the run before stay.
            lines.SharpEdges = False
            doc.recompute()
            message = support.error_message(surfaces)
            self.assertIn("got a surface", message)
            self.assertAlmostEqual(surfaces.Shape.Volume, EDGE ** 3, delta=0.01 * EDGE ** 3)
            self.assertAlmostEqual(surfaces.Shape.BoundBox.Center.z, 40.0, delta=0.1 * SPACING)
            # Back: recovered.
            lines.SharpEdges = True
            doc.recompute()
            self.assertEqual(support.error_message(surfaces), "")
            self.assertTrue(surfaces.IsSolid)
            # Saved and reopened with its faces and lists.
            path = os.path.join(support.scratch_dir("surfaces"), "box.FCStd")
            doc.saveAs(path)
            name, object_name = doc.Name, surfaces.Name
            FreeCAD.closeDocument(name)
            doc = FreeCAD.openDocument(path)
            again = doc.getObject(object_name)
            self.assertEqual(list(again.FaceKinds), ["plane"] * 6)
            self.assertAlmostEqual(again.Shape.Volume, EDGE ** 3, delta=0.01 * EDGE ** 3)
        finally:
            support.close_document(doc)

    def test_a_source_that_is_no_extraction_is_refused(self):
        doc = support.new_document("SurfacesBadSource")
        try:
            points = sampled_shapes.cube(EDGE, SPACING, 15)
            cloud, lines = support.add_extraction(doc, points)
            with self.assertRaises(TypeError):
                FeatureLines.makeSurfaces(cloud)
            with self.assertRaises(ValueError):
                FeatureLines.makeSurfaces(lines, min_points=-1)
            surfaces = FeatureLines.makeSurfaces(lines)
            surfaces.Source = cloud
            doc.recompute()
            self.assertIn("Source must be a FeatureLines extraction",
                          support.error_message(surfaces))
        finally:
            support.close_document(doc)


def cube_normal(point):
    """The outward unit normal of sampled_shapes.cube at a point of it: along the axis where
    the point lies on a face."""
    axis = max(range(3), key=lambda k: abs(point[k]))
    n = [0.0, 0.0, 0.0]
    n[axis] = 1.0 if point[axis] > 0 else -1.0
    return tuple(n)


class DeviationTest(unittest.TestCase):
    def test_a_points_deviation_is_its_noise_along_the_outward_normal(self):
        # Every point of a box moved along its face's outward normal by a known Gaussian
        # offset t: its PointDeviations entry is t (the fitted planes pass through the
        # faces' points on average, within hundredths of a spacing of the true faces), positive
        # out of the solid; a point of no patch (on the lines) has NaN.
        doc = support.new_document("SurfacesDeviation")
        try:
            clean = sampled_shapes.cube(EDGE, SPACING, 16)
            sigma = 0.3 * SPACING
            noisy = sampled_shapes.with_normal_noise(clean, cube_normal, sigma, 17)
            offsets = [sum((a - b) * n for a, b, n in zip(q, p, cube_normal(p)))
                       for p, q in zip(clean, noisy)]
            cloud, lines = support.add_extraction(doc, noisy)
            surfaces = FeatureLines.makeSurfaces(lines)
            doc.recompute()
            self.assertTrue(surfaces.IsSolid, list(surfaces.Problems))
            deviations = list(surfaces.PointDeviations)
            self.assertEqual(len(deviations), len(noisy))
            patches = list(lines.PointPatch)
            on_faces = [i for i, d in enumerate(deviations) if math.isfinite(d)]
            self.assertTrue(all(patches[i] >= 0 for i in on_faces))
            self.assertGreater(len(on_faces), len(noisy) // 2)
            close = [i for i in on_faces if abs(deviations[i] - offsets[i]) < 0.1 * SPACING]
            self.assertGreater(len(close), 0.95 * len(on_faces))
            rms = math.sqrt(sum(deviations[i] ** 2 for i in on_faces) / len(on_faces))
            self.assertAlmostEqual(rms, sigma, delta=0.1 * sigma)
            # Saved and reopened with the deviations.
            path = os.path.join(support.scratch_dir("surfaces"), "deviations.FCStd")
            doc.saveAs(path)
            name, object_name = doc.Name, surfaces.Name
            FreeCAD.closeDocument(name)
            doc = FreeCAD.openDocument(path)
            again = list(doc.getObject(object_name).PointDeviations)
            self.assertEqual(len(again), len(deviations))
            self.assertEqual([again[i] for i in on_faces], [deviations[i] for i in on_faces])
        finally:
            support.close_document(doc)


class OpenAndStaleTest(unittest.TestCase):
    def test_an_open_patch_is_reported_and_a_stale_extraction_refused(self):
        doc = support.new_document("SurfacesOpen")
        try:
            points = sampled_shapes.cube(EDGE, SPACING, 13)
            cloud, lines = support.add_extraction(doc, points)
            # Only the sharp lines of one face: its neighbours' borders are open.
            lines.SharpEdges = False
            doc.recompute()
            result = FeatureLines.fitSurfaces(lines)
            self.assertFalse(result["solid"])
            self.assertTrue(all(f["problem"] for f in result["faces"] if f["face"] is None))
            cloud.Placement = FreeCAD.Placement(FreeCAD.Vector(1, 0, 0), FreeCAD.Rotation())
            with self.assertRaises(ValueError):
                FeatureLines.fitSurfaces(lines)
        finally:
            support.close_document(doc)


if __name__ == "__main__":
    unittest.main()
