# SPDX-License-Identifier: LGPL-2.1-or-later
"""FeatureLines' patch surfaces against FreeCAD's ReverseEngineering.approxSurface (issue 21:
"Compare with FreeCAD's approxSurface applied to the same patch clouds").

For every cloud: the FeatureLines extraction with its default parameters, then
FeatureLines.fitSurfaces (timed as one call), and for every patch that got a face there,
ReverseEngineering.approxSurface on the same patch points (the points makePatchClouds and
patchBorders give the patch). Measured per patch, for both surfaces alike:

  - RMS and largest distance of the patch's points to the surface, in point spacings (the
    extraction's Spacing). Each distance is exact: the point's orthogonal projection onto the
    untrimmed surface (Part surface.parameter(), OpenCASCADE's GeomAPI_ProjectPointOnSurf,
    nearest of all extrema), the same code for both methods. fitSurfaces' own rms_deviation /
    max_deviation are reported beside it (for a B-spline face they are the height residual
    along the patch's axis, not the orthogonal distance);
  - with the part's true B-rep: those projections' distance to the true shape
    (Part's distToShape, BRepExtrema), mean and 95th percentile over up to
    APPROX_TRUTH_SAMPLES points of the patch, in spacings, and the same for the raw points
    (the noise the cloud itself has, as a yardstick);
  - the time of approxSurface per patch, and of the whole fitSurfaces call per cloud;
  - what each gives: approxSurface an untrimmed B-spline over the bounding rectangle of the
    points in their plane (its face area against the trimmed FeatureLines face's area, and the
    "border gap": how far the patch's closed border wires, the lines it would be trimmed by,
    lie from it), FeatureLines the kind it recognised, trimmed by the patch's border; any
    approxSurface exception.

approxSurface is called with its documented defaults (UDegree=VDegree=3, NbUPoles=NbVPoles=6,
Smooth=True, Weight=0.1, Grad=1.0, Bend=0.0, Curv=0.0, Iterations=5, Correction=True,
PatchFactor=1.0), the same for every patch: no per-patch tuning. APPROX_DEGREE and APPROX_POLES
change the degree and pole count (both directions) for every patch. A patch of more than
APPROX_MAX_POINTS points is handed to it (and measured) as that many of its points picked at
random (seeded); FeatureLines itself fits at most 20000 points of a patch likewise.

Run with freecadcmd, the FeatureLines module found by FreeCAD (FREECAD_USER_DATA: a folder
holding Mod/FeatureLines, e.g. a copy of BUILD/Mod; see tests/app/CMakeLists.txt). freecadcmd
reads its own command line, so the inputs come from the environment:

    APPROX_CASES        folder written by `featurelines_accuracy --write DIR`:
                        DIR/<part>-<clean|noisy>/cloud.xyz (every such case is run) and the
                        part's true B-rep truth.brep beside it
    APPROX_TRUTH        optional: folder of <part>.brep, the true B-reps, for clouds without
                        a truth.brep beside them (the demo cloud's boss_blend.brep)
    APPROX_DEMO_CLOUD   optional: a further cloud (the shipped samples/boss_blend.xyz), run as
                        case "demo"; its truth is APPROX_DEMO_PART (default boss_blend)
    APPROX_OUTPUT       the Markdown report written (default approx-results.md)
    APPROX_ONLY         optional: comma-separated case names to run (e.g. box_fillets-clean)
    APPROX_MAX_POINTS   default 20000;  APPROX_TRUTH_SAMPLES default 300
    APPROX_BORDER_SAMPLES  points along a patch's border for the border gap (default 200)
    APPROX_DEGREE       default 3;      APPROX_POLES default 6
    APPROX_SEED         seed of every random pick (default 1)

e.g. (bench/approx/run.sh does all of it from a build):

    FREECAD_USER_DATA=WORK/mod FREECAD_USER_HOME=WORK/home \\
    APPROX_CASES=WORK/cases APPROX_TRUTH=WORK/truth \\
    APPROX_DEMO_CLOUD=samples/boss_blend.xyz APPROX_OUTPUT=WORK/approx-results.md \\
        freecadcmd bench/approx/compare_approx_surface.py > WORK/freecadcmd.log

approxSurface prints its progress on standard output, hence the redirection; this script's
own progress goes to standard error. Exits 0, or 1 with the reason.
"""

