#pragma once
/// \file ordering_seed.hpp
/// The random sequence of the fill-reducing ordering that MUMPS uses inside IPOPT.
///
/// IPOPT factorises its KKT systems with MUMPS, and MUMPS, left to choose (mumps_pivot_order = 7), orders a
/// symmetric system of more than 1e4 rows by SCOTCH's nested dissection (Debian's MUMPS has SCOTCH, not
/// METIS). SCOTCH shares its work among threads in an order that changes from run to run, and draws its
/// random choices from one generator for the whole process, each analysis continuing the sequence of the one
/// before: the same problem solved twice, or after other solves, got another ordering and other digits (on
/// the 3D clamped plates of docs/performance.md at 1e4 DOFs with Coulomb friction: 1e-8 apart, and another
/// count of Coulomb iterations). The approximate minimum fill ordering, MUMPS's choice below 1e4 rows, has
/// neither but took 1.4 times the optimiser's time of those plates at 2.2e4 DOFs.

namespace symcontact {

/// SCOTCH on one thread (SCOTCH_PTHREAD_NUMBER = 1), its random sequence restarted from a fixed seed: every
/// IPOPT solve calls it first, so that its orderings depend on its own problem only.
void restart_ordering_sequence();

}  // namespace symcontact
