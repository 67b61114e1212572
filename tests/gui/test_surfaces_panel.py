# SPDX-License-Identifier: LGPL-2.1-or-later
"""From the cloud to a sewn solid in the GUI alone, on the demo part (samples/boss_blend.xyz):
the cloud selected, Extract feature lines, the first candidate accepted, then "Done, fit
surfaces" in the thresholds' stage (b). The lines' panel closes with the lines kept, a
FeatureLines::PatchSurfaces object is made from them and its panel opens: the faces by kind
(the demo part's planes, cylinders and the torus of the boss's foot, sewn into a valid solid),
per patch its surface and its points' deviations, the colour map on. The view colours the
faces by the scan's deviation (green on the face, FreeCAD's colour bar beside the view); off,
the faces are Part's grey. OK keeps it all in one undo step per panel. A new cloud without lines
(a sphere's) fails the lines' recompute with the reason; the surfaces keep their faces, and
the map turns grey once redrawn (their deviations belong to the old cloud).
Screenshot at FreeCAD's default layout (1366 x 768): surfaces_deviation
(docs/images/gui-surfaces-deviation.png)."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

from PySide2 import QtWidgets  # noqa: E402

SAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(
    os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__)))), "samples")
state = {}


def setup():
    import FreeCAD
    import FreeCADGui

    import FeatureLines

    g.prepare_window()
    doc = FreeCAD.newDocument("BossBlendSurfaces")
    state["doc"] = doc
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = FeatureLines.readCloud(os.path.join(SAMPLES, "boss_blend.xyz"))
    cloud.Label = "boss_blend"
    doc.recompute()
    state["cloud"] = cloud
    FreeCADGui.SendMsgToActiveView("ViewFit")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(cloud)


def extract():
    import FreeCADGui

    FreeCADGui.runCommand("FeatureLines_Extract")
    lines = [o for o in state["doc"].Objects if o.TypeId == "FeatureLines::Extraction"]
    g.check(len(lines) == 1, "the command adds one FeatureLines::Extraction")
    state["lines"] = lines[0]
    g.check(g.panel_is_open(), "the lines' task panel is open")


def accept_first_candidate():
    g.check(g.run_state() == "done", "the analysis: %s" % g.label("labelStatus"))
    g.check(g.stage() == "a", "stage (a): a candidate to accept")
    g.click("buttonAccept")
    g.settle()
    g.check(g.stage() == "b", "stage (b): the lines of the accepted level")
    g.check(g.button("buttonFitSurfaces").isVisible(), "Done, fit surfaces is offered")
    g.check_panel_fits("stage (b) with Done, fit surfaces")


def surfaces_panel():
    """The surfaces' panel, once it is open."""
    return g.main_window().findChild(QtWidgets.QWidget, "TaskPatchSurfaces")


def fit_surfaces():
    g.click("buttonFitSurfaces")


def surfaces_made():
    import FreeCADGui

    doc, lines = state["doc"], state["lines"]
    made = [o for o in doc.Objects if o.TypeId == "FeatureLines::PatchSurfaces"]
    g.check(len(made) == 1, "one PatchSurfaces object: %s" % made)
    feature = made[0]
    state["surfaces"] = feature
    g.check(feature.Source == lines, "its source is the lines")
    g.check(lines.ThresholdMode == "Explicit" and (list(lines.Thresholds) or
                                                    dict(lines.RegionThresholds)),
            "the accepted level is kept: %s %s %s" % (lines.ThresholdMode, list(lines.Thresholds),
                                                     dict(lines.RegionThresholds)))
    kinds = [k for k in feature.FaceKinds if k]
    g.log("surfaces: %s, solid %s, valid %s, problems %s"
          % ({k: kinds.count(k) for k in sorted(set(kinds))}, feature.IsSolid, feature.IsValid,
             list(feature.Problems)))
    g.check(feature.IsSolid and feature.IsValid, "a valid closed solid: %s" % list(feature.Problems))
    # The demo part: a plate with rounded corners, a boss with a bore and a fillet at its foot.
    g.check(kinds.count("torus") == 1, "the boss's foot fillet is a torus: %s" % kinds)
    g.check(kinds.count("cylinder") >= 5, "the bore, boss and corner fillets are cylinders: %s"
            % kinds)
    g.check(kinds.count("plane") >= 6, "the plate's and boss's flat faces are planes: %s" % kinds)
    spacing = lines.Spacing.Value
    g.check(max(feature.FaceRmsDeviations) < 0.2 * spacing,
            "every face within 0.2 spacing (RMS) of its points: %s"
            % list(feature.FaceRmsDeviations))
    # The panel: one row per patch, its kind, the summary, the colour map on.
    table = g.find(QtWidgets.QTableWidget, "tableSurfaces")
    g.check(table.rowCount() == len(feature.FacePatches), "one row per patch")
    shown = sorted(table.item(r, 1).text() for r in range(table.rowCount()))
    g.check(shown == sorted(feature.FaceKinds), "the rows show the kinds: %s" % shown)
    summary = g.label("labelSummary")
    g.check("valid closed solid" in summary, "the summary says so: %s" % summary)
    g.check(g.find(QtWidgets.QCheckBox, "checkColourMap").isChecked(), "the colour map is on")
    g.check(feature.ViewObject.DisplayMode == "Deviation", "the view shows the deviations")
    deviations = [d for d in feature.PointDeviations if d == d]
    g.check(len(deviations) > len(feature.PointDeviations) // 2,
            "most points have a deviation from their face")
    g.settle(0.5)
    g.check_panel_fits_widget(surfaces_panel(), "the surfaces' panel")
    state["cloud"].ViewObject.Visibility = False
    lines.ViewObject.Visibility = False
    view = FreeCADGui.activeDocument().activeView()
    view.viewIsometric()
    view.fitAll()
    g.settle(0.5)
    g.screenshot("surfaces_deviation")


