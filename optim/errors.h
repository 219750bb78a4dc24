#pragma once
// Typed exceptions for bad input and for problems diagnosed as having no solution before any
// optimization. Numerical outcomes (no convergence, a failed line search, a factorization that
// does not succeed) are never exceptions: they are reported in summaries.

#include <stdexcept>
#include <string>

namespace sa {

/// Base of every exception the library throws on purpose.
class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A caller passed something invalid: an index out of range, an inconsistent size, an option
/// outside its range. The message names the argument, element or field and its value.
class InvalidArgumentError : public Error {
  public:
    using Error::Error;
};

/// An input file or mesh is malformed. The message names the file and, where known, the line or
/// the element.
class InputError : public Error {
  public:
    using Error::Error;
};

/// The problem, as posed, has no solution (or none within the bound asked for), found before any
/// optimization: handles that contradict each other, labels that force more distortion than the
/// bound. The message names the source and the reason. The `sa` command exits 1 on it, as for a
/// result that is not verified, and writes nothing.
class NoSolutionError : public Error {
  public:
    using Error::Error;
};

}  // namespace sa
