# SPDX-License-Identifier: LGPL-2.1-or-later
"""Every way an extraction can fail ends in a message a CAD user understands, the last good
result is kept and the document stays sound (it saves and reopens)."""

import os
import unittest

import FreeCAD
import Points

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5


class DocumentObjectErrorTest(unittest.TestCase):
    def setUp(self):
        self.doc = support.new_document("Errors")
        self.cube = sampled_shapes.cube(EDGE, SPACING, 11)

    def tearDown(self):
        FeatureLines.setProgressObserver(None)
        support.close_document(self.doc)

    def extraction(self, **parameters):
        lines = self.doc.addObject("FeatureLines::Extraction", "FeatureLines")
        for name, value in parameters.items():
            setattr(lines, name, value)
        return lines

    def good_extraction(self):
        cloud, lines = support.add_extraction(self.doc, self.cube)
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 12)
        return cloud, lines

    def assertFailsWith(self, lines, words):
        self.doc.recompute()
        message = support.error_message(lines)
        self.assertIn(words, message)
        return message

    def assertKeptTwelveEdges(self, lines):
        self.assertEqual(lines.SharpLineCount, 12)
        self.assertEqual(len(lines.Shape.Wires), 12)
        self.assertEqual(len(lines.SharpWires.Wires), 12)
        self.assertEqual(len(lines.PointRegion), len(self.cube))

    def test_no_source(self):
        lines = self.extraction()
        self.assertFailsWith(lines, "No point cloud: set Source to a Points object")

    def test_source_is_not_a_point_cloud(self):
        box = self.doc.addObject("Part::Box", "Box")
        lines = self.extraction(Source=box)
        self.assertFailsWith(lines, "'Box' is not a point cloud")

    def test_too_few_points(self):
        cloud = support.add_cloud(self.doc, self.cube[:10])
        lines = self.extraction(Source=cloud)
        message = self.assertFailsWith(lines, "Too few points")
        self.assertIn("at least 17", message)

    def test_too_few_distinct_points(self):
        cloud = support.add_cloud(self.doc, [self.cube[0]] * 50)
        lines = self.extraction(Source=cloud)
        self.assertFailsWith(lines, "distinct points")

    def test_points_on_a_line(self):
        cloud = support.add_cloud(self.doc, [(0.1 * i, 0.0, 0.0) for i in range(100)])
        lines = self.extraction(Source=cloud)
        self.assertFailsWith(lines, "the points lie on a line")

    def test_no_features_found(self):
        # A sphere: no crease, no boundary, one curvature level (no histogram valley).
        cloud = support.add_cloud(self.doc, sampled_shapes.sphere(10.0, SPACING, 2))
        lines = self.extraction(Source=cloud)
        self.assertFailsWith(lines, "No feature lines found in 'Cloud'")

    def test_nan_coordinates(self):
        nan = float("nan")
        cloud = support.add_cloud(self.doc, self.cube[:100] + [(nan, 0.0, 0.0)])
        lines = self.extraction(Source=cloud)
        message = self.assertFailsWith(lines, "1 invalid (NaN) points")
        self.assertIn("fromValid()", message)

    def test_nothing_to_extract(self):
        cloud = support.add_cloud(self.doc, self.cube)
        lines = self.extraction(Source=cloud, SharpEdges=False, SmoothEdges=False,
                                BoundaryLines=False)
        self.assertFailsWith(lines, "nothing to extract")

    def test_negative_explicit_threshold(self):
        cloud = support.add_cloud(self.doc, self.cube)
        lines = self.extraction(Source=cloud, ThresholdMode="Explicit", Thresholds=[-0.1])
        self.assertFailsWith(lines, "must be finite and not negative")

    def test_region_thresholds_that_are_not_numbers(self):
        cloud = support.add_cloud(self.doc, self.cube)
        lines = self.extraction(Source=cloud, ThresholdMode="Explicit",
                                RegionThresholds={"0": "0.1 abc"})
        self.assertFailsWith(lines, "'abc' is not a number")
        lines.RegionThresholds = {"first": "0.1"}
        self.assertFailsWith(lines, "'first' is not a region number")

    def test_property_constraints_clamp_values_set_from_python(self):
        lines = self.extraction()
        lines.GrowAngle = 500
        self.assertEqual(lines.GrowAngle.Value, 90.0)
        lines.NeighbourCount = 1
        self.assertEqual(lines.NeighbourCount, 3)

    def test_the_last_good_result_is_kept(self):
        cloud, lines = self.good_extraction()
        cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in self.cube[:5]])
        self.assertFailsWith(lines, "Too few points")
        self.assertKeptTwelveEdges(lines)
        lines.Source = None
        self.assertFailsWith(lines, "No point cloud")
        self.assertKeptTwelveEdges(lines)

    def test_cancel_keeps_the_last_good_result(self):
        cloud, lines = self.good_extraction()
        stages = []

        def observer(done, stage):
            stages.append(stage)
            return done < 0.25  # stop once the sharp edges are under way

        FeatureLines.setProgressObserver(observer)
        lines.GrowAngle = 28  # a Regions-stage change: the sharp edges are searched again
        self.assertFailsWith(lines, "cancelled by the user")
        self.assertIn("sharp edges", stages)
        self.assertKeptTwelveEdges(lines)
        FeatureLines.setProgressObserver(None)
        self.doc.recompute()
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 12)

    def test_an_observer_that_raises_cancels(self):
        cloud, lines = self.good_extraction()

        def observer(done, stage):
            raise RuntimeError("observer broke")

        FeatureLines.setProgressObserver(observer)
        lines.ThresholdMode = "First"
        self.assertFailsWith(lines, "cancelled by the user")
        self.assertKeptTwelveEdges(lines)

    def test_the_document_stays_sound_after_errors(self):
        cloud, lines = self.good_extraction()
        cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in self.cube[:5]])
        self.assertFailsWith(lines, "Too few points")
        path = os.path.join(support.scratch_dir("errors"), "failed.FCStd")
        self.doc.saveAs(path)
        support.close_document(self.doc)
        self.doc = FreeCAD.openDocument(path)
        lines = self.doc.getObject("FeatureLines")
        self.assertKeptTwelveEdges(lines)
        self.doc.getObject("Cloud").Points = Points.Points(
            [FreeCAD.Vector(*p) for p in self.cube])
        self.doc.recompute()
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 12)


