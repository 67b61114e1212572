# SPDX-License-Identifier: LGPL-2.1-or-later
"""readCloud and the .xyz importer refuse a coordinate a FreeCAD point cannot hold, naming the
file and line: Points hold single precision, and 1e39 would become an infinite point."""

import os
import unittest

import FreeCAD

import FeatureLines
import support


class FloatRangeTest(unittest.TestCase):
    """FreeCAD's Points hold floats: a coordinate beyond 3.4e38 would become an infinite point.
    readCloud and the importer pass through the core's reader (CloudIO.h), which refuses it."""

    def write(self, name, text):
        path = os.path.join(support.scratch_dir("float-range"), name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_a_coordinate_beyond_single_precision_is_refused_with_file_and_line(self):
        path = self.write("huge.xyz", "# x y z\n0 0 0\n\n1 2 1e39\n3 4 5\n")
        with self.assertRaisesRegex(ValueError, r"huge\.xyz, line 4: .*1e39.*float range"):
            FeatureLines.readCloud(path)
        path = self.write("tiny.xyz", "0 0 0\n-3.5e38 0 0\n")
        with self.assertRaisesRegex(ValueError, r"tiny\.xyz, line 2"):
            FeatureLines.readCloud(path)

    def test_the_largest_float_is_read(self):
        path = self.write("large.xyz", "0 0 0\n3.4e38 0 0\n")
        kernel = FeatureLines.readCloud(path)
        self.assertEqual(kernel.CountPoints, 2)
        self.assertAlmostEqual(kernel.Points[1].x / 3.4e38, 1.0, places=6)

    def test_the_importer_refuses_it_and_adds_nothing(self):
        import FeatureLinesImport

        path = self.write("imported.xyz", "0 0 0\n1 1 1e39\n")
        doc = support.new_document("Import")
        try:
            with self.assertRaisesRegex(ValueError, r"imported\.xyz, line 2"):
                FeatureLinesImport.insert(path, doc.Name)
            self.assertEqual(doc.Objects, [])
        finally:
            support.close_document(doc)
        documents = set(FreeCAD.listDocuments())
        with self.assertRaisesRegex(ValueError, r"imported\.xyz, line 2"):
            FeatureLinesImport.open(path)
        self.assertEqual(set(FreeCAD.listDocuments()), documents, "no empty document is left")


if __name__ == "__main__":
    unittest.main()
