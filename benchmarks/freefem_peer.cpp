#include "freefem_peer.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "elastic_block.hpp"
#include "hertz.hpp"
#include "symcontact/app/run.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/model/problem_reader.hpp"
#include "symcontact/post/contact_results.hpp"

namespace symcontact::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kCandidateX = 0.4;  ///< the peers' contact candidates: arc nodes with x ≤ 0.4

/// ../shared/peers/mesh/hertz_quarter.geo, verbatim (only this comment line differs): the mesh every
/// peer uses. Physical curves 1 = arc (contact), 2 = top (load), 3 = symmetry; surface 10 = body.
constexpr const char* kPeerGeo = R"GEO(// hertz_quarter.geo of ../shared/peers/mesh (written by symcontact-bench --case hertz2d-freefem)
// Quarter model (x >= 0) of the lower half of a disk of radius R centred at (0,R).
// The disk touches the rigid plane y = 0 at the origin.  Plane strain.
// Physical curves: 1 = arc (contact candidate), 2 = top y = R (load), 3 = symmetry x = 0.
// Usage: gmsh -2 -setnumber h 0.01 -format msh22 hertz_quarter.geo -o out.msh
If (!Exists(h))
  h = 0.01;       // element size in the contact zone (|X - O| < rf)
EndIf
R  = 1.0;
rf = 0.25;        // radius of the fine zone around the initial contact point O
Hc = Min(0.1, 10*h);   // far-field size
Point(1) = {0, 0, 0};
Point(2) = {0, R, 0};
Point(3) = {R, R, 0};
Circle(1) = {1, 2, 3};
Line(2) = {3, 2};
Line(3) = {2, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("contact", 1) = {1};
Physical Curve("top", 2) = {2};
Physical Curve("sym", 3) = {3};
Physical Surface("body", 10) = {1};
Field[1] = Distance;
Field[1].NodesList = {1};
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = h;
Field[2].LcMax = Hc;
Field[2].DistMin = rf;
Field[2].DistMax = rf + 0.5;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6;
)GEO";

/// ../shared/peers/freefem/hertz_ipopt.edp, adapted: the mesh is read from -msh (gmshload) instead of
/// being made by calling gmsh; the RESULT line adds the CPU time before IPOPT (mesh read, assembly) and
/// the IPOPT status. Otherwise unchanged: same assembly, constraints, bounds, tol and outputs.
constexpr const char* kPeerEdp = R"EDP(// Hertz quarter model with FreeFEM + ff-Ipopt (written by symcontact-bench --case hertz2d-freefem;
// adapted from ../shared/peers/freefem/hertz_ipopt.edp: reads the mesh instead of calling gmsh).
//   min 0.5 u'Au - F'u  s.t.  u_y(x_i) + y_i >= 0 at arc nodes with x <= 0.4;  u_x = 0 on x = 0.
// Usage: FF_LOADPATH=/usr/lib/freefem++ FreeFem++ -nw hertz_ipopt_msh.edp -msh mesh.msh -out prefix -tol 1e-12
load "gmsh"
load "ff-Ipopt"

string meshfile = "hertz.msh", outp = "ff";
real tol = 1e-12;
for (int i = 0; i < ARGV.n - 1; ++i) {
  if (ARGV[i] == "-msh")  meshfile = ARGV[i+1];
  if (ARGV[i] == "-out")  outp = ARGV[i+1];
  if (ARGV[i] == "-tol")  tol = atof(ARGV[i+1]);
}

real R = 1., E = 1., nu = 0.3;
real Es = E/(1. - nu^2);
real aH = 0.1;
real P  = pi*aH^2*Es/(4.*R);
real p0 = 2.*P/(pi*aH);
real q  = P/(2.*R);
real xcand = 0.4;
real mu = E/(2.*(1. + nu)), lambda = E*nu/((1. + nu)*(1. - 2.*nu));

