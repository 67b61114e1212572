# SPDX-License-Identifier: LGPL-2.1-or-later
"""Hostile coordinates (issue 22) through the Python API and the document object: the core's
refusal text reaches the user unchanged, as a ValueError or as the object's error, and the
object recovers once the cloud is fixed. A source cloud that is deleted and replaced recovers
the same way (tests/app/test_damaged_documents.py has the emptied and NaN clouds)."""

import unittest

import FreeCAD
import Points

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5


class HostileCoordinatesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cube = sampled_shapes.cube(EDGE, SPACING, 11)

    def test_the_python_api_raises_the_core_message(self):
        cases = [
            (1e-310, 0.0, "point cloud: its size .* below the smallest supported, 1e-100"),
            (1e300, 0.0, "point cloud: point \\d+ has a coordinate beyond the float range"),
            (1.0, 1e15, "point cloud: its coordinates reach .* more than 1e8 times its size"),
        ]
        for scale, offset, words in cases:
            points = [(x * scale + offset, y * scale + offset, z * scale + offset)
                      for x, y, z in self.cube]
            with self.assertRaisesRegex(ValueError, words):
                FeatureLines.extract(points)

    def test_the_object_shows_an_outlier_as_its_error_and_recovers(self):
        # One point 1e8 away: the cube (20 wide) falls within a few cells 48 wide of the
        # neighbour search's keys.
        doc = support.new_document("Outlier")
        try:
            cloud, lines = support.add_extraction(doc, self.cube)
            self.assertEqual(lines.SharpLineCount, 12)
            cloud.Points = Points.Points(
                [FreeCAD.Vector(*p) for p in self.cube + [(1e8, 0.0, 0.0)]])
            doc.recompute()
            self.assertIn("more than 1024 points lie in one cell", support.error_message(lines))
            self.assertEqual(lines.SharpLineCount, 12, "the last good lines are kept")
            cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in self.cube])
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.SharpLineCount, 12)
        finally:
            support.close_document(doc)

    def test_a_deleted_source_is_an_error_and_a_new_one_recovers(self):
        doc = support.new_document("DeletedSource")
        try:
            cloud, lines = support.add_extraction(doc, self.cube)
            self.assertEqual(lines.SharpLineCount, 12)
            doc.removeObject(cloud.Name)
            doc.recompute()
            self.assertIn("No point cloud", support.error_message(lines))
            self.assertEqual(lines.SharpLineCount, 12, "the last good lines are kept")
            lines.Source = support.add_cloud(doc, self.cube, "NewCloud")
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.SharpLineCount, 12)
        finally:
            support.close_document(doc)


if __name__ == "__main__":
    unittest.main()
