# SPDX-License-Identifier: LGPL-2.1-or-later
"""Nothing is trusted blindly: a document whose saved result is damaged (a hand-edited or broken
.FCStd, an embedded file that fails to read) reopens with the extraction in error and a message
naming the property; the functions that read the stored lists refuse a damaged, failed or out
of date extraction; a recompute rebuilds it. A document opened in a FreeCAD without the
module loses the extraction when saved there, as docs/freecad-app.md says."""

import os
import re
import shutil
import struct
import subprocess
import textwrap
import unittest
import zipfile

import FreeCAD
import Points

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5


def rewrite_entry(path, name, change):
    """Rewrites the entry `name` of the .FCStd archive `path` as change(bytes) -> bytes."""
    copy = path + ".tmp"
    with zipfile.ZipFile(path) as source, zipfile.ZipFile(copy, "w", zipfile.ZIP_DEFLATED) as out:
        for item in source.infolist():
            data = source.read(item.filename)
            out.writestr(item, change(data) if item.filename == name else data)
    os.replace(copy, path)


def point_indices_file(path, prop):
    """The archive entry that holds the per-point list `prop` (Document.xml names it)."""
    with zipfile.ZipFile(path) as archive:
        xml = archive.read("Document.xml").decode("utf-8")
    match = re.search(r'<Property name="%s"[^>]*>\s*<PointIndices file="([^"]+)"' % prop, xml)
    return match.group(1)


def point_indices(values):
    """A per-point list as PropertyPointIndices writes it: count, then int32 values."""
    return struct.pack("<I", len(values)) + struct.pack("<%di" % len(values), *values)


def read_point_indices(data):
    (count,) = struct.unpack_from("<I", data)
    return list(struct.unpack_from("<%di" % count, data, 4))


class DamagedDocumentTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = support.scratch_dir("damaged")
        cls.cube = sampled_shapes.cube(EDGE, SPACING, 11)
        cls.saved = os.path.join(cls.folder, "cube.FCStd")
        doc = support.new_document("Saved")
        cloud, lines = support.add_extraction(doc, cls.cube)
        assert support.error_message(lines) == "" and lines.SharpLineCount == 12
        doc.saveAs(cls.saved)
        support.close_document(doc)

    def setUp(self):
        self.doc = None

    def tearDown(self):
        if self.doc:
            support.close_document(self.doc)

    def damaged_copy(self, name, entry, change):
        path = os.path.join(self.folder, name)
        shutil.copyfile(self.saved, path)
        rewrite_entry(path, entry, change)
        return path

    def reopen(self, path):
        self.doc = FreeCAD.openDocument(path)
        return self.doc.getObject("FeatureLines")

    def assertRefused(self, lines, words):
        objects = len(self.doc.Objects)
        with self.assertRaisesRegex(ValueError, words):
            FeatureLines.makePatchClouds(lines)
        with self.assertRaisesRegex(ValueError, words):
            FeatureLines.histogram(lines)
        self.assertEqual(len(self.doc.Objects), objects, "no patch was added")

    def assertRecovers(self, lines):
        self.doc.recompute()
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(lines.SharpLineCount, 12)
        self.assertEqual(len(lines.PointRegion), len(self.cube))
        self.assertEqual(len(FeatureLines.makePatchClouds(lines)), 6, "one patch per face")

    def test_the_saved_document_reopens_sound(self):
        lines = self.reopen(self.saved)
        self.assertEqual(support.error_message(lines), "")
        self.assertNotIn("Touched", lines.State)
        self.assertEqual(len(FeatureLines.makePatchClouds(lines)), 6)

    def test_a_short_point_region_is_an_error_naming_it(self):
        entry = point_indices_file(self.saved, "PointRegion")
        path = self.damaged_copy("short.FCStd", entry,
                                 lambda data: point_indices(read_point_indices(data)[:-10]))
        lines = self.reopen(path)
        self.assertIn("Invalid", lines.State)
        message = support.error_message(lines)
        self.assertIn("PointRegion holds %d values" % (len(self.cube) - 10), message)
        self.assertIn("PointPatch", message)
        self.assertRefused(lines, "PointRegion")
        self.assertRecovers(lines)

    def test_a_region_number_beyond_region_count_is_an_error(self):
        entry = point_indices_file(self.saved, "PointRegion")

        def region_99(data):
            values = read_point_indices(data)
            values[7] = 99
            return point_indices(values)

        lines = self.reopen(self.damaged_copy("region.FCStd", entry, region_99))
        self.assertIn("PointRegion[7] = 99 lies outside -1 .. RegionCount - 1 = 5",
                      support.error_message(lines))
        self.assertRefused(lines, "PointRegion\\[7\\] = 99")
        self.assertRecovers(lines)

    def test_an_embedded_file_that_fails_to_read_is_an_error(self):
        # The count promises every point, the data stops halfway: FreeCAD reports "Reading
        # failed from embedded file" and the list restores empty.
        entry = point_indices_file(self.saved, "PointPatch")
        path = self.damaged_copy("truncated.FCStd", entry,
                                 lambda data: data[:len(data) // 2])
        lines = self.reopen(path)
        self.assertEqual(len(lines.PointPatch), 0)
        message = support.error_message(lines)
        self.assertIn("PointPatch holds 0 values", message)
        self.assertRefused(lines, "PointPatch holds 0 values")
        self.assertRecovers(lines)

    def test_a_line_count_that_disagrees_with_the_wires_is_an_error(self):
        def fewer_sharp_lines(data):
            xml = data.decode("utf-8")
            xml, n = re.subn(r'(<Property name="SharpLineCount" type="App::PropertyInteger"[^>]*>'
                             r'\s*<Integer value=")12(")', r"\g<1>11\g<2>", xml)
            assert n == 1
            return xml.encode("utf-8")

        lines = self.reopen(self.damaged_copy("count.FCStd", "Document.xml", fewer_sharp_lines))
        self.assertIn("SharpLineCount is 11 but SharpWires holds 12 wires",
                      support.error_message(lines))
        self.assertRefused(lines, "SharpLineCount")
        self.assertRecovers(lines)

    def test_angles_of_fewer_wires_than_the_sharp_lines_are_an_error(self):
        # SharpAngles is a list file: its count, then doubles (App::PropertyFloatList).
        def float_list_file(path, prop):
            with zipfile.ZipFile(path) as archive:
                xml = archive.read("Document.xml").decode("utf-8")
            return re.search(r'<Property name="%s"[^>]*>\s*<FloatList file="([^"]+)"' % prop,
                             xml).group(1)

        def one_angle_less(data):
            (count,) = struct.unpack_from("<I", data)
            assert count == 12, count
            values = struct.unpack_from("<%dd" % count, data, 4)[:-1]
            return struct.pack("<I", len(values)) + struct.pack("<%dd" % len(values), *values)

        entry = float_list_file(self.saved, "SharpAngles")
        lines = self.reopen(self.damaged_copy("angles.FCStd", entry, one_angle_less))
        self.assertIn("SharpAngles holds 11 values but SharpLineCount is 12",
                      support.error_message(lines))
        self.assertRefused(lines, "SharpAngles")
        self.assertRecovers(lines)
        self.assertEqual(len(lines.SharpAngles), 12)

    def test_unpaired_threshold_lists_are_an_error(self):
        def one_more_region(data):
            xml = data.decode("utf-8")
            xml, n = re.subn(r'(<Property name="UsedThresholdRegions"[^>]*>\s*<IntegerList '
                             r'count=")0(">)\s*(</IntegerList>)',
                             r'\g<1>1\g<2><I v="0"/>\g<3>', xml)
            assert n == 1, xml[xml.find("UsedThresholdRegions") - 100:][:400]
            return xml.encode("utf-8")

        lines = self.reopen(self.damaged_copy("pairs.FCStd", "Document.xml", one_more_region))
        self.assertIn("UsedThresholds holds 0 values but UsedThresholdRegions 1",
                      support.error_message(lines))
        self.assertRecovers(lines)

    def test_lists_of_another_point_count_than_the_source_are_an_error(self):
        # Saved after the cloud changed, without a recompute: the lists belong to the old cloud.
        doc = FreeCAD.openDocument(self.saved)
        doc.getObject("Cloud").Points = Points.Points(
            [FreeCAD.Vector(*p) for p in self.cube[:-100]])
        path = os.path.join(self.folder, "changed.FCStd")
        doc.saveAs(path)
        support.close_document(doc)
        lines = self.reopen(path)
        message = support.error_message(lines)
        self.assertIn("hold %d values but the source 'Cloud' has %d points"
                      % (len(self.cube), len(self.cube) - 100), message)
        self.assertRefused(lines, "'FeatureLines'")
        self.doc.recompute()
        self.assertEqual(support.error_message(lines), "")
        self.assertEqual(len(lines.PointRegion), len(self.cube) - 100)


class StaleExtractionTest(unittest.TestCase):
    def setUp(self):
        self.doc = support.new_document("Stale")
        self.cube = sampled_shapes.cube(EDGE, SPACING, 11)
        self.cloud, self.lines = support.add_extraction(self.doc, self.cube)
        self.assertEqual(len(FeatureLines.makePatchClouds(self.lines)), 6)
        self.patches = len(self.doc.Objects)

    def tearDown(self):
        support.close_document(self.doc)

    def set_points(self, points):
        self.cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in points])

    def assertRefused(self, words):
        with self.assertRaisesRegex(ValueError, words):
            FeatureLines.makePatchClouds(self.lines)
        with self.assertRaisesRegex(ValueError, words):
            FeatureLines.histogram(self.lines)
        self.assertEqual(len(self.doc.Objects), self.patches, "no patch was added")

    def assertRecovered(self):
        self.doc.recompute()
        self.assertEqual(support.error_message(self.lines), "")
        self.assertEqual(len(FeatureLines.makePatchClouds(self.lines)), 6)

    def test_nan_points_with_the_same_count_fail_and_are_refused(self):
        nan = float("nan")
        self.set_points(self.cube[:-1] + [(nan, 0.0, 0.0)])
        self.doc.recompute()
        self.assertIn("invalid (NaN) points", support.error_message(self.lines))
        self.assertEqual(len(self.lines.PointPatch), len(self.cube), "the old lists are kept")
        self.assertRefused("failed its last recompute.*invalid \\(NaN\\) points")
        self.set_points(self.cube)
        self.assertRecovered()

    def test_an_emptied_source_fails_and_is_refused(self):
        self.set_points([])
        self.doc.recompute()
        self.assertIn("Too few points", support.error_message(self.lines))
        self.assertRefused("failed its last recompute")
        self.set_points(self.cube)
        self.assertRecovered()

    def test_a_changed_parameter_is_out_of_date(self):
        self.lines.GrowAngle = 30
        self.assertRefused("out of date")
        self.assertRecovered()

    def test_a_changed_source_is_out_of_date(self):
        moved = [(x + 1.0, y, z) for x, y, z in self.cube]
        self.set_points(moved)
        self.assertRefused("its source 'Cloud' changed")
        self.assertRecovered()

    def test_a_failed_extraction_saved_and_reopened_is_still_refused(self):
        self.set_points(self.cube[:5])
        self.doc.recompute()
        path = os.path.join(support.scratch_dir("stale"), "failed.FCStd")
        self.doc.saveAs(path)
        support.close_document(self.doc)
        self.doc = FreeCAD.openDocument(path)
        self.cloud = self.doc.getObject("Cloud")
        self.lines = self.doc.getObject("FeatureLines")
        self.patches = len(self.doc.Objects)
        self.assertIn("Too few points", support.error_message(self.lines))
        self.assertRefused("failed its last recompute")
        self.set_points(self.cube)
        self.assertRecovered()


