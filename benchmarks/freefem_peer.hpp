#pragma once
/// \file freefem_peer.hpp
/// symcontact side by side with FreeFEM + ff-Ipopt on the same 2D Hertz mesh
/// (`symcontact-bench --case hertz2d-freefem`).
///
/// The problem is the peers' benchmark (../shared/peers/README.md, section 2), not our example: the
/// quarter model x ≥ 0 of the lower half of a disk R = 1 centred at (0, 1) on the rigid plane y = 0,
/// E = 1, ν = 0.3, plane strain, P1, symmetry u_x = 0 on x = 0, a uniform traction (0, −q) on the flat
/// top y = 1 with q = P/(2R) and P = π a² E*/(4R) chosen so that the closed-form half-width is a = 0.1
/// exactly (p0 = E* a/(2R) = 0.0549450550).
///
/// Per fine size h, in one process and one after the other:
///  1. the peers' geometry (hertz_quarter.geo, kept verbatim in freefem_peer.cpp) is meshed through the
///     Gmsh API at size h and written as an ASCII MSH 2.2 file into the work directory;
///  2. symcontact reads that .msh through a problem file written next to it (body "body", Dirichlet
///     u_x = 0 on "sym", pressure q on "top", contact "body.contact" against the plane y = 0; solver
///     options from contact_options(), as `symcontact run` makes them) and solves it (`solve_contact`:
///     mortar constraints on the whole arc, geometry fixed point, IPOPT, polish);
///  3. the Cholesky floor of the same stiffness (measure_hertz_floor(), as in the Hertz sweep);
///  4. `FreeFem++ -nw` runs a script written by the bench (the peers' hertz_ipopt.edp with gmshload of
///     the same .msh instead of calling gmsh: nodal constraints u_y + y ≥ 0 on arc nodes with x ≤ 0.4,
///     IPOPT tol 1e-12) and prints one RESULT line (IPOPT CPU time, whole-script CPU time, DOFs, ...)
///     and a profile file (x, nodal force, lumped weight, residual).
/// Both profiles go through the same post-processing (the peers' postproc.py, analyse_profile()).
/// Where FreeFEM or its ff-Ipopt plugin is missing, step 4 is skipped with a message and the FreeFEM
/// columns are left empty ("-"); the benchmark does not fail.

#include <string>
#include <vector>

#include "bench_support.hpp"

namespace symcontact::bench {

/// The closed form of the peers' quarter model (see the file comment).
struct PeerHertzReference {
  double e_star = 0.0;  ///< E / (1 − ν²)
  double a = 0.1;       ///< half-width (by the choice of P)
  double load = 0.0;    ///< P, on the full half-disk (the quarter carries P/2)
  double q = 0.0;       ///< traction on the top face, P / (2R)
  double p0 = 0.0;      ///< peak pressure 2P / (π a)
};
PeerHertzReference peer_hertz_reference();

/// One row of a contact profile: a candidate node on the arc.
struct ProfileRow {
  double x = 0.0;         ///< reference abscissa
  double force = 0.0;     ///< nodal normal contact force (≥ 0)
  double weight = 0.0;    ///< lumped weight ∫ φ_i ds
  double residual = 0.0;  ///< u_y + gap (nodal) or the node's gap to the plane (symcontact)
};

/// The peers' common metrics (postproc.py, analyse()):
///   p_i = f_i / w_i; active: f_i > 1e-8 max f and f_i / max f > r_i / g_ref, g_ref = a²/(2R);
///   a_last = largest x of an active node, a_next = the next candidate's x;
///   a_fit = zero of the least-squares line p² = c0 + c1 x² over the active nodes but the outermost one;
///   p_max = max p_i over the active nodes; sum_force_x2 = 2 Σ f_i (P expected).
struct ProfileMetrics {
  double a_last = 0.0, a_next = 0.0, a_fit = 0.0, p0_fit = 0.0, p_max = 0.0, sum_force_x2 = 0.0;
  int active = 0;
};
/// NaN fields where undefined (no active node, fewer than 3 nodes for the fit).
ProfileMetrics analyse_profile(std::vector<ProfileRow> rows, const PeerHertzReference& ref);

struct FreefemPeerOptions {
  std::vector<double> h;        ///< fine mesh sizes of hertz_quarter.geo, one row each
  int repeat = 1;               ///< floor phases: minimum over this many runs (the solves run once)
  std::string freefem = "FreeFem++";  ///< the FreeFEM executable (looked up on PATH when not a path)
  double freefem_tol = 1e-12;   ///< IPOPT tol of the FreeFEM run (the peers' value)
  bool skip_freefem = false;    ///< run symcontact and the floor only
  std::string csv;
  bool markdown = false;
  bool keep_work = false;       ///< keep the .msh, .toml, .edp, logs and profiles
};

/// h = 0.005, 0.0025, 0.00125: 7.3k, 28k, 112k DOFs (the peers' sizes; 0.000625 gives 446k DOFs and
/// takes minutes: give it with --h).
std::vector<double> default_freefem_sizes();

/// Runs the sweep, printing the table as rows finish. Throws what the symcontact solve throws; a
/// failing FreeFEM run is reported (with the end of its log) and leaves its columns empty.
void run_freefem_sweep(const FreefemPeerOptions& opt, const MachineInfo& machine);

}  // namespace symcontact::bench
