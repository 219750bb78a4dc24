#pragma once
// Forward and backward substitution with a supernodal Cholesky factor L (A = L L^T), split over
// two independent parts of the elimination tree that run concurrently.
//
// Why: one triangular solve per Newton iteration reads the whole factor twice (L, then L^T), one
// dense supernode after another. CHOLMOD does it on one thread (dtrsv and dgemv per supernode);
// on a 3D mapping problem's full system it is the largest cost of an iteration after the
// factorization, with the second core idle (docs/measurements.md, "Triangular solves alone",
// bench/iteration_cost.py). The split is limited by the top, which on a mesh's tree is mostly a
// chain of large separator supernodes, solved serially.
//
// The result also does not depend on where the factor lies in memory: the dot products sum in
// fixed lanes (Eigen's start at the first aligned entry), so runs that allocate differently give
// the same bits.
//
// How: the subtrees of the supernodal elimination tree are independent in both substitutions
// except through their common ancestors. The tree is cut once, from the structure alone, into
// two groups of disjoint subtrees of about equal work and a "top" part holding every ancestor of
// them (a greedy split of the heaviest subtree while it lowers the estimated critical path
// top + max(group), the groups filled largest subtree first). Forward: each group eliminates its
// subtrees on its own thread; updates to rows of the top go to the group's own accumulator; the
// accumulators are then subtracted in group order and the top eliminated on one thread. Backward:
// the top first, then the groups concurrently (they only read the top's solution). A group's
// subtrees are ranges of consecutive supernodes, since CHOLMOD postorders the tree.
//
// The cut does not depend on the number of threads, and neither does the order of any floating-
// point operation: the result is bit-identical on one thread and on two (the groups then run one
// after the other). When the tree offers no useful split (a path, or one heavy supernode on top)
// everything is "top" and the solve is serial.
//
// Shapes follow CHOLMOD's supernodal factor (cholmod_factor with is_super): supernode s holds the
// columns first_column[s] .. first_column[s+1]-1 and the rows rows[row_start[s] ..
// row_start[s+1]-1] (its own columns first, then the rows below them in increasing order); its
// values are the dense column-major block of those rows x columns at values + value_start[s].

#include <Eigen/Core>
#include <vector>

namespace sa {

/// Views into a supernodal factor's symbolic structure (CHOLMOD's super, pi, px and s arrays).
struct SupernodalStructure {
    int num_columns = 0;
    int num_supernodes = 0;
    const int* first_column = nullptr;  ///< num_supernodes + 1 entries
    const int* row_start = nullptr;     ///< num_supernodes + 1 entries
    const int* value_start = nullptr;   ///< num_supernodes + 1 entries
    const int* rows = nullptr;          ///< row_start[num_supernodes] entries
};

class SupernodalSolve {
  public:
    /// Plans the split from the structure (copied; the views need not outlive the call). Throws
    /// InvalidArgumentError if the structure is inconsistent or not postordered.
    explicit SupernodalSolve(const SupernodalStructure& structure);

    /// Overwrites b (num_columns values, in the factor's own ordering) with the solution x of
    /// L L^T x = b, L's values given in CHOLMOD's layout. Runs on the caller's TBB arena. Not for
    /// concurrent calls on one object (it keeps its work space).
    void solve_in_place(const double* values, double* b) const;

    /// Share of the estimated work (values read) left in the serial top part, in [0, 1]; 1 when
    /// the tree was not split.
    double serial_share() const;

  private:
    struct Group {
        std::vector<int> supernodes;  ///< ascending: whole subtrees, children before parents
        std::vector<int> own_rows;    ///< per entry of `supernodes`: how many of its rows below
                                      ///< its columns belong to its subtree (the rest are top's)
        mutable std::vector<double> top_updates;  ///< size num_columns; only top rows used
        mutable Eigen::VectorXd scratch;          ///< the tallest supernode's height
    };

    void forward(int s, int own_rows, const double* values, double* b, double* outside,
                 Eigen::VectorXd& scratch) const;
    void backward(int s, const double* values, double* b, Eigen::VectorXd& scratch) const;
    void run_group(const Group& group, const double* values, double* b, bool forward_pass) const;

    int num_columns_ = 0;
    std::vector<int> first_column_, row_start_, value_start_, rows_;
    Group groups_[2];
    std::vector<int> top_;       ///< ascending
    std::vector<int> top_rows_;  ///< the columns of the top supernodes
    mutable Eigen::VectorXd top_scratch_;
    double serial_share_ = 1.0;
};

}  // namespace sa
