# FreeCAD start-up file of the FeatureLines module (run by FreeCAD for every Mod folder).
