# SPDX-License-Identifier: LGPL-2.1-or-later
"""The workbench's commands after the panel: on a rounded cube's feature lines (Automatic mode,
Fig. 7: 8 corner and 6 face loops) Colour cloud by flat / curved draws the cloud in the label
colours in place of its own points and Plain cloud gives it back; Make patch clouds makes one
Points object per patch in a group, 6 of them the flat faces, as one undo step that Std_Undo
removes and Std_Redo restores; both are recorded as macro lines."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, RADIUS, SPACING = 40.0, 6.0, 0.7
HALF = EDGE / 2
state = {}


def setup():
    import FeatureLines
    import FreeCAD
    import FreeCADGui
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("Commands")
    state["doc"] = doc
    cloud = g.add_cloud(doc, sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 6))
    lines = FeatureLines.makeExtraction(cloud)
    doc.recompute()
    g.check(lines.SmoothLineCount == 14, "8 corner + 6 face loops: %d" % lines.SmoothLineCount)
    state.update(cloud=cloud, lines=lines)
    state["macro"] = g.start_macro_recording("commands")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lines)


def menu_has(command, text):
    """The command is an item of the Feature Lines menu, with this text."""
    from PySide2 import QtWidgets

    found = []
    for action in g.main_window().findChildren(QtWidgets.QAction, command):
        menus = [w.title() for w in action.associatedWidgets() if isinstance(w, QtWidgets.QMenu)]
        found.append((action.text(), menus))
    g.check(any(t == text and "&Feature Lines" in m for t, m in found),
            "the Feature Lines menu offers %s as '%s': %s" % (command, text, found))


def colour_by_label():
    import FreeCADGui

    menu_has("FeatureLines_ColourByLabel", "Colour cloud by flat / curved (label)")
    FreeCADGui.runCommand("FeatureLines_ColourByLabel")
    lines, cloud = state["lines"], state["cloud"]
    g.check(lines.ViewObject.ColourPoints == "Label", "the view colours by label")
    g.check(not cloud.ViewObject.isVisible(), "the coloured points replace the cloud's own")
    g.screenshot("commands_colour_by_label")


def plain_cloud():
    import FreeCADGui

    FreeCADGui.runCommand("FeatureLines_ColourByCurvature")
    g.check(state["lines"].ViewObject.ColourPoints == "Curvature", "by curvature")
    FreeCADGui.runCommand("FeatureLines_ColourNothing")
    g.check(state["lines"].ViewObject.ColourPoints == "Nothing", "back to the plain cloud")
    g.check(state["cloud"].ViewObject.isVisible(), "the cloud's own points again")


def patch_clouds():
    import FreeCADGui

    menu_has("FeatureLines_MakePatchClouds", "Make patch clouds")
    doc = state["doc"]
    before = len(doc.Objects)
    FreeCADGui.runCommand("FeatureLines_MakePatchClouds")
    groups = doc.getObjectsByLabel("FeatureLines patches")
    g.check(len(groups) == 1, "one group of patch clouds")
    clouds = groups[0].Group
    g.check(len(doc.Objects) == before + 1 + len(clouds), "the group and its clouds are new")
    flat = 0
    for patch in clouds:
        pts = patch.Points.Points
        g.check(len(pts) >= 2 * state["lines"].NeighbourCount, "a patch big enough to fit")
        if all(abs(max(abs(p.x), abs(p.y), abs(p.z)) - HALF) < 1e-3 for p in pts):
            flat += 1
    g.check(flat == 6, "six patches are the flat faces: %d" % flat)
    g.check(doc.UndoNames[:1] == ["Make patch clouds"], "one undo step: %s" % doc.UndoNames)
    state["count"] = len(doc.Objects)
    FreeCADGui.runCommand("Std_Undo")
    g.check(len(doc.Objects) == before, "undo removes them")
    FreeCADGui.runCommand("Std_Redo")
    g.check(len(doc.Objects) == state["count"], "redo brings them back")


def macro_lines():
    macro = g.stop_macro_recording(state["macro"])
    for line in (".ColourPoints = 'Label'", ".ColourPoints = 'Nothing'",
                 "FeatureLines.makePatchClouds(App.getDocument('Commands').getObject("):
        g.check(line in macro, "the macro records %s:\n%s" % (line, macro))


def build(steps):
    steps.then("a rounded cube's feature lines, selected", setup)
    steps.then("Colour cloud by flat / curved", colour_by_label)
    steps.then("by curvature, then the plain cloud", plain_cloud)
    steps.then("Make patch clouds, undo, redo", patch_clouds)
    steps.then("the macro recorded it", macro_lines)


g.start("commands", build)