FREECADCMD = shutil.which("freecadcmd")

# Run in a freecadcmd of its own: argv[1] a document to open, argv[2] where to save it.
WITHOUT_MODULE = textwrap.dedent("""\
    import os, sys, traceback
    import FreeCAD
    code = 1
    try:
        source, target = os.environ["FL_SOURCE"], os.environ["FL_TARGET"]
        doc = FreeCAD.openDocument(source)
        print("OBJECTS", " ".join(o.TypeId for o in doc.Objects))
        print("POINTS", doc.getObject("Cloud").Points.CountPoints)
        doc.saveAs(target)
        code = 0
    except BaseException:
        traceback.print_exc()
    finally:
        sys.stdout.flush()
        os._exit(code)
    """)


@unittest.skipUnless(FREECADCMD, "freecadcmd not found")
class WithoutTheModuleTest(unittest.TestCase):
    """What docs/freecad-app.md says of a FreeCAD without FeatureLines, shown."""

    @classmethod
    def setUpClass(cls):
        cls.folder = support.scratch_dir("without-module")
        doc = support.new_document("Shared")
        cls.cube = sampled_shapes.cube(EDGE, SPACING, 11)
        support.add_extraction(doc, cls.cube)
        cls.source = os.path.join(cls.folder, "shared.FCStd")
        doc.saveAs(cls.source)
        support.close_document(doc)
        cls.target = os.path.join(cls.folder, "resaved.FCStd")
        script = os.path.join(cls.folder, "open_without_module.py")
        with open(script, "w") as f:
            f.write(WITHOUT_MODULE)
        empty = os.path.join(cls.folder, "home")
        for sub in ("Mod", "config", "data", "cache"):
            os.makedirs(os.path.join(empty, sub))
        env = dict(os.environ, FREECAD_USER_DATA=empty, FREECAD_USER_HOME=empty,
                   XDG_CONFIG_HOME=os.path.join(empty, "config"),
                   XDG_DATA_HOME=os.path.join(empty, "data"),
                   XDG_CACHE_HOME=os.path.join(empty, "cache"),
                   FL_SOURCE=cls.source, FL_TARGET=cls.target)
        run = subprocess.run([FREECADCMD, script], env=env, capture_output=True, text=True,
                             timeout=300)
        cls.code, cls.output = run.returncode, run.stdout + run.stderr

    def test_the_points_stay_and_the_extraction_is_gone_after_saving(self):
        self.assertEqual(self.code, 0, self.output)
        self.assertIn("OBJECTS Points::Feature\n", self.output)
        self.assertIn("POINTS %d\n" % len(self.cube), self.output)
        doc = FreeCAD.openDocument(self.target)
        try:
            self.assertEqual([o.TypeId for o in doc.Objects], ["Points::Feature"])
            self.assertEqual(doc.getObject("Cloud").Points.CountPoints, len(self.cube))
        finally:
            support.close_document(doc)
        with zipfile.ZipFile(self.target) as archive:
            names = archive.namelist()
            xml = archive.read("Document.xml").decode("utf-8")
        self.assertNotIn("FeatureLines::Extraction", xml)
        self.assertFalse(any(n.startswith("PointRegion") for n in names), names)

    def test_the_original_file_still_holds_the_extraction(self):
        doc = FreeCAD.openDocument(self.source)
        try:
            lines = doc.getObject("FeatureLines")
            self.assertEqual(support.error_message(lines), "")
            self.assertEqual(lines.SharpLineCount, 12)
        finally:
            support.close_document(doc)


if __name__ == "__main__":
    unittest.main()
