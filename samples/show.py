# SPDX-License-Identifier: LGPL-2.1-or-later
"""Shows the demo's result in the FreeCAD GUI: opens the document samples/demo.py saved, with the
Feature Lines workbench active and an isometric view of the lines on the cloud.

Run by samples/demo (FreeCAD's own command line is unusable in Debian's 0.20.2, so the inputs
come from the environment):
    FEATURELINES_SHOW_DOCUMENT  the .FCStd to open
    FEATURELINES_SHOW_PICTURE   when set, save the 3D view there as a PNG and quit (the demo does
                                this under Xvfb on a machine without a display)
"""

import os
import sys
import traceback


def show():
    import FreeCAD
    import FreeCADGui

    path = os.environ["FEATURELINES_SHOW_DOCUMENT"]
    doc = FreeCAD.openDocument(path)
    try:
        FreeCADGui.activateWorkbench("FeatureLinesWorkbench")
    except Exception:
        pass  # the lines still show with the Part view providers
    # freecadcmd saved no view data (GuiDocument.xml): show the cloud and the lines, leave the
    # patch clouds hidden.
    for obj in doc.Objects:
        obj.ViewObject.Visibility = obj.TypeId == "FeatureLines::Extraction"
    for obj in doc.Objects:
        if obj.TypeId == "FeatureLines::Extraction" and obj.Source:
            obj.Source.ViewObject.Visibility = True
            obj.Source.ViewObject.PointSize = 2
            obj.Source.ViewObject.ShapeColor = (0.62, 0.62, 0.68)  # light: the lines stand out
    view = FreeCADGui.getDocument(doc.Name).activeView()
    view.viewIsometric()
    view.fitAll()
    return view


def main():
    from PySide2 import QtCore

    picture = os.environ.get("FEATURELINES_SHOW_PICTURE")

    def step():
        code = 1
        try:
            view = show()
            if not picture:
                return
            view.saveImage(picture, 1200, 900, "White")
            code = 0 if os.path.isfile(picture) else 1
        except BaseException:
            traceback.print_exc()
        # In picture mode, and whenever the document could not be shown, quit with the result.
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)

    # The main window is up once the event loop runs.
    QtCore.QTimer.singleShot(200, step)


main()