import math
import os
import random
import sys
import time
import traceback


def log(text):
    sys.stderr.write(text + "\n")
    sys.stderr.flush()


def setting(name, default, kind=str):
    value = os.environ.get(name, "")
    return kind(value) if value else default


# ---------------------------------------------------------------------------------------------
# Measures


def pick(points, count, seed):
    """At most `count` of the points, picked at random (seeded), in their order."""
    if len(points) <= count:
        return list(points)
    rows = sorted(random.Random(seed).sample(range(len(points)), count))
    return [points[i] for i in rows]


def projections(surface, points):
    """Each point's orthogonal projection onto the untrimmed `surface` and its distance."""
    feet, distances = [], []
    for p in points:
        u, v = surface.parameter(p)
        foot = surface.value(u, v)
        feet.append(foot)
        distances.append((foot - p).Length)
    return feet, distances


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else float("nan")


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def percentile(values, fraction):
    """The value below which `fraction` of them lie (nearest rank); NaN for none."""
    if not values:
        return float("nan")
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def distances_to(shape, points):
    """Each point's distance to `shape` (BRepExtrema through Part's distToShape)."""
    import Part

    return [shape.distToShape(Part.Vertex(p))[0] for p in points]


def border_samples(wires, spacing, count, seed):
    """At most `count` points along the border wires, about a spacing apart (picked at
    random, seeded, when there are more)."""
    points = []
    for wire in wires:
        for edge in wire.Edges:
            points += edge.discretize(max(2, int(edge.Length / spacing) + 1))
    return pick(points, count, seed)


def face_area(surface):
    """The area of the whole (untrimmed) surface, NaN where OpenCASCADE cannot make it."""
    import Part

    try:
        return Part.Face(surface).Area
    except Exception:
        return float("nan")


# ---------------------------------------------------------------------------------------------
# One cloud


def approx_surface(points, degree, poles):
    """ReverseEngineering.approxSurface with its defaults but degree and poles: (surface,
    seconds, error text)."""
    import Points
    import ReverseEngineering

    kernel = Points.Points(points)
    start = time.perf_counter()
    try:
        surface = ReverseEngineering.approxSurface(
            Points=kernel, UDegree=degree, VDegree=degree, NbUPoles=poles, NbVPoles=poles,
            Smooth=True, Weight=0.1, Grad=1.0, Bend=0.0, Curv=0.0, Iterations=5,
            Correction=True, PatchFactor=1.0)
        return surface, time.perf_counter() - start, ""
    except Exception as e:  # approxSurface raises ValueError or RuntimeError
        return None, time.perf_counter() - start, "%s: %s" % (type(e).__name__, e)