real tall0 = clock();
mesh Th = gmshload(meshfile);
fespace Vh(Th, [P1, P1]);
int n = Vh.ndof;

macro epsv(u1, u2) [dx(u1), dy(u2), (dy(u1) + dx(u2))/sqrt(2.)] //
macro divv(u1, u2) (dx(u1) + dy(u2)) //
varf va([u1, u2], [v1, v2]) = int2d(Th)(lambda*divv(u1, u2)*divv(v1, v2) + 2.*mu*epsv(u1, u2)'*epsv(v1, v2));
varf vf([u1, u2], [v1, v2]) = int1d(Th, 2)(-q*v2);
varf vw([u1, u2], [v1, v2]) = int1d(Th, 1)(v2);
varf vs([u1, u2], [v1, v2]) = on(3, u1 = 1);
varf vc([u1, u2], [v1, v2]) = on(1, u2 = 1);

matrix A = va(Vh, Vh);
real[int] F = vf(0, Vh);
real[int] w = vw(0, Vh);
real[int] ons = vs(0, Vh);
real[int] onc = vc(0, Vh);
Vh [cx, cy] = [x, y];
Vh [t1, t2] = [1, 2];
assert(abs(t1[][0] - 1) < 1e-12 && abs(t1[][1] - 2) < 1e-12);

real Fy = 0.;
for (int j = 1; j < n; j += 2) Fy += F[j];
real sgn = (Fy < 0) ? 1. : -1.;
F *= sgn;
real[int] b = -F;

real[int] lb(n), ub(n);
lb = -1e19; ub = 1e19;
for (int j = 0; j < n; j += 2) if (ons[j] != 0) { lb[j] = 0.; ub[j] = 0.; }

int m = 0;
for (int j = 1; j < n; j += 2) if (onc[j] != 0 && cx[][j-1] <= xcand + 1e-12) ++m;
int[int] I(m), J(m), cand(m);
real[int] V(m), g(m), xc(m), wc(m);
int k = 0;
for (int j = 1; j < n; j += 2)
  if (onc[j] != 0 && cx[][j-1] <= xcand + 1e-12) {
    I[k] = k; J[k] = j; V[k] = 1.; cand[k] = j;
    xc[k] = cx[][j-1]; g[k] = cx[][j]; wc[k] = w[j]; ++k;
  }
matrix C = [I, J, V];
C.resize(m, n);
real[int] clb(m), cub(m);
clb = 0.; cub = 1e19;
real[int] lm(m);
lm = 0.;
real[int] X(n);
X = 0.;

real tsolve0 = clock();
real tpre = tsolve0 - tall0;
real objv = 0.;
int status = IPOPT([A, b], [C, g], X, lb = lb, ub = ub, clb = clb, cub = cub, lm = lm,
                   tol = tol, printlevel = 5, objvalue = objv);
real tsolve = clock() - tsolve0;

real sumf = 0.;
for (k = 0; k < m; ++k) sumf += abs(lm[k]);
{
  ofstream fo(outp + "_profile.txt");
  fo.precision(12);
  fo << "# x nodal_force weight residual(u_y+gap)" << endl;
  int[int] perm(m);
  real[int] xs = xc;
  for (k = 0; k < m; ++k) perm[k] = k;
  sort(xs, perm);
  for (int kk = 0; kk < m; ++kk) {
    k = perm[kk];
    fo << xc[k] << " " << abs(lm[k]) << " " << wc[k] << " " << X[cand[k]] + g[k] << endl;
  }
}
real tall = clock() - tall0;
cout.precision(10);
cout << "RESULT tool=freefem-ipopt ndof=" << n << " nv=" << Th.nv << " nt=" << Th.nt << " ncand=" << m
     << " status=" << status << " P=" << P << " sumf_x2=" << 2*sumf
     << " t_pre_cpu=" << tpre << " t_ipopt_cpu=" << tsolve << " t_script_cpu=" << tall << endl;
)EDP";

