# SPDX-License-Identifier: LGPL-2.1-or-later
"""Editing feature lines made before (by a macro, here with the face threshold only: the 6
face loops): a double click opens the panel at stage (b) with the object's threshold; the patch
preview; a higher threshold added and accepted (the corner loops), then Cancel restores the
object; opened again by setEdit, an option changed and Run writes it to the object, the higher
threshold added again, OK keeps it all as one undo step, which undo reverts."""

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
    # The face threshold as a macro finds it (Sec. 2.2: the first valley, after the faces').
    tau2 = FeatureLines.searchThreshold(lines, 0)
    g.check(0 < tau2 < FILLET, "face threshold %g" % tau2)
    lines.ThresholdMode = "Explicit"
    lines.Thresholds = [tau2]
    doc.recompute()
    g.check(lines.SmoothLineCount == 6, "6 face loops to start from")
    state.update(cloud=cloud, lines=lines, tau2=tau2, grow=lines.GrowAngle.Value)


def double_click():
    g.check(state["lines"].ViewObject.doubleClicked(), "a double click edits the object")
    g.check(g.panel_is_open(), "the panel opens")


def stage_b_from_the_object():
    g.check(g.stage() == "b", "an object with thresholds opens at stage (b)")
    g.check("6 smooth line(s), 6 closed" in g.label("labelStage"), g.label("labelStage"))
    g.select_option("comboPreview", 1)  # patches
    g.check("patch" in g.label("labelLegend"), "the legend speaks of patches")
    g.check(not state["cloud"].ViewObject.isVisible(), "the preview replaces the cloud")
    g.screenshot("edit_patches")
    g.click("buttonAddHigher")
    c = g.candidate()
    g.check(g.stage() == "a" and c > state["tau2"], "Add higher proposes one above: %g" % c)
    g.check(FILLET < c < CORNER, "between the fillets and the corners: %g" % c)
    g.click("buttonAccept")
    g.check(state["lines"].SmoothLineCount == 14, "14 loops after Accept")
    g.press_dialog_button("cancel")


def cancelled():
    lines = state["lines"]
    g.check(list(lines.Thresholds) == [state["tau2"]], "Cancel restores the thresholds")
    g.check(lines.SmoothLineCount == 6, "and the 6 loops: %d" % lines.SmoothLineCount)
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
    g.check(lines.SmoothLineCount == 6, "the explicit threshold gives the 6 loops still")
    g.click("buttonAddHigher")
    g.click("buttonAccept")
    g.check(lines.SmoothLineCount == 14, "14 loops")
    g.press_dialog_button("ok")


def kept_then_undone():
    import FreeCADGui

    lines, doc = state["lines"], state["doc"]
    g.check(len(lines.Thresholds) == 2, "OK keeps both thresholds")
    g.check(doc.UndoNames == ["Edit feature lines"], "one undo step: %s" % doc.UndoNames)
    FreeCADGui.runCommand("Std_Undo")
    g.check(list(lines.Thresholds) == [state["tau2"]], "undo: the face threshold alone")
    g.check(lines.GrowAngle.Value == state["grow"], "undo: the option as it was")
    g.check(lines.SmoothLineCount == 6, "undo: the 6 loops")


def build(steps):
    steps.then("6 face loops made by a macro", setup)
    steps.then("double click", double_click)
    steps.then("stage (b); patches; add a higher threshold, accept; Cancel",
               stage_b_from_the_object, wait_for=g.analysis_finished)
    steps.then("the object as before", cancelled, wait_for=lambda: not g.panel_is_open())
    steps.then("setEdit", set_edit)
    steps.then("GrowAngle + 5 degrees, Run", change_an_option, wait_for=g.analysis_finished)
    steps.then("the option written; a higher threshold; OK", option_written,
               wait_for=g.analysis_finished)
    steps.then("one undo step reverts the edit", kept_then_undone,
               wait_for=lambda: not g.panel_is_open())


g.start("edit feature lines", build)
