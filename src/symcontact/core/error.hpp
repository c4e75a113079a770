#pragma once
/// \file error.hpp
/// The two tiers of errors (STYLE.md §7).
///
/// - Internal invariants are checked with SYMCONTACT_ASSERT (debug builds only).
/// - Problems a user can cause (a malformed file, a missing physical group, nu >= 0.5, an inverted
///   element) throw InputError, always on, with the file, the key or entity, and what was expected.
/// - A solve that does not converge throws SolveError; the CLI maps the two to distinct exit codes.
/// - A state at which a function of the unknowns cannot be evaluated (det F ≤ 0) throws
///   EvaluationError: an optimiser catches it and backs away; it is never shown to the user as such.

#include <cassert>
#include <stdexcept>
#include <string>

#define SYMCONTACT_ASSERT(cond) assert(cond)

namespace symcontact {

/// Exit codes of the command-line program. A run stopped by a signal (interrupt.hpp) exits with
/// kExitSignalBase + the signal number: 130 for SIGINT, 143 for SIGTERM (the shell's convention).
enum ExitCode : int {
  kExitOk = 0,
  kExitInputError = 2,
  kExitSolveError = 3,
  kExitInternalError = 4,
  kExitSignalBase = 128
};

/// An error in what the user gave us. what() reads "FILE: KEY: message" (parts that are empty are left out).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string key, const std::string& message);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }
  /// The same error, located in `file` (used when a lower layer did not know the file name).
  InputError in_file(const std::string& file) const;

 private:
  std::string file_, key_, message_;
};

/// A state at which an energy cannot be evaluated (e.g. det F ≤ 0): the optimiser should back away.
/// Thrown by materials and energy terms, caught by the optimisers and the solvers (optim/, solvers/).
class EvaluationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A solve that failed (did not converge, diverged, or met an evaluation failure).
class SolveError : public std::runtime_error {
 public:
  explicit SolveError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace symcontact