/// Meshes kPeerGeo (written into `work`) at size h through the Gmsh API and writes `msh` (ASCII MSH 2.2,
/// what FreeFEM's gmshload reads and the peers' scripts write with `gmsh -format msh22`).
void write_peer_mesh(const std::string& work, double h, const std::string& msh) {
  const std::string geo = work + "/hertz_quarter.geo";
  if (!std::filesystem::exists(geo)) write_file(geo, kPeerGeo);
  char h_line[64];
  std::snprintf(h_line, sizeof h_line, "h = %.9g;\n", h);
  const std::string wrapper = work + "/hertz_quarter_h.geo";
  write_file(wrapper, std::string(h_line) + "Include \"" + std::filesystem::absolute(geo).string() + "\";\n");
  gmsh::initialize(0, nullptr, false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::open(wrapper);
    gmsh::model::mesh::generate(2);
    gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::write(msh);
  } catch (...) {
    gmsh::finalize();
    throw;
  }
  gmsh::finalize();
}

/// The problem file of the quarter model on `msh` (see the file comment of freefem_peer.hpp).
std::string quarter_problem_toml(const std::string& msh, const PeerHertzReference& ref) {
  std::ostringstream s;
  s << std::setprecision(17);
  s << "# Peers' Hertz quarter model (../shared/peers/README.md, section 2); written by symcontact-bench.\n"
    << "title = \"Hertz 2D quarter model (peers' mesh)\"\n\n"
    << "[problem]\ndimension = 2\nmodel = \"plane_strain\"\norder = 1\n\n"
    << "[[body]]\nname = \"body\"\nmesh = \"" << msh << "\"\ngroup = \"body\"\n"
    << "[body.material]\nE = 1.0\nnu = 0.3\n"
    << "[[body.dirichlet]]\nboundary = \"sym\"\nux = 0.0\n"
    << "[[body.pressure]]\nboundary = \"top\"\npressure = " << ref.q << "\n\n"
    << "[[contact]]\nname = \"floor\"\na = \"body.contact\"\n"
    << "[contact.obstacle]\ntype = \"plane\"\npoint = [0.0, 0.0]\nnormal = [0.0, 1.0]\n";
  return s.str();
}

struct SymcontactQuarter {
  std::unique_ptr<HertzRun> run;
  std::vector<ProfileRow> profile;  ///< arc nodes with x ≤ 0.4
};

/// Builds the model from the problem file on `msh`, solves it as solve_hertz() does (solve_hertz_model():
/// one step, the solver options of contact_options(), p0 and the force), and extracts the
/// profile: reference x, normal force p_k·A_k, lumped area A_k = ∫ φ_k ds, gap.
SymcontactQuarter solve_symcontact(const std::string& work, const std::string& msh_name, double h,
                                   const PeerHertzReference& ref) {
  SymcontactQuarter out;
  out.run = std::make_unique<HertzRun>();
  HertzRun& run = *out.run;
  run.which = HertzCase::kCylinderOnPlane;
  run.h = h;
  run.spec = parse_problem(quarter_problem_toml(msh_name, ref), "hertz_quarter.toml", work);
  solve_hertz_model(run);
  const Model& model = *run.model;

  const std::vector<ContactPairResult> pairs = contact_results(model.contacts(), model.dofs(), run.u, run.report);
  const ContactSideResult& side = pairs.at(0).sides.at(0);
  const ContactSurface& surface = model.contacts().surfaces.at(side.surface);
  for (Index k = 0; k < side.pressure.size(); ++k) {
    if (surface.X(0, k) > kCandidateX + 1e-12) continue;
    ProfileRow r;
    r.x = surface.X(0, k);
    r.weight = surface.nodal_area[k];
    r.force = side.pressure[k] * r.weight;
    r.residual = std::isfinite(side.gap[k]) ? side.gap[k] : std::numeric_limits<double>::infinity();
    out.profile.push_back(r);
  }
  return out;
}

