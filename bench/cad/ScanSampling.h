// SPDX-License-Identifier: LGPL-2.1-or-later
// Point clouds of a B-rep sampled as real scanners sample (issue 16): uneven, in scan rows,
// merged from misregistered views, with density gradients, occlusion holes, outliers and
// noise. docs/ACCURACY.md, "Scanner models", describes the models and their ranges.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include <Eigen/Core>

#include "FeatureLines/PointCloud.h"
#include "LineScore.h"

namespace featurelines::bench {

enum class ScanModel
{
    /// Uniform random by area: clumps and gaps, no minimum distance.
    UniformRandom,
    /// The benchmark's even sampling (sampleShape, ShapeSampling.h).
    PoissonDisk,
    /// One line scanner's view: rows of points, finer along a row than across.
    ScanLines,
    /// Two or three scan-line views merged, each slightly misregistered.
    MergedViews,
    /// Poisson disk whose density grows linearly across the part.
    DensityGradient
};

/// "uniform_random", "poisson_disk", "scan_lines", "merged_views", "density_gradient".
std::string scanModelName(ScanModel model);

/// One view of a line scanner: rays parallel to `direction` in rows along `rowDirection`.
struct ScanView
{
    /// Unit direction the scanner looks along (from the scanner into the part).
    Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();
    /// Unit direction of the rows, perpendicular to `direction`.
    Eigen::Vector3d rowDirection = Eigen::Vector3d::UnitX();
};

/// A region left unscanned: the points within `radius` of the line through `point` along
/// `direction` are removed (a cylinder through the part: a hole on each side it crosses).
struct OcclusionHole
{
    Eigen::Vector3d point;
    Eigen::Vector3d direction;
    double radius;
};

struct ScanOptions
{
    ScanModel model = ScanModel::PoissonDisk;
    /// Points wanted before holes and outliers (> 1); the scan models count the points the
    /// views see, so a single view covers part of the shape with all of them.
    double points = 50000.0;

    /// ScanLines, MergedViews: spacing across the rows / spacing along a row (>= 1).
    double rowSpacingRatio = 4.0;
    /// ScanLines (one) and MergedViews (each); empty: viewCount views drawn from the seed.
    std::vector<ScanView> views;
    /// MergedViews: views drawn when `views` is empty (ScanLines draws one).
    int viewCount = 2;
    /// Drawn views: each turned from the previous by an angle in this range (degrees).
    double minViewTurnDegrees = 45.0;
    double maxViewTurnDegrees = 120.0;
    /// A surface seen more obliquely than this angle from its normal gives no point (degrees).
    double grazingLimitDegrees = 80.0;
    /// MergedViews: largest displacement of a point by its view's rigid misregistration
    /// (half translation, half rotation about the part's centre), in along-row spacings.
    double misregistration = 0.3;

    /// DensityGradient: density at the dense end / density at the sparse end (>= 1).
    double densityRatio = 4.0;
    /// DensityGradient: direction in which the density grows; zero: drawn from the seed.
    Eigen::Vector3d gradientDirection = Eigen::Vector3d::Zero();
    /// UniformRandom, PoissonDisk, DensityGradient: Poisson-disk candidates per sample.
    double oversampling = 10.0;

    /// Occlusion holes: how many (>= 0), centred on random points of the cloud, along random
    /// directions (a view's direction for the scan models).
    int occlusionHoles = 0;
    /// Radius of each hole, in spacings (mean nearest spacing of the clean cloud).
    double holeRadius = 8.0;
    /// Share of the points displaced off the surface (0 to 1) in random directions, by a
    /// distance uniform in [outlierMinDistance, outlierMaxDistance] spacings.
    double outlierShare = 0.0;
    double outlierMinDistance = 3.0;
    double outlierMaxDistance = 20.0;
    /// Gaussian noise along the normal, standard deviation in spacings.
    double normalNoise = 0.0;
    /// Gaussian jitter in the tangent plane, standard deviation per direction in spacings.
    double tangentialJitter = 0.0;

    /// Chordal deflection of the triangulation, as a multiple of the sampling step.
    double meshDeflectionFactor = 0.1;
    std::uint32_t seed = 1;
};

struct ScannedCloud
{
    /// P  #P by 3 points.
    PointMatrix points;
    /// N  #P by 3 outward unit normals of the surface where each point was sampled (turned
    /// with its view's misregistration; an outlier keeps its sample's normal).
    NormalMatrix normals;
    /// Mean nearest spacing (meanNearestSpacing) of the clean cloud, before the holes, noise
    /// and outliers: the unit of the options given in spacings.
    double spacing = 0.0;
    /// Along-row ray spacing of the scan models (model units); 0 for the others.
    double rowStep = 0.0;
    /// Per point: the index of the view that saw it (scan models), else -1.
    std::vector<int> view;
    /// Per point: 1 for an outlier, else 0.
    std::vector<std::uint8_t> outlier;
    /// The views used (drawn or given) and the holes cut.
    std::vector<ScanView> views;
    std::vector<OcclusionHole> holes;
};

/// Samples `shape` as options.model says, then cuts the holes, adds tangential jitter and
/// normal noise and displaces the outliers. Same options, same cloud: every draw comes from
/// seeded std::mt19937 integers (the Poisson disk's from sampleShape's distributions). Throws
/// std::invalid_argument for an option out of range or a shape without faces, std::runtime_error
/// when the triangulation fails or no point is seen.
ScannedCloud sampleLikeAScanner(const TopoDS_Shape& shape, const ScanOptions& options);

/// The parts of the true edges that lie within `distance` (model units, > 0) of a point of P
/// (#P by 3): what a cloud that sees only part of the shape (one view, holes) can be scored
/// against. A line is cut where it leaves the cloud; its pieces keep its type, and a closed
/// line stays closed only when all of it is covered.
std::vector<TypedPolyline> truthCoveredBy(const std::vector<TypedPolyline>& truth,
                                          const PointMatrix& P, double distance);

/// The ranges drawScanOptions draws from.
struct ScanDrawRanges
{
    /// Points, log-uniform in [minPoints, maxPoints].
    double minPoints = 10000.0;
    double maxPoints = 1000000.0;
    /// Normal noise, one of these (spacings).
    std::vector<double> noiseLevels = {0.0, 0.1, 0.3, 0.5};
    /// Tangential jitter, uniform in [0, maxTangentialJitter] spacings.
    double maxTangentialJitter = 0.2;
    /// Row spacing ratio, uniform in [minRowSpacingRatio, maxRowSpacingRatio].
    double minRowSpacingRatio = 3.0;
    double maxRowSpacingRatio = 5.0;
    /// Merged views: 2 to maxViews; misregistration uniform in the range (along-row spacings).
    int maxViews = 3;
    double minMisregistration = 0.1;
    double maxMisregistration = 0.5;
    /// Density gradient ratio.
    double densityRatio = 4.0;
    /// Holes: none with probability 1 - holeProbability, else 1 to maxHoles of a radius
    /// uniform in [minHoleRadius, maxHoleRadius] spacings.
    double holeProbability = 0.5;
    int maxHoles = 4;
    double minHoleRadius = 3.0;
    double maxHoleRadius = 12.0;
    /// Outlier share uniform in [0, maxOutlierShare].
    double maxOutlierShare = 0.01;
};

/// A model drawn uniformly from the five and its parameters drawn from `ranges`, for one part;
/// the result's seed is derived from `seed`. Same seed, same options.
ScanOptions drawScanOptions(std::uint32_t seed, const ScanDrawRanges& ranges = {});

} // namespace featurelines::bench
