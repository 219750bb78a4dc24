#pragma once
// The optimizer layer in one include: problems of element energies, the Newton solver, its
// options, summary and callbacks, automatic differentiation and derivative checks.

#include "optim/autodiff_energy.h"
#include "optim/derivative_check.h"
#include "optim/dual.h"
#include "optim/element_energy.h"
#include "optim/errors.h"
#include "optim/newton_options.h"
#include "optim/newton_solver.h"
#include "optim/newton_summary.h"
#include "optim/parallel.h"
#include "optim/problem.h"
#include "optim/progress_printer.h"
