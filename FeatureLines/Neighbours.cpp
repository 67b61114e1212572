// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/Neighbours.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <nanoflann.hpp>
#include <omp.h>

#include "FeatureLines/CloudIO.h"

namespace featurelines {

namespace {

/// nanoflann's dataset interface over a row-major #P by 3 array (x y z contiguous). The
/// pointer is switched from the input to its copy in tree order once the tree is built.
struct TreePoints
{
    const double* xyz = nullptr;
    std::size_t count = 0;

    std::size_t kdtree_get_point_count() const { return count; }
    double kdtree_get_pt(std::uint32_t i, std::size_t d) const { return xyz[3 * i + d]; }
    template <class BoundingBox> bool kdtree_get_bbox(BoundingBox&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, TreePoints, double, std::uint32_t>, TreePoints, 3,
    std::uint32_t>;

/// Points per kd-tree leaf (at most). Each leaf is one batch of queries (below): small leaves
/// give a tight candidate ball, large ones share each tree search among more queries. 6 to 16
/// cost the same within the noise on a 1M-point scan-like cloud (leaves then hold 8 points on
/// average).
constexpr std::size_t leafSize = 12;

/// A leaf whose candidate ball holds more than this many points per query of the leaf is
/// spread too wide to batch (an outlier next to a dense cluster); its points are then searched
/// one by one. Scanning a candidate costs about 1/100 of a tree search; on a scan-like cloud
/// 1% of the leaves exceed 100.
constexpr std::size_t batchCandidatesPerQuery = 100;

int threadCount(int requested)
{
    return requested > 0 ? requested : omp_get_max_threads();
}

/// nanoflann result set collecting every point closer than a radius, unsorted, up to a cap,
/// and counting those closer than an inner radius.
class BallResultSet
{
public:
    BallResultSet(double squaredRadius, double squaredInnerRadius, std::size_t cap,
                  std::vector<std::uint32_t>& found)
        : squaredRadius_(squaredRadius), squaredInnerRadius_(squaredInnerRadius), cap_(cap),
          found_(found)
    {
        found_.clear();
    }
    double worstDist() const { return squaredRadius_; }
    bool full() const { return true; }
    bool addPoint(double squaredDistance, std::uint32_t index)
    {
        found_.push_back(index);
        inner_ += squaredDistance <= squaredInnerRadius_;
        overflow_ = found_.size() > cap_;
        return !overflow_; // stops the search once over the cap
    }
    bool overflow() const { return overflow_; }
    std::size_t inner() const { return inner_; }

private:
    double squaredRadius_;
    double squaredInnerRadius_;
    std::size_t cap_;
    std::vector<std::uint32_t>& found_;
    std::size_t inner_ = 0;
    bool overflow_ = false;
};

/// A point seen from one query.
struct Candidate
{
    double squaredDistance;
    int index; // in P
};

/// Nearest first; the index breaks ties, so the answer does not depend on the order in which
/// candidates arrive (nor on the thread count).
bool closer(const Candidate& a, const Candidate& b)
{
    return a.squaredDistance < b.squaredDistance ||
           (a.squaredDistance == b.squaredDistance && a.index < b.index);
}

void collectLeaves(const KdTree::Node* node, std::vector<const KdTree::Node*>& leaves)
{
    if (node->child1 == nullptr && node->child2 == nullptr) {
        leaves.push_back(node);
        return;
    }
    collectLeaves(node->child1, leaves);
    collectLeaves(node->child2, leaves);
}

} // namespace

Neighbourhoods nearestNeighbours(const PointMatrix& P, const NeighbourOptions& options)
{
    const int k = options.k;
    if (k < 3) {
        throw std::invalid_argument("neighbours: at least 3 neighbours per point are needed, " +
                                    std::to_string(k) + " were asked for");
    }
    if (P.rows() <= k) {
        throw std::invalid_argument("neighbours: " + std::to_string(k) +
                                    " neighbours per point need more than " + std::to_string(k) +
                                    " points, the cloud has " + std::to_string(P.rows()));
    }
    if (P.rows() > Eigen::Index(INT32_MAX)) {
        throw std::invalid_argument("neighbours: the cloud has more points than the index type "
                                    "holds");
    }
    checkFinite(P, "point cloud");

    const Eigen::Index n = P.rows();
    TreePoints points{P.data(), static_cast<std::size_t>(n)};
    KdTree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(leafSize));

