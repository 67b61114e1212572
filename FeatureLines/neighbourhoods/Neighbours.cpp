// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/neighbourhoods/Neighbours.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <omp.h>

#include "FeatureLines/io/CloudIO.h"
#include "FeatureLines/neighbourhoods/MortonOrder.h"
#include "FeatureLines/support/HugePages.h"
#include "FeatureLines/support/IdleThreads.h"

namespace featurelines {

namespace {

/// The occupied cells of one level of the keys' octree (cubes 2^level steps wide, see
/// MortonGrid), in key order: each cell's code (key >> 3 level) and its run of rows, with a
/// hash table from code to cell.
class Cells
{
public:
    Cells(const std::vector<std::uint64_t>& keys, int level)
    {
        for (std::size_t j = 0; j < keys.size(); ++j) {
            const std::uint64_t code = keys[j] >> (3 * level);
            if (j == 0 || code != codes_.back()) {
                codes_.push_back(code);
                first_.push_back(static_cast<int>(j));
            }
        }
        first_.push_back(static_cast<int>(keys.size()));
        std::size_t size = 16;
        while (size < 2 * codes_.size()) {
            size *= 2;
        }
        mask_ = size - 1;
        slots_.assign(size, empty);
        cellOfSlot_.assign(size, -1);
        for (std::size_t c = 0; c < codes_.size(); ++c) {
            std::size_t h = slot(codes_[c]);
            while (slots_[h] != empty) {
                h = (h + 1) & mask_;
            }
            slots_[h] = codes_[c];
            cellOfSlot_[h] = static_cast<int>(c);
        }
    }
    long count() const { return static_cast<long>(codes_.size()); }
    int first(long cell) const { return first_[static_cast<std::size_t>(cell)]; }
    int end(long cell) const { return first_[static_cast<std::size_t>(cell) + 1]; }
    /// The cell of a code, or -1 when no point lies in it.
    int find(std::uint64_t code) const
    {
        for (std::size_t h = slot(code);; h = (h + 1) & mask_) {
            if (slots_[h] == code) {
                return cellOfSlot_[h];
            }
            if (slots_[h] == empty) {
                return -1;
            }
        }
    }

private:
    static constexpr std::uint64_t empty = ~std::uint64_t(0); // no code has all 64 bits set
    std::size_t slot(std::uint64_t code) const
    {
        return static_cast<std::size_t>((code * 0x9E3779B97F4A7C15ULL) >> 20) & mask_;
    }
    std::vector<std::uint64_t> codes_;
    std::vector<int> first_;
    std::vector<std::uint64_t> slots_;
    std::vector<int> cellOfSlot_;
    std::size_t mask_ = 0;
};

/// Candidates of one query: squared distances and indices in P.
struct Candidates
{
    std::vector<double> distance;
    std::vector<float> rounded;
    std::vector<int> index;