/// `name` itself when it holds a '/', else the first executable `name` on PATH; "" when none.
std::string find_executable(const std::string& name) {
  auto executable = [](const std::string& p) { return access(p.c_str(), X_OK) == 0; };
  if (name.find('/') != std::string::npos) return executable(name) ? name : std::string();
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && executable(dir + "/" + name)) return dir + "/" + name;
  return {};
}

/// FF_LOADPATH for the FreeFEM runs: the caller's, or /usr/lib/freefem++ (Debian 12's
/// /etc/freefem++.pref points to a folder that does not exist; peers README, section 1).
std::string freefem_load_path() {
  const char* v = std::getenv("FF_LOADPATH");
  return v && *v ? std::string(v) : std::string("/usr/lib/freefem++");
}

/// Why FreeFEM cannot be run here, or "" when it can (the executable and ff-Ipopt are found).
std::string freefem_missing(const std::string& exe, const std::string& freefem_name) {
  if (exe.empty())
    return "'" + freefem_name + "' not found (Debian: apt-get install freefem++ libfreefem++, or "
           "scripts/install-deps --peers)";
  const std::string load_path = freefem_load_path();
  std::istringstream dirs(load_path);
  std::string dir;
  while (std::getline(dirs, dir, ';')) {
    std::istringstream sub(dir);
    std::string d;
    while (sub >> d)
      if (std::filesystem::exists(d + "/ff-Ipopt.so")) return {};
  }
  return "the ff-Ipopt plugin is not in FF_LOADPATH=" + load_path +
         " (Debian: apt-get install libfreefem++, which ships /usr/lib/freefem++/ff-Ipopt.so)";
}

struct ChildRun {
  int exit_code = -1;       ///< exit status, or 128 + signal
  double wall = 0.0;        ///< s, fork to wait
  double cpu = 0.0;         ///< user + system of the child, s
  double max_rss_mib = 0.0; ///< of the child (ru_maxrss)
};

/// Runs argv in `dir` with stdout and stderr to `log` and FF_LOADPATH set; waits for it.
ChildRun run_child(const std::vector<std::string>& argv, const std::string& dir, const std::string& log) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string load_path = freefem_load_path();
  std::cout << std::flush;
  const double t0 = wall_seconds();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || chdir(dir.c_str()) != 0) _exit(126);
    dup2(fd, 1);
    dup2(fd, 2);
    close(fd);
    setenv("FF_LOADPATH", load_path.c_str(), 1);
    execv(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) < 0) throw std::runtime_error("wait4 failed");
  ChildRun r;
  r.wall = wall_seconds() - t0;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.max_rss_mib = static_cast<double>(ru.ru_maxrss) / 1024.0;
  return r;
}

struct FreefemRun {
  bool ok = false;
  std::string failure;             ///< why not ok
  std::map<std::string, std::string> result;  ///< key=value of the RESULT line
  int ipopt_iterations = -1;
  std::string ipopt_exit;          ///< IPOPT's "EXIT: ..." message
  ChildRun process;
  std::vector<ProfileRow> profile;
  double get(const std::string& key) const {
    const auto it = result.find(key);
    return it == result.end() ? kNaN : std::strtod(it->second.c_str(), nullptr);
  }
};

/// The last `lines` lines of `text` (all of it when shorter).
std::string tail(const std::string& text, int lines) {
  std::size_t at = text.size();
  for (int k = 0; k <= lines; ++k) {
    if (at == 0) return text;
    at = text.rfind('\n', at - 1);
    if (at == std::string::npos) return text;
  }
  return text.substr(at + 1);
}

