#pragma once
// A per-simplex energy of A handed to the mesh driver (frontends/simplex_assembly/map_solve.h): the
// built-in mu E_m + E_C of the options, or a user's own E_m or barrier. The driver uses one in
// every place an energy of A appears, each through a generic adapter, never a per-type method:
//   - the engine (kind 1 of engine.h), in any layout: the linear parts of r-SA and f-SA, v-SA's
//     copies and the vertex stage's positions through VertexSimplexEnergy, which evaluates it at
//     A = X E^-1 and projects its Hessian in A;
//   - a submesh region or the simplices the vertex stage moves: ReindexedEnergy on the shared
//     energy (restricted());
//   - the hand-over test and the submesh mode's bad simplices: its value at the A of a mesh;
//   - verification and the optimal-bound rounds, for a barrier on a distortion
//     (DistortionBarrier, or any energy with distortion(A), bound() and with_bound(K)): the
//     largest distortion of the output against its bound.
// The type is erased once per term (a virtual call per term and stage), never per element: the
// engine and the vertex stage add the concrete EnergyTerm<E>.
//
// Element s of the energy is simplex s of the MappingProblem's mesh; its rest data are the
// user's, in the user's units. A is the Jacobian of the map in each simplex's rest frame
// (rest_frames.h): the mesh's own axes for tetrahedra and planar triangles, a frame in the
// triangle's plane for a surface. A does not change with the driver's normalization (both sides
// are scaled alike).

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <memory>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

#include "energies/barrier.h"
#include "energies/distortion_barrier.h"
#include "energies/reindexed_energy.h"
#include "energies/simplex_energy.h"
#include "energies/vertex_copy_energies.h"
#include "frontends/simplex_assembly/engine.h"

namespace sa {

/// What every per-simplex term is, whatever its dimension: held by MappingProblem.
class SimplexTermBase {
  public:
    explicit SimplexTermBase(std::string name) : name_(std::move(name)) {}
    virtual ~SimplexTermBase() = default;
    const std::string& name() const { return name_; }
    virtual int dimension() const = 0;

  private:
    std::string name_;
};

/// An energy E (with distortion(A), bound() and with_bound(K)) that bounds a distortion.
template <class E, int D>
concept DistortionBarrierEnergy = requires(const E& e, const Mat<D>& A) {
    { e.distortion(A) } -> std::convertible_to<double>;
    { e.bound() } -> std::convertible_to<double>;
    { e.with_bound(1.0) } -> std::convertible_to<E>;
};

/// A barrier e^{s d} on a distortion whose exponent's scale s can be changed (exponent(),
/// with_exponent(s)): the vertex stage's exponent continuation lowers it with E_C's.
template <class E, int D>
concept ExponentialBarrierEnergy = DistortionBarrierEnergy<E, D> && requires(const E& e) {
    { e.exponent() } -> std::convertible_to<double>;
    { e.with_exponent(1.0) } -> std::convertible_to<E>;
};

template <int D>
class SimplexTerm : public SimplexTermBase {
  public:
    using SimplexTermBase::SimplexTermBase;
    int dimension() const final { return D; }

    /// Adds the energy to `engine` (kind 1) on `simplices` (every simplex when empty), in any
    /// of its layouts: the assembly's linear parts or corner copies, or the vertex stage's
    /// positions.
    virtual TermId add_to(SimplexAssemblyEngine<D>& engine,
                          const std::vector<Index>& simplices = {}) const = 0;
    /// The same energy on `simplices` only: simplex k of the result is simplices[k] of this one.
    virtual std::shared_ptr<const SimplexTerm<D>> restricted(
        const std::vector<Index>& simplices) const = 0;
    /// sum_s energy(A[s]); +inf as soon as one simplex is infeasible. The same sum for any
    /// number of threads.
    virtual double sum(const std::vector<Mat<D>>& A) const = 0;
    /// Sets rejected[s] = 1 for every s whose energy at A[s] is +inf.
    virtual void mark_infeasible(const std::vector<Mat<D>>& A,
                                 std::vector<unsigned char>& rejected) const = 0;