    void reserve(std::size_t n)
    {
        if (distance.size() < n) {
            const std::size_t size = std::max(n, 2 * distance.size());
            distance.resize(size);
            rounded.resize(size);
            index.resize(size);
        }
    }
};

/// Writes the k nearest of the first `count` candidates (at least k of them, every point at
/// least as close as the k-th among them), nearest first, the index breaking ties, so the
/// answer does not depend on the order in which candidates were found (nor on the thread
/// count). Each candidate goes to its rank, counted branch-free: a comparison sort of about
/// 1.2 (k + 1) values mispredicts every other branch. The count runs on the distances rounded
/// to float, four at a time: rounding keeps their order (a smaller rounded value comes from a
/// smaller distance), so only candidates whose rounded distances are equal are compared
/// exactly.
void storeNearest(Candidates& c, std::size_t count, int k, int* indices, double* distances)
{
    for (std::size_t a = 0; a < count; ++a) {
        c.rounded[a] = static_cast<float>(c.distance[a]);
    }
    for (std::size_t a = 0; a < count; ++a) {
        const double da = c.distance[a];
        const float fa = c.rounded[a];
        const int ia = c.index[a];
        int rank = 0, equal = 0;
        for (std::size_t b = 0; b < count; ++b) { // vectorised
            rank += c.rounded[b] < fa;
            equal += c.rounded[b] == fa;
        }
        if (equal > 1) { // another candidate than a itself
            for (std::size_t b = 0; b < count; ++b) {
                rank += (c.rounded[b] == fa) &
                        ((c.distance[b] < da) | ((c.distance[b] == da) & (c.index[b] < ia)));
            }
        }
        if (rank < k) {
            indices[rank] = ia;
            distances[rank] = da;
        }
    }
}

/// Mean points per cell of the level the search runs on, per neighbour asked for. On a
/// surface a cell of 0.75 (k + 1) points is about 1.5 times as wide as the k-th neighbour's
/// distance (sqrt((k + 1) / pi) spacings), so the 27 cells around a point's cell hold its
/// neighbours; levels come in factors of 4 of points per cell, so cells are 1.5 to 3 times
/// that distance wide.
constexpr double pointsPerCellPerNeighbour = 0.75;

/// The radius a query searches first, x the k-th neighbour's distance of the query before it
/// (points come in spatial order, so the two are close): 1.1 holds about 1.2 k points and
/// falls short for about one query in a thousand, which then searches again farther.
constexpr double radiusGuess = 1.1;

/// Throws std::invalid_argument unless P has more than k finite points, k >= 3 and the rows
/// fit the index type.
void checkNeighbourInput(const PointMatrix& P, int k)
{
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
}

/// The most distinct points one key (a cell 1 / (2^21 - 1) of the cloud's size wide) may hold.
/// A surface sampled finer than that is no scan: such a cell comes from a few points far out
/// that stretch the bounding box, and would make the search compare every pair in it.
constexpr Eigen::Index maximumPointsPerKey = 1024;

/// Throws when more than maximumPointsPerKey points other than the first of a run of one key
/// differ from it: the Morton order cannot separate them.
void checkKeyResolution(const std::vector<std::uint64_t>& keys, const PointMatrix& Q)
{
    Eigen::Index runStart = 0, differing = 0;
    for (Eigen::Index j = 1; j < Q.rows(); ++j) {
        if (keys[static_cast<std::size_t>(j)] != keys[static_cast<std::size_t>(runStart)]) {
            runStart = j;
            differing = 0;
        } else if (Q.row(j) != Q.row(runStart) && ++differing > maximumPointsPerKey) {
            throw std::invalid_argument(
                "point cloud: more than " + std::to_string(maximumPointsPerKey) +
                " points lie in one cell of 1/2097151 of its size: its size is too large "
                "for its point spacing (points far out?); "
                "remove the outlying points or split the cloud");
        }
    }
}

/// Every point coincides: the neighbours of each are the others of lowest index.
void coincidentNeighbours(Neighbourhoods& result, Eigen::Index n, int k)
{
    for (Eigen::Index i = 0; i < n; ++i) {
        for (int c = 0, j = 0; c < k; ++j) {
            if (j != i) {
                result.indices(i, c) = j;
                result.squaredDistances(i, c) = 0.0;
                ++c;
            }
        }
    }
}

/// The points in key order: the cloud itself when it comes in that order (analyseCloud's
/// canonical order), else a copy. original[j] is the row of P of row j of the copy.
struct KeyOrder
{
    std::vector<std::uint64_t> keys;
    bool sorted = true;
    std::vector<int> original;
    PointMatrix copy;

