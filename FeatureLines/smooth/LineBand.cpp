// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/smooth/LineBand.h"

#include <algorithm>
#include <cmath>

namespace featurelines {

LineBand::LineBand(const std::vector<Polyline>& lines, double width) : width_(width)
{
    for (size_t l = 0; l < lines.size(); ++l) {
        sample(lines[l], static_cast<int>(l));
    }
    markNearCells();
}

void LineBand::sample(const Polyline& line, int index)
{
    const double step = 0.5 * width_;
    const Eigen::Index n = line.points.rows();
    const Eigen::Index segments = line.closed ? n : n - 1;
    if (n == 1) {
        insert(line.points.row(0), index);
    }
    for (Eigen::Index s = 0; s < segments; ++s) {
        const Eigen::RowVector3d a = line.points.row(s);
        const Eigen::RowVector3d b = line.points.row((s + 1) % n);
        const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
        for (int j = 0; j <= pieces; ++j) {
            insert(a + (b - a) * (static_cast<double>(j) / pieces), index);
        }
    }
}

void LineBand::markNearCells()
{
    // A point in none of them is farther than the width from every sample, which one look-up
    // tells (most points of a cloud are).
    for (const auto& [c, samples] : cells_) {
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    near_.insert(Key{c.x + dx, c.y + dy, c.z + dz});
                }
            }
        }
    }
}

template <class Visit> bool LineBand::forEachAround(const Eigen::RowVector3d& p, Visit visit) const
{
    const Key c = cell(p);
    if (near_.find(c) == near_.end()) {
        return false;
    }
    for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dz = -1; dz <= 1; ++dz) {
                auto it = cells_.find(Key{c.x + dx, c.y + dy, c.z + dz});
                if (it == cells_.end()) {
                    continue;
                }
                for (const Sample& s : it->second) {
                    if (!visit(s)) {
                        return true;
                    }
                }
            }
        }
    }
    return true;
}

bool LineBand::contains(const Eigen::RowVector3d& p) const
{
    bool inside = false;
    forEachAround(p, [&](const Sample& s) {
        inside = (s.position - p).squaredNorm() < width_ * width_;
        return !inside;
    });
    return inside;
}

int LineBand::nearestLine(const Eigen::RowVector3d& p) const
{
    double best = width_ * width_;
    int line = -1;
    forEachAround(p, [&](const Sample& s) {
        const double d = (s.position - p).squaredNorm();
        if (d < best) {
            best = d;
            line = s.line;
        }
        return true;
    });
    return line;
}

LineBand::Key LineBand::cell(const Eigen::RowVector3d& p) const
{
    return Key{static_cast<long long>(std::floor(p.x() / width_)),
               static_cast<long long>(std::floor(p.y() / width_)),
               static_cast<long long>(std::floor(p.z() / width_))};
}

std::vector<char> pointsNearLines(const PointMatrix& P, const std::vector<int>& points,
                                  const std::vector<Polyline>& lines, double distance)
{
    std::vector<char> near(points.size(), 0);
    if (lines.empty() || !(distance > 0.0)) {
        return near;
    }
    const LineBand band(lines, distance);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < static_cast<long>(points.size()); ++i) {
        near[static_cast<size_t>(i)] = band.contains(P.row(points[static_cast<size_t>(i)]));
    }
    return near;
}

} // namespace featurelines
