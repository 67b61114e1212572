# SPDX-License-Identifier: LGPL-2.1-or-later
"""Thresholds per smooth region: a cloud of two rounded cubes and a ball apart from each other is
three smooth regions (connected parts of the cloud, Sec. 1.2). The corner threshold accepted in
one cube's region gives it its 8 corner loops; the regions the user leaves alone keep the
Automatic mode's thresholds (the other cube its 8 corner and 6 face loops) or, where there are
none (the ball), the panel says that region gets no smooth line. Accepted in the other cube too,
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
    ball = [(x + 2 * SHIFT, y, z) for x, y, z in sampled_shapes.sphere(EDGE / 2, SPACING, 3)]
    state["counts"] = [len(first), len(second), len(ball)]
    state["doc"] = doc
    state["cloud"] = g.add_cloud(doc, first + second + ball, "TwoCubesAndABall")
    FreeCADGui.Selection.addSelection(state["cloud"])
    FreeCADGui.runCommand("FeatureLines_Extract")
    state["lines"] = [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"][0]


def region_thresholds(lines):
    """RegionThresholds as numbers: {region: [thresholds]}."""
    return {int(k): [float(t) for t in v.split()] for k, v in lines.RegionThresholds.items()}


def shape_of(wire):
    """0: the first cube, 1: the second, 2: the ball (by the x of the wire's centre)."""
    return min(2, int(g.wire_centre(wire).x / SHIFT + 0.5))


def lines_per_shape(lines):
    per_shape = [0, 0, 0]
    for w in lines.SmoothWires.Wires:
        per_shape[shape_of(w)] += 1
    return per_shape


def select_shape(shape):
    """Selects the region of `shape` (0, 1: the cubes, 2: the ball) in the region selector, found
    by its point count; returns its region number."""
    import PySide2.QtWidgets as QtWidgets

    combo = g.find(QtWidgets.QComboBox, "comboRegion")
    wanted = "(%d points)" % state["counts"][shape]
    index = [i for i in range(combo.count()) if combo.itemText(i).endswith(wanted)]
    g.check(len(index) == 1, "one region of %s: %s" % (wanted, [combo.itemText(i) for i in
                                                              range(combo.count())]))
    g.select_option("comboRegion", index[0])
    return g.thresholds_panel().property("region")


def corner_threshold(region):
    """The corner threshold of `region` (Higher when the first candidate is the face one),
    accepted."""
    g.check(g.stage() == "a", "region %d at stage (a)" % region)
    if not FILLET < g.candidate() < CORNER:
        g.click("buttonHigher")
    tau = g.candidate()
    g.check(FILLET < tau < CORNER, "corner threshold %g" % tau)
    return tau


def corner_threshold_in_first_region():
    import PySide2.QtWidgets as QtWidgets

    combo = g.find(QtWidgets.QComboBox, "comboRegion")
    g.check(combo.isVisible() and combo.count() == 3, "three regions: %d" % combo.count())
    state["regions"] = [select_shape(shape) for shape in (2, 1, 0)][::-1]
    first, second, ball = state["regions"]
    state["tau0"] = corner_threshold(first)
    g.click("buttonAccept")
    lines = state["lines"]
    g.check(lines.ThresholdMode == "Explicit", "explicit")
    g.check(list(lines.Thresholds) == [], "no threshold for other regions")
    held = region_thresholds(lines)
    g.check(held.get(first) == [state["tau0"]], "the first cube's threshold: %s" % held)
    # The regions without a threshold of the user's keep the Automatic mode's: the second cube
    # its corner and face thresholds (Sec. 2.3: faces | fillets | corners), the ball none (one
    # curvature, no valley).
    kept = held.get(second, [])
    g.check(len(kept) == 2 and FILLET < kept[0] < CORNER and 0 < kept[1] < FILLET,
            "the second cube keeps its automatic thresholds: %s" % held)
    g.check(ball not in held, "the ball has no threshold: %s" % held)
    g.check(lines_per_shape(lines) == [8, 14, 0],
            "8 corner loops, 8 corner + 6 face loops, none: %s" % lines_per_shape(lines))
    g.check(lines.ClosedLineCount == 22, "all closed: %d" % lines.ClosedLineCount)
    stage = g.label("labelStage")
    g.check("keep the automatic ones: %d (" % second in stage, "the panel says so: %s" % stage)
    g.check("No smooth lines</b> in region(s) %d" % ball in stage,
            "the panel names the region without lines: %s" % stage)
    g.check_panel_fits("stage (b) with the regions' note")
    g.screenshot("regions_first")


def corner_threshold_in_second_region():
    first, second, ball = state["regions"]
    select_shape(1)
    state["tau1"] = corner_threshold(second)
    g.screenshot("regions_second")
    g.click("buttonAccept")
    lines = state["lines"]
    g.check(region_thresholds(lines) == {first: [state["tau0"]], second: [state["tau1"]]},
            "both regions' thresholds: %s" % dict(lines.RegionThresholds))
    g.check(lines.SmoothLineCount == 16 and lines.ClosedLineCount == 16,
            "8 closed loops per cube: %d" % lines.SmoothLineCount)
    g.check(lines_per_shape(lines) == [8, 8, 0], "8 on each cube: %s" % lines_per_shape(lines))
    g.check(sorted(set(lines.SmoothLineRegions)) == sorted([first, second]),
            "lines of both cubes' regions")
    g.click("buttonDone")


def done():
    g.check(not g.panel_is_open(), "Done closes the panel")
    g.check(state["lines"].SmoothLineCount == 16, "16 loops kept")
    g.view_image("regions_lines")


def build(steps):
    steps.then("two rounded cubes and a ball apart; Extract", setup)
    steps.then("the first cube: the corner threshold, Accept", corner_threshold_in_first_region,
               wait_for=g.analysis_finished)
    steps.then("the second cube: the corner threshold, Accept, Done",
               corner_threshold_in_second_region)
    steps.then("the lines of both", done, wait_for=lambda: not g.panel_is_open())


g.start("thresholds per region", build)
