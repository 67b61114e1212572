// SPDX-License-Identifier: LGPL-2.1-or-later
// Typing by profile (beyond the papers): across every sharp line, the two faces' planes and the
// cloud's profile between them tell a crease from a small blend, which becomes two smooth lines
// on its borders (one smooth line along it when narrower than 1.2 spacings). Design:
// docs/design/profile-typing.md.
#pragma once

#include <limits>
#include <vector>

#include "FeatureLines/network/Polyline.h"
#include "FeatureLines/sharp/FirstOrderSegmentation.h"

namespace featurelines {

/// Polyline::label of the blend borders typeByProfile() puts in place of a sharp line.
constexpr int blendBorderLabel = 2;

struct ProfileTypingOptions
{
    /// Type sharp lines by their profile and split blends in two borders (true). When false,
    /// the lines still get their angle.
    bool splitBlends = true;
    /// Spacings: the faces are fitted to their points within this distance of a station (7).
    double reach = 7.0;
    /// Spacings: a station's profile holds the points within this distance of its plane
    /// across the line (1).
    double slab = 1.0;
    /// Spacings: residuals of the profile fit beyond this count as this (1.5): points of a
    /// third face or of the other sheet do not decide the fit.
    double residualLimit = 1.5;
    /// Spacings: the largest blend radius tried (12).
    double maxRadius = 12.0;
    /// Spacings: a line is a blend when its fitted radius is at least minNarrowRadius (0.6) ...
    double minNarrowRadius = 0.6;
    /// ... the blend lowers the crease model's squared residual by at least this many times the
    /// blend's own mean squared residual per point (a likelihood ratio: noise alone lowers it by
    /// about one) (30), that residual read over the whole profile or, when smaller, over its
    /// points within significanceWindow of the arc ...
    double minSignificance = 30.0;
    /// Spacings: ... the points no farther than the tangent length plus this (1) from the apex,
    /// where the blend and the crease differ. Far out, what neither model is meant to explain
    /// (the far foot of a thin wall, a face that curves) leaves a residual that says nothing of
    /// the corner. 0: the whole profile only.
    double significanceWindow = 1.0;
    /// ... and the blend explains at least this share of what the best flat cut across the
    /// corner explains (0.9): a cut that fits far better is a chamfer or a narrow third face.
    double minShareOfCut = 0.9;
    /// Spacings: a blend of radius at least this (1.2) becomes its two borders; a narrower one
    /// (from minNarrowRadius), whose borders would lie under two spacings apart, becomes one
    /// smooth line where the sharp line ran, carrying its radius.
    double minBlendRadius = 1.2;
    /// Spacings: a face's fitted plane must pass within this distance of the line's vertex
    /// (2.5); a plane farther off is the other sheet of a thin wall or a face beyond a step.
    double maxFaceOffset = 2.5;
    /// Degrees: faces closer to parallel than this define no crease, and the station is not
    /// fitted (15).
    double minTurn = 15.0;
    /// Spacings: a face's plane is fitted to its points at least this far from the line (1.5):
    /// nearer, the segmentation may give a face the start of a blend.
    double faceClearance = 1.5;
    /// Points a face needs within reach to be fitted (6).
    int minFacePoints = 6;
    /// Spacings: the radius is estimated per vertex over the stations within this arc length
    /// (a fillet's radius may vary along it) (8).
    double radiusWindow = 8.0;
    /// A sharp line is dropped when fewer than this share of its vertices (0.25) see a face:
    /// a large cluster whose plane passes within maxFaceOffset of the vertex. A crease lies on
    /// its faces; a line with none within reach runs over a surface the segmentation broke
    /// into candidates everywhere (a rod or a bore of a few spacings' radius, curved faster
    /// than the growing follows). 0: no line is dropped.
    double minFaceShare = 0.25;
    /// Spacings: open sharp lines shorter than this (21, three reaches) left hanging on a
    /// dropped line's end (and on no other line's) go with it, again and again: the pieces of
    /// the broken surface's net that reach a face. Longer ones stay, so that a true edge that
    /// ran into the broken surface is not lost.
    double maxSpurLength = 21.0;
    /// Worker threads; 0: OpenMP's default (0).
    int threads = 0;
};

/// What the profile tells of one line.
struct LineProfile
{
    /// Stations (vertices) where two faces were fitted.
    int stations = 0;
    /// Degrees: median angle between the two faces inside their wedge (90 for a box's edges).
    double angle = std::numeric_limits<double>::quiet_NaN();
    /// Length unit: the radius of the blend that fits the profile best over the whole line
    /// (0 for a crease).
    double radius = std::numeric_limits<double>::quiet_NaN();
    /// Share of the crease model's squared residual the blend explains (0 .. 1).
    double gain = std::numeric_limits<double>::quiet_NaN();
    /// How far the blend lowers the crease model's squared residual, in units of the blend's
    /// mean squared residual per point (over the profile, or near the arc when smaller:
    /// ProfileTypingOptions::significanceWindow).
    double significance = std::numeric_limits<double>::quiet_NaN();
    /// Share of the crease model's squared residual the best flat cut (a chamfer, or a narrow
    /// third face) explains, and the cut's setbacks from the apex along the two faces.
    double chamferGain = std::numeric_limits<double>::quiet_NaN();
    double setback[2] = {std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::quiet_NaN()};
    /// The line was typed a blend: replaced by its two borders, or by one smooth line when
    /// `narrow` (radius under minBlendRadius).
    bool blend = false;
    bool narrow = false;
};

struct ProfileTyping
{
    /// The network with every blend's sharp line replaced by its two borders (label
    /// blendBorderLabel), which end where the sharp line ended, or a narrow blend's by one
    /// line of that label in its place, and without the lines no face is near.
    LineNetwork network;
    /// Per line of `network`: its profile; a border carries the profile of its blend.
    std::vector<LineProfile> profiles;
};

/// Types the sharp lines (label sharpLineLabel) of `network` by the cloud's profile across
/// them. At every vertex the two largest faces within reach (the segmentation's large clusters,
/// a cluster split in two where its normals turn by minTurn) whose planes pass within
/// maxFaceOffset of it are fitted with planes; the points
/// near the plane across the line then fit either the two planes meeting in a crease or the same
/// planes joined by a circular blend tangent to both, of the radius that fits best over the line. A
/// line whose radius and gain pass the options' limits is replaced by the blend's two tangent
/// lines, or, under minBlendRadius, relabelled as one blend line. A sharp line that sees a
/// face at under minFaceShare of its vertices is dropped, with the short lines left hanging on
/// it (maxSpurLength); the junctions stay as they were. Other lines are copied; every line
/// gets its profile.
///   P        #P by 3 points
///   normals  #P by 3 unit normals (unoriented), or empty: then a face is one cluster
///   seg      the sharp stage's segmentation (its large clusters are the faces)
///   boundary #P nonzero for boundary points (fitted to no face), or empty
///   spacing  sampling spacing (samplingSpacing())
ProfileTyping typeByProfile(const PointMatrix& P, const NormalMatrix& normals,
                            const FirstOrderSegmentation& seg, const std::vector<char>& boundary,
                            const LineNetwork& network, double spacing,
                            const ProfileTypingOptions& options = {});

} // namespace featurelines
