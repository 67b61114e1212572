# SPDX-License-Identifier: LGPL-2.1-or-later
"""A saved document with hidden lines, reopened and shown: the lines are drawn in their type's
colour. PartGui rebuilds a hidden object's view when it is shown again without applying its
colour lists, so this checks the picture itself: a sampled cube's 12 sharp edges must show as
red pixels, not in the plain line colour."""

import os
import sys
import tempfile

sys.path.insert(0, os.environ.get("FEATURELINES_GUI_TEST_DIR") or os.path.dirname(__file__))

import gui_driver as g  # noqa: E402

EDGE, SPACING = 20.0, 0.5
state = {}


def count_pixels(path, accept):
    """Pixels of the PNG whose (r, g, b), 0..255, `accept` returns True for."""
    from PySide2 import QtGui

    image = QtGui.QImage(path)
    g.check(not image.isNull(), "cannot read " + path)
    n = 0
    for y in range(image.height()):
        for x in range(image.width()):
            p = image.pixel(x, y)
            if accept(p >> 16 & 255, p >> 8 & 255, p & 255):
                n += 1
    return n


def make_and_save():
    import FreeCAD
    import FeatureLines
    import sampled_shapes

    g.prepare_window()
    doc = FreeCAD.newDocument("Reopen")
    cloud = g.add_cloud(doc, sampled_shapes.cube(EDGE, SPACING, 1), "Cube")
    lines = FeatureLines.makeExtraction(cloud)
    doc.recompute()
    g.check(lines.SharpLineCount == 12, "12 sharp edges: %d" % lines.SharpLineCount)
    cloud.ViewObject.Visibility = False
    lines.ViewObject.Visibility = False
    path = os.path.join(tempfile.mkdtemp(), "reopen.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    state["path"] = path


def reopen_and_show():
    import FreeCAD
    import FreeCADGui

    doc = FreeCAD.openDocument(state["path"])
    lines = [o for o in doc.Objects if o.TypeId == "FeatureLines::Extraction"][0]
    g.check(not lines.ViewObject.Visibility, "saved hidden")
    lines.ViewObject.Visibility = True
    view = FreeCADGui.getDocument(doc.Name).activeView()
    view.viewIsometric()
    view.fitAll()
    state["lines"] = lines


def check_colours():
    path = g.view_image("reopen_lines", 800, 600)
    sharp = [int(round(255 * c)) for c in state["lines"].ViewObject.SharpColor[:3]]

    def red(r, gr, b):
        return abs(r - sharp[0]) < 40 and abs(gr - sharp[1]) < 40 and abs(b - sharp[2]) < 40

    def dark(r, gr, b):  # the plain line colour, near black
        return max(r, gr, b) < 100

    n_red, n_dark = count_pixels(path, red), count_pixels(path, dark)
    g.log("pixels in the sharp colour %d, dark %d" % (n_red, n_dark))
    # 12 edges of 20 units across most of an 800 x 600 view, 3 px wide: thousands of pixels,
    # red; drawn in the plain line colour they would be dark with red dots (the vertices).
    g.check(n_red > 2000, "the sharp edges are drawn red: %d pixels" % n_red)
    g.check(n_dark < n_red / 10, "few dark pixels: %d (red %d)" % (n_dark, n_red))


def build(steps):
    steps.then("a cube's lines, saved hidden, document closed", make_and_save)
    steps.then("reopened, the lines shown", reopen_and_show)
    steps.then("the picture has the sharp colour", check_colours)


g.start("reopened document", build)
