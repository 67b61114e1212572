# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cleaning the lines of an extraction (FeatureLines.cleanLines, the Cleaning properties) on a
sampled cube, whose twelve sharp edges meet three at each of its eight corners: dropping lines
shorter than half an edge keeps the twelve, deleting two leaves ten, and once one edge is deleted
its two corners hold only two lines each, which merging joins into one line each."""

import unittest

import FeatureLines
import sampled_shapes
import support

EDGE, SPACING = 20.0, 0.5


def edge_count(wire):
    return len(wire.Edges)


def corner_of(wire):
    """The corner two lines of an L-shaped wire meet at: the vertex furthest from both ends."""
    start, end = support.wire_ends(wire)
    return max((v.Point for v in wire.OrderedVertexes),
               key=lambda p: min(p.distanceToPoint(start), p.distanceToPoint(end)))


class CleanLinesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("CleanLines")
        cls.cloud, cls.lines = support.add_extraction(cls.doc,
                                                      sampled_shapes.cube(EDGE, SPACING, 11))

    @classmethod
    def tearDownClass(cls):
        support.close_document(cls.doc)

    def setUp(self):
        FeatureLines.cleanLines(self.lines, restore=True)
        self.doc.recompute()
        self.assertEqual(len(self.lines.Shape.Wires), 12)

    def recompute(self):
        self.doc.recompute()
        self.assertEqual(support.error_message(self.lines), "")
        return self.lines.Shape.Wires

    def test_every_line_has_its_own_id(self):
        self.assertEqual(sorted(int(i) for i in self.lines.LineIds), list(range(12)))

    def test_dropping_lines_shorter_than_half_an_edge_keeps_twelve(self):
        FeatureLines.cleanLines(self.lines, minLength=EDGE / 2)
        self.assertEqual(self.lines.MinLineLength.Value, EDGE / 2)
        self.assertEqual(len(self.recompute()), 12)
        self.assertEqual(self.lines.SharpLineCount, 12)

    def test_dropping_lines_longer_than_every_edge_keeps_none(self):
        # Each edge line is shorter than the edge (it ends on the corner junctions).
        longest = max(w.Length for w in self.lines.Shape.Wires)
        self.assertLessEqual(longest, EDGE * 1.01)
        FeatureLines.cleanLines(self.lines, minLength=longest * 1.01)
        self.assertEqual(len(self.recompute()), 0)
        self.assertEqual(self.lines.SharpLineCount, 0)
        FeatureLines.cleanLines(self.lines, minLength=0)
        self.assertEqual(len(self.recompute()), 12)

    def test_deleting_two_lines_leaves_ten_and_survives_recompute(self):
        wires = self.lines.Shape.Wires
        gone = [wires[2].BoundBox.Center, wires[7].BoundBox.Center]
        ids = [self.lines.LineIds[2], self.lines.LineIds[7]]
        FeatureLines.cleanLines(self.lines, remove=[2, 7])
        self.assertEqual(sorted(self.lines.RemovedLines), sorted(int(i) for i in ids))
        left = self.recompute()
        self.assertEqual(len(left), 10)
        self.assertEqual(self.lines.SharpLineCount, 10)
        for centre in gone:
            self.assertGreater(min(w.BoundBox.Center.distanceToPoint(centre) for w in left), 1.0)
        # A recompute from the source (touched) gives the same ten.
        self.lines.touch()
        self.assertEqual(len(self.recompute()), 10)
        # Indices name the wires now shown: deleting wire 0 again takes one more line.
        FeatureLines.cleanLines(self.lines, remove=[0])
        self.assertEqual(len(self.recompute()), 9)
        FeatureLines.cleanLines(self.lines, restore=True)
        self.assertEqual(len(self.recompute()), 12)

    def test_merging_alone_changes_nothing_where_three_lines_meet(self):
        FeatureLines.cleanLines(self.lines, mergeEndToEnd=True)
        self.assertEqual(len(self.recompute()), 12)

    def test_lines_meeting_two_at_a_corner_merge_into_one(self):
        # Deleting one edge leaves its two corners with two lines each: 11 lines, 9 once merged,
        # two of them L-shaped (two edges long, turning at a corner).
        removed = self.lines.Shape.Wires[0]
        ends = support.wire_ends(removed)
        FeatureLines.cleanLines(self.lines, remove=[0])
        self.assertEqual(len(self.recompute()), 11)
        single = sorted(w.Length for w in self.lines.Shape.Wires)
        FeatureLines.cleanLines(self.lines, mergeEndToEnd=True)
        wires = self.recompute()
        self.assertEqual(len(wires), 9)
        merged = [w for w, ids in zip(wires, self.lines.LineIds) if len(ids.split()) == 2]
        self.assertEqual(len(merged), 2)
        # A merged line keeps an angle (its pieces', by length): still a right angle, or NaN.
        self.assertEqual(len(self.lines.SharpAngles), 9)
        self.assertEqual(support.estimates_outside(self.lines.SharpAngles, 75.0, 105.0), [])
        for wire in merged:
            self.assertFalse(wire.isClosed())
            self.assertGreater(wire.Length, 1.9 * single[0])
            # It turns at one of the deleted edge's corners.
            self.assertLess(min(corner_of(wire).distanceToPoint(e) for e in ends), 1e-6)
        # Dropping lines shorter than 1.5 edges keeps exactly the two merged ones.
        FeatureLines.cleanLines(self.lines, minLength=1.5 * single[-1])
        self.assertEqual(len(self.recompute()), 2)

    def test_merged_lines_are_deleted_whole(self):
        FeatureLines.cleanLines(self.lines, remove=[0], mergeEndToEnd=True)
        wires = self.recompute()
        self.assertEqual(len(wires), 9)
        merged = [i for i, ids in enumerate(self.lines.LineIds) if len(ids.split()) == 2]
        FeatureLines.cleanLines(self.lines, remove=merged[:1])
        self.assertEqual(len(self.lines.RemovedLines), 3)
        # The three edges of one corner are gone; its three neighbours keep two lines each, which
        # merge: 9 edges in 6 lines, three of them L-shaped.
        wires = self.recompute()
        self.assertEqual(len(wires), 6)
        self.assertEqual(sum(len(ids.split()) for ids in self.lines.LineIds), 9)
        self.assertEqual(sorted(len(ids.split()) for ids in self.lines.LineIds), [1, 1, 1, 2, 2, 2])

    def test_bad_arguments_are_refused_before_anything_changes(self):
        with self.assertRaisesRegex(ValueError, "no wire 12"):
            FeatureLines.cleanLines(self.lines, remove=[12])
        with self.assertRaisesRegex(ValueError, "minLength must be 0 or more"):
            FeatureLines.cleanLines(self.lines, minLength=-1, remove=[0])
        with self.assertRaisesRegex(TypeError, "no keyword 'min_length'"):
            FeatureLines.cleanLines(self.lines, min_length=1)
        with self.assertRaisesRegex(TypeError, "FeatureLines::Extraction"):
            FeatureLines.cleanLines(self.cloud, minLength=1)
        self.assertEqual(list(self.lines.RemovedLines), [])
        self.assertEqual(self.lines.MinLineLength.Value, 0)


if __name__ == "__main__":
    unittest.main()
