#pragma once
// Disjoint sets of the integers 0..n-1 (union-find with path halving), for the components,
// planes, chains and sheets that geometry/ and the PolyCube front-end group: one implementation
// instead of a private one per file.
//
//   UnionFind sets(n);
//   sets.join(a, b);                   // false when a and b were in one set already
//   if (sets.find(a) == sets.find(c))  // a representative per set
//
// A set's representative is one of its members, which one depends on the order of the joins
// (join() puts a's set under b's): callers use it as a set's name, never its rank.

#include <numeric>
#include <vector>

#include "optim/types.h"

namespace sa {

class UnionFind {
  public:
    explicit UnionFind(Index n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), Index(0));
    }

    /// The representative of x's set.
    Index find(Index x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }

    /// Joins the sets of a and b; returns whether they were two.
    bool join(Index a, Index b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent_[a] = b;
        return true;
    }

    /// Makes x a set of its own again. Only for an x that is no other element's parent (every
    /// element of a set being reset together, say).
    void reset(Index x) { parent_[x] = x; }

  private:
    std::vector<Index> parent_;
};

}  // namespace sa
