// SPDX-License-Identifier: LGPL-2.1-or-later
// A uniform hash grid over 3D points for fixed-radius queries: the benchmark asks only "is
// there a point within r of q" (scoring, Poisson-disk sampling), for which a grid with
// cells of size r needs at most 27 cell look-ups per query and no tree.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace featurelines::bench {

class PointGrid
{
public:
    /// An empty grid answering queries of radius up to `cellSize` (> 0).
    explicit PointGrid(double cellSize) : cell(cellSize) {}

    /// Stores point `id` at position p.
    void insert(const Eigen::Vector3d& p, int id) { cells[key(cellOf(p))].push_back({p, id}); }

    /// Calls visit(id, squaredDistance) for every stored point within `radius` of q and
    /// stops early when visit returns false. radius must not exceed the cell size.
    template <class Visit>
    void forEachWithin(const Eigen::Vector3d& q, double radius, Visit visit) const
    {
        const Eigen::Vector3i c = cellOf(q);
        const double r2 = radius * radius;
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    auto it = cells.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                    if (it == cells.end()) {
                        continue;
                    }
                    for (const Entry& e : it->second) {
                        const double d2 = (e.position - q).squaredNorm();
                        if (d2 <= r2 && !visit(e.id, d2)) {
                            return;
                        }
                    }
                }
            }
        }
    }

    /// True when a stored point lies within `radius` (<= cell size) of q.
    bool anyWithin(const Eigen::Vector3d& q, double radius) const
    {
        bool found = false;
        forEachWithin(q, radius, [&found](int, double) {
            found = true;
            return false;
        });
        return found;
    }

    double cellSize() const { return cell; }

private:
    struct Entry
    {
        Eigen::Vector3d position;
        int id;
    };

    Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const
    {
        return Eigen::Vector3i(static_cast<int>(std::floor(p.x() / cell)),
                               static_cast<int>(std::floor(p.y() / cell)),
                               static_cast<int>(std::floor(p.z() / cell)));
    }

    static std::uint64_t key(const Eigen::Vector3i& c)
    {
        // 21 bits per axis: about two million cells along each axis, far more than a cloud
        // sampled at its own spacing needs.
        const auto wrap = [](int v) { return static_cast<std::uint64_t>(v) & 0x1FFFFFu; };
        return (wrap(c.x()) << 42) | (wrap(c.y()) << 21) | wrap(c.z());
    }

    double cell;
    std::unordered_map<std::uint64_t, std::vector<Entry>> cells;
};

} // namespace featurelines::bench