FreefemRun run_freefem(const std::string& exe, const std::string& work, const std::string& msh_name,
                       const std::string& prefix, double tol) {
  FreefemRun ff;
  const std::string edp = "hertz_ipopt_msh.edp";
  if (!std::filesystem::exists(work + "/" + edp)) write_file(work + "/" + edp, kPeerEdp);
  char tol_text[32];
  std::snprintf(tol_text, sizeof tol_text, "%.3g", tol);
  const std::string log = work + "/" + prefix + "_log.txt";
  ff.process = run_child({exe, "-nw", edp, "-msh", msh_name, "-out", prefix, "-tol", tol_text}, work, log);
  const std::string text = read_file(log);
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("RESULT ", 0) == 0) {
      std::istringstream tokens(line.substr(7));
      std::string kv;
      while (tokens >> kv) {
        const auto eq = kv.find('=');
        if (eq != std::string::npos) ff.result[kv.substr(0, eq)] = kv.substr(eq + 1);
      }
    } else if (line.rfind("Number of Iterations....:", 0) == 0) {
      ff.ipopt_iterations = std::atoi(line.substr(25).c_str());
    } else if (line.rfind("EXIT:", 0) == 0) {
      ff.ipopt_exit = line.substr(6);
    }
  }
  if (ff.process.exit_code != 0 || ff.result.empty()) {
    ff.failure = "FreeFem++ exited with " + std::to_string(ff.process.exit_code) +
                 (ff.result.empty() ? " and no RESULT line" : "") + "; end of its log (" + log +
                 ", kept with --keep-work):\n" + (text.empty() ? std::string("(empty)\n") : tail(text, 12));
    return ff;
  }
  std::ifstream in(work + "/" + prefix + "_profile.txt");
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream v(line);
    ProfileRow r;
    if (v >> r.x >> r.force >> r.weight >> r.residual) ff.profile.push_back(r);
  }
  if (ff.profile.empty()) {
    ff.failure = "no profile written by FreeFEM (" + work + "/" + prefix + "_profile.txt)";
    return ff;
  }
  ff.ok = true;
  return ff;
}

using Kind = ResultTable::Kind;