    const PointMatrix& points(const PointMatrix& P) const { return sorted ? P : copy; }
    int rowOf(Eigen::Index j) const
    {
        return sorted ? static_cast<int>(j) : original[static_cast<std::size_t>(j)];
    }
};

KeyOrder keyOrder(const PointMatrix& P, const MortonGrid& grid, int threads)
{
    const Eigen::Index n = P.rows();
    KeyOrder order;
    std::vector<std::uint64_t>& keys = order.keys;
    keys.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
    for (Eigen::Index i = 0; i < n; ++i) {
        keys[static_cast<std::size_t>(i)] = grid.key(P, i);
    }
    order.sorted = std::is_sorted(keys.begin(), keys.end());
    if (order.sorted) {
        return order;
    }
    std::vector<std::pair<std::uint64_t, int>> keyed(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        keyed[static_cast<std::size_t>(i)] = {keys[static_cast<std::size_t>(i)],
                                              static_cast<int>(i)};
    }
    sortByMortonKey(keyed);
    order.original.resize(static_cast<std::size_t>(n));
    order.copy.resize(n, 3);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
    for (Eigen::Index j = 0; j < n; ++j) {
        keys[static_cast<std::size_t>(j)] = keyed[static_cast<std::size_t>(j)].first;
        order.original[static_cast<std::size_t>(j)] = keyed[static_cast<std::size_t>(j)].second;
        order.copy.row(j) = P.row(keyed[static_cast<std::size_t>(j)].second);
    }
    return order;
}

/// The level the search runs on: the finest whose cells hold the wanted mean number of points
/// (pointsPerCellPerNeighbour). Consecutive keys first differ at bit b: a new cell starts there
/// on every level up to b / 3.
int searchLevel(const std::vector<std::uint64_t>& keys, Eigen::Index n, int k)
{
    std::vector<long> newCells(mortonBitsPerAxis + 1, 0);
    for (std::size_t j = 1; j < keys.size(); ++j) {
        const std::uint64_t differ = keys[j] ^ keys[j - 1];
        if (differ != 0) {
            ++newCells[static_cast<std::size_t>((63 - __builtin_clzll(differ)) / 3)];
        }
    }
    int level = 1;
    for (long cells = 1 + std::accumulate(newCells.begin() + 1, newCells.end(), 0L);
         level < mortonBitsPerAxis &&
         double(n) < pointsPerCellPerNeighbour * (k + 1) * double(cells);
         ++level) {
        cells -= newCells[static_cast<std::size_t>(level)];
    }
    return level;
}

/// Each cell is cut into 8 sub-cells (one level finer), the unit of the scan: a query looks at
/// the sub-cells its search box overlaps among the 6 x 6 x 6 of the 27 cells around its own.
constexpr int width = 6;

/// Margins for rounding in steps: positions are exact to about 1e-9 step.
constexpr double stepMargin = 1e-3;

/// Calls visit(dx, dy, dz, code) for each of the 27 cells cc + (dx, dy, dz) inside the grid
/// [0, top]^3 (code: the cell's Morton key), dz slowest, dx fastest.
template <class Visit>
void forEachCellAround(const std::int64_t cc[3], std::int64_t top, const Visit& visit)
{
    for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const std::int64_t x = cc[0] + dx, y = cc[1] + dy, z = cc[2] + dz;
                if (x < 0 || y < 0 || z < 0 || x > top || y > top || z > top) {
                    continue;
                }
                visit(dx, dy, dz, mortonKey(std::uint64_t(x), std::uint64_t(y), std::uint64_t(z)));
            }
        }
    }
}

/// A run of rows of the key order: the points of one sub-cell.
struct Run
{
    int first = 0, end = 0;
};

/// What one thread keeps from query to query: the sub-cells' runs of the block around the
/// current cell, the candidates, and the radius of the next first search.
struct Worker
{
    std::vector<Run> table = std::vector<Run>(width * width * width);
    Candidates candidates;
    std::vector<double> scratch;
    double guess = 0.0;
};

/// What the search runs on: the points Q in key order (order.points(P)), their grid, order
/// and cells at `level`, and the neighbours wanted per point.
struct CellSearchInput
{
    const MortonGrid& grid;
    const PointMatrix& Q;
    const KeyOrder& order;
    const Cells& cells;
    int level;
    int k;
};

/// The exact search over the cells of one level of the key order, writing into `result`.
class CellSearch
{
public:
    CellSearch(const CellSearchInput& in, Neighbourhoods& result)
        : grid_(in.grid), Q_(in.Q), order_(in.order), keys_(in.order.keys), cells_(in.cells),
          level_(in.level), k_(in.k), result_(result), subLevel_(in.level - 1),
          subSteps_(double(std::uint64_t(1) << subLevel_)),
          lastCell_((std::int64_t(1) << (mortonBitsPerAxis - in.level)) - 1),
          lastSub_((std::int64_t(1) << (mortonBitsPerAxis - subLevel_)) - 1),
          oneStep_(1.0 / in.grid.scale)
    {
    }

    /// Every point's neighbours, the cells shared among the threads.
    void run(int threads, const ProgressSpan& progress) const;

private:
    /// The queries of one cell: each first within a box about it in the sub-cells of the 27
    /// cells around, else searchWide.
    void searchCell(long cell, Worker& w) const;

