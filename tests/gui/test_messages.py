# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the user is told instead of a crash: Extract feature lines with nothing or something
else than a point cloud selected (a message, no object), a cloud of too few points (the
analysis fails in the panel, Cancel leaves no object), and a sharp cube whose six faces are six
smooth regions without a curvature valley (a region selector, "no candidate", OK computes its
twelve sharp edges in the sharp colour), and a dense noisy rounded cube whose curvature is taken
at a coarser scale (the status says so)."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

state = {}


def extractions(doc):
    return [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"]


def setup():
    import FreeCAD

    g.prepare_window()
    doc = FreeCAD.newDocument("Messages")
    state["doc"] = doc
    state["box"] = doc.addObject("Part::Box", "Box")
    doc.recompute()


def nothing_selected():
    import FreeCADGui

    FreeCADGui.Selection.clearSelection()
    seen = g.capture_message_box(lambda: FreeCADGui.runCommand("FeatureLines_Extract"),
                                 "message_no_cloud")
    g.check(seen.get("title") == "Select a point cloud", "a message box: %s" % seen)
    g.check("Points object" in seen.get("text", ""), "it says what to select: %s" % seen)
    g.check(not extractions(state["doc"]), "no object is added")
    g.check(not g.panel_is_open(), "no panel opens")


def a_box_selected():
    import FreeCADGui

    FreeCADGui.Selection.addSelection(state["box"])
    seen = g.capture_message_box(lambda: FreeCADGui.runCommand("FeatureLines_Extract"))
    g.check(seen.get("title") == "Select a point cloud", "a box is no cloud: %s" % seen)
    g.check(not extractions(state["doc"]), "no object is added")
    FreeCADGui.Selection.clearSelection()


def too_few_points():
    import FreeCADGui

    points = [(float(i % 3), float(i // 3), 0.1 * i) for i in range(10)]
    state["tiny"] = g.add_cloud(state["doc"], points, "Tiny")
    FreeCADGui.Selection.addSelection(state["tiny"])
    FreeCADGui.runCommand("FeatureLines_Extract")
    g.check(g.panel_is_open(), "the panel opens on a cloud")


def too_few_points_message():
    status = g.label("labelStatus")
    g.check("failed" in status and "points" in status, "the analysis says why: %s" % status)
    g.check(not g.thresholds_panel().isEnabled(), "no thresholds without an analysis")
    g.screenshot("message_too_few_points")
    g.press_dialog_button("cancel")


def too_few_points_closed():
    g.check(not extractions(state["doc"]), "Cancel removes the new object")
    g.check(state["tiny"].ViewObject.isVisible(), "the cloud is shown again")


def sharp_cube():
    import FreeCADGui
    import sampled_shapes

    state["doc"].removeObject("Tiny")
    state["doc"].removeObject("Box")
    state["cube"] = g.add_cloud(state["doc"], sampled_shapes.cube(20.0, 0.5, 11), "Cube")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(state["cube"])
    FreeCADGui.runCommand("FeatureLines_Extract")


def six_regions_without_valley():
    import PySide2.QtWidgets as QtWidgets

    combo = g.find(QtWidgets.QComboBox, "comboRegion")
    g.check(combo.isVisible() and combo.count() == 6, "one region per face: %d" % combo.count())
    g.check(g.stage() == "a", "stage (a)")
    g.check(g.candidate() != g.candidate(), "a flat face has no candidate (NaN)")
    g.check("No candidate threshold" in g.label("labelStage"), g.label("labelStage"))
    g.check(not g.button("buttonAccept").isEnabled(), "nothing to accept")
    g.select_option("comboRegion", 3)
    g.check(g.thresholds_panel().property("region") == 3, "region 3 selected")
    g.check("No candidate threshold" in g.label("labelStage"), "nor on another face")
    g.screenshot("message_no_valley")
    g.press_dialog_button("ok")


def sharp_edges_kept():
    lines = extractions(state["doc"])
    g.check(len(lines) == 1, "OK keeps the object")
    lines = lines[0]
    g.check(lines.ThresholdMode == "Automatic", "untouched thresholds stay automatic")
    g.check(lines.SharpLineCount == 12, "a cube's 12 sharp edges: %d (%s %s)"
            % (lines.SharpLineCount, lines.State, lines.getStatusString()))
    g.check(lines.SmoothLineCount == 0, "flat faces have no smooth edge")
    sharp = lines.ViewObject.SharpColor
    colours = lines.ViewObject.LineColorArray
    g.check(len(colours) == len(lines.Shape.Edges), "one colour per edge")
    g.check(all(c[:3] == sharp[:3] for c in colours), "sharp edges in the sharp colour")
    g.check(state["cube"] in lines.ViewObject.claimChildren(), "the cloud is shown under it")
    g.view_image("cube_sharp_lines")


def dense_noisy_cube():
    import FreeCADGui
    import sampled_shapes

    # Fillets of 32 spacings under noise of 0.3 spacing: at the cloud's own spacing their
    # curvature lies in the noise (CurvatureScale.h); the panel says which regions are taken
    # at a coarser scale.
    edge, radius, h = 30.0, 8.0, 0.25
    points = sampled_shapes.with_normal_noise(
        sampled_shapes.rounded_cube(edge, radius, h, 5),
        lambda p: sampled_shapes.rounded_cube_normal(p, edge, radius), 0.3 * h, 15)
    state["dense"] = g.add_cloud(state["doc"], points, "DenseNoisy")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(state["dense"])
    FreeCADGui.runCommand("FeatureLines_Extract")


def coarser_scale_named():
    status = g.label("labelStatus")
    g.check("1 part(s) between sharp edges (smooth regions)" in status, status)
    g.check("coarser scale" in status and "region 0 at" in status,
            "the status names the region taken at a coarser scale: %s" % status)
    g.screenshot("message_coarser_scale")
    g.press_dialog_button("cancel")


def build(steps):
    steps.then("a document with a box", setup)
    steps.then("Extract with nothing selected", nothing_selected)
    steps.then("Extract with a box selected", a_box_selected)
    steps.then("Extract on a cloud of ten points", too_few_points)
    steps.then("the analysis fails with a message; Cancel", too_few_points_message,
               wait_for=g.analysis_finished)
    steps.then("the new object is gone", too_few_points_closed,
               wait_for=lambda: not g.panel_is_open())
    steps.then("Extract on a sharp cube", sharp_cube)
    steps.then("six regions, no valley; OK", six_regions_without_valley,
               wait_for=g.analysis_finished)
    steps.then("the cube's sharp edges", sharp_edges_kept, wait_for=lambda: not g.panel_is_open())
    steps.then("Extract on a dense noisy rounded cube", dense_noisy_cube)
    steps.then("the status names the coarser scale; Cancel", coarser_scale_named,
               wait_for=g.analysis_finished)


g.start("messages", build)