std::vector<ResultTable::Column> columns() {
  return {
      {"h", "h", Kind::kFixed, 6},
      {"nodes", "", Kind::kInteger, 0},
      {"dofs", "DOFs", Kind::kInteger, 0},
      {"meshing_s", "", Kind::kFixed, 3},
      // symcontact
      {"sym_constraints", "constr.", Kind::kInteger, 0},
      {"sym_geometry_iterations", "geom it", Kind::kInteger, 0},
      {"sym_ipopt_iterations", "IPOPT it", Kind::kInteger, 0},
      {"sym_read_setup_s", "", Kind::kFixed, 3},
      {"sym_optimizer_s", "", Kind::kFixed, 3},
      {"sym_polish_s", "", Kind::kFixed, 3},
      {"sym_contact_s", "", Kind::kFixed, 3},
      {"sym_phases", "", Kind::kText, 0},  // every phase of the solve report, "name=s;..."
      {"sym_solve_wall_s", "sym [s]", Kind::kFixed, 3},
      {"sym_solve_cpu_s", "sym CPU [s]", Kind::kFixed, 3},
      {"sym_total_wall_s", "", Kind::kFixed, 3},
      {"sym_peak_rss_mib", "", Kind::kInteger, 0},
      {"sym_ipopt_status", "", Kind::kText, 0},
      // floor
      {"floor_s", "floor [s]", Kind::kFixed, 3},
      {"floor_cpu_s", "floor CPU [s]", Kind::kFixed, 3},
      {"floor_analyze_s", "", Kind::kFixed, 3},
      {"floor_factorize_s", "", Kind::kFixed, 3},
      {"floor_solve_s", "", Kind::kFixed, 3},
      {"floor_relative_residual", "", Kind::kScientific, 1},
      // FreeFEM
      {"ff_dofs", "", Kind::kInteger, 0},
      {"ff_candidates", "FF cand.", Kind::kInteger, 0},
      {"ff_ipopt_iterations", "FF it", Kind::kInteger, 0},
      {"ff_pre_cpu_s", "", Kind::kFixed, 3},
      {"ff_ipopt_cpu_s", "FF IPOPT [s]", Kind::kFixed, 3},
      {"ff_script_cpu_s", "", Kind::kFixed, 3},
      {"ff_process_cpu_s", "", Kind::kFixed, 3},
      {"ff_wall_s", "FF wall [s]", Kind::kFixed, 3},
      {"ff_max_rss_mib", "", Kind::kInteger, 0},
      {"ff_ipopt_exit", "", Kind::kText, 0},
      // ratios
      {"sym_over_ff", "sym/FF", Kind::kFixed, 2},
      {"sym_over_ff_whole", "", Kind::kFixed, 2},
      {"sym_over_floor", "sym/floor", Kind::kFixed, 1},
      {"ff_over_floor", "FF/floor", Kind::kFixed, 1},
      // accuracy (same post-processing)
      {"sym_a_last", "sym a_last", Kind::kFixed, 5},
      {"sym_a_next", "", Kind::kFixed, 5},
      {"sym_a_fit_error_pct", "sym a_fit err [%]", Kind::kFixed, 2},
      {"sym_p_max", "", Kind::kScientific, 6},
      {"sym_p_max_error_pct", "sym p_max err [%]", Kind::kFixed, 2},
      {"sym_p0_fit", "", Kind::kScientific, 6},
      {"sym_force_error", "", Kind::kScientific, 1},
      {"sym_active", "", Kind::kInteger, 0},
      {"ff_a_last", "FF a_last", Kind::kFixed, 5},
      {"ff_a_next", "", Kind::kFixed, 5},
      {"ff_a_fit_error_pct", "FF a_fit err [%]", Kind::kFixed, 2},
      {"ff_p_max", "", Kind::kScientific, 6},
      {"ff_p_max_error_pct", "FF p_max err [%]", Kind::kFixed, 2},
      {"ff_p0_fit", "", Kind::kScientific, 6},
      {"ff_force_error", "", Kind::kScientific, 1},
      {"ff_active", "", Kind::kInteger, 0},
      {"repeat", "", Kind::kInteger, 0},
      {"openblas_threads", "", Kind::kInteger, 0},
  };
}

}  // namespace

PeerHertzReference peer_hertz_reference() {
  constexpr double E = 1.0, nu = 0.3, R = 1.0;
  PeerHertzReference r;
  r.e_star = E / (1 - nu * nu);
  r.a = 0.1;
  r.load = M_PI * r.a * r.a * r.e_star / (4 * R);
  r.q = r.load / (2 * R);
  r.p0 = 2 * r.load / (M_PI * r.a);
  return r;
}

ProfileMetrics analyse_profile(std::vector<ProfileRow> rows, const PeerHertzReference& ref) {
  ProfileMetrics m;
  m.a_last = m.a_next = m.a_fit = m.p0_fit = m.p_max = kNaN;
  std::sort(rows.begin(), rows.end(), [](const ProfileRow& a, const ProfileRow& b) { return a.x < b.x; });
  double f_max = 0.0, sum = 0.0;
  for (const auto& r : rows) {
    f_max = std::max(f_max, r.force);
    sum += r.force;
  }
  m.sum_force_x2 = 2 * sum;
  if (f_max <= 0) return m;
  const double g_ref = ref.a * ref.a / 2.0;  // a² / (2R), R = 1
  std::vector<bool> active(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const ProfileRow& r = rows[k];
    active[k] = r.force > 1e-8 * f_max && r.force / f_max > r.residual / g_ref;
    if (!active[k]) continue;
    ++m.active;
    m.a_last = std::isnan(m.a_last) ? r.x : std::max(m.a_last, r.x);
    const double p = r.force / r.weight;
    m.p_max = std::isnan(m.p_max) ? p : std::max(m.p_max, p);
  }
  if (m.active == 0) return m;
  for (const auto& r : rows)
    if (r.x > m.a_last + 1e-14) {
      m.a_next = r.x;
      break;
    }
  // Least squares p² = c0 + c1 x² over the active nodes left of a_last.
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (!active[k] || rows[k].x >= m.a_last - 1e-14) continue;
    const double X = rows[k].x * rows[k].x, p = rows[k].force / rows[k].weight, Y = p * p;
    n += 1;
    sx += X;
    sy += Y;
    sxx += X * X;
    sxy += X * Y;
  }
  if (n >= 3) {
    const double c1 = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    const double c0 = (sy - c1 * sx) / n;
    if (c0 > 0 && c1 < 0) {
      m.a_fit = std::sqrt(-c0 / c1);
      m.p0_fit = std::sqrt(c0);
    }
  }
  return m;
}

