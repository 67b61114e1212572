# SPDX-License-Identifier: LGPL-2.1-or-later
"""Save and reopen: every property and the result come back, and the reopened document shows
the same wires without a recompute."""

import math
import os
import shutil
import unittest
import zipfile

import FreeCAD

import FeatureLines
import sampled_shapes
import support

RADIUS = 6.0

# Parameters away from their defaults, so that a property falling back to its default on
# reopening is seen.
CHANGED = dict(GrowAngle=25.0, JoinAngle=12.0, NeighbourCount=18, BandWidth=3.0,
               Smoothing="Never", SmoothingIterations=7, HistogramBins=60, OutlierPercent=0.5,
               MaxThresholds=2, ThresholdMode="Explicit", Thresholds=[0.75 / RADIUS],
               RegionThresholds={0: [0.75 / RADIUS, 0.04]}, MinComponentLength=7.0)

OUTPUTS = ("SharpLineCount", "SmoothLineCount", "BoundaryLineCount", "ClosedLineCount",
           "RegionCount", "PatchCount", "UsedThresholds", "UsedThresholdRegions",
           "SmoothLineRegions", "SmoothLineThresholds", "PointRegion", "PointPatch",
           "PointLabel")


def wire_vertices(shape):
    return [[(v.Point.x, v.Point.y, v.Point.z) for v in w.OrderedVertexes] for w in shape.Wires]


class SaveAndReopenTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        folder = support.scratch_dir("persistence")
        cls.path = os.path.join(folder, "rounded.FCStd")
        doc = support.new_document("Saved")
        points = sampled_shapes.rounded_cube(40.0, RADIUS, 0.5, 7)
        cloud, lines = support.add_extraction(doc, points, **CHANGED)
        cls.error = support.error_message(lines)
        cls.names = [p["name"] for p in FeatureLines.parameters()]
        cls.saved = {name: lines.getPropertyByName(name) for name in cls.names}
        cls.outputs = {name: lines.getPropertyByName(name) for name in OUTPUTS}
        cls.curvature = list(lines.PointCurvature)
        cls.estimates = {name: list(lines.getPropertyByName(name))
                         for name in ("SharpAngles", "SmoothBlendRadii")}
        cls.junctions = [(j.x, j.y, j.z) for j in lines.Junctions]
        cls.shapes = {name: wire_vertices(lines.getPropertyByName(name))
                      for name in ("Shape", "SharpWires", "SmoothWires", "BoundaryWires")}
        cls.spacing = lines.Spacing.Value
        doc.saveAs(cls.path)
        support.close_document(doc)
        # Nothing may come from the cache: reopening reads the file only.
        FeatureLines.clearCache()
        cls.doc = FreeCAD.openDocument(cls.path)
        cls.lines = cls.doc.getObject("FeatureLines")
        cls.statistics_after_opening = FeatureLines.cacheStatistics()

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_the_saved_extraction_was_good(self):
        self.assertEqual(self.error, "")
        self.assertEqual(self.outputs["SmoothLineCount"], 8 + 6, "corner and face loops")

    def test_every_parameter_comes_back(self):
        self.assertEqual(self.lines.TypeId, "FeatureLines::Extraction")
        self.assertEqual(self.lines.Source.Name, "Cloud")
        for name in self.names:
            self.assertEqual(self.lines.getPropertyByName(name), self.saved[name], name)
        self.assertEqual(self.lines.ThresholdMode, "Explicit")
        self.assertEqual(list(self.lines.Thresholds), [0.75 / RADIUS])
        self.assertEqual(self.lines.RegionThresholds, {"0": "%.17g %.17g" % (0.75 / RADIUS, 0.04)})

    def test_every_output_comes_back_without_a_recompute(self):
        self.assertNotIn("Touched", self.lines.State)
        for name in OUTPUTS:
            self.assertEqual(self.lines.getPropertyByName(name), self.outputs[name], name)
        curvature = list(self.lines.PointCurvature)
        self.assertEqual(len(curvature), len(self.curvature))
        for a, b in zip(curvature, self.curvature):
            self.assertTrue(a == b or (math.isnan(a) and math.isnan(b)))
        # NaN (not estimated) comes back as NaN.
        self.assertEqual(len(self.estimates["SmoothBlendRadii"]), 8 + 6)
        for name, saved in self.estimates.items():
            reopened = list(self.lines.getPropertyByName(name))
            self.assertEqual(len(reopened), len(saved), name)
            for a, b in zip(reopened, saved):
                self.assertTrue(a == b or (math.isnan(a) and math.isnan(b)), name)
        self.assertEqual([(j.x, j.y, j.z) for j in self.lines.Junctions], self.junctions)
        self.assertEqual(self.lines.Spacing.Value, self.spacing)

    def test_opening_runs_no_extraction(self):
        self.assertEqual(self.statistics_after_opening["geometry_misses"], 0)
        self.assertEqual(self.statistics_after_opening["geometry_hits"], 0)

    def test_the_same_wires_come_back_without_a_recompute(self):
        for name, wires in self.shapes.items():
            reopened = wire_vertices(self.lines.getPropertyByName(name))
            self.assertEqual([len(w) for w in reopened], [len(w) for w in wires], name)
            for a, b in zip(sum(reopened, []), sum(wires, [])):
                # BREP text keeps 15 significant digits.
                self.assertLess(max(abs(x - y) for x, y in zip(a, b)), 1e-9, name)
        for wire in self.lines.SmoothWires.Wires:
            self.assertTrue(wire.isClosed())

    def test_per_point_lists_are_stored_as_binary_files(self):
        with zipfile.ZipFile(self.path) as archive:
            xml = archive.read("Document.xml").decode("utf-8")
        for name in ("PointRegion", "PointPatch", "PointLabel"):
            self.assertIn('<PointIndices file="%s"/>' % name, xml)
        # Only the short lists (per region, per line) are written element by element.
        self.assertLess(xml.count("<I v="), 100)

    def test_a_recompute_after_reopening_gives_the_same_result(self):
        # On a copy: the other tests look at the document as it was opened.
        copy = os.path.join(os.path.dirname(self.path), "copy.FCStd")
        shutil.copyfile(self.path, copy)
        doc = FreeCAD.openDocument(copy)
        try:
            lines = doc.getObject("FeatureLines")
            lines.touch()
            doc.recompute()
            self.assertEqual(support.error_message(lines), "")
            for name in OUTPUTS:
                self.assertEqual(lines.getPropertyByName(name), self.outputs[name], name)
        finally:
            support.close_document(doc)


