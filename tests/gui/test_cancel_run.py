# SPDX-License-Identifier: LGPL-2.1-or-later
"""A long analysis runs in the background: on a cloud of about 95 000 points the panel shows its
progress while the interface goes on (this test's own steps run meanwhile), Cancel stops it
with the document as it was, and Cancel of the dialog leaves no object and no undo step.

However fast the machine, the run must still be going when Cancel is pressed: a progress
observer (FeatureLines.setProgressObserver, which the panel's runs report to as recomputes do)
holds the worker thread at its first report until this test has pressed Cancel run."""

import os
import sys
import threading
import time

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

state = {}


def setup():
    import FreeCAD
    import FreeCADGui
    import sampled_shapes

    import FeatureLines

    pressed = threading.Event()
    state["pressed"] = pressed

    def hold_until_cancel_is_pressed(done, stage):
        # Runs in the worker thread; waiting releases the interpreter to the GUI's steps.
        deadline = time.monotonic() + 60
        while not pressed.is_set() and time.monotonic() < deadline:
            time.sleep(0.02)
        return True

    FeatureLines.setProgressObserver(hold_until_cancel_is_pressed)
    g.prepare_window()
    doc = FreeCAD.newDocument("Cancel")
    state["doc"] = doc
    state["cloud"] = g.add_cloud(doc, sampled_shapes.rounded_cube(60.0, 8.0, 0.45, 3), "Big")
    FreeCADGui.Selection.addSelection(state["cloud"])
    FreeCADGui.runCommand("FeatureLines_Extract")
    lines = [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"]
    g.check(len(lines) == 1, "the command adds the object")
    state["lines"] = lines[0]
    state["neighbours"] = lines[0].NeighbourCount


def running():
    import PySide2.QtWidgets as QtWidgets

    # This step runs from the event loop while the worker thread analyses the cloud.
    g.check(g.analysis_running(), "the analysis runs in the background")
    g.check(not g.button("buttonRun").isEnabled(), "no second run meanwhile")
    g.check(not g.thresholds_panel().isEnabled(), "no thresholds before the analysis")
    bar = g.find(QtWidgets.QProgressBar, "progressBar")
    g.check(bar.isVisible(), "the progress bar shows")
    status = g.label("labelStatus")
    # (The observer holds the worker in its first report, before the panel hears of it.)
    g.check(status.startswith("Analysing"), "the status line says what runs: %s" % status)
    g.check("neighbours" not in bar.text(), "the bar shows the share only: %s" % bar.text())
    g.grab_widget(g.find(QtWidgets.QWidget, "TaskExtractionOptions"), "cancel_running_panel")
    g.check_panel_fits("analysis running")
    g.click("buttonCancelRun")
    state["pressed"].set()


def cancelled():
    import FeatureLines

    FeatureLines.setProgressObserver(None)
    lines = state["lines"]
    status = g.label("labelStatus")
    g.check("cancelled" in status, "the panel says so: %s" % status)
    g.check(g.panel_is_open(), "the panel stays open")
    g.check(lines.Shape.isNull(), "no lines were made")
    g.check(lines.SmoothLineCount == 0 and lines.SharpLineCount == 0, "no outputs")
    g.check("Touched" in lines.State, "the object was not recomputed")
    g.check(lines.NeighbourCount == state["neighbours"], "its parameters are unchanged")
    g.check(g.button("buttonRun").isEnabled(), "Run is offered again")
    g.screenshot("cancel_done")
    g.press_dialog_button("cancel")


def closed():
    doc = state["doc"]
    g.check([o.Name for o in doc.Objects] == [state["cloud"].Name], "no object is left")
    g.check(doc.UndoNames == [], "no undo step: %s" % doc.UndoNames)
    g.check(state["cloud"].ViewObject.isVisible(), "the cloud is shown again")


def build(steps):
    steps.then("Extract feature lines on 95 000 points", setup)
    steps.then("the analysis runs: Cancel run", running, wait_for=g.analysis_running)
    steps.then("the run stops, the document as it was; Cancel", cancelled,
               wait_for=g.analysis_finished)
    steps.then("no object, no undo step", closed, wait_for=lambda: not g.panel_is_open())


g.start("cancel a run", build)
