# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cleaning a cube's twelve sharp lines from the Feature Lines menu at FreeCAD's default layout:
Drop short lines... at half an edge keeps the twelve; Delete selected lines with edges of two
lines selected in the 3D view leaves ten, Undo brings the twelve back and Redo the ten; with one
line deleted its two corners hold two lines each, and Merge lines meeting end to end joins them
(11 -> 9 lines), undone in one step; Restore all lines gives the twelve back. Each is one undo
step and a macro line."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, SPACING = 20.0, 0.5
state = {}


def setup():
    import FeatureLines
    import FreeCAD
    import FreeCADGui
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("CleanLines")
    state["doc"] = doc
    cloud = g.add_cloud(doc, sampled_shapes.cube(EDGE, SPACING, 11))
    lines = FeatureLines.makeExtraction(cloud)
    doc.recompute()
    g.check(len(lines.Shape.Wires) == 12, "a cube's 12 edges: %d" % len(lines.Shape.Wires))
    cloud.ViewObject.Visibility = False
    lines.ViewObject.LineWidth = 4
    state.update(cloud=cloud, lines=lines)
    state["macro"] = g.start_macro_recording("clean_lines")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lines)


def run_from_menu(command, text):
    """Runs the command of the Feature Lines menu's item, checked to read `text` (as
    test_commands does: the item's enabled state follows the selection on a timer)."""
    import FreeCADGui

    menu_action(command, text)
    FreeCADGui.runCommand(command)


def menu_action(command, text):
    """The command's item of the Feature Lines menu, checked to read `text`."""
    from PySide2 import QtWidgets

    for action in g.main_window().findChildren(QtWidgets.QAction, command):
        menus = [w.title() for w in action.associatedWidgets() if isinstance(w, QtWidgets.QMenu)]
        if "&Feature Lines" in menus:
            g.check(action.text() == text, "%s reads '%s'" % (command, action.text()))
            return action
    g.check(False, "the Feature Lines menu has no %s" % command)


def wires():
    return len(state["lines"].Shape.Wires)


def undo_names():
    return state["doc"].UndoNames


def drop_short():
    from PySide2 import QtCore, QtWidgets


    def fill():
        dialog = QtWidgets.QApplication.activeModalWidget()
        if not isinstance(dialog, QtWidgets.QInputDialog):
            QtCore.QTimer.singleShot(50, fill)
            return
        dialog.setDoubleValue(EDGE / 2)
        g.screenshot("clean_lines_drop_short_dialog")
        dialog.accept()

    QtCore.QTimer.singleShot(50, fill)
    run_from_menu("FeatureLines_DropShortLines", "Drop short lines...")
    lines = state["lines"]
    g.check(abs(lines.MinLineLength.Value - EDGE / 2) < 1e-9,
            "MinLineLength %s" % lines.MinLineLength)
    g.check(wires() == 12, "no edge is shorter than half an edge: %d" % wires())
    g.check(undo_names()[:1] == ["Drop short lines"], "one undo step: %s" % undo_names())


def select_edges_of(wire_indices):
    """Selects one edge of each of the wires, as clicks in the 3D view do."""
    import FreeCADGui

    lines = state["lines"]
    edges = lines.Shape.Edges
    FreeCADGui.Selection.clearSelection()
    for w in wire_indices:
        edge = lines.Shape.Wires[w].Edges[0]
        index = next(i for i, e in enumerate(edges) if e.isSame(edge))
        FreeCADGui.Selection.addSelection(lines, "Edge%d" % (index + 1))
    g.settle(0.5)
    g.log("selected: %s" % [(s.ObjectName, s.SubElementNames)
                            for s in FreeCADGui.Selection.getSelectionEx()])


def delete_two():
    import FreeCADGui

    lines = state["lines"]
    state["gone"] = [lines.Shape.Wires[w].BoundBox.Center for w in (2, 7)]
    select_edges_of([2, 7])
    g.screenshot("clean_lines_two_selected")
    run_from_menu("FeatureLines_DeleteLines", "Delete selected lines")
    g.check(wires() == 10, "two lines deleted: %d left" % wires())
    for centre in state["gone"]:
        nearest = min(w.BoundBox.Center.distanceToPoint(centre) for w in lines.Shape.Wires)
        g.check(nearest > 1.0, "the selected lines are the ones gone")
    g.check(undo_names()[:1] == ["Delete selected lines"], "one undo step: %s" % undo_names())
    g.screenshot("clean_lines_two_deleted")
    FreeCADGui.Selection.addSelection(lines)
    FreeCADGui.runCommand("Std_Undo")
    g.check(wires() == 12, "Undo brings the two lines back: %d" % wires())
    g.check(list(lines.RemovedLines) == [], "and empties RemovedLines")
    FreeCADGui.runCommand("Std_Redo")
    g.check(wires() == 10, "Redo deletes them again: %d" % wires())
    FreeCADGui.runCommand("Std_Undo")
    g.check(wires() == 12, "undone again: %d" % wires())


def merge_after_deleting_one():
    import FreeCADGui

    lines = state["lines"]
    select_edges_of([0])
    run_from_menu("FeatureLines_DeleteLines", "Delete selected lines")
    g.check(wires() == 11, "one line deleted: %d" % wires())
    FreeCADGui.Selection.addSelection(lines)
    run_from_menu("FeatureLines_MergeLines", "Merge lines meeting end to end")
    g.check(wires() == 9, "the two corners of the deleted edge join their lines: %d" % wires())
    merged = [ids for ids in lines.LineIds if len(ids.split()) == 2]
    g.check(len(merged) == 2, "two merged lines: %s" % list(lines.LineIds))
    g.check(undo_names()[:1] == ["Merge lines meeting end to end"], "one undo step: %s" % undo_names())
    g.screenshot("clean_lines_merged")
    FreeCADGui.runCommand("Std_Undo")
    g.check(wires() == 11 and not lines.MergeEndToEnd, "Undo unmerges: %d" % wires())


def restore_all():
    import FreeCADGui

    FreeCADGui.Selection.addSelection(state["lines"])
    run_from_menu("FeatureLines_RestoreLines", "Restore all lines")
    lines = state["lines"]
    g.check(wires() == 12, "every line back: %d" % wires())
    g.check(list(lines.RemovedLines) == [] and lines.MinLineLength.Value == 0,
            "no cleaning left")


def macro_lines():
    macro = g.stop_macro_recording(state["macro"])
    obj = "FeatureLines.cleanLines(App.getDocument('CleanLines').getObject('FeatureLines'), "
    for args in ("minLength=10.000000)", "remove=[2, 7])", "remove=[0])", "mergeEndToEnd=True)",
                 "restore=True)"):
        g.check(obj + args in macro, "the macro records %s:\n%s" % (obj + args, macro))


def build(steps):
    steps.then("a cube's feature lines, selected", setup)
    steps.then("Drop short lines... at half an edge", drop_short)
    steps.then("Delete selected lines, Undo, Redo", delete_two)
    steps.then("Merge lines meeting end to end after one line is deleted", merge_after_deleting_one)
    steps.then("Restore all lines", restore_all)
    steps.then("the macro recorded it", macro_lines)


g.start("clean lines", build)