    /// Fills `table` with the runs of rows of the sub-cells of the 27 cells around cell cc;
    /// returns the number of points they hold.
    std::size_t gatherBlock(const std::int64_t cc[3], std::vector<Run>& table) const;

    /// The runs of the sub-cells of cell `other`, at offset (dx, dy, dz) of the block's centre.
    void addSubCells(int other, int dx, int dy, int dz, std::vector<Run>& table) const;

    /// The k nearest lie within R of the query when at least k points do: every point within R
    /// is in the sub-cells the box [q - R, q + R] overlaps. R starts from the guess and grows
    /// while fewer than k are found and the box stays in the table. False when it left the
    /// table first.
    bool searchNear(int j, const std::int64_t origin[3], Worker& w) const;

    /// The sub-cells [lo, hi] of the table that the box of half-width R about u (in steps)
    /// overlaps; false when it reaches outside the table.
    bool boxInTable(const double u[3], double R, const std::int64_t origin[3], int lo[3],
                    int hi[3]) const;

    /// The other points within R of query j in the sub-cells [lo, hi], as candidates (rows of
    /// the key order); returns their count.
    std::size_t pointsWithin(int j, double R, const int lo[3], const int hi[3], Worker& w) const;

    /// Exact for any query, at any level from the search's up: the points of the 27 cells
    /// around the query's cell, when the k-th nearest among them is closer than the block's
    /// faces; otherwise the next level. The top level's block is the whole cloud. Returns the
    /// k-th squared distance.
    double searchWide(Eigen::Index j, Candidates& c, std::vector<double>& scratch) const;

    /// The other points of the 27 cells of level l around cell cc as candidates (rows of P);
    /// returns their count.
    std::size_t gatherWide(Eigen::Index j, const std::int64_t cc[3], int l, std::int64_t top,
                           Candidates& c) const;

    /// True when every point within the k-th distance of the query at u (in steps) lies in the
    /// block of the 27 cells of level l around cell cc.
    bool blockHolds(const double u[3], const std::int64_t cc[3], int l, std::int64_t top,
                    double kth) const;

    const MortonGrid& grid_;
    const PointMatrix& Q_;
    const KeyOrder& order_;
    const std::vector<std::uint64_t>& keys_;
    const Cells& cells_;
    const int level_;
    const int k_;
    Neighbourhoods& result_;
    const int subLevel_;
    const double subSteps_;
    const std::int64_t lastCell_;
    const std::int64_t lastSub_;
    const double oneStep_;
};

void CellSearch::run(int threads, const ProgressSpan& progress) const
{
    LoopProgress loop(progress, cells_.count());
#pragma omp parallel num_threads(threads)
    {
        Worker worker;
#pragma omp for schedule(dynamic, 16)
        for (long cell = 0; cell < cells_.count(); ++cell) {
            if (loop.next(cell)) {
                searchCell(cell, worker);
            }
        }
    }
    loop.finish();
}

void CellSearch::searchCell(long cell, Worker& w) const
{
    std::int64_t cc[3];
    for (int d = 0; d < 3; ++d) {
        cc[d] = static_cast<std::int64_t>(grid_.steps(Q_(cells_.first(cell), d), d)) >> level_;
    }
    const std::size_t blockPoints = gatherBlock(cc, w.table);
    w.candidates.reserve(blockPoints);
    const std::int64_t origin[3] = {2 * (cc[0] - 1), 2 * (cc[1] - 1), 2 * (cc[2] - 1)};
    if (!(w.guess > 0.0)) {
        w.guess = 0.5 * subSteps_ * oneStep_;
    }
    for (int j = cells_.first(cell); j < cells_.end(cell); ++j) {
        if (!searchNear(j, origin, w)) {
            w.guess = radiusGuess * std::sqrt(searchWide(j, w.candidates, w.scratch));
        }
    }
}

std::size_t CellSearch::gatherBlock(const std::int64_t cc[3], std::vector<Run>& table) const
{
    std::fill(table.begin(), table.end(), Run{});
    std::size_t blockPoints = 0;
    forEachCellAround(cc, lastCell_, [&](int dx, int dy, int dz, std::uint64_t code) {
        const int other = cells_.find(code);
        if (other < 0) {
            return;
        }
        blockPoints += static_cast<std::size_t>(cells_.end(other) - cells_.first(other));
        addSubCells(other, dx, dy, dz, table);
    });
    return blockPoints;
}

