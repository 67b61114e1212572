# SPDX-License-Identifier: LGPL-2.1-or-later
"""Editing feature lines made before (by a macro, here with the corner threshold only): a
double click opens the panel at stage (b) with the object's threshold; the patch preview; a
lower threshold added and accepted, then Cancel restores the object; opened again by setEdit,
an option changed and Run writes it to the object, a threshold added, OK keeps it all as one
undo step, which undo reverts."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, RADIUS, SPACING = 40.0, 6.0, 0.7
FILLET, CORNER = 1 / (2 * RADIUS), 1 / RADIUS
state = {}


def setup():
    import FeatureLines
    import FreeCAD
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("Edit")
    state["doc"] = doc
    cloud = g.add_cloud(doc, sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 6))
    lines = FeatureLines.makeExtraction(cloud)
    doc.recompute()
    # The corner threshold as a macro finds it (Sec. 2.3: the valley above the fillets').
    tau1 = FeatureLines.searchThreshold(lines, 0, lower=FILLET / 2)
    g.check(FILLET < tau1 < CORNER, "corner threshold %g" % tau1)
    lines.ThresholdMode = "Explicit"
    lines.Thresholds = [tau1]
    doc.recompute()
    g.check(lines.SmoothLineCount == 8, "8 corner loops to start from")
    state.update(cloud=cloud, lines=lines, tau1=tau1, grow=lines.GrowAngle.Value)


def double_click():
    g.check(state["lines"].ViewObject.doubleClicked(), "a double click edits the object")
    g.check(g.panel_is_open(), "the panel opens")


def stage_b_from_the_object():
    g.check(g.stage() == "b", "an object with thresholds opens at stage (b)")
    g.check("8 smooth line(s), 8 closed" in g.label("labelStage"), g.label("labelStage"))
    g.select_option("comboPreview", 1)  # patches
    g.check("patch" in g.label("labelLegend"), "the legend speaks of patches")
    g.check(not state["cloud"].ViewObject.isVisible(), "the preview replaces the cloud")
    g.screenshot("edit_patches")
    g.click("buttonAddLower")
    g.check(g.stage() == "a" and 0 < g.candidate() < FILLET, "a face threshold proposed")
    g.click("buttonAccept")
    g.check(state["lines"].SmoothLineCount == 14, "14 loops after Accept")
    g.press_dialog_button("cancel")


def cancelled():
    lines = state["lines"]
    g.check(list(lines.Thresholds) == [state["tau1"]], "Cancel restores the thresholds")
    g.check(lines.SmoothLineCount == 8, "and the 8 loops: %d" % lines.SmoothLineCount)
    g.check(state["cloud"].ViewObject.isVisible(), "the preview is gone")
    g.check(state["doc"].UndoNames == [], "no undo step: %s" % state["doc"].UndoNames)


def set_edit():
    import FreeCADGui

    FreeCADGui.ActiveDocument.setEdit(state["lines"].Name)
    g.check(g.panel_is_open(), "setEdit opens the panel")


def change_an_option():
    import PySide2.QtWidgets as QtWidgets

    g.check(g.stage() == "b", "stage (b) again")
    # A sharp-edge option: the regions are analysed again, the rounded cube stays one region.
    g.find(QtWidgets.QDoubleSpinBox, "GrowAngle").setValue(state["grow"] + 5)
    g.check(state["lines"].GrowAngle.Value == state["grow"], "not before Run")
    g.click("buttonRun")


def option_written():
    lines = state["lines"]
    g.check(lines.GrowAngle.Value == state["grow"] + 5, "Run writes the option to the object")
    g.check(lines.SmoothLineCount == 8, "the explicit threshold gives the 8 loops still")
    g.click("buttonAddLower")
    g.click("buttonAccept")
    g.check(lines.SmoothLineCount == 14, "14 loops")
    g.press_dialog_button("ok")


def kept_then_undone():
    import FreeCADGui

    lines, doc = state["lines"], state["doc"]
    g.check(len(lines.Thresholds) == 2, "OK keeps both thresholds")
    g.check(doc.UndoNames == ["Edit feature lines"], "one undo step: %s" % doc.UndoNames)
    FreeCADGui.runCommand("Std_Undo")
    g.check(list(lines.Thresholds) == [state["tau1"]], "undo: the corner threshold alone")
    g.check(lines.GrowAngle.Value == state["grow"], "undo: the option as it was")
    g.check(lines.SmoothLineCount == 8, "undo: the 8 loops")


def build(steps):
    steps.then("8 corner loops made by a macro", setup)
    steps.then("double click", double_click)
    steps.then("stage (b); patches; add a lower threshold, accept; Cancel",
               stage_b_from_the_object, wait_for=g.analysis_finished)
    steps.then("the object as before", cancelled, wait_for=lambda: not g.panel_is_open())
    steps.then("setEdit", set_edit)
    steps.then("GrowAngle + 5 degrees, Run", change_an_option, wait_for=g.analysis_finished)
    steps.then("the option written; a lower threshold; OK", option_written,
               wait_for=g.analysis_finished)
    steps.then("one undo step reverts the edit", kept_then_undone,
               wait_for=lambda: not g.panel_is_open())


g.start("edit feature lines", build)
