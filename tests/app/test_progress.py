# SPDX-License-Identifier: LGPL-2.1-or-later
"""Progress within a stage, as FreeCAD's bar and a script's observer see it: the observer
(FeatureLines.setProgressObserver) hears of the long stages as their loops go, the fraction
rising within the stage, and a False from it inside a stage cancels the run there.

The core reports within a stage at most every 0.2 s. However fast the machine, the observer
makes the reports due: it waits 0.25 s at each report of the normals stage, so every later
report of that stage's loop comes after the interval."""

import time
import unittest

import FeatureLines
import sampled_shapes

WAITS = 5


class ProgressWithinAStageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cube = sampled_shapes.rounded_cube(20.0, 3.0, 0.25, 5)

    def setUp(self):
        FeatureLines.clearCache()

    def tearDown(self):
        FeatureLines.setProgressObserver(None)

    def test_the_observer_hears_of_a_stage_as_it_goes(self):
        calls = []

        def observer(done, stage):
            calls.append((done, stage))
            if stage == "normals" and sum(1 for c in calls if c[1] == "normals") <= WAITS:
                time.sleep(0.25)
            return True

        FeatureLines.setProgressObserver(observer)
        FeatureLines.extract(self.cube)
        normals = [done for done, stage in calls if stage == "normals"]
        self.assertGreater(len(normals), WAITS, calls)
        self.assertTrue(all(a < b for a, b in zip(normals, normals[1:])), normals)
        self.assertTrue(all(0.15 <= done < 0.2 for done in normals), normals)
        self.assertEqual(calls[-1], (1.0, "done"))

    def test_false_within_a_stage_cancels_there(self):
        calls = []

        def observer(done, stage):
            calls.append((done, stage))
            if stage != "normals":
                return True
            time.sleep(0.25)
            # The stage's start goes on, its first report from within the loop cancels.
            return sum(1 for c in calls if c[1] == "normals") < 2

        FeatureLines.setProgressObserver(observer)
        with self.assertRaisesRegex(RuntimeError, "cancelled"):
            FeatureLines.extract(self.cube)
        self.assertEqual(calls[-1][1], "normals")
        self.assertLess(calls[-1][0], 0.4)


if __name__ == "__main__":
    unittest.main()
