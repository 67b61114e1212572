// SPDX-License-Identifier: LGPL-2.1-or-later
// The one table of an extraction's scalar parameters, one row each, in the order of the
// properties: an X-macro. Who includes it defines
//   FEATURELINES_PARAMETER(Name, Kind, Stage, Group, Minimum, Maximum, Step, Choices, Option, Doc)
// and gets one expansion per row: ExtractionParameters.cpp the table of parameters() (the Python
// keywords), ExtractionFeature.h the property members, ExtractionFeature.cpp their initialisation.
//   Name     property name and Python keyword
//   Kind     ParameterKind: the property type (Integer, Float, Spacing, Angle, Switch, Choice)
//   Stage    ParameterStage: the first cached step it affects (Cloud, Regions, Lines)
//   Group    property group
//   Minimum, Maximum, Step   the property's range and step
//   Choices  Choice only: the null-terminated names of the values (nullptr otherwise)
//   Option   the field of featurelines::ExtractionOptions `o` it maps to (its default is the
//            parameter's default)
//   Doc      property tool tip and Python documentation
// No include guard: it is included once per expansion.

// Neighbourhood
FEATURELINES_PARAMETER(
    NeighbourCount, Integer, Cloud, "Neighbourhood", 3, 1000, 1, nullptr, o.neighbours.k,
    "k: the nearest neighbours of every point used for normals, curvature and the graphs "
    "(Sec. 2.1). More neighbours smooth noise but blur small features.")

// Sharp edges
FEATURELINES_PARAMETER(
    SharpEdges, Switch, Regions, "Sharp edges", 0, 1, 1, nullptr, o.sharpEdges,
    "Extract sharp edges (tangent discontinuities) by first-order segmentation (Demarsin et "
    "al. 2007). They divide the cloud into the smooth regions whose curvature is thresholded "
    "on its own (Sec. 1.2).")
FEATURELINES_PARAMETER(
    BoundaryLines, Switch, Regions, "Sharp edges", 0, 1, 1, nullptr, o.sharp.includeBoundary,
    "Extract the external boundary of an open cloud (a scan of one side of a part) and let "
    "sharp lines end on it (Sec. 1.2, Fig. 1 c).")
FEATURELINES_PARAMETER(
    GrowAngle, Angle, Regions, "Sharp edges", 1, 90, 1, nullptr, o.sharp.segmentation.growAngle,
    "A point may stop the growing of a surface cluster only when the normals of its "
    "neighbours spread more than this around its own (and its points bend like a crease, "
    "see MinFilletRadius). Lower it to find shallower creases.")
FEATURELINES_PARAMETER(
    JoinAngle, Angle, Regions, "Sharp edges", 1, 90, 1, nullptr, o.sharp.segmentation.joinAngle,
    "A neighbour joins the cluster of a growing point when their normals differ by less "
    "than this; points on a crease join neither face.")
FEATURELINES_PARAMETER(
    MinFilletRadius, Spacing, Regions, "Sharp edges", 0.5, 1000, 0.5, nullptr,
    o.sharp.segmentation.minFilletRadius,
    "Blends of this radius (x point spacing) or more are smooth edges, found by the "
    "curvature histogram; tighter bends are sharp edges.")
FEATURELINES_PARAMETER(
    CreaseFitRadius, Spacing, Regions, "Sharp edges", 0.5, 100, 0.5, nullptr, o.sharp.fitRadius,
    "Sharp lines are moved onto the intersection of planes fitted to the faces within this "
    "radius (x point spacing).")
FEATURELINES_PARAMETER(
    MinCreaseAngle, Angle, Regions, "Sharp edges", 0, 90, 1, nullptr, o.sharp.minCreaseAngle,
    "Two fitted faces closer to parallel than this define no crease: the line stays where "
    "the points are.")
FEATURELINES_PARAMETER(
    BoundaryGapAngle, Angle, Regions, "Sharp edges", 10, 350, 5, nullptr,
    o.sharp.boundary.minGapAngle,
    "A point is on the boundary when its neighbours, seen in its tangent plane, leave an "
    "empty sector wider than this.")

