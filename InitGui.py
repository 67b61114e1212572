# SPDX-License-Identifier: LGPL-2.1-or-later
# FreeCAD GUI start-up file of the FeatureLines module: the "Feature Lines" workbench. FreeCAD
# runs this file with exec() and separate globals and locals, without __file__: the module's
# folder is found among FreeCAD's Mod folders, and the class body cannot see the names defined
# here (the icon is set after it). The C++ Gui module (command, task panel, view provider) is
# imported when the workbench is first activated, or by FreeCAD when a document holding feature
# lines is opened.
import os

import FreeCAD
import FreeCADGui


def _featurelines_icon(name):
    for folder in FreeCAD.__ModDirs__:
        path = os.path.join(folder, "Resources", "icons", name)
        if os.path.basename(os.path.normpath(folder)) == "FeatureLines" and os.path.isfile(path):
            return path
    return ""


class FeatureLinesWorkbench(FreeCADGui.Workbench):
    MenuText = "Feature Lines"
    ToolTip = ("Closed feature lines (sharp edges, fillet borders, boundary) of point clouds, "
               "by curvature histogram thresholding")

    def Initialize(self):
        import FeatureLinesGui  # noqa: F401  (registers the command and the view provider)

        commands = ["FeatureLines_Extract", "FeatureLines_MakePatchClouds",
                    "FeatureLines_FitSurfaces"]
        colouring = ["FeatureLines_ColourByRegion", "FeatureLines_ColourByPatch",
                     "FeatureLines_ColourByLabel", "FeatureLines_ColourByCurvature",
                     "FeatureLines_ColourNothing"]
        cleaning = ["FeatureLines_DropShortLines", "FeatureLines_DeleteLines",
                    "FeatureLines_MergeLines", "FeatureLines_RestoreLines"]
        self.appendToolbar("Feature Lines", commands + cleaning)
        self.appendMenu("&Feature Lines",
                        commands + ["Separator"] + cleaning + ["Separator"] + colouring)

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FeatureLinesWorkbench.Icon = _featurelines_icon("FeatureLines_Workbench.svg")
FreeCADGui.addWorkbench(FeatureLinesWorkbench())
