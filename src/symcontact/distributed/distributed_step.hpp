#pragma once
/// \file distributed_step.hpp
/// The contact solver of `symcontact run` on the distributed path (`mpirun -np N symcontact run CASE.toml`):
/// a load step of a model with linear-elastic bodies in contact with rigid obstacles, with each other
/// or with themselves, frictionless or with friction (hyperelastic bodies: frictionless), solved by the interior
/// point of contact_interior_point.hpp on the same constraints and friction terms as the serial solver, so
/// that both give the same answer to their tolerances.
///
/// Each step is a geometry fixed point, as the serial one (solvers/geometry_fixed_point.hpp): the contact
/// set is linearised at u (ContactSet::linearize: the weak gap rows A u + b ≥ 0 of every pair), the program
/// min ½ uᵀKu − fᵀu + j(u) subject to those rows solved, and the linearisation taken again at the answer,
/// until ‖u_{k+1} − u_k‖∞ ≤ geometry_tolerance ‖u_{k+1}‖∞, or the rows come out the same, or (frictionless)
/// the answer already solves the new rows' program to the interior point's tolerance (a plane obstacle: one
/// solve); not after a solve whose interior point took a force scale far above its answer's forces (a stiff
/// body moved by fixed values: the next solves take the answer's, answer_force_scale in the .cpp). Without
/// rows the stiffness system alone is solved. Row j is passed divided by its support
/// Σ w φ_j (a gap in length units, its force in force units: the interior point's scales); its multiplier
/// is then μ_j = λ_j / support_j, the serial solver's. The contact forces are recovered as the serial solver
/// does (solvers/contact_forces.hpp).
///
/// Friction: j is the sum of the serial friction terms of the step's thresholds (solvers/friction_state.hpp:
/// one point per slave node, its slip the node's against the opposite surface at its projection or against
/// the obstacle, on 6-node triangles in the modified test basis), handed to the interior point as its friction
/// at the rows of the same nodes, each with the term's relative-displacement map (NodalConstraints::slip_map);
/// Coulomb is the serial Coulomb fixed point (lagged_fixed_point.hpp with CoulombThresholds) around the
/// geometry fixed point, each solve starting from the current displacement, the thresholds following the
/// interior point's iterates where coulomb_update says so (FollowBounds).
///
/// A hyperelastic energy enters each geometry iteration as its second-order model at the current u, so that
/// the fixed point is also the step's Newton iteration; where that model's program does not solve (a Hessian
/// that is not positive definite), its Hessian is shifted by δ diag K (Levenberg–Marquardt), and only an
/// unshifted step ends the step.
/// What the path does not solve yet is an input error before any work (check_distributed_support): friction
/// with a hyperelastic body. A symmetric pair is solved, with or without friction, the interior point's polish
/// settling its two nearly dependent families of rows; where a solve with such a pair fails, the message
/// advises one-pass mode (symmetric_pair_hint in the .cpp).
/// The meshes are whole on every rank; each rank assembles the stiffness rows it owns, the nodes numbered for
/// PETSc by NodeOrdering (node_ordering.hpp) and back to the model's numbering for everything else.
#include "symcontact/app/run.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"

namespace symcontact {

/// Throws InputError naming the key of the first thing in `spec` the distributed path does not solve.
void check_distributed_support(const ProblemSpec& spec);

/// The step solver for run_problem(): the geometry fixed point above with the problem's geometry_tolerance
/// and max_geometry_iterations ([contact_solver]), each solve with `options`. Collective: every rank runs
/// the same steps. Logs a line per geometry iteration (at the default level once a step has run 5 s).
StepSolver distributed_step_solver(const ProblemSpec& spec, const ContactInteriorPointOptions& options,
                                   const Logger& log);

}  // namespace symcontact