// Smooth edges
FEATURELINES_PARAMETER(
    SmoothEdges, Switch, Regions, "Smooth edges", 0, 1, 1, nullptr, o.smoothEdges,
    "Extract smooth edges (curvature discontinuities such as fillet borders) by histogram "
    "thresholding of the mean curvature in every smooth region (Sec. 2-3).")
FEATURELINES_PARAMETER(
    BandWidth, Spacing, Regions, "Smooth edges", 0, 50, 0.5, nullptr, o.regions.bandWidth,
    "Points closer than this to a sharp line (x point spacing) belong to no smooth region: "
    "their neighbourhoods straddle the crease.")
FEATURELINES_PARAMETER(
    Smoothing, Choice, Regions, "Smooth edges", 0, 2, 1, smoothingChoices, o.smooth.smoothing,
    "Taubin smoothing of a region before its curvature is estimated (Sec. 2.4): Automatic "
    "smooths the regions whose noise exceeds NoiseThreshold.")
FEATURELINES_PARAMETER(SmoothingIterations, Integer, Regions, "Smooth edges", 0, 1000, 1, nullptr,
                       o.smooth.smoothingOptions.iterations, "Taubin smoothing passes (Sec. 2.4).")
FEATURELINES_PARAMETER(
    NoiseThreshold, Spacing, Regions, "Smooth edges", 0, 10, 0.01, nullptr, o.smooth.noiseThreshold,
    "Noise (x point spacing) above which Automatic smoothing applies; a clean surface shows "
    "less than 0.005.")
FEATURELINES_PARAMETER(
    SignedCurvature, Switch, Regions, "Smooth edges", 0, 1, 1, nullptr,
    o.smooth.curvature.signedCurvature,
    "Threshold the signed mean curvature instead of its magnitude (concave and convex "
    "fillets of one radius then fall in different histogram peaks).")
FEATURELINES_PARAMETER(
    MaxCurvatureScale, Spacing, Regions, "Smooth edges", 1, 64, 1, nullptr,
    o.smooth.scales.maxScale,
    "Coarsest scale (x point spacing) at which a noisy region's curvature is also computed, "
    "averaged onto coarser grids, when the noise would hide fillets larger than this at the "
    "cloud's own spacing; the scale with the most significant thresholds is used. 1: the "
    "cloud's own spacing only, as the paper.")
FEATURELINES_PARAMETER(
    PlaceCoarseLines, Switch, Lines, "Smooth edges", 0, 1, 1, nullptr, o.smooth.placeCoarseLines,
    "Where a region's curvature was read at a coarser scale, move its smooth lines onto the "
    "curvature step of the points under them (a fit of the surface's profile across each "
    "line): the coarse scale alone leaves them a few point spacings off the fillet border.")
FEATURELINES_PARAMETER(
    PlaceOwnScaleLines, Switch, Lines, "Smooth edges", 0, 1, 1, nullptr,
    o.smooth.placeOwnScaleLines,
    "Where a region's curvature was read at the cloud's own spacing, move its smooth lines "
    "onto the curvature step of the points under them too, fitted within 6 point spacings: "
    "the curvature's levels alone leave them up to a spacing or two off the fillet border.")

// Line graph (Demarsin et al. 2007, reused for smooth edges in Sec. 3): one length for the
// graphs of sharp and smooth edges alike (graphLength).
FEATURELINES_PARAMETER(
    NodeRadius, Spacing, Regions, "Line graph", 0, 20, 0.5, nullptr,
    graphLength<&featurelines::ClusterGraphOptions::nodeRadius>(o),
    "Candidate points within this radius (x point spacing) form one graph node, so a band "
    "of candidates becomes a chain one node wide.")
FEATURELINES_PARAMETER(
    ExtendedRadius, Spacing, Regions, "Line graph", 0, 50, 0.5, nullptr,
    graphLength<&featurelines::ClusterGraphOptions::extendedRadius>(o),
    "Nodes closer than this (x point spacing) are joined, bridging gaps of missing "
    "candidates (G_extended).")
