# SPDX-License-Identifier: LGPL-2.1-or-later
"""The demo's figures quoted in the README and docs/freecad-app.md are what the demo prints:
samples/demo.py is run (freecadcmd, the module of this build) on the shipped cloud and each
quote between the "demo figures" markers is compared with its summary (demo_figures.py)."""

import os
import shutil
import subprocess
import tempfile
import unittest

import demo_figures

REPOSITORY = os.path.dirname(os.path.dirname(os.environ["FEATURELINES_TEST_DIR"]))


class DemoFiguresTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        freecadcmd = shutil.which("freecadcmd")
        samples = os.environ["FEATURELINES_SAMPLES"]
        with tempfile.TemporaryDirectory() as folder:
            env = dict(os.environ,
                       FEATURELINES_DEMO_CLOUD=os.path.join(samples, "boss_blend.xyz"),
                       FEATURELINES_DEMO_OUTPUT=os.path.join(folder, "demo.FCStd"))
            run = subprocess.run([freecadcmd, os.path.join(samples, "demo.py")], env=env,
                                 cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 universal_newlines=True, timeout=600)
        cls.output = run.stdout
        cls.code = run.returncode

    def test_the_demo_runs_and_prints_a_summary(self):
        self.assertEqual(self.code, 0, self.output)
        printed = demo_figures.summary(self.output)
        self.assertTrue(printed[0].startswith("Feature lines of boss_blend"), printed)
        self.assertTrue(any(l.startswith("  sharp lines") for l in printed), printed)

    def test_every_quote_is_what_the_demo_prints(self):
        printed = demo_figures.summary(self.output)
        for name in demo_figures.QUOTING_FILES:
            with open(os.path.join(REPOSITORY, name), encoding="utf-8") as f:
                text = f.read()
            with self.subTest(file=name):
                self.assertTrue(demo_figures.quotes(text), "%s quotes no demo figures" % name)
                self.assertEqual(demo_figures.differences(text, printed), [])


class QuoteCheckTest(unittest.TestCase):
    """The comparison itself, on a made-up summary: a drifted figure is found, the seconds are
    not compared, a partial quote is checked line by line."""

    PRINTED = ["Feature lines of part", "  points          100", "  sharp lines     5",
               "  smooth lines    10 (fillet borders)", "  time            0.53 s",
               "  patch clouds    14 (Points objects for surface fitting)"]

    def quote(self, body, whole=False):
        return "text\n<!-- demo figures%s: x -->\n```\n%s\n```\n<!-- end of demo figures -->\n" % (
            " (all)" if whole else "", "\n".join(body))

    def test_a_drifted_figure_is_found(self):
        text = self.quote(["  sharp lines     5", "  smooth lines    26 (fillet borders)"])
        found = demo_figures.differences(text, self.PRINTED)
        self.assertEqual(len(found), 1, found)
        self.assertIn("26", found[0])
        self.assertIn("10 (fillet borders)", found[0])

    def test_seconds_differ_freely_but_a_whole_quote_must_be_whole(self):
        whole = list(self.PRINTED)
        whole[4] = "  time            9.99 s"
        self.assertEqual(demo_figures.differences(self.quote(whole, True), self.PRINTED), [])
        self.assertEqual(len(demo_figures.differences(self.quote(whole[:3], True),
                                                      self.PRINTED)), 1)

    def test_rewriting_takes_the_printed_lines(self):
        text = self.quote(["  smooth lines    26 (fillet borders)"])
        new = demo_figures.rewritten(text, self.PRINTED)
        self.assertIn("  smooth lines    10 (fillet borders)\n", new)
        self.assertEqual(demo_figures.differences(new, self.PRINTED), [])