def compare_cloud(case, cloud_path, truth, options):
    """Runs both methods on one cloud; returns the case's summary and per-patch rows."""
    import FreeCAD
    import FeatureLines
    import Part

    doc = FreeCAD.newDocument("Approx")
    try:
        cloud = doc.addObject("Points::Feature", "Cloud")
        cloud.Points = FeatureLines.readCloud(cloud_path)
        start = time.perf_counter()
        lines = FeatureLines.makeExtraction(cloud)
        doc.recompute()
        extraction_seconds = time.perf_counter() - start
        spacing = lines.Spacing.Value

        start = time.perf_counter()
        fitted = FeatureLines.fitSurfaces(lines)
        fit_seconds = time.perf_counter() - start

        # The patch clouds (the same patches and min_points rule as makePatchClouds) and
        # their closed border wires.
        borders = FeatureLines.patchBorders(lines)
        patch_points = {p["patch"]: p["points"] for p in borders}
        patch_wires = {p["patch"]: p["wires"] for p in borders}

        rows = []
        for f in fitted["faces"]:
            if f["face"] is None:
                continue
            patch = f["patch"]
            points = patch_points[patch]
            if f["points"] != len(points):
                log("  patch %d: fitSurfaces counts %d points, patchBorders %d" % (
                    patch, f["points"], len(points)))
            seed = options["seed"] * 100003 + patch
            used = pick(points, options["max_points"], seed)
            row = {"patch": patch, "points": len(points), "used": len(used), "kind": f["kind"],
                   "fl_rms_own": f["rms_deviation"] / spacing,
                   "fl_max_own": f["max_deviation"] / spacing}

            # FeatureLines' face: the same orthogonal distances as for approxSurface.
            fl_surface = f["face"].Surface
            fl_feet, fl_dist = projections(fl_surface, used)
            row["fl_rms"] = rms(fl_dist) / spacing
            row["fl_max"] = max(fl_dist) / spacing
            fl_area = f["face"].Area

            # approxSurface on the same points.
            surface, seconds, error = approx_surface(used, options["degree"], options["poles"])
            row["ap_seconds"] = seconds
            row["ap_error"] = error
            if surface is not None:
                ap_feet, ap_dist = projections(surface, used)
                row["ap_rms"] = rms(ap_dist) / spacing
                row["ap_max"] = max(ap_dist) / spacing
                row["area_ratio"] = face_area(surface) / fl_area if fl_area > 0 else float("nan")
                # Does the untrimmed surface reach the patch's border (the lines it would be
                # trimmed by)? The border's distance to the surface's face.
                try:
                    border = border_samples(patch_wires[patch], spacing,
                                            options["border_samples"], seed + 2)
                    gaps = [d / spacing for d in distances_to(Part.Face(surface), border)]
                    row["border_gap_mean"], row["border_gap_max"] = mean(gaps), max(gaps)
                except Exception as e:
                    log("  patch %d: border gap not measured (%s)" % (patch, e))

            # Against the truth: the projections of the same few points on each surface.
            if truth is not None:
                rows_t = sorted(random.Random(seed + 1).sample(
                    range(len(used)), min(len(used), options["truth_samples"])))
                raw = [used[i] for i in rows_t]
                row["raw_truth"] = [d / spacing for d in distances_to(truth, raw)]
                row["fl_truth"] = [d / spacing
                                   for d in distances_to(truth, [fl_feet[i] for i in rows_t])]
                if surface is not None:
                    row["ap_truth"] = [d / spacing for d in
                                       distances_to(truth, [ap_feet[i] for i in rows_t])]
            rows.append(row)
            log("  patch %3d %-8s %6d pts  FL rms %.3f  approx %s  %.2f s" % (
                patch, f["kind"], len(points), row["fl_rms"],
                "rms %.3f" % row["ap_rms"] if "ap_rms" in row else error, seconds))

        summary = {"case": case, "points": cloud.Points.CountPoints, "spacing": spacing,
                   "patches": len(fitted["faces"]),
                   "no_face": sum(1 for f in fitted["faces"] if f["face"] is None),
                   "extraction_seconds": extraction_seconds, "fit_seconds": fit_seconds,
                   "solid": fitted["solid"], "valid": fitted["valid"], "truth": truth is not None}
        return summary, rows
    finally:
        FreeCAD.closeDocument(doc.Name)


# ---------------------------------------------------------------------------------------------
# The report


def fmt(value, digits=3):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return "%.*f" % (digits, value)


def collect(rows, key):
    return [r[key] for r in rows if key in r]


def pooled(rows, key):
    """The per-point truth distances of all rows, pooled."""
    return [d for r in rows for d in r.get(key, [])]


def kinds_text(rows):
    counts = {}
    for r in rows:
        counts[r["kind"]] = counts.get(r["kind"], 0) + 1
    return ", ".join("%d %s" % (n, k) for k, n in sorted(counts.items()))


def pair(a, b, digits=3, digits_b=None):
    """'a / b' for a table cell."""
    return "%s / %s" % (fmt(a, digits), fmt(b, digits if digits_b is None else digits_b))


def table_row(cells):
    return "| " + " | ".join(str(c) for c in cells) + " |"


def poor_fit(r):
    """approxSurface returned a surface more than a spacing (RMS) from the patch's points: a
    surface, but not the patch's."""
    return r.get("ap_rms", 0.0) > 1.0


def approx_lower(r):
    return "ap_rms" in r and r["ap_rms"] < r["fl_rms"]


def failures(rows):
    """'raised / RMS > 1 spacing' of approxSurface, for a table cell."""
    return "%d / %d" % (sum(1 for r in rows if r["ap_error"]), sum(1 for r in rows if poor_fit(r)))


def largest(values):
    return max(values) if values else float("nan")


