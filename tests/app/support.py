# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the App tests share: documents with sampled clouds, a scratch folder, wire geometry."""

import math
import os
import shutil
import tempfile

import FreeCAD
import Points

import FeatureLines


def scratch_dir(name):
    """An empty folder for files a test writes, inside the build tree when run by ctest."""
    root = os.environ.get("FEATURELINES_TEST_TMP") or tempfile.gettempdir()
    path = os.path.join(root, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def new_document(name):
    return FreeCAD.newDocument(name)


def close_document(doc):
    if doc.Name in FreeCAD.listDocuments():
        FreeCAD.closeDocument(doc.Name)


def add_cloud(doc, points, name="Cloud"):
    """A Points feature holding `points` ((x, y, z) tuples)."""
    cloud = doc.addObject("Points::Feature", name)
    cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in points])
    return cloud


def add_extraction(doc, points, **parameters):
    """A cloud and its FeatureLines::Extraction with the given parameters, recomputed."""
    cloud = add_cloud(doc, points)
    lines = FeatureLines.makeExtraction(cloud, **parameters)
    doc.recompute()
    return cloud, lines


def error_message(obj):
    """The recompute error of `obj`, '' when it has none."""
    if "Invalid" not in obj.State and "Error" not in obj.State:
        return ""
    return obj.getStatusString()


def wire_ends(wire):
    """The first and last vertex of an open wire."""
    vertices = wire.OrderedVertexes
    return vertices[0].Point, vertices[-1].Point


def vertex_points(shape):
    return [v.Point for v in shape.Vertexes]


def default_value(name):
    """The default of a parameter as its property takes it (a choice by its name)."""
    for p in FeatureLines.parameters():
        if p["name"] == name:
            if p["kind"] == "Choice":
                return p["choices"][int(p["default"])]
            if p["kind"] in ("Integer",):
                return int(p["default"])
            if p["kind"] == "Switch":
                return bool(p["default"])
            return p["default"]
    raise KeyError(name)


def face_of(p):
    """The face of an axis-aligned box a point lies on: (axis of its largest coordinate, sign)."""
    axis = max(range(3), key=lambda a: abs(p[a]))
    return axis, p[axis] > 0


def not_estimated(value):
    """A line's angle or blend radius that was not estimated: NaN in a property, None in a dict."""
    return value is None or math.isnan(value)


def estimates_outside(values, low, high):
    """The estimated values (not_estimated ones skipped) outside the open range (low, high)."""
    return [v for v in values if not not_estimated(v) and not low < v < high]
