// SPDX-License-Identifier: LGPL-2.1-or-later
// First-order segmentation: region growing on the normals, in the phases segmentByNormals names.
#include "FeatureLines/sharp/FirstOrderSegmentation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <omp.h>

#include "FeatureLines/support/DisjointSets.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

constexpr double pi = 3.14159265358979323846;

void requireAngle(double degrees, const char* name)
{
    if (!(degrees > 0.0 && degrees <= 90.0)) {
        throw std::invalid_argument(std::string("first-order segmentation: ") + name +
                                    " must be an angle in degrees between 0 and 90, not " +
                                    std::to_string(degrees));
    }
}

/// What segmentByNormals was given, passed on to its phases.
struct SegmentationInput
{
    const PointMatrix& P;
    const NormalMatrix& normals;
    const Neighbourhoods& N;
    double spacing;
    const FirstOrderSegmentationOptions& options;
};

void requireValidInput(const SegmentationInput& in)
{
    const FirstOrderSegmentationOptions& options = in.options;
    const Eigen::Index n = in.P.rows();
    if (in.N.size() != n || in.normals.rows() != n) {
        throw std::invalid_argument(
            "first-order segmentation: the normals and neighbourhoods must have one row per "
            "point (" +
            std::to_string(n) + " points, " + std::to_string(in.normals.rows()) + " normals, " +
            std::to_string(in.N.size()) + " neighbourhoods)");
    }
    if (!(in.spacing > 0.0) || !std::isfinite(in.spacing)) {
        throw std::invalid_argument("first-order segmentation: the point spacing must be a "
                                    "positive number");
    }
    if (!(options.noiseSpreadFactor >= 0.0) || !(options.noiseSpreadTail >= 0.0)) {
        throw std::invalid_argument("first-order segmentation: the noise spread factor and tail "
                                    "must not be negative");
    }
    if (!(options.minFilletRadius > 0.0)) {
        throw std::invalid_argument("first-order segmentation: the smallest fillet radius must "
                                    "be positive");
    }
    if (!in.normals.allFinite()) {
        throw std::invalid_argument("first-order segmentation: a normal is NaN or infinite");
    }
    requireAngle(options.growAngle, "the grow angle");
    requireAngle(options.joinAngle, "the join angle");
    if (options.shallowCreaseAngle != 0.0) {
        requireAngle(options.shallowCreaseAngle, "the shallow crease angle");
    }
    if (!(options.creasePlaneTolerance > 0.0) || !(options.creaseLineReach > 0.0) ||
        options.minFacePoints < 3) {
        throw std::invalid_argument("first-order segmentation: the crease plane tolerance and "
                                    "line reach must be positive, and a face's plane needs at "
                                    "least 3 points");
    }
}

double cosOfDegrees(double degrees)
{
    return std::cos(degrees * pi / 180.0);
}

/// Unoriented normals: n and -n are the same plane.
double similarity(const NormalMatrix& normals, Eigen::Index a, Eigen::Index b)
{
    return std::abs(normals.row(a).dot(normals.row(b)));
}

/// Medians of an evenly strided sample of at most ~100 000 points are as good and cheap.
Eigen::Index sampleStride(Eigen::Index n)
{
    return std::max<Eigen::Index>(1, n / 100000);
}