def case_line(summary, rows):
    """One row of the overall table."""
    fl_rms, ap_rms = collect(rows, "fl_rms"), collect(rows, "ap_rms")
    cells = [summary["case"], summary["patches"], len(rows),
             pair(mean(fl_rms), percentile(fl_rms, 0.95)),
             pair(mean(ap_rms), percentile(ap_rms, 0.95)),
             sum(1 for r in rows if approx_lower(r)),
             failures(rows)]
    for key in ("raw_truth", "fl_truth", "ap_truth"):
        values = pooled(rows, key)
        cells.append(pair(mean(values), percentile(values, 0.95)) if summary["truth"] else "-")
    cells.append(closer_to_truth(rows) if summary["truth"] else "-")
    cells += [pair(mean(collect(rows, "border_gap_mean")),
                   largest(collect(rows, "border_gap_max")), 2, 1),
              summary["no_face"], kinds_text(rows), "%.2f" % summary["fit_seconds"],
              "%.2f" % sum(r["ap_seconds"] for r in rows)]
    return table_row(cells)


OVERALL_HEADER = (
    "| case | patches | compared | FL RMS mean / p95 | approx RMS mean / p95 | approx RMS lower | "
    "approx failed / RMS > 1 | points to truth mean / p95 | FL to truth mean / p95 | "
    "approx to truth mean / p95 | closer to truth FL / approx / tie | "
    "approx border gap mean / max | FL no face | FL kinds | FL fitSurfaces s | approx s |\n"
    "|---|--:|--:|---|---|--:|---|---|---|---|---|---|--:|---|--:|--:|")

PATCH_HEADER = (
    "| case | patch | points (used) | FL kind | FL RMS / max | FL own RMS / max | "
    "approx RMS / max | approx area / FL area | approx border gap mean / max | "
    "points to truth mean | FL to truth mean / p95 | approx to truth mean / p95 | approx s | "
    "approx error |\n"
    "|---|--:|---|---|---|---|---|--:|---|--:|---|---|--:|---|")


def patch_line(case, r):
    """One row of a part's table: one patch."""
    used = "%d" % r["points"] if r["used"] == r["points"] else "%d (%d)" % (r["points"], r["used"])
    fl_truth, ap_truth = r.get("fl_truth", []), r.get("ap_truth", [])
    return table_row([
        case, r["patch"], used, r["kind"], pair(r["fl_rms"], r["fl_max"]),
        pair(r["fl_rms_own"], r["fl_max_own"]), pair(r.get("ap_rms"), r.get("ap_max")),
        fmt(r.get("area_ratio"), 1), pair(r.get("border_gap_mean"), r.get("border_gap_max"), 2, 1),
        fmt(mean(r.get("raw_truth", []))), pair(mean(fl_truth), percentile(fl_truth, 0.95)),
        pair(mean(ap_truth), percentile(ap_truth, 0.95)), "%.2f" % r["ap_seconds"],
        r["ap_error"].replace("|", "/")])


# Two surfaces whose mean distances to the truth differ by at most this (spacings) are as close.
TIE = 0.01

KIND_HEADER = (
    "| FL kind | patches | FL RMS mean / p95 | approx RMS mean / p95 | approx RMS lower | "
    "approx failed / RMS > 1 | FL to truth mean | approx to truth mean | "
    "closer to truth FL / approx / tie | approx border gap mean |\n"
    "|---|--:|---|---|--:|---|--:|--:|---|--:|")


def closer_to_truth(rows):
    """Patches whose surface is the closer one to the truth (its projections' mean distance,
    lower by more than TIE spacing): "FL / approx / tie"; a failed approxSurface counts for
    FeatureLines."""
    fl = ap = tie = 0
    for r in rows:
        if "fl_truth" not in r:
            continue
        difference = mean(r["fl_truth"]) - mean(r.get("ap_truth", [float("inf")]))
        if abs(difference) <= TIE:
            tie += 1
        elif difference > 0:
            ap += 1
        else:
            fl += 1
    return "%d / %d / %d" % (fl, ap, tie)