void CellSearch::addSubCells(int other, int dx, int dy, int dz, std::vector<Run>& table) const
{
    const int end = cells_.end(other);
    for (int first = cells_.first(other); first < end;) {
        // The sub-cell: the key's three bits below the cell's.
        const unsigned sub = unsigned(keys_[first] >> (3 * subLevel_)) & 7u;
        int last = first + 1;
        while (last < end && (unsigned(keys_[last] >> (3 * subLevel_)) & 7u) == sub) {
            ++last;
        }
        const int X = 2 * (dx + 1) + int(sub & 1u);
        const int Y = 2 * (dy + 1) + int((sub >> 1) & 1u);
        const int Z = 2 * (dz + 1) + int(sub >> 2);
        table[static_cast<std::size_t>((Z * width + Y) * width + X)] = {first, last};
        first = last;
    }
}

bool CellSearch::searchNear(int j, const std::int64_t origin[3], Worker& w) const
{
    double u[3];
    for (int d = 0; d < 3; ++d) {
        u[d] = grid_.steps(Q_(j, d), d);
    }
    for (double R = std::max(w.guess, oneStep_);;) {
        int lo[3], hi[3];
        if (!boxInTable(u, R, origin, lo, hi)) {
            return false;
        }
        const std::size_t count = pointsWithin(j, R, lo, hi, w);
        if (count >= static_cast<std::size_t>(k_)) {
            if (!order_.sorted) {
                for (std::size_t a = 0; a < count; ++a) {
                    w.candidates.index[a] =
                        order_.original[static_cast<std::size_t>(w.candidates.index[a])];
                }
            }
            const int i = order_.rowOf(j);
            storeNearest(w.candidates, count, k_, &result_.indices(i, 0),
                         &result_.squaredDistances(i, 0));
            w.guess = radiusGuess * std::sqrt(result_.squaredDistances(i, k_ - 1));
            return true;
        }
        // About (count + 1) / R^2 points per area: aim at k + 1 with a margin.
        R *= std::max(1.25, 1.1 * std::sqrt((k_ + 1.0) / (count + 1.0)));
    }
}

bool CellSearch::boxInTable(const double u[3], double R, const std::int64_t origin[3], int lo[3],
                            int hi[3]) const
{
    const double reach = R * grid_.scale * (1.0 + 1e-9) + stepMargin;
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
        // Sub-cells outside the grid hold no point.
        const std::int64_t a = std::max<std::int64_t>(
            0, static_cast<std::int64_t>(std::floor((u[d] - reach) / subSteps_)));
        const std::int64_t b = std::min<std::int64_t>(
            lastSub_, static_cast<std::int64_t>(std::floor((u[d] + reach) / subSteps_)));
        lo[d] = static_cast<int>(a - origin[d]);
        hi[d] = static_cast<int>(b - origin[d]);
        inside = inside && lo[d] >= 0 && hi[d] < width;
    }
    return inside;
}

std::size_t CellSearch::pointsWithin(int j, double R, const int lo[3], const int hi[3],
                                     Worker& w) const
{
    const double R2 = R * R;
    std::size_t count = 0;
    for (int Z = lo[2]; Z <= hi[2]; ++Z) {
        for (int Y = lo[1]; Y <= hi[1]; ++Y) {
            for (int X = lo[0]; X <= hi[0]; ++X) {
                const Run run = w.table[static_cast<std::size_t>((Z * width + Y) * width + X)];
                for (int r = run.first; r < run.end; ++r) { // branch-free
                    const double d2 = (Q_.row(r) - Q_.row(j)).squaredNorm();
                    w.candidates.distance[count] = d2;
                    w.candidates.index[count] = r;
                    count += (d2 <= R2) & (r != j);
                }
            }
        }
    }
    return count;
}