    /// A barrier on a distortion: verified on the output, lowered by the optimal bound.
    virtual bool bounds_a_distortion() const { return false; }
    /// Its bound K (+inf for other energies and unbounded barriers).
    virtual double bound() const { return kInfinity; }
    /// Its largest distortion over A (+inf where det A <= 0); 0 for other energies.
    virtual double max_distortion(const std::vector<Mat<D>>&) const { return 0.0; }
    /// Whether the barrier's e^{s d} at A is beyond barrier.h's exponent cap, where it no longer
    /// ranks the other simplices (the built-in SimplexEnergy; false for other energies).
    virtual bool beyond_exponent_cap(const Mat<D>&) const { return false; }
    /// For a barrier with a finite bound K on a distortion d (the built-in SimplexEnergy or a
    /// DistortionBarrier): sets marked[s] = 1 for every s whose d(A[s]) >= d_I + (1 - band)
    /// (K - d_I), d_I the distortion of the identity; nothing for other energies.
    virtual void mark_near_bound(const std::vector<Mat<D>>&, double,
                                 std::vector<unsigned char>&) const {}
    /// The same barrier with bound K; throws InvalidArgumentError for other energies.
    virtual std::shared_ptr<const SimplexTerm<D>> with_bound(double) const {
        throw InvalidArgumentError(name() + ": not a barrier on a distortion, it has no bound");
    }
    /// For a barrier e^{s d} of the problem's own (a DistortionBarrier): s; 0 for other energies.
    virtual double exponent() const { return 0.0; }
    /// Its distortion d at A (+inf where det A <= 0); 0 for other energies.
    virtual double distortion(const Mat<D>&) const { return 0.0; }
    /// The same barrier at exponent scale s; throws InvalidArgumentError for other energies.
    virtual std::shared_ptr<const SimplexTerm<D>> with_exponent(double) const {
        throw InvalidArgumentError(name() + ": not an exponential barrier");
    }
};

template <int D, ElementEnergy E>
class SimplexTermOf final : public SimplexTerm<D> {
  public:
    static_assert(E::arity == D * D, "a per-simplex energy is an energy of vec(A)");

    /// Element s of `energy` is simplex selected[s] (every simplex when `selected` is empty).
    SimplexTermOf(std::string name, std::shared_ptr<const E> energy,
                  std::vector<Index> selected = {})
        : SimplexTerm<D>(std::move(name)),
          energy_(std::move(energy)),
          selected_(std::move(selected)) {}

    TermId add_to(SimplexAssemblyEngine<D>& engine,
                  const std::vector<Index>& simplices) const override {
        std::vector<Index> on = simplices;
        if (on.empty()) {
            on.resize(engine.num_simplices());
            std::iota(on.begin(), on.end(), Index(0));
        }
        bool identity = selected_.empty() && Index(on.size()) == engine.num_simplices();
        for (Index k = 0; identity && k < Index(on.size()); ++k) identity = on[k] == k;
        if (identity) return engine.add_simplex_energy(this->name(), *energy_);
        if (!selected_.empty() && Index(selected_.size()) != engine.num_simplices()) {
            throw InvalidArgumentError(
                this->name() + ": restricted to " + std::to_string(selected_.size()) +
                " simplices, the engine has " + std::to_string(engine.num_simplices()));
        }
        // One re-indexing for both the restriction and the subset: element k of the term is
        // simplex on[k] of the engine and element of(on)[k] of the energy.
        // (of(on) first: the arguments' order of evaluation is unspecified.)
        ReindexedEnergy<E> reindexed(energy_, of(on));
        return engine.add_simplex_energy(this->name(), std::move(reindexed), std::move(on));
    }

    std::shared_ptr<const SimplexTerm<D>> restricted(
        const std::vector<Index>& simplices) const override {
        return std::make_shared<SimplexTermOf>(this->name(), energy_, of(simplices));
    }

    double sum(const std::vector<Mat<D>>& A) const override {
        return tbb::parallel_deterministic_reduce(
            tbb::blocked_range<Index>(0, Index(A.size()), 1024), 0.0,
            [&](const tbb::blocked_range<Index>& r, double acc) {
                for (Index s = r.begin(); s != r.end() && acc < kInfinity; ++s) acc += value(A, s);
                return acc;
            },
            std::plus<double>());
    }

    void mark_infeasible(const std::vector<Mat<D>>& A,
                         std::vector<unsigned char>& rejected) const override {
        tbb::parallel_for(Index(0), Index(A.size()), [&](Index s) {
            if (!std::isfinite(value(A, s))) rejected[s] = 1;
        });
    }

