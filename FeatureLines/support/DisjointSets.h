// SPDX-License-Identifier: LGPL-2.1-or-later
// Disjoint sets (union-find) that threads may join at once: the connected components of a graph
// visited in a parallel loop (regions, patches, clusters), the same at any number of threads.
// Design: docs/design/pipeline.md (Support).
#pragma once

#include <atomic>
#include <memory>
#include <utility>
#include <vector>

namespace featurelines {

/// Each set's representative is its smallest element, whatever the order in which the edges
/// were joined.
class DisjointSets
{
public:
    /// n singletons {0}, {1}, ..., {n - 1}.
    explicit DisjointSets(int n);

    int size() const { return n_; }

    /// The smallest element of x's set. Safe beside join() on other threads; once every
    /// join has returned (after the parallel loop), the answer is final.
    int find(int x) const
    {
        for (;;) {
            const int p = parent_[x].load(std::memory_order_relaxed);
            if (p == x) {
                return x;
            }
            const int g = parent_[p].load(std::memory_order_relaxed);
            if (g != p) {
                // Path halving. x is no root, and never will be again: pointing it at an
                // ancestor keeps every set as it is.
                parent_[x].store(g, std::memory_order_relaxed);
            }
            x = g;
        }
    }

    /// Joins the sets of a and b; thread-safe. Returns the smaller of their two roots: the
    /// root of the joined set, or an element of it (another thread may join it on). Passed
    /// back as `a` for the next neighbour of the same point, it spares most of a's look-ups.
    int join(int a, int b)
    {
        bool linked = false;
        return link(a, b, linked);
    }

    /// Joins the sets of a and b; thread-safe. False when they were one set already (this
    /// call linked nothing).
    bool unite(int a, int b)
    {
        bool linked = false;
        link(a, b, linked);
        return linked;
    }

    /// Per element the smallest element of its set (a parallel loop).
    std::vector<int> representatives() const;

private:
    /// join() and unite(): `linked` tells whether this call hung one root under the other.
    int link(int a, int b, bool& linked)
    {
        for (;;) {
            a = find(a);
            b = find(b);
            if (a == b) {
                return a;
            }
            if (a < b) {
                std::swap(a, b);
            }
            // The larger root hangs under the smaller, unless another thread has just hung
            // it elsewhere: then look again.
            int expected = a;
            if (parent_[a].compare_exchange_strong(expected, b, std::memory_order_relaxed)) {
                linked = true;
                return b;
            }
        }
    }

    int n_;
    std::unique_ptr<std::atomic<int>[]> parent_;
};

} // namespace featurelines
