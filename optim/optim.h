#pragma once
// The optimizer layer in one include: problems of element energies (structs or lambdas, of fixed
// or run-time arity), the variables of points and simplices, the Newton solver, its options,
// summary and callbacks, the evaluation of E and its derivatives for loops of one's own,
// automatic differentiation and derivative checks.

#include "optim/autodiff_energy.h"
#include "optim/derivative_check.h"
#include "optim/dual.h"
#include "optim/dynamic_element_energy.h"
#include "optim/element_energy.h"
#include "optim/errors.h"
#include "optim/lambda_energy.h"
#include "optim/newton_options.h"
#include "optim/newton_solver.h"
#include "optim/newton_summary.h"
#include "optim/parallel.h"
#include "optim/point_variables.h"
#include "optim/problem.h"
#include "optim/problem_evaluation.h"
#include "optim/progress_printer.h"
#include "optim/ragged_elements.h"