class BlendBordersSaveAndReopenTest(unittest.TestCase):
    """Fillets of two spacings come out as the two borders of each blend, typed by their
    profile: they lie in no region (-1) and border no threshold (NaN); such a document opens
    again as it was saved."""

    def test_blend_borders_come_back(self):
        folder = support.scratch_dir("persistence-blends")
        path = os.path.join(folder, "blends.FCStd")
        doc = support.new_document("Blends")
        radius = 2.0
        points = sampled_shapes.rounded_cube(30.0, radius, 1.0, 3)
        cloud, lines = support.add_extraction(doc, points)
        self.assertEqual(support.error_message(lines), "")
        regions = list(lines.SmoothLineRegions)
        thresholds = list(lines.SmoothLineThresholds)
        radii = list(lines.SmoothBlendRadii)
        self.assertEqual(lines.SharpLineCount, 0)
        self.assertEqual(lines.SmoothLineCount, 24, "two borders of each of the 12 fillets")
        self.assertEqual(set(regions), {-1})
        self.assertTrue(all(math.isnan(t) for t in thresholds))
        self.assertTrue(all(0.7 * radius < r < 1.5 * radius for r in radii), radii)
        doc.saveAs(path)
        support.close_document(doc)
        FeatureLines.clearCache()
        doc = FreeCAD.openDocument(path)
        try:
            lines = doc.getObject("FeatureLines")
            self.assertEqual(support.error_message(lines), "")
            self.assertNotIn("Touched", lines.State)
            self.assertEqual(list(lines.SmoothLineRegions), regions)
            self.assertTrue(all(math.isnan(t) for t in lines.SmoothLineThresholds))
            self.assertEqual(list(lines.SmoothBlendRadii), radii)
        finally:
            support.close_document(doc)

if __name__ == "__main__":
    unittest.main()