std::vector<double> default_freefem_sizes() { return {0.005, 0.0025, 0.00125}; }

void run_freefem_sweep(const FreefemPeerOptions& opt, const MachineInfo& machine) {
  const PeerHertzReference ref = peer_hertz_reference();
  const std::string name = "hertz2d-freefem";
  std::cout << "\n## " << name << ": the peers' Hertz quarter model (../shared/peers, hertz_quarter.geo), "
            << "symcontact and FreeFEM + ff-Ipopt on the same .msh; P = " << std::setprecision(10) << ref.load
            << ", closed form a = " << ref.a << ", p0 = " << ref.p0 << std::setprecision(6)
            << "; floor phases min of " << opt.repeat << " run(s), solves once\n";
  std::cout << "# sym = solve_contact() (mortar, whole arc; geometry fixed point, IPOPT, polish); FF IPOPT = CPU"
               " clock() around IPOPT() in FreeFEM (nodal, arc x <= 0.4, tol "
            << opt.freefem_tol << ");\n# FF wall = the whole FreeFem++ process (start-up, gmshload, assembly,"
                                  " IPOPT, output); floor = CHOLMOD analyze + factorize + solve of K_ff;\n"
            << "# sym/FF = sym CPU / FF IPOPT CPU; sym/floor = sym CPU / floor CPU; FF/floor = FF IPOPT CPU /"
               " floor CPU;\n# accuracy: the peers' postproc.py on both profiles (arc nodes x <= 0.4): a_last, a_fit,"
               " p_max against a = 0.1, p0\n";

  const std::string exe = opt.skip_freefem ? std::string() : find_executable(opt.freefem);
  std::string missing = opt.skip_freefem ? "--skip-freefem given" : freefem_missing(exe, opt.freefem);
  if (!missing.empty())
    std::cout << "# FreeFEM + ff-Ipopt: SKIPPED (" << missing
              << "); symcontact and the floor only, FreeFEM columns '-'\n";
  else
    std::cout << "# FreeFEM: " << exe << ", FF_LOADPATH=" << freefem_load_path() << "\n";
  std::cout << "\n";

  ResultTable table(columns(), std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);

  const std::string work = make_work_dir();
  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  for (const double h : opt.h) {
    char stem[64];
    std::snprintf(stem, sizeof stem, "hertz_quarter_h%.6g", h);
    const std::string msh_name = std::string(stem) + ".msh";
    const double t_mesh = wall_seconds();
    write_peer_mesh(work, h, work + "/" + msh_name);
    const double meshing = wall_seconds() - t_mesh;

    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    SymcontactQuarter sym = solve_symcontact(work, msh_name, h, ref);
    const HertzRun& run = *sym.run;
    const double peak_sym = peak_rss_mib();
    const ProfileMetrics ms = analyse_profile(sym.profile, ref);

    Index floor_free = 0;
    int pinned = 0;
    const CholeskyFloor floor = measure_hertz_floor(run, opt.repeat, floor_free, pinned);

    FreefemRun ff;
    ProfileMetrics mf;
    mf.a_last = mf.a_next = mf.a_fit = mf.p0_fit = mf.p_max = mf.sum_force_x2 = kNaN;
    if (missing.empty()) {
      try {
        ff = run_freefem(exe, work, msh_name, stem, opt.freefem_tol);
      } catch (const std::exception& e) {  // fork/wait/log reading: report, do not stop the sweep
        ff = FreefemRun();
        ff.failure = e.what();
      }
      if (ff.ok) {
        mf = analyse_profile(ff.profile, ref);
        const double ff_dofs = ff.get("ndof");
        if (ff_dofs != static_cast<double>(run.model->dofs().num_dofs()))
          std::cout << "# warning: FreeFEM has " << ff_dofs << " DOFs, symcontact "
                    << run.model->dofs().num_dofs() << " on the same mesh\n";
      } else {
        std::cout << "# FreeFEM run at h = " << h << " failed: " << ff.failure << "\n";
      }
    }

    Index nodes = run.model->bodies().at(0)->mesh.num_nodes();
    const PhaseTimes& t = run.report.times;
    std::ostringstream phase_list;
    for (const auto& [phase, seconds] : t.entries())
      phase_list << (phase_list.tellp() > 0 ? ";" : "") << phase << "=" << seconds;
    const std::string phases = phase_list.str();
    const double read_setup = run.build_times.get("meshing") + run.build_times.get("setup");
    const double ff_ipopt = ff.ok ? ff.get("t_ipopt_cpu") : kNaN;
    const double ff_wall = ff.ok ? ff.process.wall : kNaN;
    auto pct = [](double v, double ref_v) { return 100 * (v / ref_v - 1); };
    table.add_row({h, static_cast<double>(nodes), static_cast<double>(run.model->dofs().num_dofs()), meshing,
                   static_cast<double>(run.report.num_constraints),
                   static_cast<double>(run.report.geometry_iterations),
                   static_cast<double>(run.report.ipopt_iterations), read_setup, t.get("optimizer"),
                   t.get("polish"), run.contact_seconds(), phases, run.solve_wall, run.solve_cpu,
                   read_setup + run.solve_wall, peak_sym, run.report.ipopt_status, floor.factor_and_solve(),
                   floor.cpu_factor_and_solve, floor.analyze, floor.factorize, floor.solve,
                   floor.relative_residual, ff.ok ? ff.get("ndof") : kNaN, ff.ok ? ff.get("ncand") : kNaN,
                   ff.ok ? static_cast<double>(ff.ipopt_iterations) : kNaN, ff.ok ? ff.get("t_pre_cpu") : kNaN,
                   ff_ipopt, ff.ok ? ff.get("t_script_cpu") : kNaN, ff.ok ? ff.process.cpu : kNaN, ff_wall,
                   ff.ok ? ff.process.max_rss_mib : kNaN, ff.ok ? "\"" + ff.ipopt_exit + "\"" : std::string("-"),
                   run.solve_cpu / ff_ipopt, (read_setup + run.solve_wall) / ff_wall,
                   run.solve_cpu / floor.cpu_factor_and_solve, ff_ipopt / floor.cpu_factor_and_solve, ms.a_last,
                   ms.a_next, pct(ms.a_fit, ref.a), ms.p_max, pct(ms.p_max, ref.p0), ms.p0_fit,
                   std::abs(2 * run.force / ref.load - 1), static_cast<double>(ms.active), mf.a_last, mf.a_next,
                   pct(mf.a_fit, ref.a), mf.p_max, pct(mf.p_max, ref.p0), mf.p0_fit,
                   std::abs(mf.sum_force_x2 / ref.load - 1), ff.ok ? static_cast<double>(mf.active) : kNaN,
                   static_cast<double>(opt.repeat), static_cast<double>(machine.openblas_threads)});
  }
  finish_sweep(name, t_sweep, rss_reset_ok, "reading + setup + the symcontact solve", work, opt.keep_work);
}

}  // namespace symcontact::bench