class PythonErrorTest(unittest.TestCase):
    def tearDown(self):
        FeatureLines.setProgressObserver(None)

    def test_bad_clouds(self):
        with self.assertRaisesRegex(ValueError, "at least 17"):
            FeatureLines.extract([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
        with self.assertRaisesRegex(ValueError, "point 100 has a coordinate that is not a finite"):
            FeatureLines.extract(sampled_shapes.cube(EDGE, SPACING, 1)[:99] +
                                 [(float("nan"), 0, 0)])
        with self.assertRaisesRegex(TypeError, "three numbers"):
            FeatureLines.extract([(0, 0)] * 50)
        with self.assertRaisesRegex(TypeError, "Points object"):
            FeatureLines.extract(42)

    def test_a_document_object_that_is_not_a_cloud(self):
        doc = support.new_document("NotACloud")
        try:
            box = doc.addObject("Part::Box", "Box")
            with self.assertRaisesRegex(TypeError, "'Box' is not a point cloud"):
                FeatureLines.extract(box)
            with self.assertRaisesRegex(TypeError, "Points feature"):
                FeatureLines.makeExtraction(box)
            with self.assertRaisesRegex(TypeError, "Extraction object"):
                FeatureLines.makePatchClouds(box)
            self.assertEqual([o.Name for o in doc.Objects], ["Box"])
        finally:
            support.close_document(doc)

    def test_bad_parameters(self):
        cube = sampled_shapes.cube(EDGE, SPACING, 1)
        with self.assertRaisesRegex(TypeError, "unknown parameter 'Bogus'"):
            FeatureLines.extract(cube, Bogus=1)
        with self.assertRaisesRegex(ValueError, "GrowAngle = 500 is outside 1 .. 90"):
            FeatureLines.extract(cube, GrowAngle=500)
        with self.assertRaisesRegex(ValueError, "NeighbourCount must be a whole number"):
            FeatureLines.extract(cube, NeighbourCount=16.5)
        with self.assertRaisesRegex(ValueError, "choose one of Automatic, First, Explicit"):
            FeatureLines.extract(cube, ThresholdMode="Sometimes")
        with self.assertRaisesRegex(ValueError, "not negative"):
            FeatureLines.extract(cube, ThresholdMode="Explicit", Thresholds=[-1])
        with self.assertRaisesRegex(TypeError, "must be a number"):
            FeatureLines.extract(cube, BandWidth="wide")
        # Text the core's parsers refuse arrives as a Python error, not as a crash.
        with self.assertRaisesRegex(ValueError, "'abc' is not a number"):
            FeatureLines.extract(cube, ThresholdMode="Explicit", Thresholds="0.1 abc")
        with self.assertRaisesRegex(ValueError, "'x' is not a region number"):
            FeatureLines.extract(cube, ThresholdMode="Explicit", RegionThresholds={"x": [0.1]})
        with self.assertRaisesRegex(TypeError, "a point must be"):
            FeatureLines.histogram(["low", "high"])

    def test_bad_histograms(self):
        with self.assertRaisesRegex(ValueError, "all values are equal"):
            FeatureLines.histogram([0.5] * 100)
        with self.assertRaisesRegex(ValueError, "not both"):
            FeatureLines.histogram([0.1, 0.2, 0.3, 0.9], below=0.5, above=0.2)

    def test_bad_files(self):
        folder = support.scratch_dir("bad-files")
        with self.assertRaisesRegex(ValueError, "missing.xyz"):
            FeatureLines.readCloud(os.path.join(folder, "missing.xyz"))
        path = os.path.join(folder, "words.xyz")
        with open(path, "w") as f:
            f.write("1 2 3\nfour five six\n")
        with self.assertRaisesRegex(ValueError, "line 2"):
            FeatureLines.readCloud(path)

    def test_cancel_from_python(self):
        FeatureLines.setProgressObserver(lambda done, stage: False)
        with self.assertRaisesRegex(RuntimeError, "cancelled"):
            FeatureLines.extract(sampled_shapes.cube(EDGE, SPACING, 2))
        with self.assertRaisesRegex(TypeError, "callable"):
            FeatureLines.setProgressObserver(3)


if __name__ == "__main__":
    unittest.main()
