// SPDX-License-Identifier: LGPL-2.1-or-later
// The band around a set of lines: which points lie within a distance of them (Sec. 1.2: the
// band around the sharp lines parts the smooth regions). Design: docs/design/smooth-regions.md.
#pragma once

#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "FeatureLines/network/ClusterGraph.h"

namespace featurelines {

/// Samples of the lines, at most half the width apart, each with its line, in a uniform hash
/// grid of cells `width` wide (length unit).
class LineBand
{
public:
    LineBand(const std::vector<Polyline>& lines, double width);

    /// Whether p lies closer than the width to a sample.
    bool contains(const Eigen::RowVector3d& p) const;
    /// The line (index in the constructor's list) of the sample nearest p, if closer than the
    /// width; -1 for none.
    int nearestLine(const Eigen::RowVector3d& p) const;
    /// Whether there are no lines (no point lies in the band).
    bool empty() const { return cells_.empty(); }

private:
    struct Key
    {
        long long x, y, z;
        bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct KeyHash
    {
        size_t operator()(const Key& k) const
        {
            return static_cast<size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
        }
    };

    struct Sample
    {
        Eigen::RowVector3d position;
        int line;
    };

    Key cell(const Eigen::RowVector3d& p) const;
    void insert(const Eigen::RowVector3d& p, int line) { cells_[cell(p)].push_back({p, line}); }
    void sample(const Polyline& line, int index);
    /// Calls visit(sample) for the samples of the cells around p's; false when p's cell is
    /// near no sample.
    template <class Visit> bool forEachAround(const Eigen::RowVector3d& p, Visit visit) const;
    void markNearCells();

    double width_;
    std::unordered_map<Key, std::vector<Sample>, KeyHash> cells_;
    /// The cells next to a sample cell (and those cells).
    std::unordered_set<Key, KeyHash> near_;
};

/// Per listed point (rows of P): nonzero when it lies within `distance` of one of the lines.
std::vector<char> pointsNearLines(const PointMatrix& P, const std::vector<int>& points,
                                  const std::vector<Polyline>& lines, double distance);

} // namespace featurelines