FEATURELINES_PARAMETER(
    MaxEdgeLength, Spacing, Regions, "Line graph", 0.5, 100, 0.5, nullptr,
    graphLength<&featurelines::ClusterGraphOptions::maxEdgeLength>(o),
    "Spanning tree edges longer than this (x point spacing) are cut: they join two "
    "features, not two pieces of one.")
FEATURELINES_PARAMETER(MinBranchLength, Spacing, Regions, "Line graph", 0, 100, 0.5, nullptr,
                       graphLength<&featurelines::ClusterGraphOptions::minBranchLength>(o),
                       "Branches to a free end shorter than this (x point spacing) are pruned.")
FEATURELINES_PARAMETER(
    ReconnectRadius, Spacing, Regions, "Line graph", 0, 200, 0.5, nullptr,
    graphLength<&featurelines::ClusterGraphOptions::reconnectRadius>(o),
    "A free line end is joined to the nearest node ahead of it within this distance (x "
    "point spacing), so lines close.")
FEATURELINES_PARAMETER(ReconnectAngle, Angle, Regions, "Line graph", 0, 180, 5, nullptr,
                       graphLength<&featurelines::ClusterGraphOptions::reconnectAngle>(o),
                       "\"Ahead\" of a free end is within this angle of the line's direction.")
FEATURELINES_PARAMETER(
    MinComponentLength, Spacing, Regions, "Line graph", 0, 10000, 1, nullptr,
    graphLength<&featurelines::ClusterGraphOptions::minComponentLength>(o),
    "Connected pieces of lines shorter than this in total (x point spacing) are dropped as "
    "noise.")
FEATURELINES_PARAMETER(
    ResampleSpacing, Spacing, Regions, "Line graph", 0, 100, 0.5, nullptr, resampleSpacing(o),
    "Lines are resampled at this step (x point spacing); 0 keeps one vertex per node.")

// Thresholds
FEATURELINES_PARAMETER(
    ThresholdMode, Choice, Lines, "Thresholds", 0, 2, 1, thresholdModeChoices, o.thresholdMode,
    "Automatic: per region, every significant valley of the curvature histogram (Sec. "
    "2.3); First: the first threshold only; Explicit: Thresholds and RegionThresholds.")
FEATURELINES_PARAMETER(
    HistogramBins, Integer, Lines, "Thresholds", 2, 100000, 1, nullptr, o.smooth.histogram.bins,
    "L_start: the bins of the start histogram of the multi-resolution search (Sec. 2.2; "
    "the paper's default is 50).")
FEATURELINES_PARAMETER(
    OutlierPercent, Float, Lines, "Thresholds", -1, 50, 0.5, nullptr,
    o.smooth.histogram.outlierPercent,
    "Percentage of the highest curvature values dropped before the histogram is built "
    "(Sec. 2.4); -1 chooses 1 % for a smoothed (noisy) region and none for a clean one.")
FEATURELINES_PARAMETER(
    MinPeakPercent, Float, Lines, "Thresholds", 0, 50, 0.5, nullptr,
    o.smooth.histogram.minPeakPercent,
    "Smallest histogram peak a threshold may follow, in percent of the values; 0 is the "
    "paper as is (Sec. 2.2).")
FEATURELINES_PARAMETER(MaxThresholds, Integer, Lines, "Thresholds", 1, 20, 1, nullptr,
                       o.smooth.automatic.maxThresholds,
                       "Automatic mode: at most this many thresholds per region.")
FEATURELINES_PARAMETER(
    MinValleyRatio, Float, Lines, "Thresholds", 1, 1000, 0.1, nullptr, o.smooth.automatic.minRatio,
    "Automatic mode: a threshold needs a valley ratio e = b1 / b2 of at least this (Sec. "
    "2.2).")
FEATURELINES_PARAMETER(
    MinContrast, Float, Lines, "Thresholds", 1, 1000, 0.1, nullptr, o.smooth.automatic.minContrast,
    "Automatic mode: the median curvature above a threshold over the median below it must "
    "reach this (two curvature levels, not one split in two).")