def green_share(name):
    """The share of the part's pixels (not the white background) whose colour is mostly green:
    the colour map's colour for a point on its face."""
    from PySide2 import QtGui

    image = QtGui.QImage(g.view_image(name, 600, 450))
    part = green = 0
    for y in range(0, image.height(), 3):
        for x in range(0, image.width(), 3):
            c = QtGui.QColor(image.pixel(x, y))
            r, gr, b = c.red(), c.green(), c.blue()
            if min(r, gr, b) > 235:
                continue  # the background
            part += 1
            green += 1 if gr > r + 40 and gr > b + 40 else 0
    return green / max(part, 1), part


def colour_map_on_and_off():
    feature = state["surfaces"]
    on, part = green_share("deviation_on")
    g.check(part > 1000, "the part fills the view: %d pixels" % part)
    g.check(on > 0.5, "with the colour map most of the part is green (on its faces): %.2f" % on)
    g.find(QtWidgets.QCheckBox, "checkColourMap").click()
    g.settle()
    g.check(feature.ViewObject.DisplayMode == "Flat Lines", "off: Part's Flat Lines")
    off, _ = green_share("deviation_off")
    g.check(off < 0.05, "without it the part is Part's grey: %.2f green" % off)
    g.find(QtWidgets.QCheckBox, "checkColourMap").click()
    g.settle()
    g.check(feature.ViewObject.DisplayMode == "Deviation", "on again")
    # A range of its own, as a user types it: the view takes it, the note says it.
    g.find(QtWidgets.QDoubleSpinBox, "spinColourRange").setValue(0.01)
    g.settle()
    g.check(abs(feature.ViewObject.DeviationRange - 0.01) < 1e-12,
            "the range is the view's: %s" % feature.ViewObject.DeviationRange)
    g.check("0.01 mm" in g.label("labelColourRange"), g.label("labelColourRange"))


def ok():
    g.press_dialog_button("ok")


def closed():
    doc = state["doc"]
    g.check(state["surfaces"].ViewObject.DisplayMode == "Deviation", "OK keeps the colour map")
    g.log("undo steps: %s" % doc.UndoNames)
    # The panel changed nothing of the document (the view's mode is no document change): the
    # fit is one undo step after the lines'.
    g.check(doc.UndoNames[:2] == ["Fit surfaces", "Extract feature lines"],
            "one undo step for the fit: %s" % doc.UndoNames)


def failed_refit():
    """The cloud replaced by a whole sphere's: no line at all, so the lines' recompute fails
    with the reason and the surfaces keep their faces and deviations. Those belong to the old
    cloud: once the view draws the faces again (a finer tessellation), the map is grey, not
    colours of points that are gone."""
    import FreeCAD
    import Points
    import sampled_shapes

    doc, cloud, feature = state["doc"], state["cloud"], state["surfaces"]
    lines = state["lines"]
    volume = feature.Shape.Volume
    cloud.Points = Points.Points([FreeCAD.Vector(*p)
                                  for p in sampled_shapes.sphere(10.0, 0.5, 31)])
    doc.recompute()
    g.settle()
    g.log("the lines after the new cloud: %s" % lines.getStatusString())
    g.check("No feature lines found" in lines.getStatusString(), "the lines say why")
    g.check(abs(feature.Shape.Volume - volume) < 1e-6 * volume, "the faces of the run before stay")
    g.check(len(feature.PointDeviations) != len(cloud.Points.Points),
            "the deviations are the old cloud's")
    feature.ViewObject.Deviation = 0.05
    green, part = green_share("deviation_stale")
    g.check(part > 1000 and green < 0.05, "the map is grey: %.2f green of %d pixels" % (green, part))


def build(steps):
    steps.then("the demo cloud, selected", setup)
    steps.then("Extract feature lines", extract)
    steps.then("the first candidate accepted: stage (b)", accept_first_candidate,
               wait_for=g.analysis_finished)
    steps.then("Done, fit surfaces", fit_surfaces)
    steps.then("the surfaces made, their panel open", surfaces_made,
               wait_for=lambda: surfaces_panel() is not None)
    steps.then("the colour map on and off", colour_map_on_and_off)
    steps.then("OK", ok)
    steps.then("the panel closed, the surfaces kept", closed,
               wait_for=lambda: not g.panel_is_open())
    steps.then("a failed refit keeps the faces, the map grey", failed_refit)


g.start("from the cloud to surfaces in the GUI", build)