    // The searches run on a copy Q of the points in the tree's leaf order: the points of a
    // leaf, and of neighbouring leaves, are then neighbours in memory too. This halves the
    // time on a cloud stored in scan order and avoids a further factor of two on a cloud
    // stored in random order. The tree itself stays valid with Q as its data set and the
    // identity as its index permutation. original[j] is the index in P of Q's row j.
    const std::vector<std::uint32_t> original = tree.vAcc;
    PointMatrix Q(n, 3);
#pragma omp parallel for schedule(static, 4096) num_threads(threadCount(options.threads))
    for (Eigen::Index j = 0; j < n; ++j) {
        Q.row(j) = P.row(original[j]);
    }
    points.xyz = Q.data();
    for (std::size_t j = 0; j < tree.vAcc.size(); ++j) {
        tree.vAcc[j] = static_cast<std::uint32_t>(j);
    }
    std::vector<const KdTree::Node*> leaves;
    collectLeaves(tree.root_node, leaves);

    Neighbourhoods result;
    result.indices.resize(n, k);
    result.squaredDistances.resize(n, k);

    // The points of one leaf are close together, so they share their neighbours. If the
    // ball of radius r0 around the leaf's most central point q0 holds k + 1 points, those lie
    // within r0 + |q - q0| of any q of the leaf, so the k nearest others of q lie in the ball
    // around q0 of radius r0 + 2 max|q - q0|. One radius search fetches that ball and each
    // query of the leaf scans it exactly: one tree descent per leaf instead of one per point.
    // r0 is guessed from the previous leaf of the thread (leaves come in spatial order) and
    // checked by counting the points within it; a kNN search from q0 gives it otherwise.
    const std::size_t wanted = static_cast<std::size_t>(k) + 1;
#pragma omp parallel num_threads(threadCount(options.threads))
    {
        std::vector<std::uint32_t> found(wanted);
        std::vector<double> foundDistances(wanted);
        std::vector<std::uint32_t> ball;
        std::vector<float> cx, cy, cz, cd;
        std::vector<std::uint32_t> passed;
        std::vector<Candidate> near(wanted);
        std::vector<double> nearDistance;
        std::vector<float> nearRounded;
        std::vector<int> nearIndex;
        double radiusGuess = 0.0;
        // The k nearest of point i are the first k of `near`, sorted.
        const auto store = [&](std::uint32_t i) {
            for (int c = 0; c < k; ++c) {
                result.indices(i, c) = near[c].index;
                result.squaredDistances(i, c) = near[c].squaredDistance;
            }
        };
#pragma omp for schedule(dynamic, 64)
        for (std::size_t leaf = 0; leaf < leaves.size(); ++leaf) {
            const auto& range = leaves[leaf]->node_type.lr;
            const Eigen::Index first = static_cast<Eigen::Index>(range.left);
            const Eigen::Index last = static_cast<Eigen::Index>(range.right);
            const std::size_t cap =
                batchCandidatesPerQuery * static_cast<std::size_t>(last - first);

            const Eigen::RowVector3d centre =
                Q.middleRows(first, last - first).colwise().sum() / double(last - first);
            Eigen::Index q0 = first;
            double best = std::numeric_limits<double>::infinity();
            for (Eigen::Index j = first; j < last; ++j) {
                const double d = (Q.row(j) - centre).squaredNorm();
                if (d < best) {
                    best = d;
                    q0 = j;
                }
            }
            double spread = 0.0;
            for (Eigen::Index j = first; j < last; ++j) {
                spread = std::max(spread, (Q.row(j) - Q.row(q0)).squaredNorm());
            }
            spread = std::sqrt(spread);

            // A relative margin for rounding; the smallest positive bound still admits the
            // zero distances of a leaf of coincident points.
            const auto squared = [](double r) {
                return std::max(r * r * (1.0 + 1e-9), std::numeric_limits<double>::denorm_min());
            };
            double r0 = radiusGuess;
            bool batched = false;
            bool overflow = false;
            if (r0 > 0.0) {
                BallResultSet inBall(squared(r0 + 2.0 * spread), squared(r0), cap, ball);
                tree.findNeighbors(inBall, Q.row(q0).data(), nanoflann::SearchParams(0, 0.0f));
                overflow = inBall.overflow();
                batched = !overflow && inBall.inner() >= wanted;
                if (batched) {
                    // Aim at about 1.3 (k + 1) points within the guess: the area, and so the
                    // count, grows with the square of the radius on a surface.
                    const double ratio = 1.3 * double(wanted) / double(inBall.inner());
                    radiusGuess = r0 * std::sqrt(std::clamp(ratio, 0.25, 4.0));
                }
            }
            if (!batched && !overflow) {
                nanoflann::KNNResultSet<double, std::uint32_t, std::uint32_t> nearest(wanted);
                nearest.init(found.data(), foundDistances.data());
                tree.findNeighbors(nearest, Q.row(q0).data(), nanoflann::SearchParams(0, 0.0f));
                r0 = std::sqrt(foundDistances[k]);
                radiusGuess = r0 * std::sqrt(1.3);
                BallResultSet inBall(squared(r0 + 2.0 * spread), squared(r0), cap, ball);
                tree.findNeighbors(inBall, Q.row(q0).data(), nanoflann::SearchParams(0, 0.0f));
                overflow = inBall.overflow();
            }

            if (overflow) {
                // Too spread for a batch: an exact kNN search per point.
                for (Eigen::Index j = first; j < last; ++j) {
                    nanoflann::KNNResultSet<double, std::uint32_t, std::uint32_t> own(wanted);
                    own.init(found.data(), foundDistances.data());
                    tree.findNeighbors(own, Q.row(j).data(), nanoflann::SearchParams(0, 0.0f));
                    // The point itself is dropped by index (its exact duplicates stay); if
                    // k + 1 others tie at distance 0 it may be absent, then the k + 1 are
                    // sorted and the farthest dropped.
                    std::size_t count = 0;
                    for (std::size_t c = 0; c < wanted; ++c) {
                        if (found[c] != static_cast<std::uint32_t>(j)) {
                            near[count++] = {(Q.row(found[c]) - Q.row(j)).squaredNorm(),
                                             static_cast<int>(original[found[c]])};
                        }
                    }
                    std::sort(near.begin(), near.begin() + count, closer);
                    store(original[j]);
                }
                continue;
            }

            // Candidates relative to q0 in float for a vectorised first cut; every candidate
            // that passes it is then measured exactly in double.
            const std::size_t m = ball.size();
            cx.resize(m);
            cy.resize(m);
            cz.resize(m);
            cd.resize(m);
            passed.resize(m);
            near.resize(std::max(m, wanted));
            nearDistance.resize(m);
            nearRounded.resize(m);
            nearIndex.resize(m);
            for (std::size_t c = 0; c < m; ++c) {
                cx[c] = static_cast<float>(Q(ball[c], 0) - Q(q0, 0));
                cy[c] = static_cast<float>(Q(ball[c], 1) - Q(q0, 1));
                cz[c] = static_cast<float>(Q(ball[c], 2) - Q(q0, 2));
            }
            for (Eigen::Index j = first; j < last; ++j) {
                const float x = static_cast<float>(Q(j, 0) - Q(q0, 0));
                const float y = static_cast<float>(Q(j, 1) - Q(q0, 1));
                const float z = static_cast<float>(Q(j, 2) - Q(q0, 2));
                for (std::size_t c = 0; c < m; ++c) { // vectorised
                    const float dx = cx[c] - x, dy = cy[c] - y, dz = cz[c] - z;
                    cd[c] = dx * dx + dy * dy + dz * dz;
                }
                const auto countWithin = [&](float cut) {
                    std::size_t count = 0;
                    for (std::size_t c = 0; c < m; ++c) { // vectorised
                        count += cd[c] <= cut;
                    }
                    return count;
                };
                // No neighbour of q lies farther than r0 + |q - q0|: about 3 (k + 1)
                // candidates on a surface. The float cut is narrowed towards 1.25 (k + 1) (the
                // count grows like the squared distance on a surface), kept only if k + 1
                // points, q included, stay inside it. The cut keeps a relative margin of 1e-4:
                // a true neighbour and q lie within twice the bound of q0, so float rounding of
                // their offsets is 2^-24 of the bound, and narrowing shrinks the cut by at most
                // the candidate cap over k + 1, which keeps that rounding below 1e-5 of it.
                const double bound = r0 + (Q.row(j) - Q.row(q0)).norm();
                const double squaredBound = bound * bound * (1.0 + 1e-9);
                float cut = static_cast<float>(squaredBound * (1.0 + 1e-4));
                const float narrower = cut * (1.25f * float(wanted) / float(countWithin(cut)));
                if (countWithin(narrower * (1.0f - 1e-4f)) >= wanted) {
                    cut = narrower;
                }
                std::size_t passing = 0;
                for (std::size_t c = 0; c < m; ++c) { // branch-free compaction
                    passed[passing] = static_cast<std::uint32_t>(c);
                    passing += cd[c] <= cut;
                }
                std::size_t count = 0;
                for (std::size_t c = 0; c < passing; ++c) {
                    const std::uint32_t candidate = ball[passed[c]];
                    const double d2 = (Q.row(candidate) - Q.row(j)).squaredNorm();
                    if (d2 <= squaredBound && candidate != static_cast<std::uint32_t>(j)) {
                        nearDistance[count] = d2;
                        nearRounded[count] = static_cast<float>(d2);
                        nearIndex[count] = static_cast<int>(original[candidate]);
                        ++count;
                    }
                }
                // count >= k: the k + 1 points within r0 of q0, but q, are within the bound.
                // Each candidate goes to its rank in the closer() order, counted branch-free:
                // a comparison sort of about 1.25 (k + 1) values mispredicts every other branch.
                // The count runs on the distances rounded to float, four at a time: rounding
                // keeps their order (a smaller rounded value comes from a smaller distance), so
                // only candidates whose rounded distances are equal are compared exactly.
                const Eigen::Index i = original[j];
                for (std::size_t a = 0; a < count; ++a) {
                    const double da = nearDistance[a];
                    const float fa = nearRounded[a];
                    const int ia = nearIndex[a];
                    int rank = 0, equal = 0;
                    for (std::size_t b = 0; b < count; ++b) { // vectorised
                        rank += nearRounded[b] < fa;
                        equal += nearRounded[b] == fa;
                    }
                    if (equal > 1) { // another candidate than a itself
                        for (std::size_t b = 0; b < count; ++b) {
                            rank += (nearRounded[b] == fa) &
                                    ((nearDistance[b] < da) |
                                     ((nearDistance[b] == da) & (nearIndex[b] < ia)));
                        }
                    }
                    if (rank < k) {
                        result.indices(i, rank) = ia;
                        result.squaredDistances(i, rank) = da;
                    }
                }
            }
        }
    }
    return result;
}

double meanSpacing(const Neighbourhoods& neighbourhoods)
{
    const Eigen::Index n = neighbourhoods.size();
    double sum = 0.0;
    Eigen::Index counted = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        for (int j = 0; j < neighbourhoods.k(); ++j) {
            const double d2 = neighbourhoods.squaredDistances(i, j);
            if (d2 > 0.0) {
                sum += std::sqrt(d2);
                ++counted;
                break;
            }
        }
    }
    if (counted == 0) {
        throw std::invalid_argument("mean point spacing: every point coincides with its "
                                    "neighbours, the cloud has no extent");
    }
    return sum / static_cast<double>(counted);
}

} // namespace featurelines
