# SPDX-License-Identifier: LGPL-2.1-or-later
"""File > Open and File > Import of .xyz point clouds, which FreeCAD's Points module does not read.

The cloud becomes a Points feature (one point per line, x y z separated by white space or commas;
further columns are ignored, lines starting with '#', '//' or '%' are skipped), ready for
FeatureLines.makeExtraction(). From a macro:

    import FeatureLinesImport
    cloud = FeatureLinesImport.insert("part.xyz", App.ActiveDocument.Name)
"""

import os

import FreeCAD
import FeatureLines  # loads Points as well

# FreeCAD calls the module's open(); keep Python's own under another name.
pythonopen = open


def _baseName(filename):
    return os.path.splitext(os.path.basename(filename))[0] or "Points"


def _addCloud(doc, filename, kernel):
    cloud = doc.addObject("Points::Feature", _baseName(filename))
    cloud.Label = _baseName(filename)
    cloud.Points = kernel
    doc.recompute()
    return cloud


def insert(filename, docname):
    """Adds the cloud of `filename` to the document named `docname` (created when missing) as a
    Points feature and returns it. Raises ValueError naming the problem for a bad file; the file
    is read first, so a bad file adds nothing and creates no document."""
    kernel = FeatureLines.readCloud(filename)
    try:
        doc = FreeCAD.getDocument(docname)
    except NameError:
        doc = FreeCAD.newDocument(docname)
    return _addCloud(doc, filename, kernel)


def open(filename):
    """Opens `filename` in a new document named after the file and returns the document; a bad
    file raises ValueError before any document is created."""
    kernel = FeatureLines.readCloud(filename)
    doc = FreeCAD.newDocument(_baseName(filename))
    _addCloud(doc, filename, kernel)
    return doc