double median(std::vector<double>& v)
{
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

/// The faces of flat points met among the neighbours of a point's neighbours, and the test of
/// shallowCreaseAngle: does the point lie on a shallow crease between two of them?
class ShallowCreaseTest
{
public:
    struct Inputs
    {
        const PointMatrix& P;
        const NormalMatrix& normals;
        const Neighbourhoods& N;
        const std::vector<char>& grows;
        const std::vector<int>& face;
        double cosJoin;
        double cosShallow;     // faces closer to parallel than this are a shallow crease
        double sinMinAngle;    // ... and farther from parallel than this
        double planeTolerance; // model units
        double lineReach;      // model units
        int minFacePoints;
    };

    explicit ShallowCreaseTest(const Inputs& in) : in_(in) {}

    bool operator()(int i);

private:
    struct FaceSum
    {
        int face;
        int count;
        Eigen::Vector3d point, normal;
    };

    void collectWindow(int i);
    void sumFacesInWindow();
    bool onCrease(const FaceSum& a, const FaceSum& b, const Eigen::Vector3d& x) const;
    bool joinedAround(int i, int a, int b);

    const Inputs& in_;
    std::vector<int> windowOf_; // per point: the last point whose window holds it
    std::vector<int> seenBy_;   // per point: the last search that reached it
    int search_ = 0;
    std::vector<int> window_;
    std::vector<FaceSum> faces_;
    std::vector<int> queue_;
};

bool ShallowCreaseTest::operator()(int i)
{
    if (windowOf_.empty()) { // the first test of this thread
        windowOf_.assign(static_cast<std::size_t>(in_.P.rows()), -1);
        seenBy_.assign(static_cast<std::size_t>(in_.P.rows()), -1);
    }
    collectWindow(i);
    sumFacesInWindow();
    const Eigen::Vector3d x = in_.P.row(i).transpose();
    for (std::size_t a = 0; a < faces_.size(); ++a) {
        for (std::size_t b = a + 1; b < faces_.size(); ++b) {
            if (onCrease(faces_[a], faces_[b], x) &&
                !joinedAround(i, faces_[a].face, faces_[b].face)) {
                return true;
            }
        }
    }
    return false;
}

/// The point and the neighbours of its neighbours, once each (marked with i).
void ShallowCreaseTest::collectWindow(int i)
{
    const int k = in_.N.k();
    window_.clear();
    auto add = [&](int q) {
        if (windowOf_[q] != i) {
            windowOf_[q] = i;
            window_.push_back(q);
        }
    };
    add(i);
    for (int j = 0; j < k; ++j) {
        const int a = in_.N.indices(i, j);
        add(a);
        for (int l = 0; l < k; ++l) {
            add(in_.N.indices(a, l));
        }
    }
}

/// Each face's flat points in the window: their mean and mean normal (turned to agree).
void ShallowCreaseTest::sumFacesInWindow()
{
    faces_.clear();
    for (int q : window_) {
        const int f = in_.face[q];
        if (f < 0) {
            continue;
        }
        auto at = std::find_if(faces_.begin(), faces_.end(),
                               [&](const FaceSum& s) { return s.face == f; });
        if (at == faces_.end()) {
            faces_.push_back({f, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
            at = faces_.end() - 1;
        }
        Eigen::Vector3d normal = in_.normals.row(q).transpose();
        if (at->count > 0 && normal.dot(at->normal) < 0.0) {
            normal = -normal;
        }
        at->point += in_.P.row(q).transpose();
        at->normal += normal;
        ++at->count;
    }
}

/// x lies at the meeting of the two faces' planes, which meet at a shallow angle.
bool ShallowCreaseTest::onCrease(const FaceSum& a, const FaceSum& b, const Eigen::Vector3d& x) const
{
    if (a.count < in_.minFacePoints || b.count < in_.minFacePoints) {
        return false;
    }
    const Eigen::Vector3d na = a.normal.normalized(), nb = b.normal.normalized();
    const double c = na.dot(nb);
    if (std::abs(c) < in_.cosShallow || na.cross(nb).norm() < in_.sinMinAngle) {
        return false;
    }
    // Signed offsets of x from the planes, then the point of their line nearest to x.
    const double ha = na.dot(x - a.point / a.count), hb = nb.dot(x - b.point / b.count);
    if (std::min(std::abs(ha), std::abs(hb)) > in_.planeTolerance) {
        return false;
    }
    const double det = 1.0 - c * c;
    const Eigen::Vector3d shift =
        -((ha - c * hb) / det) * na - ((hb - c * ha) / det) * nb; // x + shift on the line
    return shift.norm() <= in_.lineReach;
}

/// Growing points within the window of point i join a flat point of face a to one of face
/// b (through neighbours whose normals differ by less than joinAngle).
bool ShallowCreaseTest::joinedAround(int i, int a, int b)
{
    const int k = in_.N.k();
    ++search_; // marks the points this search has reached
    queue_.clear();
    for (int q : window_) {
        if (in_.face[q] == a) {
            seenBy_[q] = search_;
            queue_.push_back(q);
        }
    }
    for (std::size_t h = 0; h < queue_.size(); ++h) {
        const int u = queue_[h];
        for (int l = 0; l < k; ++l) {
            const int v = in_.N.indices(u, l);
            if (seenBy_[v] == search_ || windowOf_[v] != i || !in_.grows[v] ||
                std::abs(in_.normals.row(u).dot(in_.normals.row(v))) < in_.cosJoin) {
                continue;
            }
            if (in_.face[v] == b) {
                return true;
            }
            seenBy_[v] = search_;
            queue_.push_back(v);
        }
    }
    return false;
}

/// #P surface variation over the point and all k neighbours, and over the point and its
/// nearest `fineNeighbours` (0: one scale only, `fine` empty).
struct SurfaceVariation
{
    Eigen::VectorXd full;
    Eigen::VectorXd fine;
    int fineNeighbours = 0;
};

/// The normal spread of every point (into `spread`) and its surface variation at two scales.
SurfaceVariation measureSpreadAndVariation(const SegmentationInput& in, Eigen::VectorXd& spread)
{
    const PointMatrix& P = in.P;
    const NormalMatrix& normals = in.normals;
    const Neighbourhoods& N = in.N;
    const Eigen::Index n = P.rows();
    const int k = N.k();
    spread.resize(n);
    // Surface variation at two scales: over the point and all k neighbours, and over the
    // point and its nearest `fine` (0: one scale only).
    const int fine = in.options.fineNeighbours >= 3 && in.options.fineNeighbours < k
                         ? in.options.fineNeighbours
                         : 0;
    SurfaceVariation result;
    result.fineNeighbours = fine;
    Eigen::VectorXd& variation = result.full;
    Eigen::VectorXd& fineVariation = result.fine;
    variation.resize(n);
    fineVariation.resize(fine > 0 ? n : 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(in.options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        double lowest = 1.0;
        // Surface variation lambda0 / (lambda0 + lambda1 + lambda2) of the point and its
        // neighbours, with lambda0 read along the given normal: n^T C n / trace C.
        const Eigen::RowVector3d origin = P.row(i);
        const Eigen::RowVector3d normal = normals.row(i);
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        double squares = 0.0;
        double heights = 0.0;
        double heightSquares = 0.0;
        auto variationSoFar = [&](int count) {
            const double trace = squares / count - (sum / count).squaredNorm();
            const double across = heightSquares / count - std::pow(heights / count, 2);
            return trace > 0.0 ? std::max(0.0, across) / trace : 0.0;
        };
        for (int j = 0; j < k; ++j) {
            const int q = N.indices(i, j);
            lowest = std::min(lowest, similarity(normals, i, q));
            const Eigen::RowVector3d d = P.row(q) - origin;
            const double h = d.dot(normal);
            sum += d;
            squares += d.squaredNorm();
            heights += h;
            heightSquares += h * h;
            if (j + 1 == fine) {
                fineVariation(i) = variationSoFar(fine + 1);
            }
        }
        variation(i) = variationSoFar(k + 1);
        spread(i) = std::acos(std::min(1.0, lowest)) * 180.0 / pi;
    }
    return result;
}

/// The planarity excess, its limit and the scale they were measured at (into `result`).
void measurePlanarityExcess(const SegmentationInput& in, const SurfaceVariation& variation,
                            FirstOrderSegmentation& result)
{
    const Eigen::Index n = in.P.rows();
    const Eigen::Index stride = sampleStride(n);
    // The excess of surface variation over the cloud's typical value. Noise along the normal
    // adds its variance to lambda0 everywhere, so the cloud's median (most points lie on
    // smooth patches) is the noise floor, and its spread (the median absolute deviation) how
    // far noise alone reaches above it.
    const double filletRadius = in.options.minFilletRadius * in.spacing;
    // The excess a point needs at one scale: that of a spherical blend of minFilletRadius, or
    // noiseMargin deviations of the noise, whichever is higher. A sphere of radius r sampled
    // over a ball of radius R has surface variation R^2 / (24 r^2) (heights rho^2 / 2r over
    // the disc), a cylinder R^2 / (32 r^2); R is the typical distance to the farthest
    // neighbour of the scale.
    auto excessAtScale = [&](const Eigen::VectorXd& values, int neighbours,
                             Eigen::VectorXd& excess) {
        std::vector<double> sample;
        for (Eigen::Index i = 0; i < n; i += stride) {
            sample.push_back(values(i));
        }
        const double floor = median(sample);
        excess = values.array() - floor;
        for (double& v : sample) {
            v = std::abs(v - floor);
        }
        const double noiseDeviation = 1.4826 * median(sample); // sigma from the MAD
        std::vector<double> reach;
        for (Eigen::Index i = 0; i < n; i += stride) {
            reach.push_back(in.N.squaredDistances(i, neighbours - 1));
        }
        return std::max(median(reach) / (24.0 * filletRadius * filletRadius),
                        in.options.noiseMargin * noiseDeviation);
    };
    result.minExcess = excessAtScale(variation.full, in.N.k(), result.planarityExcess);
    result.excessNeighbours = in.N.k();
    // A crease's surface variation does not depend on the scale (a V looks the same at any
    // size), a blend's grows with R^2 and the noise's falls with it: the scale whose limit is
    // lower tells creases from blends and noise better. On a clean cloud that is the fine
    // one (half the blend's variation), on a noisy one the full neighbourhood.
    const int fine = variation.fineNeighbours;
    if (fine > 0) {
        Eigen::VectorXd fineExcess;
        const double fineMin = excessAtScale(variation.fine, fine, fineExcess);
        if (fineMin < result.minExcess) {
            result.minExcess = fineMin;
            result.planarityExcess = std::move(fineExcess);
            result.excessNeighbours = fine;
        }
    }
}

/// #P nonzero for the points that grow their cluster; sets the spread limits of `result`.
std::vector<char> growingPoints(const SegmentationInput& in, FirstOrderSegmentation& result)
{
    const FirstOrderSegmentationOptions& options = in.options;
    const Eigen::Index n = in.P.rows();
    const Eigen::Index stride = sampleStride(n);
    // The spread limit follows the cloud's noise: most points lie on smooth patches, so the
    // median spread is what noise alone gives there, and twice it about the largest. Never
    // below the join angle (a point whose neighbours all lie within joinAngle of its normal
    // is inside a surface by the growing's own measure), never above growAngle.
    std::vector<double> spreads;
    for (Eigen::Index i = 0; i < n; i += stride) {
        spreads.push_back(result.spread(i));
    }
    const double medianSpread = median(spreads);
    result.growAngle =
        std::clamp(options.noiseSpreadFactor * medianSpread,
                   std::min(options.joinAngle, options.growAngle), options.growAngle);
    result.noiseSpreadLimit = options.noiseSpreadTail * medianSpread;
    std::vector<char> grows(n, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        grows[i] =
            result.spread(i) <= result.growAngle || result.planarityExcess(i) <= result.minExcess
                ? 1
                : 0;
    }
    return grows;
}

/// #P face of every flat point: the sets of flat points joined so far, numbered by their
/// lowest point, splinters of k points or fewer left out (-1).
std::vector<int> facesOfFlatPoints(const DisjointSets& sets, const std::vector<char>& flat, int k)
{
    const Eigen::Index n = static_cast<Eigen::Index>(flat.size());
    std::vector<int> face(n, -1);
    std::vector<int> flatInRoot(n, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (flat[i]) {
            face[i] = sets.find(static_cast<int>(i));
            ++flatInRoot[face[i]];
        }
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (flat[i] && flatInRoot[face[i]] <= k) {
            face[i] = -1; // a splinter, not a face
        }
    }
    return face;
}

/// The clusters of the growing points (#P representative of every point's set; a point that
/// does not grow is alone in its own) and, for shallowCreaseAngle, the faces (into `result`).
std::vector<int> growClusters(const SegmentationInput& in, const std::vector<char>& grows,
                              FirstOrderSegmentation& result)
{
    const FirstOrderSegmentationOptions& options = in.options;
    const Neighbourhoods& N = in.N;
    const Eigen::Index n = in.P.rows();
    const int k = N.k();
    const double cosJoin = cosOfDegrees(options.joinAngle);
    // Growing points reached from one another form one cluster: the connected components of
    // the "grows and joins" relation, found with disjoint sets instead of a queue so the
    // result depends neither on the choice of seeds nor on the threads that join them. For
    // shallowCreaseAngle the points whose normals spread within the limit (flat points, which
    // all grow) are joined among themselves first: the sets then are the faces of flat
    // points, read off before the other growing points join them.
    const bool shallowCreases = options.shallowCreaseAngle > 0.0;
    const double flatAngle = std::clamp(
        result.noiseSpreadLimit, std::min(options.joinAngle, result.growAngle), result.growAngle);
    std::vector<char> flat(shallowCreases ? n : 0, 0);
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(flat.size()); ++i) {
        flat[i] = result.spread(i) <= flatAngle ? 1 : 0;
    }
    DisjointSets sets(static_cast<int>(n));
    // In the first pass a flat point notes whether it has growing neighbours that are not
    // flat; the second pass visits only those and the points that are not flat.
    std::vector<char> mixed(shallowCreases ? n : 0, 0);
    auto joinGrowing = [&](bool flatPairs) {
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
        for (Eigen::Index i = 0; i < n; ++i) {
            if (!grows[i] || (shallowCreases && flat[i] != flatPairs && !(flat[i] && mixed[i]))) {
                continue;
            }
            int root = static_cast<int>(i);
            for (int j = 0; j < k; ++j) {
                const int q = N.indices(i, j);
                if (!grows[q]) {
                    continue;
                }
                // The flat pairs in the first pass only, the others in the second.
                if (shallowCreases && flatPairs != (flat[i] && flat[q])) {
                    mixed[i] = mixed[i] || flatPairs;
                    continue;
                }
                if (sets.find(q) != sets.find(root) && similarity(in.normals, i, q) >= cosJoin) {
                    root = sets.join(root, q);
                }
            }
        }
    };
    result.face.assign(n, -1);
    if (shallowCreases) {
        joinGrowing(true);
        result.face = facesOfFlatPoints(sets, flat, k);
    }
    joinGrowing(false);
    return sets.representatives();
}

/// The growing neighbour each point that does not grow joins (#P, -1 for growing points and
/// for the points that stay candidates).
std::vector<int> joinStoppedPoints(const SegmentationInput& in, const std::vector<char>& grows,
                                   const std::vector<int>& root,
                                   const FirstOrderSegmentation& result)
{
    const Neighbourhoods& N = in.N;
    const Eigen::Index n = in.P.rows();
    const int k = N.k();
    const double cosJoin = cosOfDegrees(in.options.joinAngle);
    const bool shallowCreases = in.options.shallowCreaseAngle > 0.0;
    // A point that cannot grow joins the cluster of the growing neighbour whose normal is
    // closest to its own (the nearest such neighbour on a tie), unless its neighbours hold
    // growing points of two clusters that can be surface patches (at least k + 1 growing
    // points, what a large cluster needs for one interior point): then it lies between two
    // faces, on a crease too shallow to leave a band wider than a neighbourhood between
    // them, and stays a candidate. Smaller clusters are splinters noise breaks off a patch.
    std::vector<int> growingInRoot(n, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        growingInRoot[root[i]] += grows[i];
    }
    const ShallowCreaseTest::Inputs creaseInputs{in.P,
                                                 in.normals,
                                                 N,
                                                 grows,
                                                 result.face,
                                                 cosJoin,
                                                 cosOfDegrees(in.options.shallowCreaseAngle),
                                                 std::sin(in.options.joinAngle * pi / 180.0),
                                                 in.options.creasePlaneTolerance * in.spacing,
                                                 in.options.creaseLineReach * in.spacing,
                                                 in.options.minFacePoints};

    std::vector<int> owner(n, -1);
#pragma omp parallel num_threads(threadCount(in.options.threads))
    {
        ShallowCreaseTest onShallowCrease(creaseInputs);
#pragma omp for schedule(static, 4096)
        for (Eigen::Index i = 0; i < n; ++i) {
            if (grows[i]) {
                continue;
            }
            double best = cosJoin;
            int firstFace = -1;
            bool betweenFaces = false;
            for (int j = 0; j < k; ++j) {
                const int q = N.indices(i, j);
                if (!grows[q]) {
                    continue;
                }
                if (growingInRoot[root[q]] > k) {
                    betweenFaces = betweenFaces || (firstFace >= 0 && root[q] != firstFace);
                    firstFace = root[q];
                }
                const double s = similarity(in.normals, i, q);
                if (s > best || (s == best && owner[i] < 0)) {
                    best = s;
                    owner[i] = q;
                }
            }
            // A point without a growing neighbour of similar normal stays a candidate anyway.
            if (betweenFaces ||
                (shallowCreases && owner[i] >= 0 && onShallowCrease(static_cast<int>(i)))) {
                owner[i] = -1;
            }
        }
    }
    return owner;
}

/// Cluster ids in the order of each cluster's first point (into `result`). A point neither
/// growing nor joined stays alone: a cluster of one point.
void numberClusters(const std::vector<char>& grows, const std::vector<int>& owner,
                    const std::vector<int>& root, FirstOrderSegmentation& result)
{
    const Eigen::Index n = static_cast<Eigen::Index>(grows.size());
    result.cluster.assign(n, -1);
    std::vector<int> idOfRoot(n, -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        const int anchor = grows[i]        ? static_cast<int>(i)
                           : owner[i] >= 0 ? owner[i]
                                           : static_cast<int>(i);
        const int r = root[anchor];
        if (idOfRoot[r] < 0) {
            idOfRoot[r] = static_cast<int>(result.clusterSize.size());
            result.clusterSize.push_back(0);
        }
        result.cluster[i] = idOfRoot[r];
        ++result.clusterSize[idOfRoot[r]];
    }
}

/// Small clusters: fewer than minInteriorPoints points whose whole neighbourhood is inside.
void markSmallClusters(const SegmentationInput& in, FirstOrderSegmentation& result)
{
    const Neighbourhoods& N = in.N;
    const Eigen::Index n = in.P.rows();
    const int k = N.k();
    std::vector<char> interior(n, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(in.options.threads))
    for (Eigen::Index i = 0; i < n; ++i) {
        bool inside = true;
        for (int j = 0; j < k && inside; ++j) {
            inside = result.cluster[N.indices(i, j)] == result.cluster[i];
        }
        interior[i] = inside ? 1 : 0;
    }
    std::vector<int> interiorCount(result.clusterSize.size(), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        interiorCount[result.cluster[i]] += interior[i];
    }
    result.smallCluster.resize(result.clusterSize.size());
    for (std::size_t c = 0; c < interiorCount.size(); ++c) {
        result.smallCluster[c] = interiorCount[c] < in.options.minInteriorPoints ? 1 : 0;
    }
}

} // namespace

FirstOrderSegmentation segmentByNormals(const PointMatrix& P, const NormalMatrix& normals,
                                        const Neighbourhoods& N, double spacing,
                                        const FirstOrderSegmentationOptions& options)
{
    const SegmentationInput in{P, normals, N, spacing, options};
    requireValidInput(in);
    FirstOrderSegmentation result;
    if (P.rows() == 0) {
        return result;
    }
    const SurfaceVariation variation = measureSpreadAndVariation(in, result.spread);
    measurePlanarityExcess(in, variation, result);
    const std::vector<char> grows = growingPoints(in, result);
    const std::vector<int> root = growClusters(in, grows, result);
    const std::vector<int> owner = joinStoppedPoints(in, grows, root, result);
    numberClusters(grows, owner, root, result);
    markSmallClusters(in, result);
    return result;
}

} // namespace featurelines
