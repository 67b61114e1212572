# FreeCAD start-up file of the FeatureLines module (run by FreeCAD for every Mod folder).
# The document object type FeatureLines::Extraction is registered when the C++ module
# FeatureLines is imported; FreeCAD imports it by itself when a document using it is opened.
import FreeCAD

FreeCAD.addImportType("XYZ point cloud (*.xyz)", "FeatureLinesImport")