    bool bounds_a_distortion() const override { return DistortionBarrierEnergy<E, D>; }
    double bound() const override {
        if constexpr (DistortionBarrierEnergy<E, D>) {
            return energy_->bound();
        } else {
            return kInfinity;
        }
    }
    double max_distortion(const std::vector<Mat<D>>& A) const override {
        if constexpr (DistortionBarrierEnergy<E, D>) {
            return tbb::parallel_reduce(
                tbb::blocked_range<Index>(0, Index(A.size()), 1024), 0.0,
                [&](const tbb::blocked_range<Index>& r, double largest) {
                    for (Index s = r.begin(); s != r.end(); ++s)
                        largest = std::max(largest, double(energy_->distortion(A[s])));
                    return largest;
                },
                [](double a, double b) { return std::max(a, b); });
        } else {
            return 0.0;
        }
    }
    bool beyond_exponent_cap(const Mat<D>& A) const override {
        if constexpr (std::is_same_v<E, SimplexEnergy<D>>) {
            return energy_->options().barrier.s * energy_->barrier_distortion(A) >
                   kBarrierExponentCap;
        } else {
            return false;
        }
    }
    void mark_near_bound(const std::vector<Mat<D>>& A, double band,
                         std::vector<unsigned char>& marked) const override {
        if constexpr (std::is_same_v<E, SimplexEnergy<D>> || DistortionBarrierEnergy<E, D>) {
            auto distortion = [&](const Mat<D>& a) -> double {
                if constexpr (std::is_same_v<E, SimplexEnergy<D>>) {
                    return energy_->barrier_distortion(a);
                } else {
                    return double(energy_->distortion(a));
                }
            };
            double K;
            if constexpr (std::is_same_v<E, SimplexEnergy<D>>) {
                K = energy_->options().barrier.bound;
            } else {
                K = energy_->bound();
            }
            if (!std::isfinite(K)) return;
            const double identity = distortion(Mat<D>::Identity());
            const double threshold = identity + (1.0 - band) * (K - identity);
            tbb::parallel_for(Index(0), Index(A.size()), [&](Index s) {
                if (!(distortion(A[s]) < threshold)) marked[s] = 1;
            });
        }
    }
    std::shared_ptr<const SimplexTerm<D>> with_bound(double K) const override {
        if constexpr (DistortionBarrierEnergy<E, D>) {
            return std::make_shared<SimplexTermOf>(
                this->name(), std::make_shared<const E>(energy_->with_bound(K)), selected_);
        } else {
            return SimplexTerm<D>::with_bound(K);
        }
    }

    double exponent() const override {
        if constexpr (ExponentialBarrierEnergy<E, D>) {
            return energy_->exponent();
        } else {
            return 0.0;
        }
    }
    double distortion(const Mat<D>& A) const override {
        if constexpr (ExponentialBarrierEnergy<E, D>) {
            return energy_->distortion(A);
        } else {
            return 0.0;
        }
    }
    std::shared_ptr<const SimplexTerm<D>> with_exponent(double s) const override {
        if constexpr (ExponentialBarrierEnergy<E, D>) {
            return std::make_shared<SimplexTermOf>(
                this->name(), std::make_shared<const E>(energy_->with_exponent(s)), selected_);
        } else {
            return SimplexTerm<D>::with_exponent(s);
        }
    }

  private:
    Index element(Index s) const { return selected_.empty() ? s : selected_[s]; }
    double value(const std::vector<Mat<D>>& A, Index s) const {
        return energy_->value(element(s), Eigen::Map<const Vec<D * D>>(A[s].data()));
    }
    /// The energy's elements of the given simplices of this term.
    std::vector<Index> of(const std::vector<Index>& simplices) const {
        if (selected_.empty()) return simplices;
        std::vector<Index> mapped(simplices.size());
        for (std::size_t k = 0; k < simplices.size(); ++k) mapped[k] = selected_[simplices[k]];
        return mapped;
    }

    std::shared_ptr<const E> energy_;
    std::vector<Index> selected_;
};

// Compiled once, with the engine's terms of the same energies (engine.h).
extern template class SimplexTermOf<2, SimplexEnergy<2>>;
extern template class SimplexTermOf<3, SimplexEnergy<3>>;
extern template class SimplexTermOf<2, DistortionBarrier<2, BuiltinDistortion<2>>>;
extern template class SimplexTermOf<3, DistortionBarrier<3, BuiltinDistortion<3>>>;

/// A per-simplex energy for MappingProblem::energies (element s = simplex s of its mesh).
template <int D, ElementEnergy E>
std::shared_ptr<const SimplexTerm<D>> simplex_term(std::string name, E energy) {
    return std::make_shared<SimplexTermOf<D, E>>(std::move(name),
                                                 std::make_shared<const E>(std::move(energy)));
}

}  // namespace sa
