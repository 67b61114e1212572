# SPDX-License-Identifier: LGPL-2.1-or-later
"""A document saved by FreeCAD 0.20.2 (Debian 12) with the module opens in the FreeCAD running the
test (0.20.2, or 1.0 on Debian 13) with its extraction, its parameters and its lines.

data/cube-freecad-0.20.2.FCStd: a 10 mm cube sampled every 0.5 mm (2400 points, seed 11), its
extraction with GrowAngle 25 and HistogramBins 60 (not the defaults, so a parameter falling back
to its default is seen), recomputed and saved by FreeCAD 0.20.2."""

import os
import shutil
import unittest
import xml.etree.ElementTree as ElementTree
import zipfile

import FreeCAD

import support

HALF = 5.0
TOLERANCE = 2.0  # 4 x the sampling spacing, as the cube tests of test_extraction


def on_cube_edge(p):
    """Two coordinates at +-HALF: the point lies on one of the cube's twelve edges."""
    a = sorted(abs(c) for c in (p.x, p.y, p.z))
    return abs(a[1] - HALF) < TOLERANCE and abs(a[2] - HALF) < TOLERANCE and a[0] <= HALF + TOLERANCE


def wire_vertices(shape):
    return [[(v.Point.x, v.Point.y, v.Point.z) for v in w.OrderedVertexes] for w in shape.Wires]


class SavedByFreeCAD020Test(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        original = os.path.join(os.environ["FEATURELINES_TEST_DIR"], "data",
                                "cube-freecad-0.20.2.FCStd")
        with zipfile.ZipFile(original) as archive:
            cls.program_version = ElementTree.fromstring(
                archive.read("Document.xml")).get("ProgramVersion")
        # A copy: the test never writes the file in the repository.
        cls.path = os.path.join(support.scratch_dir("older_release"), "cube.FCStd")
        shutil.copyfile(original, cls.path)
        cls.doc = FreeCAD.openDocument(cls.path)
        cls.lines = cls.doc.getObject("FeatureLines")
        cls.opened = wire_vertices(cls.lines.Shape) if cls.lines else []
        cls.opened_error = support.error_message(cls.lines) if cls.lines else None
        cls.opened_estimates = [list(cls.lines.getPropertyByName(name)) if cls.lines else None
                                for name in ("SharpAngles", "SmoothBlendRadii")]

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_the_file_was_written_by_freecad_0_20(self):
        self.assertTrue(self.program_version.startswith("0.20"), self.program_version)

    def test_the_extraction_and_its_parameters_come_back(self):
        self.assertIsNotNone(self.lines)
        self.assertEqual(self.lines.TypeId, "FeatureLines::Extraction")
        self.assertEqual(self.lines.Source.TypeId, "Points::Feature")
        self.assertEqual(self.lines.Source.Points.CountPoints, 2400)
        self.assertAlmostEqual(self.lines.GrowAngle.Value, 25.0)
        self.assertEqual(self.lines.HistogramBins, 60)

    def test_the_lines_come_back_without_a_recompute(self):
        # FreeCAD 1.0 marks shapes saved by an older release for a recompute (its element maps);
        # the saved lines are there meanwhile.
        self.assertEqual(self.lines.SharpLineCount, 12)
        self.assertEqual(len(self.opened), 12)
        self.assertEqual(len(self.lines.SharpWires.Wires), 12)
        for p in support.vertex_points(self.lines.Shape):
            self.assertTrue(on_cube_edge(p), p)

    def test_the_lines_saved_before_angles_existed_open_without_them(self):
        # The file predates SharpAngles and SmoothBlendRadii: they are empty, not an error,
        # until a recompute (test_a_recompute_gives_the_same_lines) fills them.
        self.assertEqual(self.opened_error, "")
        self.assertEqual(self.opened_estimates, [[], []])

    def test_a_recompute_gives_the_same_lines(self):
        self.lines.touch()
        self.doc.recompute()
        self.assertEqual(support.error_message(self.lines), "")
        # The file holds the lines as polylines in Shape; since issue 18 Shape holds the curves
        # fitted to them and Polylines the polylines.
        self.assertEqual(len(self.lines.Shape.Wires), len(self.opened))
        self.assertEqual(len(self.lines.SharpAngles), 12)
        recomputed = wire_vertices(self.lines.Polylines)
        self.assertEqual([len(w) for w in recomputed], [len(w) for w in self.opened])
        for a, b in zip(sum(recomputed, []), sum(self.opened, [])):
            # BREP text keeps 15 significant digits.
            self.assertLess(max(abs(x - y) for x, y in zip(a, b)), 1e-9)
