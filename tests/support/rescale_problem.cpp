#include "support/rescale_problem.hpp"

#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <toml++/toml.h>

namespace symcontact::testing {

namespace fs = std::filesystem;

namespace {

/// Multiplies the number, or every number of the array, at `key` of `t` (absent: nothing).
void scale_key(toml::table& t, const std::string& key, double factor) {
  toml::node* n = t.get(key);
  if (!n || factor == 1.0) return;
  if (auto v = n->value<double>()) {
    t.insert_or_assign(key, *v * factor);
  } else if (toml::array* a = n->as_array()) {
    toml::array scaled;
    for (const toml::node& e : *a) {
      const auto x = e.value<double>();
      if (!x) throw std::runtime_error("rescale_problem: " + key + " holds a non-number");
      scaled.push_back(*x * factor);
    }
    t.insert_or_assign(key, std::move(scaled));
  } else {
    throw std::runtime_error("rescale_problem: " + key + " is neither a number nor an array of numbers");
  }
}

template <class F>
void for_each_table(toml::table& t, const std::string& key, const F& f) {
  if (toml::array* a = t[key].as_array())
    for (toml::node& e : *a)
      if (toml::table* s = e.as_table()) f(*s);
}

struct MeshSettings {
  int dim = 2;
  int order = 1;
  double mesh_size = 0.0;
};

/// Meshes (.geo) or reads (.msh) `in` and writes it to `out` with coordinates × `length`.
void write_scaled_mesh(const std::string& in, const std::string& out, const MeshSettings& m, double length) {
  gmsh::initialize(0, nullptr, false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(in);
    if (fs::path(in).extension() == ".geo") {
      if (m.mesh_size > 0) gmsh::option::setNumber("Mesh.MeshSizeMax", m.mesh_size);
      gmsh::model::mesh::generate(m.dim);
    }
    gmsh::model::mesh::setOrder(m.order);
    gmsh::option::setNumber("Mesh.ScalingFactor", length);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    gmsh::write(out);
  } catch (const std::string& e) {
    gmsh::finalize();
    throw std::runtime_error("rescale_problem: Gmsh failed on " + in + ": " + e);
  } catch (...) {
    gmsh::finalize();
    throw;
  }
  gmsh::finalize();
}

/// Replaces the mesh path at `key` by a scaled copy in `out_dir` (one per distinct source file).
void rescale_mesh_key(toml::table& t, const fs::path& base, const fs::path& out_dir, const MeshSettings& m,
                      double length, std::map<std::string, std::string>& written) {
  const auto name = t["mesh"].value<std::string>();
  if (!name) return;
  const fs::path src = fs::weakly_canonical(base / *name);
  auto [it, fresh] = written.try_emplace(src.string(), "");
  if (fresh) {
    it->second = "mesh" + std::to_string(written.size()) + "_" + src.stem().string() + ".msh";
    write_scaled_mesh(src.string(), (out_dir / it->second).string(), m, length);
  }
  t.insert_or_assign("mesh", it->second);
}

}  // namespace

namespace {

toml::table parse_problem_file(const std::string& problem_path) {
  try {
    return toml::parse_file(problem_path);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("rescale_problem: " + problem_path + ": " + std::string(e.description()));
  }
}

void write_problem(const toml::table& root, const fs::path& out) {
  std::ofstream f(out);
  f << root << "\n";
  if (!f) throw std::runtime_error("rescale_problem: cannot write " + out.string());
}

void make_mesh_path_absolute(toml::table& t, const fs::path& base) {
  if (const auto name = t["mesh"].value<std::string>())
    t.insert_or_assign("mesh", fs::weakly_canonical(base / *name).string());
}

/// Replaces the `.geo` mesh of `t` (an absolute path) by a wrapper in `out_dir` that reads `definitions`
/// and then Includes it (ProblemVariant::geo_definitions); one wrapper per distinct source file.
void wrap_geo(toml::table& t, const std::string& definitions, const fs::path& out_dir,
              std::map<std::string, std::string>& written) {
  const auto name = t["mesh"].value<std::string>();
  if (!name || fs::path(*name).extension() != ".geo") return;
  auto [it, fresh] = written.try_emplace(*name, "");
  if (fresh) {
    it->second = (out_dir / ("wrapped" + std::to_string(written.size()) + "_" + fs::path(*name).filename().string())).string();
    std::ofstream f(it->second);
    f << definitions << "\nInclude \"" << *name << "\";\n";
    if (!f) throw std::runtime_error("write_variant: cannot write " + it->second);
  }
  t.insert_or_assign("mesh", it->second);
}

}  // namespace

std::string write_variant(const std::string& problem_path, const ProblemVariant& variant, const std::string& out_dir) {
  toml::table root = parse_problem_file(problem_path);
  fs::create_directories(out_dir);
  const fs::path base = fs::path(problem_path).parent_path();
  if (toml::table* p = root["problem"].as_table()) {
    if (variant.order > 0) p->insert_or_assign("order", variant.order);
    if (variant.mesh_size > 0) p->insert_or_assign("mesh_size", variant.mesh_size);
  }
  std::map<std::string, std::string> wrapped;
  for_each_table(root, "body", [&](toml::table& body) {
    make_mesh_path_absolute(body, base);
    if (!variant.geo_definitions.empty()) wrap_geo(body, variant.geo_definitions, out_dir, wrapped);
  });
  for_each_table(root, "contact", [&](toml::table& c) {
    if (toml::table* o = c["obstacle"].as_table()) make_mesh_path_absolute(*o, base);
    if (variant.coulomb_mu >= 0) {
      c.erase("tau");
      c.erase("alpha");
      c.insert_or_assign("friction", "coulomb");
      c.insert_or_assign("mu", variant.coulomb_mu);
    }
  });
  const fs::path out = fs::path(out_dir) / "problem.toml";
  write_problem(root, out);
  return out.string();
}

std::string rescale_problem(const std::string& problem_path, const UnitChange& change, const std::string& out_dir) {
  toml::table root = parse_problem_file(problem_path);
  fs::create_directories(out_dir);
  const fs::path base = fs::path(problem_path).parent_path();
  const double L = change.length, S = change.stress(), B = change.force / (L * L * L);
  MeshSettings m;
  if (toml::table* p = root["problem"].as_table()) {
    m.dim = p->get("dimension") ? (*p)["dimension"].value_or(2) : 2;
    m.order = (*p)["order"].value_or(1);
    m.mesh_size = (*p)["mesh_size"].value_or(0.0);
    scale_key(*p, "mesh_size", L);
  }
  std::map<std::string, std::string> written;
  for_each_table(root, "body", [&](toml::table& body) {
    rescale_mesh_key(body, base, out_dir, m, L, written);
    scale_key(body, "body_force", B);
    if (toml::table* mat = body["material"].as_table())
      for (const char* k : {"E", "mu", "lambda", "c1", "c2", "kappa"}) scale_key(*mat, k, S);
    for_each_table(body, "dirichlet", [&](toml::table& d) {
      for (const char* k : {"ux", "uy", "uz"}) scale_key(d, k, L);
    });
    // A resultant or point force: [force] in 3D, [force / length] (per unit thickness) in 2D.
    const double F = m.dim == 3 ? S * L * L : S * L;
    for_each_table(body, "traction", [&](toml::table& d) {
      scale_key(d, "traction", S);
      scale_key(d, "total_force", F);
    });
    for_each_table(body, "point_load", [&](toml::table& d) { scale_key(d, "force", F); });
    for_each_table(body, "pressure", [&](toml::table& d) { scale_key(d, "pressure", S); });
  });
  for_each_table(root, "contact", [&](toml::table& c) {
    for (const char* k : {"search_distance", "alpha"}) scale_key(c, k, L);
    scale_key(c, "tau", S);
    if (toml::table* o = c["obstacle"].as_table()) {
      for (const char* k : {"point", "center", "radius"}) scale_key(*o, k, L);
      rescale_mesh_key(*o, base, out_dir, m, L, written);
    }
  });
  const fs::path out = fs::path(out_dir) / "problem.toml";
  write_problem(root, out);
  return out.string();
}

}  // namespace symcontact::testing
