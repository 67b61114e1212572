// SPDX-License-Identifier: LGPL-2.1-or-later
#include "FeatureLines/network/LineNetworkEdits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "FeatureLines/support/DisjointSets.h"

namespace featurelines {

namespace {

/// Direction of a line at one end (pointing out of the line), from the end vertex and the
/// vertex about `length` back along it.
Eigen::RowVector3d endDirection(const PointMatrix& V, bool atEnd, double length)
{
    const Eigen::Index n = V.rows();
    const Eigen::Index tip = atEnd ? n - 1 : 0;
    const Eigen::Index step = atEnd ? -1 : 1;
    Eigen::Index back = tip;
    double walked = 0.0;
    while (back + step >= 0 && back + step < n && walked < length) {
        walked += (V.row(back + step) - V.row(back)).norm();
        back += step;
    }
    const Eigen::RowVector3d d = V.row(tip) - V.row(back);
    const double norm = d.norm();
    return norm > 0.0 ? Eigen::RowVector3d(d / norm) : Eigen::RowVector3d::Zero();
}

/// Closest point to p on the polylines; false when there is none.
bool closestOnLines(const std::vector<Polyline>& lines, const Eigen::RowVector3d& p,
                    Eigen::RowVector3d& closest)
{
    double best = std::numeric_limits<double>::infinity();
    for (const Polyline& line : lines) {
        const Eigen::Index n = line.points.rows();
        const Eigen::Index segments = line.closed ? n : n - 1;
        if (n == 1) {
            const double d = (line.points.row(0) - p).squaredNorm();
            if (d < best) {
                best = d;
                closest = line.points.row(0);
            }
        }
        for (Eigen::Index s = 0; s < segments; ++s) {
            const Eigen::RowVector3d a = line.points.row(s);
            const Eigen::RowVector3d ab = line.points.row((s + 1) % n) - a;
            const double len2 = ab.squaredNorm();
            const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
            const Eigen::RowVector3d q = a + t * ab;
            const double d = (q - p).squaredNorm();
            if (d < best) {
                best = d;
                closest = q;
            }
        }
    }
    return std::isfinite(best);
}

/// A line's end: (line, 0 for its start | 1 for its end).
using LineEnd = std::pair<size_t, int>;

/// Per junction, the ends of the open lines not removed that lie on it.
std::map<int, std::vector<LineEnd>> lineEndsAtJunctions(const std::vector<Polyline>& lines,
                                                        const std::vector<char>& removed)
{
    std::map<int, std::vector<LineEnd>> ends;
    for (size_t l = 0; l < lines.size(); ++l) {
        if (removed[l] || lines[l].closed) {
            continue;
        }
        if (lines[l].startJunction >= 0) {
            ends[lines[l].startJunction].emplace_back(l, 0);
        }
        if (lines[l].endJunction >= 0) {
            ends[lines[l].endJunction].emplace_back(l, 1);
        }
    }
    return ends;
}

/// Joins line b onto line a where they meet (a ends at the junction, b starts there, after
/// reversing either as needed): a + b stays as a, b is removed. `anchored` follows.
void joinLines(std::vector<Polyline>& lines, std::vector<char>& anchored,
               std::vector<char>& removed, LineEnd aAt, LineEnd bAt)
{
    auto [a, aEnd] = aAt;
    auto [b, bEnd] = bAt;
    auto reverse = [&](size_t l) {
        Polyline& line = lines[l];
        line.points = line.points.colwise().reverse().eval();
        std::swap(line.startJunction, line.endJunction);
        std::swap(anchored[2 * l], anchored[2 * l + 1]);
    };
    if (aEnd == 0) {
        reverse(a);
    }
    if (bEnd == 1) {
        reverse(b);
    }
    Polyline& first = lines[a];
    const Polyline& second = lines[b];
    PointMatrix joined(first.points.rows() + second.points.rows() - 1, 3);
    joined << first.points, second.points.bottomRows(second.points.rows() - 1);
    first.points = std::move(joined);
    first.endJunction = second.endJunction;
    anchored[2 * a + 1] = anchored[2 * b + 1];
    removed[b] = 1;
}

/// A junction left with the line ends `at`: with one, that end becomes an end on nothing (it
/// ended on lines that are gone); with two, they are one line through the point (a loop when
/// both are the same line's). Returns whether lines were joined or closed.
bool mendJunction(std::vector<Polyline>& lines, std::vector<char>& anchored,
                  std::vector<char>& removed, const std::vector<LineEnd>& at)
{
    if (at.size() >= 3) {
        return false;
    }
    if (at.size() == 1) {
        Polyline& line = lines[at[0].first];
        (at[0].second == 0 ? line.startJunction : line.endJunction) = -1;
        anchored[2 * at[0].first + static_cast<size_t>(at[0].second)] = 0;
        return false;
    }
    const size_t a = at[0].first, b = at[1].first;
    if (removed[a] || removed[b]) {
        return false; // touched by a merge of this pass
    }
    if (a == b) {
        Polyline& line = lines[a];
        if (line.points.rows() > 2) {
            line.points.conservativeResize(line.points.rows() - 1, 3);
        }
        line.closed = true;
        line.startJunction = line.endJunction = -1;
        return true;
    }
    joinLines(lines, anchored, removed, at[0], at[1]);
    return true;
}

/// Keeps the lines flagged in `keep`, in their order, and the junctions they end on, renumbered
/// in the order the kept lines meet them. `anchored` (two flags per line; null: none) follows
/// the lines.
void keepLines(LineNetwork& network, const std::vector<char>& keep, std::vector<char>* anchored)
{
    std::vector<Polyline> kept;
    std::vector<char> keptAnchored;
    std::map<int, int> newJunction;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        if (!keep[l]) {
            continue;
        }
        Polyline line = std::move(network.lines[l]);
        for (int* j : {&line.startJunction, &line.endJunction}) {
            if (*j >= 0) {
                *j = newJunction.emplace(*j, static_cast<int>(newJunction.size())).first->second;
            }
        }
        kept.push_back(std::move(line));
        if (anchored) {
            keptAnchored.push_back((*anchored)[2 * l]);
            keptAnchored.push_back((*anchored)[2 * l + 1]);
        }
    }
    PointMatrix junctions(static_cast<Eigen::Index>(newJunction.size()), 3);
    for (const auto& [old, now] : newJunction) {
        junctions.row(now) = network.junctions.row(old);
    }
    network.lines = std::move(kept);
    if (anchored) {
        *anchored = std::move(keptAnchored);
    }
    network.junctions = std::move(junctions);
}

/// A piece of a network: lines joined through shared junctions.
struct Piece
{
    double length = 0.0;
    int openLines = 0;
    int looseEnds = 0; // ends on no junction, anchored or not
    int freeEnds = 0;  // ends on nothing at all
    std::vector<int> junctions;
    bool closedLine = false;
};

/// Joins in `sets` (one element per line) the lines that share a junction.
void joinLinesAtJunctions(const LineNetwork& network, DisjointSets& sets)
{
    std::map<int, int> lineAtJunction;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        for (int j : {network.lines[l].startJunction, network.lines[l].endJunction}) {
            if (j < 0) {
                continue;
            }
            auto [it, inserted] = lineAtJunction.emplace(j, static_cast<int>(l));
            if (!inserted) {
                sets.join(static_cast<int>(l), it->second);
            }
        }
    }
}