double CellSearch::searchWide(Eigen::Index j, Candidates& c, std::vector<double>& scratch) const
{
    double u[3];
    std::int64_t q[3];
    for (int d = 0; d < 3; ++d) {
        u[d] = grid_.steps(Q_(j, d), d);
        q[d] = static_cast<std::int64_t>(u[d]);
    }
    for (int l = level_;; ++l) {
        const std::int64_t top = (std::int64_t(1) << (mortonBitsPerAxis - l)) - 1;
        std::int64_t cc[3];
        for (int d = 0; d < 3; ++d) {
            cc[d] = q[d] >> l;
        }
        const std::size_t count = gatherWide(j, cc, l, top, c);
        if (count < static_cast<std::size_t>(k_)) {
            continue;
        }
        scratch.assign(c.distance.begin(), c.distance.begin() + count);
        std::nth_element(scratch.begin(), scratch.begin() + (k_ - 1), scratch.end());
        const double kth = scratch[static_cast<std::size_t>(k_ - 1)];
        if (!blockHolds(u, cc, l, top, kth)) {
            continue;
        }
        std::size_t kept = 0;
        for (std::size_t a = 0; a < count; ++a) {
            c.distance[kept] = c.distance[a];
            c.index[kept] = c.index[a];
            kept += c.distance[a] <= kth;
        }
        storeNearest(c, kept, k_, &result_.indices(order_.rowOf(j), 0),
                     &result_.squaredDistances(order_.rowOf(j), 0));
        return kth;
    }
}

std::size_t CellSearch::gatherWide(Eigen::Index j, const std::int64_t cc[3], int l,
                                   std::int64_t top, Candidates& c) const
{
    std::size_t count = 0;
    forEachCellAround(cc, top, [&](int, int, int, std::uint64_t code) {
        const auto from = std::lower_bound(keys_.begin(), keys_.end(), code << (3 * l));
        const auto to = std::lower_bound(from, keys_.end(), (code + 1) << (3 * l));
        for (auto at = from; at != to; ++at) {
            const Eigen::Index r = at - keys_.begin();
            if (r == j) {
                continue;
            }
            c.reserve(count + 1);
            c.distance[count] = (Q_.row(r) - Q_.row(j)).squaredNorm();
            c.index[count] = order_.rowOf(r);
            ++count;
        }
    });
    return count;
}

bool CellSearch::blockHolds(const double u[3], const std::int64_t cc[3], int l, std::int64_t top,
                            double kth) const
{
    const double reach = std::sqrt(kth) * grid_.scale * (1.0 + 1e-9) + stepMargin;
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
        inside = inside && (cc[d] == 0 || std::floor(u[d] - reach) >= double((cc[d] - 1) << l)) &&
                 (cc[d] == top || std::floor(u[d] + reach) < double((cc[d] + 2) << l));
    }
    return inside;
}

} // namespace

void Neighbourhoods::allocate(Eigen::Index rows, int k)
{
    indices.resize(rows, k);
    squaredDistances.resize(rows, k);
    adviseHugePagesOf(indices);
    adviseHugePagesOf(squaredDistances);
}

Neighbourhoods nearestNeighbours(const PointMatrix& P, const NeighbourOptions& options,
                                 const ProgressSpan& progress)
{
    const int k = options.k;
    checkNeighbourInput(P, k);
    const Eigen::Index n = P.rows();
    const int threads = threadCount(options.threads);
    Neighbourhoods result;
    result.allocate(n, k);
    const MortonGrid grid(P);
    if (!(grid.scale > 0.0)) {
        coincidentNeighbours(result, n, k);
        return result;
    }
    const KeyOrder order = keyOrder(P, grid, threads);
    releaseIdleThreads(); // the level and the cells' hash table are serial
    checkKeyResolution(order.keys, order.points(P));
    const int level = searchLevel(order.keys, n, k);
    const Cells cells(order.keys, level);
    const CellSearchInput in{grid, order.points(P), order, cells, level, k};
    CellSearch(in, result).run(threads, progress);
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

double samplingSpacing(const Neighbourhoods& neighbourhoods)
{
    const double nearest = meanSpacing(neighbourhoods);
    const Eigen::Index n = neighbourhoods.size();
    const int k = neighbourhoods.k();
    std::vector<double> radii(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        radii[static_cast<std::size_t>(i)] = neighbourhoods.squaredDistances(i, k - 1);
    }
    const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
    std::nth_element(radii.begin(), middle, radii.end());
    constexpr double evenSamplingShare = 0.8;
    const double area = std::sqrt(M_PI * *middle / static_cast<double>(k));
    return std::max(nearest, evenSamplingShare * area);
}

} // namespace featurelines
