#pragma once
/// \file problem_spec.hpp
/// The problem as the user wrote it: plain data read from the TOML problem file (problem_reader.hpp),
/// before any mesh is loaded. Every item remembers `key`, the TOML path it came from (for example
/// "body[2].dirichlet[1].boundary"), so that errors found later (a missing physical group) can name it.
///
/// Load histories: every load and imposed displacement is multiplied, at load step k, by its own
/// `factors[k]` when given, else by the problem's `steps.load_factors[k]`.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "symcontact/materials/analysis_model.hpp"

namespace symcontact {

struct MaterialSpec {
  std::string key;             ///< e.g. "body[0].material"
  std::string model = "linear_elastic";
  double young = 0.0;          ///< E > 0, [stress]
  double poisson = 0.0;        ///< nu in (-1, 0.5)
};

/// u_i = value_i × factor on a named boundary (facet group) or node group; unset components are free.
struct DirichletSpec {
  std::string key;
  std::string group;
  std::array<std::optional<double>, 3> value;  ///< ux, uy, uz
  std::vector<double> factors;                 ///< per-step multipliers (empty: the global ones)
};

/// A surface traction t (force per unit area, or per unit length in 2D) on a named boundary.
struct TractionSpec {
  std::string key;
  std::string group;
  std::vector<double> traction;  ///< dim components
  std::vector<double> factors;
};

/// A pressure p (follows the outward normal inwards: t = −p n) on a named boundary.
struct PressureSpec {
  std::string key;
  std::string group;
  double pressure = 0.0;
  std::vector<double> factors;
};

struct BodySpec {
  std::string key;                ///< "body[i]"
  std::string name;               ///< unique; used in output file names
  std::string mesh_file;          ///< as written in the problem file
  std::string mesh_path;          ///< resolved against the problem file's folder
  std::string group;              ///< physical group of cells forming the body; empty: all cells of the file
  MaterialSpec material;
  std::vector<double> body_force; ///< force per unit volume, dim components (empty: none)
  std::vector<double> body_force_factors;
  std::vector<DirichletSpec> dirichlet;
  std::vector<TractionSpec> tractions;
  std::vector<PressureSpec> pressures;
};

struct OutputSpec {
  bool vtu = true;        ///< VTU per body per step + PVD collection
  bool summary = true;    ///< summary.json
};

struct ProblemSpec {
  std::string file;                 ///< path of the problem file (for messages)
  std::string title;
  int dim = 2;                      ///< 2 or 3
  AnalysisModel model = AnalysisModel::kPlaneStrain;
  int order = 1;                    ///< Lagrange order 1 or 2
  double mesh_size = 0.0;           ///< maximum element size for .geo meshing; 0: the .geo's own sizes
  std::vector<BodySpec> bodies;
  std::vector<double> load_factors{1.0};  ///< one entry per load step
  OutputSpec output;
};

}  // namespace symcontact
