# SPDX-License-Identifier: LGPL-2.1-or-later
"""The time of the surfaces' deviation colour map in the FreeCAD GUI (docs/PERFORMANCE.md,
"Patch surfaces"): a cloud's extraction and surfaces recomputed, then, in Part's Flat Lines
mode, a finer tessellation (Part alone), the switch to the Deviation mode (the map made for it:
the mesh refined to about a spacing and each vertex's deviation) and a new colour range (the
colours alone); the process's peak memory; a picture of the map.

Run in the GUI (the map is the view's), e.g. under Xvfb, with the FeatureLines module found by
FreeCAD (FREECAD_USER_DATA: a folder holding Mod/FeatureLines, as the GUI tests' freecad-home):

    CMAP_CLOUD=cloud.xyz CMAP_OUT=times.txt FREECAD_USER_DATA=build/tests/gui/freecad-home \\
        xvfb-run -a -s "-screen 0 1366x768x24" freecad bench/gui/time_colour_map.py

It writes the times to CMAP_OUT and the picture to CMAP_OUT.png, and quits."""

import os
import resource
import time
import traceback

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import FeatureLines


def settle(seconds=0.0):
    """Lets the event loop run (at least once) for `seconds`."""
    end = time.monotonic() + seconds
    while True:
        QtWidgets.QApplication.processEvents()
        if time.monotonic() >= end:
            return
        time.sleep(0.02)


def main(out):
    FreeCADGui.activateWorkbench("FeatureLinesWorkbench")
    FreeCADGui.getMainWindow().showMaximized()
    doc = FreeCAD.newDocument("ColourMapTime")
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = FeatureLines.readCloud(os.environ["CMAP_CLOUD"])
    lines = FeatureLines.makeExtraction(cloud)
    t = time.perf_counter()
    doc.recompute()
    out.write("%d points; extraction %.2f s\n" % (len(cloud.Points.Points), time.perf_counter() - t))
    cloud.ViewObject.Visibility = False
    lines.ViewObject.Visibility = False
    surfaces = FeatureLines.makeSurfaces(lines)
    t = time.perf_counter()
    doc.recompute()
    settle()
    kinds = [k for k in surfaces.FaceKinds if k]
    out.write("surfaces and their view (fit, sew, tessellation, map) %.2f s: %d faces of %d "
              "patches\n" % (time.perf_counter() - t, len(kinds), len(surfaces.FaceKinds)))
    view = surfaces.ViewObject
    view.DisplayMode = "Flat Lines"
    settle(0.1)
    t = time.perf_counter()
    view.Deviation = 0.05
    settle()
    out.write("a finer tessellation in Flat Lines (Part alone) %.2f s\n" % (time.perf_counter() - t))
    t = time.perf_counter()
    view.DisplayMode = "Deviation"
    settle()
    out.write("the map for it (Deviation mode) %.2f s\n" % (time.perf_counter() - t))
    t = time.perf_counter()
    view.DeviationRange = 0.01
    settle()
    out.write("a new colour range %.3f s\n" % (time.perf_counter() - t))
    out.write("peak resident memory of FreeCAD %.0f MB\n"
              % (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))
    FreeCADGui.SendMsgToActiveView("ViewFit")
    settle(1.0)
    FreeCADGui.activeDocument().activeView().saveImage(os.environ["CMAP_OUT"] + ".png", 800, 600,
                                                       "White")


with open(os.environ["CMAP_OUT"], "w") as out:
    try:
        main(out)
    except Exception:
        out.write(traceback.format_exc())
os._exit(0)