def group_text(label, rows):
    """The summary of a group of patches, one sentence."""
    fl_rms, ap_rms = collect(rows, "fl_rms"), collect(rows, "ap_rms")
    truth = ["%s %s / %s" % (name, fmt(mean(pooled(rows, key))),
                             fmt(percentile(pooled(rows, key), 0.95)))
             for name, key in (("points", "raw_truth"), ("FL", "fl_truth"),
                               ("approx", "ap_truth"))]
    return ("**%s** (%d patches): RMS (mean / p95) FL %s, approx %s; approx RMS lower on %d; "
            "approx failed on %d, RMS > 1 spacing on %d; to truth (mean / p95): %s; closer to "
            "truth (FL / approx / tie): %s; approx area / FL face area median %s; approx border "
            "gap mean %s, largest %s." % (
                label, len(rows), pair(mean(fl_rms), percentile(fl_rms, 0.95)),
                pair(mean(ap_rms), percentile(ap_rms, 0.95)),
                sum(1 for r in rows if approx_lower(r)), sum(1 for r in rows if r["ap_error"]),
                sum(1 for r in rows if poor_fit(r)), ", ".join(truth), closer_to_truth(rows),
                fmt(percentile(collect(rows, "area_ratio"), 0.5), 1),
                fmt(mean(collect(rows, "border_gap_mean")), 2),
                fmt(largest(collect(rows, "border_gap_max")), 1)))


def part_of(case):
    return case.rsplit("-", 1)[0] if case != "demo" else "demo"


INTRO = """Written by bench/approx/compare_approx_surface.py. Every length is in point spacings
(the extraction's Spacing of each cloud).

- FL: FeatureLines.fitSurfaces with default parameters (trimmed faces, sewn);
  approx: ReverseEngineering.approxSurface (degree %d, %dx%d poles, its other defaults: Smooth,
  Weight 0.1, Grad 1, Bend 0, Curv 0, 5 iterations with parameter correction, PatchFactor 1),
  the same for every patch, on the same patch points (at most %d of them, picked at random,
  seed %d). Only patches where FL made a face are compared ("compared"; "FL no face": the
  others).
- RMS / max: the points' orthogonal distances to the untrimmed surface
  (GeomAPI_ProjectPointOnSurf), the same measure for both. "FL own": fitSurfaces'
  rms_deviation / max_deviation (for a B-spline face the height residual along the patch's
  axis). "approx RMS lower": patches where approxSurface's RMS is below FL's. "RMS > 1":
  approxSurface returned a surface more than a spacing (RMS) from the patch's points;
  "failed": it raised.
- To truth: up to %d points of the patch projected onto the surface, their distance to the
  true B-rep (BRepExtrema); "points to truth": the raw points' own distance (the cloud's
  noise). "Closer to truth": patches whose surface has the lower mean, by more than %s
  spacing, else a tie (a failed approxSurface counts for FL).
- Border gap: the distance of points along the patch's closed border wires (the lines, about
  a spacing apart, at most %d) to approxSurface's untrimmed face: 0 where it reaches the lines
  it would be trimmed by (FL's face is trimmed by them). Area: the untrimmed approx face's
  area over FL's trimmed face's.
- Times: FL the whole fitSurfaces call (fit, trim and sew every patch), approx the sum of its
  calls. Total run %.0f s.
"""


