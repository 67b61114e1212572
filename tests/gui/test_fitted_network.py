# SPDX-License-Identifier: LGPL-2.1-or-later
"""The lines as CAD geometry in the GUI, on the demo part (samples/boss_blend.xyz): the
extraction's Shape is a few tens of fitted edges (lines, arcs, circles, B-splines) on shared
vertices, drawn by type colour; then FreeCAD's own Surface::Filling is built on one patch's
closed border wire (its edges picked from the extraction, as a user picks them in Surface >
Filling) and lies on that patch's points. Then the command Fit surfaces (FeatureLines.makeSurfaces) makes the patches' surfaces, sewn
into the demo part's solid.
Screenshots at FreeCAD's default layout (1366 x 768): fitted_network
(docs/images/gui-fitted-network.png), patch_filling (docs/images/gui-patch-filling.png) and
surfaces (docs/images/gui-surfaces.png)."""

import os
import sys

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

SAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(
    os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__)))), "samples")
state = {}


def setup():
    import FreeCAD
    import FreeCADGui

    import FeatureLines

    g.prepare_window()
    doc = FreeCAD.newDocument("BossBlend")
    state["doc"] = doc
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = FeatureLines.readCloud(os.path.join(SAMPLES, "boss_blend.xyz"))
    cloud.Label = "boss_blend"
    state["cloud"] = cloud
    state["lines"] = FeatureLines.makeExtraction(cloud)
    doc.recompute()
    # The points faint under the lines; the lines' shared vertices drawn as dots.
    cloud.ViewObject.PointSize = 1
    cloud.ViewObject.ShapeColor = (0.62, 0.62, 0.62)
    state["lines"].ViewObject.PointSize = 6
    view = FreeCADGui.getDocument(doc.Name).activeView()
    view.viewIsometric()
    view.fitAll()


def fitted_network():
    lines = state["lines"]
    g.check(lines.getStatusString() in ("", "Valid"), "recomputed: %s" % lines.getStatusString())
    edges = lines.Shape.Edges
    polyline_edges = len(lines.Polylines.Edges)
    g.check(0 < len(edges) < 100, "tens of edges, not thousands: %d (the polylines have %d)"
            % (len(edges), polyline_edges))
    g.check(polyline_edges > 10 * len(edges), "far fewer edges than the polylines' %d"
            % polyline_edges)
    kinds = list(lines.CurveKinds)
    g.check(len(kinds) == len(edges), "a curve kind per edge")
    g.log("curves: %s" % {k: kinds.count(k) for k in sorted(set(kinds))})
    g.check(kinds.count("polyline") <= len(kinds) // 10,
            "at most one edge in ten left a polyline: %s" % list(lines.CurveProblems))
    # One vertex per junction: where three lines meet there is one vertex, not three.
    g.check(len(lines.Shape.Vertexes) <= len(lines.Junctions) + 2 * len(lines.Shape.Wires),
            "shared vertices: %d vertices, %d junctions, %d lines"
            % (len(lines.Shape.Vertexes), len(lines.Junctions), len(lines.Shape.Wires)))
    colours = lines.ViewObject.LineColorArray
    g.check(len(colours) == len(edges), "one colour per fitted edge")
    g.screenshot("fitted_network")


def filling():
    import Part
    import Surface  # noqa: F401  (Surface::Filling)

    import FeatureLines

    lines, doc = state["lines"], state["doc"]
    patches = [p for p in FeatureLines.patchBorders(lines) if p["closed"]]
    g.check(patches, "some patch has a closed border: %s" % list(lines.OpenPatchReasons))
    # The largest patch with a single border wire (no hole), so the filling has one boundary.
    patch = max((p for p in patches if len(p["wires"]) == 1), key=lambda p: len(p["points"]))
    wire = patch["wires"][0]
    surface = doc.addObject("Surface::Filling", "Filling")
    surface.BoundaryEdges = [(lines, name) for name in patch["edge_names"][0]]
    doc.recompute()
    g.check(surface.getStatusString() in ("", "Valid"), "Filling: %s" % surface.getStatusString())
    face = surface.Shape.Faces[0]
    spacing = lines.Spacing.Value
    worst = max(face.distToShape(Part.Vertex(p))[0] for p in patch["points"][::10])
    g.log("patch %d: %d points, %d border edges, farthest point %.3g spacings from the filling"
          % (patch["patch"], len(patch["points"]), len(wire.Edges), worst / spacing))
    g.check(worst < 1.0 * spacing, "the filling lies on the patch's points: %.3g" % worst)
    surface.ViewObject.ShapeColor = (0.55, 0.75, 0.95)
    surface.ViewObject.Transparency = 20
    g.screenshot("patch_filling")


def surfaces():
    import FreeCADGui

    lines, doc = state["lines"], state["doc"]
    if "Filling" in [o.Name for o in doc.Objects]:
        doc.getObject("Filling").ViewObject.Visibility = False
    # As a user does: the lines selected, Feature Lines > Fit surfaces.
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(lines)
    FreeCADGui.runCommand("FeatureLines_FitSurfaces")
    g.settle()
    # The command opens the surfaces' panel (tests/gui/test_surfaces_panel.py): OK closes it.
    g.check(g.panel_is_open(), "the surfaces' task panel is open")
    g.press_dialog_button("ok")
    g.settle()
    made = [o for o in doc.Objects if o.TypeId == "FeatureLines::PatchSurfaces"]
    g.check(len(made) == 1, "the command made one Surfaces object: %s" % made)
    feature = made[0]
    g.check(feature.Source == lines, "its source is the selected lines")
    g.check(doc.UndoNames[:1] == ["Fit surfaces"], "one undo step: %s" % doc.UndoNames)
    kinds = [k for k in feature.FaceKinds if k]
    g.log("surfaces: %s, solid %s, valid %s, tolerance %.3g"
          % ({k: kinds.count(k) for k in sorted(set(kinds))}, feature.IsSolid,
             feature.IsValid, feature.SewingTolerance))
    g.check(feature.IsSolid and feature.IsValid, "the demo part's faces close into a valid "
            "solid: %s" % list(feature.Problems))
    # Each face coloured by its kind: planes grey-blue, cylinders green, the torus orange.
    colours = {"plane": (0.62, 0.70, 0.85), "cylinder": (0.55, 0.80, 0.55),
               "torus": (0.95, 0.65, 0.30), "cone": (0.85, 0.55, 0.85),
               "sphere": (0.90, 0.85, 0.40), "bspline": (0.85, 0.45, 0.45)}
    names = {"Plane": "plane", "Cylinder": "cylinder", "Toroid": "torus", "Cone": "cone",
             "Sphere": "sphere"}
    by_face = [colours[names.get(type(face.Surface).__name__, "bspline")]
               for face in feature.Shape.Faces]
    g.check(sorted(names.get(type(f.Surface).__name__, "bspline") for f in feature.Shape.Faces)
            == sorted(kinds), "the sewn faces keep their kinds")
    # Part's Flat Lines mode with a colour per face (the default mode colours by deviation).
    feature.ViewObject.DisplayMode = "Flat Lines"
    feature.ViewObject.DiffuseColor = by_face
    state["cloud"].ViewObject.Visibility = False
    lines.ViewObject.Visibility = False
    g.screenshot("surfaces")


def build(steps):
    steps.then("the demo part's cloud, its feature lines recomputed", setup)
    steps.then("the fitted network: tens of edges on shared vertices", fitted_network)
    steps.then("a Surface::Filling on a patch's border wire", filling)
    steps.then("the patches' surfaces sewn into the demo part's solid", surfaces)


g.start("fitted network of the demo part", build, limit=280)
