#pragma once
/// \file polish_strategy.hpp
/// Which polish closes each geometry iteration of a contact solve (active_set_polish.hpp).
///
/// An interior point leaves every active constraint open by about μ_barrier / μ_i; with the nearly dependent
/// families of the symmetric formulation some μ_i are small and the interface stays open far beyond the
/// optimiser's tolerance. The polish removes that offset:
///  - closing: the active set S solved as equalities (A_S x + b_S = 0), a KKT point of the inequality problem
///    or rejected; the dual does it in its own form (dual_subproblem.hpp), the primal after IPOPT;
///  - force balance: the active rows held at the values the optimiser left; it removes the stationarity error
///    only, and is always consistent.
/// Closing is tried first and given up, for the rest of the solve, when
///  - it is rejected (the two families of a curved symmetric pair cannot all be closed at once);
///  - with a non-quadratic energy (friction), it was rejected in the previous solve of the run
///    (ContactWorkspace::closing_polish_rejected; for a non-quadratic energy the set does not grow, and the
///    rejection repeats);
///  - the fixed point stalls with the set closed: closed exactly, the map can have a growing mode that the
///    barrier offset of the force-balancing variant damps (the V7 3D self-contact). Without acceleration:
///    once the change has grown twice in a row; with it (the change is not monotone): once the change has made
///    no new low in memory + 2 closed iterations.
/// With a non-quadratic energy and closing given up, the force balance moves the iterate by no more than the
/// optimiser's tolerance, far below the geometry tolerance: it is applied once, to the iterate that ends the
/// fixed point (balance_at_end), and not to an inexact solve's (an intermediate of the Coulomb iteration).
/// So it is after a closing with linear-elastic bodies and friction terms: a closing by the method of
/// multipliers (rows that the direct solve leaves unclosed), its ρ scaled by the friction term's curvature
/// τA/α, leaves up to 1e-7 of the forces unbalanced where nodes stick, and the force balance, holding the
/// closed values, removes that error (a direct solve). Not with
/// finite-strain bodies: there each solve's last iterate steers the load path, and that extra Newton solve
/// moved a hard step of the frictional ironing test (its geometry fixed point then cycles at a change of 3e-2).

/// The bodies' energy E (without the friction terms).
enum class BodiesEnergy { kQuadratic, kNonQuadratic };

#include <limits>
#include <vector>

#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/optim/constrained_problem.hpp"

namespace symcontact {

struct ContactWorkspace;
struct IpoptResult;

class PolishStrategy {
 public:
  /// `enabled` false: no polish at all. `acceleration_memory`: of the Anderson acceleration of the fixed
  /// point, 0 when it is not accelerated.
  PolishStrategy(bool enabled, ContactWorkspace& workspace, int acceleration_memory,
                 BodiesEnergy bodies = BodiesEnergy::kNonQuadratic);

  /// Whether the next subproblem should be closed exactly.
  bool closes() const { return enabled_ && closing_works_; }
  /// The closing (done by the subproblem method itself) was not applied: `reason` logged, closing given up.
  void closing_rejected(const std::string& reason, const Logger& log);

  /// After a primal optimiser solve: polishes res.x and res.multipliers (in target's variables) unless the
  /// force balance is deferred to the end of the fixed point. Returns whether the set was closed exactly.
  bool polish_primal(ConstrainedProblem& target, IpoptResult& res, const Logger& log, PhaseTimes& times);
  /// The last polish_primal() deferred the force balance to the iterate that ends the fixed point.
  bool balance_deferred() const { return balance_at_end_; }
  /// That deferred force balance, of xt (target's variables) with the multipliers mu.
  void balance(ConstrainedProblem& target, VectorXd& xt, VectorXd& mu, const Logger& log, PhaseTimes& times) const;
  /// The subproblem's method closed the set itself, or handed back its dual's point: no polish of this
  /// iteration, nothing deferred.
  void closed_by_method() { balance_at_end_ = false; }

  /// The geometry change of an iteration (`history`: the changes before it), and whether its set was
  /// closed exactly: gives closing up when the fixed point stalls with the set closed.
  void record_change(double change, bool closed, const std::vector<double>& history, const Logger& log);

 private:
  bool enabled_;
  ContactWorkspace& workspace_;
  int acceleration_memory_;
  BodiesEnergy bodies_;
  bool closing_works_ = true;
  bool balance_at_end_ = false;
  double best_closed_change_ = std::numeric_limits<double>::infinity();  ///< smallest change with the set closed
  int closed_since_best_ = 0;  ///< closed iterations since that smallest change
};

}  // namespace symcontact