def report(results, options, total_seconds):
    out = []
    out.append("# FeatureLines' patch surfaces against FreeCAD's approxSurface\n")
    out.append(INTRO % (options["degree"], options["poles"], options["poles"],
                        options["max_points"], options["seed"], options["truth_samples"],
                        TIE, options["border_samples"], total_seconds))

    out.append("## Overall\n")
    out.append(OVERALL_HEADER)
    for summary, rows in results:
        out.append(case_line(summary, rows))
    out.append("")
    all_rows = [r for _, rows in results for r in rows]
    groups = (("all", all_rows),
              ("clean (with the demo cloud)",
               [r for s, rows in results if not s["case"].endswith("-noisy") for r in rows]),
              ("noisy", [r for s, rows in results if s["case"].endswith("-noisy") for r in rows]))
    for label, chosen in groups:
        out.append("- " + group_text(label, chosen))

    out.append("\n### By the kind FeatureLines recognised\n")
    out.append(KIND_HEADER)
    kinds = sorted(set(r["kind"] for r in all_rows))
    for kind in kinds:
        rows = [r for r in all_rows if r["kind"] == kind]
        fl_rms, ap_rms = collect(rows, "fl_rms"), collect(rows, "ap_rms")
        out.append(table_row([
            kind, len(rows), pair(mean(fl_rms), percentile(fl_rms, 0.95)),
            pair(mean(ap_rms), percentile(ap_rms, 0.95)), sum(1 for r in rows if approx_lower(r)),
            failures(rows),
            fmt(mean(pooled(rows, "fl_truth"))), fmt(mean(pooled(rows, "ap_truth"))),
            closer_to_truth(rows), fmt(mean(collect(rows, "border_gap_mean")), 2)]))

    out.append("\n## Per part\n")
    parts = []
    for summary, _ in results:
        if part_of(summary["case"]) not in parts:
            parts.append(part_of(summary["case"]))
    for part in parts:
        out.append("### %s\n" % part)
        for summary, rows in results:
            if part_of(summary["case"]) == part:
                out.append("- %s: %d points, spacing %.4g, %d patches (%d without a FL face), "
                           "FL solid %s, valid %s; extraction %.2f s, fitSurfaces %.2f s, "
                           "approxSurface %.2f s in all." % (
                               summary["case"], summary["points"], summary["spacing"],
                               summary["patches"], summary["no_face"], summary["solid"],
                               summary["valid"], summary["extraction_seconds"],
                               summary["fit_seconds"], sum(r["ap_seconds"] for r in rows)))
        out.append("")
        out.append(PATCH_HEADER)
        for summary, rows in results:
            if part_of(summary["case"]) == part:
                for r in rows:
                    out.append(patch_line(summary["case"], r))
        out.append("")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------------------------------------


def cases_to_run():
    """(case, cloud file, part of its truth) in a fixed order: the written cases, then the
    demo cloud."""
    cases = []
    folder = os.environ.get("APPROX_CASES", "")
    if folder:
        for name in sorted(os.listdir(folder)):
            cloud = os.path.join(folder, name, "cloud.xyz")
            if os.path.isfile(cloud):
                cases.append((name, cloud, part_of(name)))
    demo = os.environ.get("APPROX_DEMO_CLOUD", "")
    if demo:
        cases.append(("demo", demo, setting("APPROX_DEMO_PART", "boss_blend")))
    only = [c for c in os.environ.get("APPROX_ONLY", "").split(",") if c]
    if only:
        cases = [c for c in cases if c[0] in only]
    return cases


def main():
    import Part

    options = {"max_points": setting("APPROX_MAX_POINTS", 20000, int),
               "truth_samples": setting("APPROX_TRUTH_SAMPLES", 300, int),
               "border_samples": setting("APPROX_BORDER_SAMPLES", 200, int),
               "degree": setting("APPROX_DEGREE", 3, int),
               "poles": setting("APPROX_POLES", 6, int),
               "seed": setting("APPROX_SEED", 1, int)}
    output = setting("APPROX_OUTPUT", "approx-results.md")
    truth_folder = os.environ.get("APPROX_TRUTH", "")
    cases = cases_to_run()
    if not cases:
        raise ValueError("no clouds: set APPROX_CASES and/or APPROX_DEMO_CLOUD")
    start = time.perf_counter()
    results = []
    for case, cloud, part in cases:
        truth = None
        # The case's own truth.brep (featurelines_accuracy --write), else APPROX_TRUTH's.
        brep = os.path.join(os.path.dirname(cloud), "truth.brep")
        if not os.path.isfile(brep):
            brep = os.path.join(truth_folder, part + ".brep") if truth_folder else ""
        if brep and os.path.isfile(brep):
            truth = Part.read(brep)
        log("%s (%s)%s" % (case, cloud, "" if truth is not None else ", no truth B-rep"))
        results.append(compare_cloud(case, cloud, truth, options))
        # The report so far, so that an interrupted run leaves what it measured.
        with open(output, "w") as f:
            f.write(report(results, options, time.perf_counter() - start))
    log("wrote %s (%.0f s)" % (output, time.perf_counter() - start))


# freecadcmd imports the script as a module and runs it again when the import raises: catch
# everything and leave with a real exit code (as tests/app/run_tests.py does).
code = 1
try:
    main()
    code = 0
except BaseException:
    traceback.print_exc()
finally:
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
