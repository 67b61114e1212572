# SPDX-License-Identifier: LGPL-2.1-or-later
"""Fig. 7 of Demarsin et al. (2008) in the GUI alone: a rounded cube's cloud selected, Extract
feature lines run, the candidate moved with Higher and Lower (Lower after Higher is the first
candidate again), the corner threshold accepted (8 closed corner loops), a threshold a hair below
it refused (it repeats those lines), a lower threshold added and accepted (6 face loops more),
Done; then undo
and redo, and the macro recorded meanwhile replayed. The document is checked after every step
against the shape: flat faces (curvature 0), fillets (1/(2r)), corners (1/r)."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, RADIUS, SPACING = 40.0, 6.0, 0.7
INNER = EDGE / 2 - RADIUS
FILLET, CORNER = 1 / (2 * RADIUS), 1 / RADIUS  # mean curvatures
state = {}


def setup():
    import FreeCAD
    import FreeCADGui
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("RoundedCube")
    state["doc"] = doc
    state["cloud"] = g.add_cloud(doc, sampled_shapes.rounded_cube(EDGE, RADIUS, SPACING, 6))
    state["macro"] = g.start_macro_recording("rounded_cube")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(state["cloud"])


def run_command():
    import FreeCADGui

    FreeCADGui.runCommand("FeatureLines_Extract")
    doc = state["doc"]
    lines = [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"]
    g.check(len(lines) == 1, "the command adds one FeatureLines::Extraction")
    state["lines"] = lines[0]
    g.check(lines[0].Source == state["cloud"], "it reads the selected cloud")
    g.check(g.panel_is_open(), "the task panel is open")


def first_candidate():
    g.check(g.run_state() == "done", "the analysis: %s" % g.label("labelStatus"))
    g.check(g.stage() == "a", "a new object starts at stage (a)")
    c = g.candidate()
    # A clean cloud's first valley follows the flat faces' spike at zero (Sec. 2.2).
    g.check(0 < c < FILLET, "first candidate %g between faces and fillets" % c)
    g.check("low" in g.label("labelLegend"), "the label colours are explained")
    g.check(not g.button("buttonBack").isVisible(), "nothing accepted yet to go back to")
    g.check(not state["cloud"].ViewObject.isVisible(), "the preview replaces the cloud's view")
    g.check_panel_fits("stage (a), both boxes open")
    state["first"] = c


def higher():
    g.click("buttonHigher")
    c = g.candidate()
    g.check(c > state["first"], "Higher moves the candidate up (%g > %g)" % (c, state["first"]))
    g.check(FILLET < c < CORNER, "candidate %g between fillets and corners" % c)
    state["tau1"] = c


def lower():
    from PySide2 import QtWidgets

    # Lower and Higher step through the candidates as a history: Lower after Higher comes back
    # to the first candidate, Higher again to the corner one.
    g.click("buttonLower")
    c = g.candidate()
    g.check(c == state["first"], "Lower comes back to the first candidate: %r, first %r"
            % (c, state["first"]))
    g.click("buttonHigher")
    c = g.candidate()
    g.check(c == state["tau1"], "Higher from there finds the corner candidate again: %r, was %r"
            % (c, state["tau1"]))
    g.check(FILLET < c < CORNER, "candidate %g between fillets and corners" % c)
    g.check("inner" in g.label("labelStage"), "the stage text counts the labels")
    # The thresholds box whole on a 768-pixel screen: the analysis box folded, as a user
    # folds it once the cloud is analysed.
    g.fold_task_box("TaskExtractionOptions")
    g.settle(1.5)  # the box folds in an animation
    g.check_panel_fits("stage (a), the analysis box folded")
    g.screenshot("rounded_cube_labels")
    # The one-screen help: plain words, the paper's terms in parentheses, within the panel.
    g.click("buttonHelp")
    g.check(g.find(QtWidgets.QLabel, "labelHelp").isVisible(), "the help shows")
    text = g.label("labelHelp")
    for words in ("mean curvature", "(candidate threshold", "(inner)", "(border)", "Accept"):
        g.check(words in text, "the help explains %s" % words)
    g.check_panel_fits("the help open")
    g.screenshot("rounded_cube_help")
    g.click("buttonHelp")
    g.check(not g.find(QtWidgets.QLabel, "labelHelp").isVisible(), "a second click hides it")


def corner_of(point):
    return tuple(c > 0 for c in (point.x, point.y, point.z))


def accept_corner_threshold():
    lines = state["lines"]
    g.check(lines.SmoothLineCount == 0 and lines.Shape.isNull(), "no lines before Accept")
    g.click("buttonAccept")
    g.check(lines.ThresholdMode == "Explicit", "the accepted threshold is explicit")
    g.check(list(lines.Thresholds) == [state["tau1"]], "Thresholds %s" % list(lines.Thresholds))
    g.check(lines.State == [] or "Invalid" not in lines.State, lines.getStatusString())
    g.check(lines.SmoothLineCount == 8, "8 corner loops, got %d" % lines.SmoothLineCount)
    g.check(lines.ClosedLineCount == 8, "all closed, got %d" % lines.ClosedLineCount)
    corners = set()
    for wire in lines.SmoothWires.Wires:
        c = g.wire_centre(wire)
        g.check(all(abs(x) > INNER for x in (c.x, c.y, c.z)), "a loop around a corner: %s" % c)
        corners.add(corner_of(c))
    g.check(len(corners) == 8, "one loop per corner")
    g.check(g.stage() == "b", "stage (b) after Accept")
    g.check(g.button("buttonDone").isVisible(), "Done is offered")
    g.check("8 smooth line(s), 8 closed" in g.label("labelStage"), g.label("labelStage"))
    g.check_panel_fits("stage (b)")
    # Narrower still, as the paper-width panel of FreeCAD's smaller layouts: 230 pixels.
    g.narrow_combo_view(230)
    g.check_panel_fits("stage (b), 230 px")
    g.screenshot("rounded_cube_stage_b_230px")


def refuse_repeated_threshold():
    # A threshold a hair below the accepted one gives the same patches: its lines would repeat
    # the 8 corner loops. The panel refuses to accept it and says why.
    lines = state["lines"]
    tau1 = state["tau1"]
    g.choose_in_histogram(tau1 * (1 - 1e-9))
    g.check(g.stage() == "a" and g.candidate() == tau1 * (1 - 1e-9), "the clicked candidate")
    g.click("buttonAccept")
    message = g.label("labelMessage")
    g.check("same patches" in message, "the panel says why: %s" % message)
    g.check(g.stage() == "a", "not accepted")
    g.check(list(lines.Thresholds) == [tau1], "Thresholds unchanged: %s" % list(lines.Thresholds))
    g.check(lines.SmoothLineCount == 8, "no repeated lines: %d" % lines.SmoothLineCount)
    g.click("buttonBack")
    g.check(g.stage() == "b", "Back to the accepted lines")


def add_lower():
    g.click("buttonAddLower")
    c = g.candidate()
    g.check(g.stage() == "a", "Add lower goes back to stage (a)")
    g.check(c < state["tau1"], "the added threshold %g lies below the accepted one" % c)
    g.check(0 < c < FILLET, "candidate %g between faces and fillets (Fig. 5)" % c)
    g.check(g.button("buttonBack").isVisible(), "Back to the accepted lines is offered")
    state["tau2"] = c


def accept_face_threshold():
    lines = state["lines"]
    g.click("buttonAccept")
    tau1, tau2 = state["tau1"], state["tau2"]
    g.check(list(lines.Thresholds) == [tau1, tau2], "both thresholds, high to low")
    g.check(lines.SmoothLineCount == 14, "8 corner + 6 face loops, got %d" % lines.SmoothLineCount)
    g.check(lines.ClosedLineCount == 14, "all closed, got %d" % lines.ClosedLineCount)
    g.check(sorted(lines.SmoothLineThresholds) == sorted([tau2] * 6 + [tau1] * 8),
            "8 lines at tau1, 6 at tau2")
    faces = set()
    for wire, t in zip(lines.SmoothWires.Wires, lines.SmoothLineThresholds):
        if t == tau2:
            c = g.wire_centre(wire)
            axis = max(range(3), key=lambda a: abs(c[a]))
            g.check(abs(abs(c[axis]) - EDGE / 2) < RADIUS, "a loop on a face: %s" % c)
            faces.add((axis, c[axis] > 0))
    g.check(len(faces) == 6, "one loop per face")
    g.check(g.stage() == "b", "stage (b)")


def done():
    g.click("buttonDone")


def closed():
    import FreeCADGui

    lines, cloud, doc = state["lines"], state["cloud"], state["doc"]
    g.check(not g.panel_is_open(), "Done closes the panel")
    g.check(lines.ThresholdMode == "Explicit", "Explicit mode")
    g.check(list(lines.Thresholds) == [state["tau1"], state["tau2"]], "both thresholds kept")
    g.check(lines.SmoothLineCount == 14, "the 14 loops are kept")
    g.check(cloud.ViewObject.isVisible(), "the preview is gone, the cloud shown again")
    g.check(doc.UndoNames[:1] == ["Extract feature lines"], "one undo step: %s" % doc.UndoNames)
    g.check(lines.ViewObject.LineWidth == 3, "lines drawn 3 pixels wide")
    colours = lines.ViewObject.LineColorArray
    smooth = lines.ViewObject.SmoothColor
    g.check(len(colours) == len(lines.Shape.Edges), "one colour per edge")
    g.check(all(c[:3] == smooth[:3] for c in colours), "smooth lines in the smooth colour")
    g.screenshot("rounded_cube_done")
    # Seen from a dimetric direction the front and back corner loops do not coincide.
    view = FreeCADGui.getDocument(doc.Name).activeView()
    view.viewDimetric()
    view.fitAll()
    g.view_image("rounded_cube_lines")
    macro = g.stop_macro_recording(state["macro"])
    for line in ("addObject('FeatureLines::Extraction', 'FeatureLines')",
                 ".ThresholdMode = 'Explicit'", ".Thresholds = [", ".recompute()"):
        g.check(line in macro, "the macro records %s:\n%s" % (line, macro))
    state["macro_text"] = macro


def undo():
    import FreeCADGui

    FreeCADGui.runCommand("Std_Undo")
    doc = state["doc"]
    g.check([o.Name for o in doc.Objects] == [state["cloud"].Name], "undo removes the object")
    FreeCADGui.runCommand("Std_Redo")
    lines = doc.getObject(state["lines"].Name)
    g.check(lines is not None, "redo brings it back")
    g.check(list(lines.Thresholds) == [state["tau1"], state["tau2"]], "with both thresholds")
    g.check(lines.SmoothLineCount == 14, "and its 14 loops")


def replay_macro():
    import FreeCAD
    import FreeCADGui

    # The recorded macro alone makes the same lines: undo, then run it in the namespace FreeCAD
    # runs macros in (App and Gui defined).
    name = state["lines"].Name
    FreeCADGui.runCommand("Std_Undo")
    doc = state["doc"]
    g.check(doc.getObject(name) is None, "undone")
    namespace = {"App": FreeCAD, "Gui": FreeCADGui}
    exec(compile(state["macro_text"], state["macro"], "exec"), namespace)
    lines = doc.getObject(name)
    g.check(lines is not None, "the macro adds the object again")
    g.check(list(lines.Thresholds) == [state["tau1"], state["tau2"]], "with both thresholds")
    g.check(lines.SmoothLineCount == 14 and lines.ClosedLineCount == 14, "and the 14 loops")


def build(steps):
    steps.then("a rounded cube's cloud, selected", setup)
    steps.then("Extract feature lines", run_command)
    steps.then("the analysis finishes: stage (a) with the first candidate", first_candidate,
               wait_for=g.analysis_finished)
    steps.then("Higher", higher)
    steps.then("Lower, then Higher again", lower)
    steps.then("Accept the corner threshold", accept_corner_threshold)
    steps.then("a threshold repeating the accepted one is refused", refuse_repeated_threshold)
    steps.then("Add a lower threshold", add_lower)
    steps.then("Accept the face threshold", accept_face_threshold)
    steps.then("Done", done)
    steps.then("the panel closed with the lines kept", closed,
               wait_for=lambda: not g.panel_is_open())
    steps.then("undo and redo", undo)
    steps.then("undo, then the recorded macro makes the lines again", replay_macro)


g.start("rounded cube, Fig. 7", build)
