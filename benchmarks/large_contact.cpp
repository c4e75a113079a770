#include "large_contact.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "elastic_block.hpp"
#include "problem_run.hpp"
#include "symcontact/core/error.hpp"

namespace symcontact::bench {

namespace {

using Kind = ResultTable::Kind;

constexpr double kMu = 0.3;

/// The pad [−½, ½]^(dim−1) × [0, ¼], vertical axis last: groups "solid", "bottom", "top".
std::string pad_geo(int dim) {
  if (dim == 2)
    return "Point(1) = {-0.5, 0, 0}; Point(2) = {0.5, 0, 0}; Point(3) = {0.5, 0.25, 0}; Point(4) = {-0.5, 0.25, 0};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
           "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
           "Physical Surface(\"solid\") = {1};\nPhysical Curve(\"bottom\") = {1};\nPhysical Curve(\"top\") = {3};\n";
  return "Point(1) = {-0.5, -0.5, 0}; Point(2) = {0.5, -0.5, 0}; Point(3) = {0.5, 0.5, 0}; Point(4) = {-0.5, 0.5, 0};\n"
         "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
         "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
         "e[] = Extrude {0, 0, 0.25} { Surface{1}; };\n"
         "Physical Volume(\"solid\") = {e[1]};\nPhysical Surface(\"bottom\") = {1};\n"
         "Physical Surface(\"top\") = {e[0]};\n";
}

/// A plate of thickness 0.2 from the vertical coordinate z0 up, with the hole r < 0.1 and the washer annulus
/// 0.1 ≤ r ≤ 0.2 on both faces (3D: [−½, ½]² less the hole; 2D: the section x ∈ [0.1, 0.5]): groups
/// "solid", "bottom", "top", "washer_bottom", "washer_top".
std::string plate_geo(int dim, double z0) {
  std::ostringstream g;
  g << "z0 = " << z0 << "; t = 0.2; rh = 0.1; rw = 0.2;\n";
  if (dim == 2) {
    g << "Point(1) = {rh, z0, 0}; Point(2) = {rw, z0, 0}; Point(3) = {0.5, z0, 0};\n"
         "Point(4) = {0.5, z0 + t, 0}; Point(5) = {rw, z0 + t, 0}; Point(6) = {rh, z0 + t, 0};\n"
         "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};\n"
         "Curve Loop(1) = {1, 2, 3, 4, 5, 6};\nPlane Surface(1) = {1};\n"
         "Physical Surface(\"solid\") = {1};\nPhysical Curve(\"bottom\") = {1, 2};\nPhysical Curve(\"top\") = {4, 5};\n"
         "Physical Curve(\"washer_bottom\") = {1};\nPhysical Curve(\"washer_top\") = {5};\n";
    return g.str();
  }
  g << "Point(1) = {0, 0, z0};\n"
       "For k In {0:1}\n"
       "  r = (k == 0) ? rh : rw;\n"
       "  Point(2 + 4*k) = {r, 0, z0}; Point(3 + 4*k) = {0, r, z0}; Point(4 + 4*k) = {-r, 0, z0}; Point(5 + 4*k) = {0, -r, z0};\n"
       "  Circle(1 + 4*k) = {2 + 4*k, 1, 3 + 4*k}; Circle(2 + 4*k) = {3 + 4*k, 1, 4 + 4*k};\n"
       "  Circle(3 + 4*k) = {4 + 4*k, 1, 5 + 4*k}; Circle(4 + 4*k) = {5 + 4*k, 1, 2 + 4*k};\n"
       "EndFor\n"
       "Point(10) = {-0.5, -0.5, z0}; Point(11) = {0.5, -0.5, z0}; Point(12) = {0.5, 0.5, z0}; Point(13) = {-0.5, 0.5, z0};\n"
       "Line(9) = {10, 11}; Line(10) = {11, 12}; Line(11) = {12, 13}; Line(12) = {13, 10};\n"
       "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8}; Curve Loop(3) = {9, 10, 11, 12};\n"
       "Plane Surface(1) = {2, 1};\nPlane Surface(2) = {3, 2};\n"
       "e[] = Extrude {0, 0, t} { Surface{1, 2}; };\n"
       "Coherence;\n"
       "Physical Volume(\"solid\") = {e[1], e[11]};\n"
       "Physical Surface(\"bottom\") = {1, 2};\nPhysical Surface(\"top\") = {e[0], e[10]};\n"
       "Physical Surface(\"washer_bottom\") = {1};\nPhysical Surface(\"washer_top\") = {e[0]};\n";
  return g.str();
}

/// A TOML array of numbers.
std::string toml_array(const std::vector<double>& v) {
  std::ostringstream s;
  s << std::setprecision(9) << "[";
  for (std::size_t k = 0; k < v.size(); ++k) s << (k ? ", " : "") << std::showpoint << v[k];
  return s.str() + "]";
}

/// [0, …, 0, v]: a point or vector with only its vertical (last) component.
std::string vertical_vector(int dim, double v) {
  return toml_array(dim == 2 ? std::vector<double>{0.0, v} : std::vector<double>{0.0, 0.0, v});
}

/// A body of material E = 1, ν = 0.3 whose `boundary` is moved: down by `down` with the load factors, held
/// in y (3D), and along x by `along` with its own `along_factors`.
std::string moved_body(int dim, const std::string& name, const std::string& mesh, const std::string& boundary,
                       double down, double along, const std::vector<double>& along_factors) {
  std::ostringstream s;
  s << std::setprecision(9) << "[[body]]\nname = \"" << name << "\"\nmesh = \"" << mesh
    << "\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
    << "[[body.dirichlet]]\nboundary = \"" << boundary << "\"\n" << (dim == 2 ? "uy" : "uz") << " = " << -down
    << "\n" << (dim == 3 ? "uy = 0.0\n" : "") << "[[body.dirichlet]]\nboundary = \"" << boundary
    << "\"\nux = " << along << "\nfactors = " << toml_array(along_factors) << "\n\n";
  return s.str();
}

/// What a case writes and how its table reads it.
struct CaseFiles {
  std::string description;
  std::string toml;                                       ///< the problem file, without [problem]
  std::vector<std::pair<std::string, std::string>> geo;   ///< file name, text
  std::string moved_body;                                 ///< whose reaction the table reports
  bool gross_slip = false;                                ///< |R_t / R_n| = μ expected at the last step
};

int case_dimension(LargeContactCase c) {
  return c == LargeContactCase::kPadFlat2d || c == LargeContactCase::kPadBall2d ||
                 c == LargeContactCase::kClampedPlates2d
             ? 2
             : 3;
}

/// The [[contact]] table of surface `a`; its friction lines are added by problem_text().
std::string contact_pair(const std::string& a) { return "[[contact]]\nname = \"interface\"\na = \"" + a + "\"\n"; }

/// What the pad is pressed onto.
enum class PadObstacle { kPlane, kBall };

CaseFiles pad_case(int dim, PadObstacle obstacle) {
  CaseFiles f;
  f.moved_body = "pad";
  f.geo = {{"pad.geo", pad_geo(dim)}};
  const char* plane = dim == 2 ? "plane strain" : "3D";
  if (obstacle == PadObstacle::kPlane) {
    f.description = std::string("pad on a rigid plane, ") + plane +
                    ", P1; 4 load steps (2 press 0.005, 2 drag 0.02): the whole bottom face in contact, sliding "
                    "in the last two";
    f.gross_slip = true;
    f.toml = "[steps]\nload_factors = [0.5, 1.0, 1.0, 1.0]\n\n" +
             moved_body(dim, "pad", "pad.geo", "top", 0.005, 0.02, {0.0, 0.0, 0.5, 1.0}) + contact_pair("pad.bottom") +
             "[contact.obstacle]\ntype = \"plane\"\npoint = " + vertical_vector(dim, 0.0) +
             "\nnormal = " + vertical_vector(dim, 1.0) + "\n";
    return f;
  }
  f.description = std::string("pad on a rigid ") + (dim == 2 ? "cylinder" : "sphere") + " of radius 1, " + plane +
                  ", P1; 6 load steps (4 press 0.03: the zone grows, 2 drag 0.05)";
  f.toml = "[steps]\nload_factors = [0.25, 0.5, 0.75, 1.0, 1.0, 1.0]\n\n" +
           moved_body(dim, "pad", "pad.geo", "top", 0.03, 0.05, {0.0, 0.0, 0.0, 0.0, 0.5, 1.0}) +
           contact_pair("pad.bottom") + "[contact.obstacle]\ntype = \"" + (dim == 2 ? "circle" : "sphere") +
           "\"\ncenter = " + vertical_vector(dim, -1.0) + "\nradius = 1.0\n";
  return f;
}

CaseFiles plates_case(int dim) {
  CaseFiles f;
  f.moved_body = "upper";
  f.geo = {{"upper.geo", plate_geo(dim, 0.0)}, {"lower.geo", plate_geo(dim, -0.2)}};
  f.description = std::string("two plates with a hole, ") + (dim == 2 ? "plane-strain section" : "3D") +
                  ", P1, symmetric pair; lower washer clamped, upper washer pressed 0.002 (2 steps), then moved "
                  "5e-4 along x (2 steps)";
  std::ostringstream lower;
  lower << "[[body]]\nname = \"lower\"\nmesh = \"lower.geo\"\ngroup = \"solid\"\nmaterial = { E = 1.0, nu = 0.3 }\n"
        << "[[body.dirichlet]]\nboundary = \"washer_bottom\"\nux = 0.0\nuy = 0.0\n" << (dim == 3 ? "uz = 0.0\n" : "")
        << "\n";
  f.toml = "[steps]\nload_factors = [0.5, 1.0, 1.0, 1.0]\n\n" +
           moved_body(dim, "upper", "upper.geo", "washer_top", 0.002, 5e-4, {0.0, 0.0, 0.5, 1.0}) + lower.str() +
           contact_pair("upper.bottom") + "b = \"lower.top\"\n";
  return f;
}

CaseFiles case_files(LargeContactCase c) {
  const int dim = case_dimension(c);
  switch (c) {
    case LargeContactCase::kPadFlat:
    case LargeContactCase::kPadFlat2d: return pad_case(dim, PadObstacle::kPlane);
    case LargeContactCase::kPadBall:
    case LargeContactCase::kPadBall2d: return pad_case(dim, PadObstacle::kBall);
    case LargeContactCase::kClampedPlates:
    case LargeContactCase::kClampedPlates2d: return plates_case(dim);
  }
  throw std::logic_error("case_files: unknown large-contact case");
}

/// The problem file at element size h: [problem] with mesh_size = h, then the case's text with the friction
/// law in its [[contact]] table.
std::string problem_text(const LargeContactBenchOptions& opt, const CaseFiles& f, double h) {
  std::ostringstream law;
  law << "[[contact]]\n";
  if (opt.friction == LargeContactFriction::kCoulomb) law << "friction = \"coulomb\"\nmu = " << kMu << "\n";
  std::string toml = f.toml;
  const std::size_t at = toml.find("[[contact]]\n");
  if (at == std::string::npos) throw std::logic_error("problem_text: the case has no [[contact]]");
  toml.replace(at, std::string("[[contact]]\n").size(), law.str());
  std::ostringstream s;
  s << std::setprecision(9) << "title = \"" << large_contact_name(opt.which) << "\"\n\n[problem]\ndimension = "
    << case_dimension(opt.which) << "\nmesh_size = " << h << "\n\n"
    << toml << "\n[contact_solver]\n";
  if (!opt.subproblem_solver.empty()) s << "subproblem_solver = \"" << opt.subproblem_solver << "\"\n";
  if (!opt.coulomb_update.empty()) s << "coulomb_update = \"" << opt.coulomb_update << "\"\n";
  if (!opt.warm_start.empty()) s << "warm_start = \"" << opt.warm_start << "\"\n";
  if (!opt.condense) s << "static_condensation = false\n";
  return s.str();
}

/// |R_t| / |R_n| of the reaction of `body` at the last step (R_n its vertical component).
double reaction_ratio(const ProblemRun& run, const std::string& body) {
  const Eigen::VectorXd r = run.body_reaction(body);
  const Index n = r.size() - 1;
  return r.head(n).norm() / std::abs(r[n]);
}

}  // namespace

const std::vector<LargeContactCase>& large_contact_cases() {
  static const std::vector<LargeContactCase> all = {
      LargeContactCase::kPadFlat2d, LargeContactCase::kPadBall2d, LargeContactCase::kClampedPlates2d,
      LargeContactCase::kPadFlat,   LargeContactCase::kPadBall,   LargeContactCase::kClampedPlates};
  return all;
}

std::string large_contact_name(LargeContactCase c) {
  switch (c) {
    case LargeContactCase::kPadFlat: return "pad-flat";
    case LargeContactCase::kPadBall: return "pad-ball";
    case LargeContactCase::kClampedPlates: return "clamped-plates";
    case LargeContactCase::kPadFlat2d: return "pad-flat-2d";
    case LargeContactCase::kPadBall2d: return "pad-ball-2d";
    case LargeContactCase::kClampedPlates2d: return "clamped-plates-2d";
  }
  throw std::logic_error("large_contact_name: unknown large-contact case");
}

std::optional<LargeContactCase> large_contact_case(const std::string& name) {
  for (const LargeContactCase c : large_contact_cases())
    if (large_contact_name(c) == name) return c;
  return std::nullopt;
}

std::vector<double> default_large_contact_sizes(LargeContactCase c, bool large) {
  switch (c) {
    case LargeContactCase::kPadFlat2d:
    case LargeContactCase::kPadBall2d:
      if (large) return {0.0008, 0.00045};
      return {0.008, 0.0046, 0.0025, 0.00145};
    case LargeContactCase::kClampedPlates2d:
      if (large) return {0.00064, 0.00037};
      return {0.0064, 0.0037, 0.002, 0.00117};
    case LargeContactCase::kPadFlat:
      if (large) return {0.045, 0.035, 0.028};
      return {0.08, 0.065, 0.05};
    case LargeContactCase::kPadBall:
      if (large) return {0.05, 0.045, 0.035};
      return {0.1, 0.08, 0.065};
    case LargeContactCase::kClampedPlates:
      if (large) return {0.05, 0.04};
      return {0.1, 0.08, 0.065};
  }
  throw std::logic_error("default_large_contact_sizes: unknown large-contact case");
}

void run_large_contact_sweep(const LargeContactBenchOptions& opt, const MachineInfo& machine) {
  const std::string name = large_contact_name(opt.which);
  const CaseFiles files = case_files(opt.which);
  const bool coulomb = opt.friction == LargeContactFriction::kCoulomb;
  std::cout << "\n## " << name << ": " << files.description << (coulomb ? "; Coulomb mu = 0.3" : "; frictionless")
            << "; floor phases min of " << opt.repeat
            << " run(s), contact solves once\n"
            << "# h: problem.mesh_size; floor RSS: peak RSS of the floor; Rt/Rn: |tangential / normal| reaction of "
            << files.moved_body << " at the last step" << (files.gross_slip && coulomb ? ", err against mu (gross slip)" : "") << "\n"
            << kProblemRunLegend;
  ResultTable table(problem_sweep_columns(5, {{"reaction_ratio", "Rt/Rn", Kind::kFixed, 6},
                                              {"reaction_ratio_error_pct", "err [%]", Kind::kFixed, 3}}),
                    std::cout, opt.markdown);
  if (!opt.csv.empty()) table.write_csv(opt.csv);

  const std::string work = make_work_dir();
  for (const auto& [file, text] : files.geo) write_file(work + "/" + file, text);
  const auto t_sweep = std::chrono::steady_clock::now();
  bool rss_reset_ok = true;
  std::string first_failure;
  for (const double h : opt.h) {
    rss_reset_ok = reset_peak_rss() && rss_reset_ok;
    std::unique_ptr<ProblemRun> run;
    try {
      const std::string text = problem_text(opt, files, h);
      if (opt.keep_work) {
        std::ostringstream file;
        file << name << "_h" << h << ".toml";
        write_file(work + "/" + file.str(), text);  // `symcontact run` solves it from the folder as it is
      }
      run = solve_problem(text, name + ".toml", work);
      const double peak_contact = peak_rss_mib();
      const double ratio = reaction_ratio(*run, files.moved_body);
      const bool closed_form = files.gross_slip && opt.friction == LargeContactFriction::kCoulomb;
      const double error = closed_form ? 100 * (ratio / kMu - 1) : std::numeric_limits<double>::quiet_NaN();
      add_problem_sweep_row(table, name, h, *run, peak_contact, {ratio, error}, opt.repeat, machine);
    } catch (const SolveError& e) {
      std::ostringstream at;
      at << "h = " << std::defaultfloat << std::setprecision(6) << h << ": " << e.what();
      std::cout << "# " << at.str() << ": FAILED\n" << std::flush;
      if (first_failure.empty()) first_failure = at.str();
    } catch (const FactorTooLarge& e) {
      std::cout << "# stopped at h = " << std::defaultfloat << std::setprecision(6) << h << ": " << e.what() << "\n";
      break;
    }
  }
  finish_sweep(name, t_sweep, rss_reset_ok, "meshing + setup + the contact solves", work, opt.keep_work);
  if (!first_failure.empty()) throw SolveError(name + ": the smallest size that failed, " + first_failure);
}

}  // namespace symcontact::bench
