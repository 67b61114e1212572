# SPDX-License-Identifier: LGPL-2.1-or-later
"""The interactive thresholding of Sec. 2.3 the task panel drives (App/InteractiveThresholds.h):
on a rounded cube (flat faces, fillets of mean curvature 1/(2r), corners of 1/r; Fig. 7 of
Demarsin et al. 2008) the first threshold, the next higher and lower ones lie between those
levels, the labels at the corner threshold put the inner points on the corners, and the patches
at two thresholds are the six faces, the eight corners and the fillets."""

import math
import unittest

import FeatureLines
import sampled_shapes
import support

EDGE, RADIUS, SPACING = 40.0, 6.0, 0.7
INNER = EDGE / 2 - RADIUS  # where the flat faces end and the fillets begin
FILLET, CORNER = 1 / (2 * RADIUS), 1 / RADIUS  # mean curvatures


def part_of(p):
    """'face', 'fillet' or 'corner': how many coordinates lie beyond the flat faces' square."""
    beyond = sum(1 for c in p if abs(c) > INNER)
    return ("face", "face", "fillet", "corner")[beyond]


def deep_in(p, part, margin):
    """p lies on `part` at least `margin` from its borders with the other parts."""
    a = sorted(abs(c) for c in p)
    if part == "face":
        return a[1] < INNER - margin
    if part == "corner":
        return a[0] > INNER + margin
    return a[1] > INNER + margin and a[0] < INNER - margin


class InteractiveThresholdTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("Interactive")
        cls.points = sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 6)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, cls.points)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_the_histogram_holds_every_point_of_the_region(self):
        h = FeatureLines.regionHistogram(self.lines, 0)
        self.assertEqual(len(h["counts"]), self.lines.HistogramBins)
        self.assertEqual(sum(h["counts"]), len(self.points), "one region, nothing dropped")
        self.assertTrue(math.isnan(h["outlier_cut"]), "a clean region keeps its outliers")
        top = h["minimum"] + len(h["counts"]) * h["bin_width"]
        self.assertLess(h["minimum"], FILLET / 4, "the flat faces' curvature is about 0")
        self.assertGreater(top, CORNER * 0.9, "the corners' curvature is in range")

    def test_the_first_threshold_is_the_cores(self):
        first = FeatureLines.searchThreshold(self.lines, 0)
        self.assertAlmostEqual(first, FeatureLines.histogram(self.lines, region=0)["threshold"])

    def test_higher_and_lower_thresholds_separate_the_three_levels(self):
        # Sec. 2.3: the clean faces' spike at zero is the first peak; above it the fillets',
        # then the corners'. Higher from a threshold between faces and fillets finds the one
        # between fillets and corners; lower from there finds the faces' again.
        first = FeatureLines.searchThreshold(self.lines, 0)
        self.assertTrue(0 < first < FILLET, first)
        tau1 = FeatureLines.searchThreshold(self.lines, 0, lower=first)
        self.assertTrue(FILLET < tau1 < CORNER, tau1)
        tau2 = FeatureLines.searchThreshold(self.lines, 0, upper=tau1)
        self.assertTrue(0 < tau2 < FILLET, tau2)
        between = FeatureLines.searchThreshold(self.lines, 0, lower=tau2, upper=tau1)
        self.assertTrue(tau2 < between <= tau1, between)

    def test_labels_at_the_corner_threshold_are_fig_7a(self):
        tau1 = FeatureLines.searchThreshold(self.lines, 0, lower=FILLET / 2)
        labels = FeatureLines.regionLabels(self.lines, 0, tau1)
        self.assertEqual(len(labels), len(self.points))
        inner = [p for p, l in zip(self.points, labels) if l == 1]
        self.assertTrue(inner)
        # Inner points lie on the corners (within a neighbourhood of their border).
        for p in inner:
            self.assertTrue(deep_in(p, "corner", -3 * SPACING), p)
        corners = {tuple(c > 0 for c in p) for p in inner}
        self.assertEqual(len(corners), 8, "every corner has inner points")
        for p, l in zip(self.points, labels):
            if deep_in(p, "face", 2 * SPACING) or deep_in(p, "fillet", 3 * SPACING):
                self.assertEqual(l, 0, p)  # low
            if deep_in(p, "corner", 3 * SPACING):
                self.assertEqual(l, 1, p)  # inner
        self.assertIn(2, labels, "border points ring the corners")

    def test_patches_at_two_thresholds_are_faces_fillets_and_corners(self):
        tau1 = FeatureLines.searchThreshold(self.lines, 0, lower=FILLET / 2)
        tau2 = FeatureLines.searchThreshold(self.lines, 0, upper=tau1)
        patches = FeatureLines.regionPatches(self.lines, 0, [tau1, tau2])
        self.assertEqual(len(patches), len(self.points))
        self.assertNotIn(-1, patches, "the whole cloud is one region")
        # The points deep inside one part of the surface share one patch per part, and the
        # 6 faces, 12 fillets and 8 corners are 26 different patches.
        of_part = {}
        for p, patch in zip(self.points, patches):
            kind = part_of(p)
            if not deep_in(p, kind, 3 * SPACING):
                continue
            if kind == "face":
                key = (kind,) + support.face_of(p)
            elif kind == "corner":
                key = (kind,) + tuple(c > 0 for c in p)
            else:
                axis = min(range(3), key=lambda a: abs(p[a]))
                key = (kind, axis) + tuple(p[a] > 0 for a in range(3) if a != axis)
            of_part.setdefault(key, set()).add(patch)
        self.assertEqual(len(of_part), 26)
        for key, ids in of_part.items():
            self.assertEqual(len(ids), 1, key)
        patch = {key: next(iter(ids)) for key, ids in of_part.items()}
        faces = {patch[k] for k in patch if k[0] == "face"}
        corners = {patch[k] for k in patch if k[0] == "corner"}
        fillets = {patch[k] for k in patch if k[0] == "fillet"}
        self.assertEqual(len(faces), 6)
        self.assertEqual(len(corners), 8)
        # Two fillets touch where they meet a face at a corner: the fillet level may be one
        # patch; it is neither a face nor a corner.
        self.assertFalse(fillets & (faces | corners))

    def test_patches_are_the_objects_after_a_recompute_with_those_thresholds(self):
        tau1 = FeatureLines.searchThreshold(self.lines, 0, lower=FILLET / 2)
        tau2 = FeatureLines.searchThreshold(self.lines, 0, upper=tau1)
        patches = FeatureLines.regionPatches(self.lines, 0, [tau1, tau2])
        try:
            self.lines.ThresholdMode = "Explicit"
            self.lines.Thresholds = [tau1, tau2]
            self.doc.recompute()
            self.assertEqual(support.error_message(self.lines), "")
            self.assertEqual(self.lines.SmoothLineCount, 14, "8 corner and 6 face loops")
            # The same partition (the numbering may differ).
            pairs = set(zip(patches, self.lines.PointPatch))
            self.assertEqual(len(pairs), len(set(patches)))
            self.assertEqual(len(pairs), len(set(self.lines.PointPatch)))
        finally:
            self.lines.ThresholdMode = "Automatic"
            self.lines.Thresholds = []
            self.doc.recompute()

    def test_a_recomputed_object_is_not_analysed_again(self):
        before = FeatureLines.cacheStatistics()
        FeatureLines.searchThreshold(self.lines, 0)
        after = FeatureLines.cacheStatistics()
        self.assertEqual(after["geometry_misses"], before["geometry_misses"])
        self.assertEqual(after["analysis_misses"], before["analysis_misses"])

    def test_bad_requests_are_refused_with_a_message(self):
        with self.assertRaisesRegex(ValueError, "no smooth region 3"):
            FeatureLines.searchThreshold(self.lines, 3)
        with self.assertRaisesRegex(ValueError, "finite"):
            FeatureLines.regionLabels(self.lines, 0, float("nan"))
        with self.assertRaisesRegex(ValueError, "no curvature values"):
            FeatureLines.searchThreshold(self.lines, 0, lower=2 * CORNER)
        with self.assertRaises(TypeError):
            FeatureLines.searchThreshold(self.cloud, 0)


