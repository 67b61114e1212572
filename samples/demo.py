# SPDX-License-Identifier: LGPL-2.1-or-later
"""The main job, headless: the FeatureLines FreeCAD module turns a scanned cloud into closed
feature lines (Part wires) and saves a document a user opens in FreeCAD.

Run by samples/demo (which installs the module first), or by hand:

    FREECAD_USER_HOME=DIR freecadcmd samples/demo.py

with the module installed into DIR (cmake --install BUILD --prefix DIR). freecadcmd reads its
own command line, so the inputs come from the environment:
    FEATURELINES_DEMO_CLOUD   the cloud (default: boss_blend.xyz next to this script)
    FEATURELINES_DEMO_OUTPUT  the document written (default: <cloud name>-lines.FCStd in the
                              current folder)
Prints a summary and exits 0, or 1 with the reason.
"""

import os
import sys
import time
import traceback


def open_line_ends(lines, tolerance):
    """Of the open wires, how many have both ends within `tolerance` of another wire (a network
    joined at its ends, e.g. a fillet border ending on a sharp edge) and how many do not."""
    import Part

    wires = lines.SharpWires.Wires + lines.SmoothWires.Wires + lines.BoundaryWires.Wires
    joined = free = 0
    for i, wire in enumerate(wires):
        if wire.isClosed():
            continue
        others = Part.makeCompound([w for j, w in enumerate(wires) if j != i] or [wire])
        ends = (wire.OrderedVertexes[0], wire.OrderedVertexes[-1])
        if len(wires) < 2 or any(others.distToShape(end)[0] > tolerance for end in ends):
            free += 1
        else:
            joined += 1
    return joined, free


def summary(cloud, lines, seconds):
    spacing = lines.Spacing.Value
    print("")
    print("Feature lines of %s" % cloud.Label)
    print("  points          %d" % cloud.Points.CountPoints)
    print("  point spacing   %.4g (every length parameter is a multiple of it)" % spacing)
    print("  sharp lines     %d" % lines.SharpLineCount)
    print("  smooth lines    %d (fillet borders)" % lines.SmoothLineCount)
    print("  boundary lines  %d" % lines.BoundaryLineCount)
    total = lines.SharpLineCount + lines.SmoothLineCount + lines.BoundaryLineCount
    joined, free = open_line_ends(lines, 3 * spacing)
    print("  closed          %d of %d; %d end on other lines, %d have a free end" %
          (lines.ClosedLineCount, total, joined, free))
    print("  smooth regions  %d, patches %d" % (lines.RegionCount, lines.PatchCount))
    by_region = {}
    for region, threshold in zip(lines.UsedThresholdRegions, lines.UsedThresholds):
        by_region.setdefault(region, []).append(threshold)
    for region in sorted(by_region):
        print("  region %-3d      thresholds %s (1/length)" %
              (region, ", ".join("%.4g" % t for t in by_region[region])))
    regions_without = lines.RegionCount - len(by_region)
    if regions_without:
        print("  %d region(s) without a curvature valley (no smooth edge)" % regions_without)
    print("  time            %.2f s" % seconds)


def main():
    import FreeCAD
    import FeatureLines
    import FeatureLinesImport

    here = os.path.dirname(os.path.abspath(__file__))
    cloud_path = os.environ.get("FEATURELINES_DEMO_CLOUD") or os.path.join(here,
                                                                           "boss_blend.xyz")
    name = os.path.splitext(os.path.basename(cloud_path))[0]
    output = os.environ.get("FEATURELINES_DEMO_OUTPUT") or os.path.join(os.getcwd(),
                                                                        name + "-lines.FCStd")
    doc = FreeCAD.newDocument(name.replace("-", "_") + "_lines")
    cloud = FeatureLinesImport.insert(cloud_path, doc.Name)
    lines = FeatureLines.makeExtraction(cloud)
    start = time.time()
    doc.recompute()
    seconds = time.time() - start
    if "Invalid" in lines.State:
        print("Feature line extraction failed: %s" % lines.getStatusString())
        return 1
    patches = FeatureLines.makePatchClouds(lines)
    for patch in patches:
        patch.Visibility = False  # shown on demand in the tree, the lines stay in view
    summary(cloud, lines, seconds)
    print("  patch clouds    %d (Points objects for surface fitting)" % len(patches))
    doc.saveAs(output)
    print("")
    print("Saved %s: open it in FreeCAD (with the FeatureLines module installed) to see the "
          "wires on the cloud." % output)
    return 0


code = 1
try:
    code = main()
except BaseException:
    traceback.print_exc()
finally:
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
