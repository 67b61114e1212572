# SPDX-License-Identifier: LGPL-2.1-or-later
"""Thresholds per smooth region: a cloud of two rounded cubes apart from each other is two
smooth regions (connected parts of the cloud, Sec. 1.2). The corner threshold accepted in one
region gives that cube its 8 corner loops and nothing to the other; accepted in the other too,
RegionThresholds holds both and each cube has its 8 loops."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, RADIUS, SPACING = 20.0, 4.0, 0.5
SHIFT = 2 * EDGE  # the second cube's centre on the x axis
FILLET, CORNER = 1 / (2 * RADIUS), 1 / RADIUS
state = {}


def setup():
    import FreeCAD
    import FreeCADGui
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("Regions")
    first = sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 1)
    second = [(x + SHIFT, y, z) for x, y, z in sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 2)]
    state["doc"] = doc
    state["cloud"] = g.add_cloud(doc, first + second, "TwoCubes")
    FreeCADGui.Selection.addSelection(state["cloud"])
    FreeCADGui.runCommand("FeatureLines_Extract")
    state["lines"] = [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"][0]


def region_thresholds(lines):
    """RegionThresholds as numbers: {region: [thresholds]}."""
    return {int(k): [float(t) for t in v.split()] for k, v in lines.RegionThresholds.items()}


def cube_of(wire):
    return 1 if g.wire_centre(wire).x > SHIFT / 2 else 0


def corner_threshold_in_first_region():
    import PySide2.QtWidgets as QtWidgets

    combo = g.find(QtWidgets.QComboBox, "comboRegion")
    g.check(combo.isVisible() and combo.count() == 2, "two regions: %d" % combo.count())
    g.check(g.thresholds_panel().property("region") == 0, "region 0 first")
    if not FILLET < g.candidate() < CORNER:
        g.click("buttonHigher")
    g.check(FILLET < g.candidate() < CORNER, "corner threshold %g" % g.candidate())
    state["tau0"] = g.candidate()
    g.click("buttonAccept")
    lines = state["lines"]
    g.check(lines.ThresholdMode == "Explicit", "explicit")
    g.check(list(lines.Thresholds) == [], "no threshold for the regions not chosen")
    g.check(region_thresholds(lines) == {0: [state["tau0"]]},
            "region 0's threshold: %s" % dict(lines.RegionThresholds))
    g.check(lines.SmoothLineCount == 8, "8 corner loops: %d" % lines.SmoothLineCount)
    cubes = {cube_of(w) for w in lines.SmoothWires.Wires}
    g.check(len(cubes) == 1, "all on one cube")
    state["first_cube"] = cubes.pop()


def corner_threshold_in_second_region():
    g.select_option("comboRegion", 1)
    g.check(g.thresholds_panel().property("region") == 1, "region 1")
    g.check(g.stage() == "a", "region 1 still at stage (a)")
    if not FILLET < g.candidate() < CORNER:
        g.click("buttonHigher")
    g.check(FILLET < g.candidate() < CORNER, "corner threshold %g" % g.candidate())
    state["tau1"] = g.candidate()
    g.screenshot("regions_second")
    g.click("buttonAccept")
    lines = state["lines"]
    g.check(region_thresholds(lines) == {0: [state["tau0"]], 1: [state["tau1"]]},
            "both regions' thresholds: %s" % dict(lines.RegionThresholds))
    g.check(lines.SmoothLineCount == 16 and lines.ClosedLineCount == 16,
            "8 closed loops per cube: %d" % lines.SmoothLineCount)
    per_cube = [0, 0]
    for w in lines.SmoothWires.Wires:
        per_cube[cube_of(w)] += 1
    g.check(per_cube == [8, 8], "8 on each cube: %s" % per_cube)
    g.check(sorted(set(lines.SmoothLineRegions)) == [0, 1], "lines of both regions")
    g.click("buttonDone")


def done():
    g.check(not g.panel_is_open(), "Done closes the panel")
    g.check(state["lines"].SmoothLineCount == 16, "16 loops kept")
    g.view_image("regions_lines")


def build(steps):
    steps.then("two rounded cubes apart; Extract", setup)
    steps.then("region 0: the corner threshold, Accept", corner_threshold_in_first_region,
               wait_for=g.analysis_finished)
    steps.then("region 1: the corner threshold, Accept, Done", corner_threshold_in_second_region)
    steps.then("the lines of both", done, wait_for=lambda: not g.panel_is_open())


g.start("thresholds per region", build)