if __name__ == "__main__":
    unittest.main()


class RepeatedThresholdTest(unittest.TestCase):
    """A candidate that gives the same patches as an accepted threshold (no patch between the
    two) repeats it; one with the fillets' patches between them does not (the task panel never
    offers or accepts the former)."""

    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("Repeated")
        points = sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 6)
        cls.cloud, cls.lines = support.add_extraction(cls.doc, points)
        cls.tau1 = FeatureLines.searchThreshold(cls.lines, 0, lower=FILLET / 2)

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def test_a_hair_below_or_above_an_accepted_threshold_repeats_it(self):
        tau1 = self.tau1
        self.assertTrue(FILLET < tau1 < CORNER, tau1)
        for candidate in (tau1 * (1 - 1e-9), tau1, tau1 * (1 + 1e-9)):
            self.assertEqual(FeatureLines.repeatedThreshold(self.lines, 0, candidate, [tau1]),
                             tau1, candidate)

    def test_the_face_threshold_under_the_corner_threshold_adds_the_fillets(self):
        tau2 = FeatureLines.searchThreshold(self.lines, 0, upper=self.tau1)
        self.assertTrue(0 < tau2 < FILLET, tau2)
        self.assertIsNone(FeatureLines.repeatedThreshold(self.lines, 0, tau2, [self.tau1]))
        self.assertIsNone(FeatureLines.repeatedThreshold(self.lines, 0, self.tau1, []))

    def test_a_threshold_above_every_corner_point_repeats_the_one_below(self):
        # Nothing is more curved than the corners: the level above such a candidate is empty.
        self.assertEqual(FeatureLines.repeatedThreshold(self.lines, 0, 10 * CORNER, [self.tau1]),
                         self.tau1)