/// The pieces of the network by their set in `sets`: length, lines, ends and junctions.
std::map<int, Piece> measurePieces(const LineNetwork& network, const DisjointSets& sets,
                                   const std::vector<char>& anchored)
{
    std::map<int, Piece> pieces;
    for (size_t l = 0; l < network.lines.size(); ++l) {
        const Polyline& line = network.lines[l];
        Piece& p = pieces[sets.find(static_cast<int>(l))];
        for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
            p.length += (line.points.row(i) - line.points.row(i - 1)).norm();
        }
        if (line.closed) {
            p.closedLine = true;
            continue;
        }
        ++p.openLines;
        const int ends[2] = {line.startJunction, line.endJunction};
        for (int e = 0; e < 2; ++e) {
            if (ends[e] >= 0) {
                p.junctions.push_back(ends[e]);
                continue;
            }
            ++p.looseEnds;
            if (!anchored[2 * l + static_cast<size_t>(e)]) {
                ++p.freeEnds;
            }
        }
    }
    return pieces;
}

/// A piece is kept when it has a cycle, no end on nothing, or at least minLength of lines.
bool keepPiece(Piece& p, double minLength)
{
    std::sort(p.junctions.begin(), p.junctions.end());
    const auto junctions =
        std::unique(p.junctions.begin(), p.junctions.end()) - p.junctions.begin();
    // A tree of E lines has E + 1 end nodes (junctions and loose ends); more lines than
    // that close a cycle.
    const bool cycle = p.closedLine || p.openLines >= junctions + p.looseEnds;
    return cycle || p.freeEnds == 0 || p.length >= minLength;
}

} // namespace

