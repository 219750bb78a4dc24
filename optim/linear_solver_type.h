#pragma once
// Which sparse factorization solves the Newton system and with which fill-reducing ordering:
// the choices of LinearSolver (linear_solver.h, which says what each does), apart from the
// solver itself so that options and summaries name them without including the sparse module.

#include <string>

namespace sa {

enum class LinearSolverType { kAuto, kCholmodSupernodal, kCholmodSimplicial, kEigenLDLT };

std::string to_string(LinearSolverType type);
/// "cholmod-supernodal", "cholmod-simplicial" or "eigen-ldlt"; throws InvalidArgumentError.
LinearSolverType parse_linear_solver(const std::string& name);

inline constexpr double kAutoSupernodalFlops = 2e6;

enum class FillOrdering { kBest, kAmd };

}  // namespace sa
