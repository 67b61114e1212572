# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Python functions macros use: extract(), histogram(), makeExtraction(), parameters(),
readCloud() and the .xyz importer."""

import math
import os
import random
import unittest

import FreeCAD
import Part
import Points

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5
RADIUS = 6.0


class ExtractTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cube = sampled_shapes.cube(EDGE, SPACING, 11)
        cls.result = FeatureLines.extract(cls.cube)

    def test_a_list_of_points_gives_twelve_sharp_wires(self):
        r = self.result
        self.assertEqual(len(r["sharp"]), 12)
        self.assertEqual(r["smooth"], [])
        self.assertEqual(r["boundary"], [])
        self.assertEqual(len(r["junctions"]), 8)
        for wire in r["sharp"]:
            self.assertIsInstance(wire, Part.Wire)
            self.assertFalse(wire.isClosed(), "an edge runs from corner to corner")
            self.assertAlmostEqual(wire.Length, EDGE, delta=4 * SPACING)

    def test_each_sharp_wire_has_its_angle_or_none(self):
        # A cube's edges are right angles; None where the angle was not estimated.
        r = self.result
        self.assertEqual(len(r["sharp_angles"]), len(r["sharp"]))
        for angle in r["sharp_angles"]:
            self.assertTrue(angle is None or isinstance(angle, float), angle)
        self.assertEqual(support.estimates_outside(r["sharp_angles"], 75.0, 105.0), [])
        self.assertEqual(r["smooth_blend_radii"], [])

    def test_per_point_results(self):
        r = self.result
        for key in ("regions", "patches", "labels", "curvature"):
            self.assertEqual(len(r[key]), len(self.cube), key)
        self.assertEqual(max(r["regions"]) + 1, 6, "one region per face")
        self.assertEqual(set(r["thresholds"].keys()), set(range(6)))
        self.assertTrue(all(t == [] for t in r["thresholds"].values()), "flat faces")
        self.assertTrue(set(r["labels"]) <= {-1, 0})
        self.assertAlmostEqual(r["spacing"], SPACING, delta=0.3 * SPACING)

    def test_a_points_feature_gives_world_coordinates(self):
        doc = support.new_document("World")
        try:
            cloud = support.add_cloud(doc, self.cube)
            shift = FreeCAD.Vector(0, 0, 1000)
            cloud.Placement.Base = shift
            doc.recompute()
            r = FeatureLines.extract(cloud)
            self.assertEqual(len(r["sharp"]), 12)
            box = Part.Compound(r["sharp"]).BoundBox
            self.assertLess(box.Center.distanceToPoint(shift), 2 * SPACING)
            kernel = FeatureLines.extract(cloud.Points)  # a kernel carries the placement too
            self.assertLess(Part.Compound(kernel["sharp"]).BoundBox.Center.distanceToPoint(shift),
                            2 * SPACING)
        finally:
            support.close_document(doc)

    def test_extract_gives_what_the_document_object_holds(self):
        # One conversion of the core's result: the dict and the object's outputs agree.
        doc = support.new_document("SameOutputs")
        try:
            cloud = support.add_cloud(doc, self.cube)
            cloud.Placement = FreeCAD.Placement(FreeCAD.Vector(5, -3, 2),
                                                FreeCAD.Rotation(FreeCAD.Vector(1, 1, 0), 30))
            lines = FeatureLines.makeExtraction(cloud)
            doc.recompute()
            r = FeatureLines.extract(cloud)
            for key, name in (("regions", "PointRegion"), ("patches", "PointPatch"),
                              ("labels", "PointLabel")):
                self.assertEqual(list(r[key]), list(getattr(lines, name)), key)
            self.assertEqual(len(r["sharp"]), lines.SharpLineCount)
            for mine, theirs in zip(r["sharp"], lines.SharpWires.Wires):
                self.assertEqual([v.Point for v in mine.OrderedVertexes],
                                 [v.Point for v in theirs.OrderedVertexes])
            self.assertEqual(list(r["junctions"]), list(lines.Junctions))
            self.assertEqual([t for ts in r["thresholds"].values() for t in ts],
                             list(lines.UsedThresholds))
            self.assertEqual(r["closed"], lines.ClosedLineCount)
            # None in the dict where the property holds NaN: not estimated.
            self.assertEqual(len(r["sharp_angles"]), len(lines.SharpAngles))
            for mine, theirs in zip(r["sharp_angles"], lines.SharpAngles):
                self.assertTrue(mine == theirs or (mine is None and math.isnan(theirs)))
            self.assertAlmostEqual(r["spacing"], lines.Spacing.Value, places=12)
        finally:
            support.close_document(doc)

    def test_rounded_cube_wires_per_type_and_threshold(self):
        points = sampled_shapes.rounded_cube(40.0, RADIUS, SPACING, 6)
        r = FeatureLines.extract(points, ThresholdMode="Explicit",
                                 Thresholds=[0.75 / RADIUS, 0.25 / RADIUS])
        self.assertEqual(r["sharp"], [])
        self.assertEqual(r["thresholds"], {0: [0.75 / RADIUS, 0.25 / RADIUS]})
        self.assertEqual(len(r["smooth"]), 14)
        self.assertEqual(sorted(r["smooth_thresholds"]),
                         sorted([0.25 / RADIUS] * 6 + [0.75 / RADIUS] * 8))
        self.assertEqual(set(r["smooth_regions"]), {0})
        self.assertEqual(r["closed"], 14)
        # Every blend of the part has radius RADIUS; None where not estimated.
        self.assertEqual(len(r["smooth_blend_radii"]), 14)
        self.assertEqual(support.estimates_outside(r["smooth_blend_radii"], RADIUS / 2,
                                                   2 * RADIUS), [])
        self.assertEqual(r["sharp_angles"], [])
        # The same keyword names as the properties, per region:
        same = FeatureLines.extract(points, ThresholdMode="Explicit",
                                    RegionThresholds={0: "0.125 0.0416666"})
        self.assertEqual(len(same["smooth"]), 14)


class HistogramTest(unittest.TestCase):
    def test_two_levels_are_split_in_the_valley(self):
        rnd = random.Random(4)
        low = [rnd.gauss(0.02, 0.004) for _ in range(2000)]
        high = [rnd.gauss(0.20, 0.01) for _ in range(500)]
        h = FeatureLines.histogram(low + high)
        self.assertTrue(max(low) < h["threshold"] < min(high), h["threshold"])
        self.assertGreater(h["ratio"], 1.0)
        self.assertEqual(sum(h["counts"]), 2500, "no outliers dropped")
        self.assertEqual(len(h["counts"]), 50)
        self.assertAlmostEqual(h["minimum"], min(low + high))
        self.assertAlmostEqual(h["bin_width"] * 50, max(low + high) - min(low + high))
        dropped = FeatureLines.histogram(low + high, bins=20, outliers=1.0)
        self.assertEqual(sum(dropped["counts"]), 2500 - 25)
        self.assertEqual(len(dropped["counts"]), 20)

    def test_lower_and_higher_thresholds(self):
        # Three levels (Sec. 2.3): the next threshold below and above the middle one.
        rnd = random.Random(5)
        low = [rnd.gauss(0.01, 0.002) for _ in range(2000)]
        middle = [rnd.gauss(0.10, 0.005) for _ in range(1000)]
        high = [rnd.gauss(0.30, 0.01) for _ in range(500)]
        levels = low + middle + high
        below = FeatureLines.histogram(levels, below=0.2)
        self.assertTrue(max(low) <= below["threshold"] < min(middle), below["threshold"])
        above = FeatureLines.histogram(levels, above=0.05)
        self.assertTrue(max(middle) <= above["threshold"] < min(high), above["threshold"])

    def test_histogram_of_an_extraction_region(self):
        doc = support.new_document("Histogram")
        try:
            cloud, lines = support.add_extraction(
                doc, sampled_shapes.rounded_cube(40.0, RADIUS, SPACING, 6))
            h = FeatureLines.histogram(lines, region=0)
            # The first threshold of the region's histogram lies in the valley of one the
            # extraction used (the extraction applies it mid-valley): almost no curvature
            # value of the region falls between the two.
            curvature = [c for c, r in zip(lines.PointCurvature, lines.PointRegion) if r == 0]
            between = min(sum(1 for c in curvature if min(t, h["threshold"]) < c <= max(t, h["threshold"]))
                          for t in lines.UsedThresholds)
            self.assertLess(between, 0.01 * len(curvature))
            self.assertEqual(sum(h["counts"]), sum(1 for r in lines.PointRegion if r == 0))
            with self.assertRaisesRegex(ValueError, "no curvature values in region 5"):
                FeatureLines.histogram(lines, region=5)
            # A cloud: the mean curvature of the whole cloud.
            whole = FeatureLines.histogram(cloud)
            self.assertTrue(0 < whole["threshold"] < 1 / RADIUS, whole["threshold"])
        finally:
            support.close_document(doc)


class DocumentFunctionsTest(unittest.TestCase):
    def test_make_extraction_sets_the_parameters_given(self):
        doc = support.new_document("Make")
        try:
            cloud = support.add_cloud(doc, sampled_shapes.cube(EDGE, SPACING, 3))
            lines = FeatureLines.makeExtraction(cloud, "Edges", GrowAngle=25, Smoothing="Never",
                                                Thresholds=[0.1], RegionThresholds={2: [0.3]})
            self.assertEqual(lines.Name, "Edges")
            self.assertEqual(lines.TypeId, "FeatureLines::Extraction")
            self.assertEqual(lines.Source, cloud)
            self.assertEqual(lines.GrowAngle.Value, 25)
            self.assertEqual(lines.Smoothing, "Never")
            self.assertEqual(list(lines.Thresholds), [0.1])
            self.assertEqual(lines.RegionThresholds, {"2": "0.29999999999999999"})
            doc.recompute()
            self.assertEqual(lines.SharpLineCount, 12)
            with self.assertRaisesRegex(ValueError, "JoinAngle"):
                FeatureLines.makeExtraction(cloud, JoinAngle=0)
            self.assertEqual(len(doc.Objects), 2, "a refused call adds nothing")
        finally:
            support.close_document(doc)

    def test_parameters_are_the_properties(self):
        doc = support.new_document("Parameters")
        try:
            lines = doc.addObject("FeatureLines::Extraction", "FeatureLines")
            for p in FeatureLines.parameters():
                self.assertIn(p["name"], lines.PropertiesList)
                self.assertEqual(lines.getGroupOfProperty(p["name"]), p["group"])
                self.assertTrue(p["doc"])
                self.assertEqual(lines.getDocumentationOfProperty(p["name"]), p["doc"])
                if p["kind"] in ("Thresholds", "FloatList", "Map"):
                    continue
                value = getattr(lines, p["name"])
                if p["kind"] == "Choice":
                    self.assertEqual(value, p["choices"][int(p["default"])])
                elif p["kind"] == "Angle":
                    self.assertEqual(value.Value, p["default"])
                    self.assertEqual(value.Unit, FreeCAD.Units.Angle)
                else:
                    self.assertEqual(value, p["default"], p["name"])
            self.assertEqual(lines.NeighbourCount, 16)
            self.assertEqual(lines.HistogramBins, 50, "L_start of Sec. 2.2")
        finally:
            support.close_document(doc)


class CloudFilesTest(unittest.TestCase):
    def write_plane(self, name):
        path = os.path.join(support.scratch_dir("files"), name)
        points = sampled_shapes.plane(EDGE, SPACING, 8)
        with open(path, "w") as f:
            f.write("# a sheet\n")
            for p in points:
                f.write("%.9g %.9g %.9g\n" % p)
        return path, points

    def test_read_cloud(self):
        path, points = self.write_plane("sheet.xyz")
        kernel = FeatureLines.readCloud(path)
        self.assertIsInstance(kernel, Points.Points)
        self.assertEqual(kernel.CountPoints, len(points))
        self.assertLess(kernel.Points[5].distanceToPoint(FreeCAD.Vector(*points[5])), 1e-5)

    def test_xyz_files_are_importable(self):
        self.assertIn("FeatureLinesImport", FreeCAD.getImportType("xyz"))
        import FeatureLinesImport

        path, points = self.write_plane("imported.xyz")
        doc = support.new_document("Import")
        try:
            cloud = FeatureLinesImport.insert(path, doc.Name)
            self.assertEqual(cloud.TypeId, "Points::Feature")
            self.assertEqual(cloud.Label, "imported")
            self.assertEqual(cloud.Points.CountPoints, len(points))
            r = FeatureLines.extract(cloud)
            self.assertEqual(len(r["boundary"]), 1)
        finally:
            support.close_document(doc)
        opened = FeatureLinesImport.open(path)
        try:
            self.assertEqual(opened.Objects[0].Points.CountPoints, len(points))
        finally:
            support.close_document(opened)

    def test_a_bad_file_imports_nothing(self):
        import FeatureLinesImport

        path = os.path.join(support.scratch_dir("bad-import"), "words.xyz")
        with open(path, "w") as f:
            f.write("1 2 3\nfour five six\n")
        documents = set(FreeCAD.listDocuments())
        with self.assertRaisesRegex(ValueError, r"words\.xyz, line 2"):
            FeatureLinesImport.open(path)
        with self.assertRaisesRegex(ValueError, r"words\.xyz, line 2"):
            FeatureLinesImport.insert(path, "NotThere")
        self.assertEqual(set(FreeCAD.listDocuments()), documents, "no empty document is left")

    def test_the_shipped_sample_imports(self):
        path = os.path.join(os.environ.get("FEATURELINES_SAMPLES", ""), "boss_blend.xyz")
        if not os.path.exists(path):
            self.skipTest("samples/boss_blend.xyz not found")
        with open(path) as f:
            rows = sum(1 for line in f if line.strip() and not line.lstrip().startswith("#"))
        self.assertEqual(FeatureLines.readCloud(path).CountPoints, rows)


class CacheTest(unittest.TestCase):
    def test_statistics_and_capacity(self):
        FeatureLines.clearCache()
        s = FeatureLines.cacheStatistics()
        self.assertEqual((s["geometry_hits"], s["geometry_misses"]), (0, 0))
        self.assertEqual(s["capacity"], 2)
        cube = sampled_shapes.cube(EDGE, SPACING, 9)
        FeatureLines.extract(cube)
        FeatureLines.extract(cube, ThresholdMode="First")
        s = FeatureLines.cacheStatistics()
        self.assertEqual((s["geometry_misses"], s["geometry_hits"]), (1, 1))
        self.assertEqual((s["analysis_misses"], s["analysis_hits"]), (1, 1))
        FeatureLines.setCacheCapacity(0)
        FeatureLines.extract(cube)
        s = FeatureLines.cacheStatistics()
        self.assertEqual((s["geometry_entries"], s["analysis_entries"]), (0, 0))
        self.assertEqual(s["geometry_misses"], 2)
        FeatureLines.setCacheCapacity(2)


if __name__ == "__main__":
    unittest.main()