std::vector<char> anchorLineEnds(LineNetwork& network, const std::vector<Polyline>& anchors,
                                 double reach, double maxAngleDegrees)
{
    std::vector<char> anchored(2 * network.lines.size(), 0);
    if (anchors.empty() || !(reach > 0.0)) {
        return anchored;
    }
    const double cosMax = std::cos(maxAngleDegrees * 3.14159265358979323846 / 180.0);
    for (size_t l = 0; l < network.lines.size(); ++l) {
        Polyline& line = network.lines[l];
        if (line.closed || line.points.rows() < 2) {
            continue;
        }
        for (int end = 0; end < 2; ++end) {
            const bool atEnd = end == 1;
            if ((atEnd ? line.endJunction : line.startJunction) >= 0) {
                continue;
            }
            const Eigen::Index tip = atEnd ? line.points.rows() - 1 : 0;
            const Eigen::RowVector3d p = line.points.row(tip);
            Eigen::RowVector3d q;
            if (!closestOnLines(anchors, p, q)) {
                continue;
            }
            const double distance = (q - p).norm();
            if (distance > reach) {
                continue;
            }
            // Ahead of the end: the line runs on towards the anchor line, not along it.
            const Eigen::RowVector3d direction = endDirection(line.points, atEnd, reach);
            if (distance > 0.0 && direction.dot((q - p) / distance) < cosMax) {
                continue;
            }
            PointMatrix extended(line.points.rows() + 1, 3);
            if (atEnd) {
                extended << line.points, q;
            } else {
                extended << q, line.points;
            }
            line.points = std::move(extended);
            anchored[2 * l + static_cast<size_t>(end)] = 1;
        }
    }
    return anchored;
}

void dropLines(LineNetwork& network, std::vector<char>& anchored, const std::vector<char>& drop)
{
    std::vector<Polyline>& lines = network.lines;
    anchored.resize(2 * lines.size(), 0);
    std::vector<char> removed = drop;
    removed.resize(lines.size(), 0);
    // Junctions left with fewer than three line ends are mended. Merges can leave a line with
    // both ends at one junction, hence the passes.
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& junction : lineEndsAtJunctions(lines, removed)) {
            changed = mendJunction(lines, anchored, removed, junction.second) || changed;
        }
    }
    std::vector<char> keep(lines.size(), 0);
    for (size_t l = 0; l < lines.size(); ++l) {
        keep[l] = !removed[l];
    }
    keepLines(network, keep, &anchored);
}

int pruneDanglingLines(LineNetwork& network, std::vector<char>& anchored, double minLength)
{
    if (!(minLength > 0.0)) {
        return 0;
    }
    anchored.resize(2 * network.lines.size(), 0);
    int pruned = 0;
    for (;;) {
        // Short lines from a junction to an end on nothing.
        std::vector<char> drop(network.lines.size(), 0);
        int found = 0;
        for (size_t l = 0; l < network.lines.size(); ++l) {
            const Polyline& line = network.lines[l];
            if (line.closed) {
                continue;
            }
            const bool startFree = line.startJunction < 0 && !anchored[2 * l];
            const bool endFree = line.endJunction < 0 && !anchored[2 * l + 1];
            const bool dangling =
                (startFree && line.endJunction >= 0) || (endFree && line.startJunction >= 0);
            double length = 0.0;
            for (Eigen::Index i = 1; i < line.points.rows(); ++i) {
                length += (line.points.row(i) - line.points.row(i - 1)).norm();
            }
            if (dangling && length < minLength) {
                drop[l] = 1;
                ++found;
            }
        }
        if (found == 0) {
            return pruned;
        }
        pruned += found;
        dropLines(network, anchored, drop);
    }
}

int dropOpenPieces(LineNetwork& network, const std::vector<char>& anchored, double minLength)
{
    const size_t lineCount = network.lines.size();
    if (!(minLength > 0.0) || lineCount == 0) {
        return 0;
    }
    DisjointSets sets(static_cast<int>(lineCount));
    joinLinesAtJunctions(network, sets);
    std::map<int, Piece> pieces = measurePieces(network, sets, anchored);
    std::vector<char> keepPieceOf(lineCount, 0);
    for (auto& [id, p] : pieces) {
        keepPieceOf[static_cast<size_t>(id)] = keepPiece(p, minLength);
    }
    std::vector<char> keep(lineCount, 0);
    int dropped = 0;
    for (size_t l = 0; l < lineCount; ++l) {
        keep[l] = keepPieceOf[static_cast<size_t>(sets.find(static_cast<int>(l)))];
        dropped += keep[l] ? 0 : 1;
    }
    keepLines(network, keep, nullptr);
    return dropped;
}

} // namespace featurelines
