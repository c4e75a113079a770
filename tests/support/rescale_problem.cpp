#include "support/rescale_problem.hpp"

#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <cctype>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <toml++/toml.h>

namespace symcontact::testing {

namespace fs = std::filesystem;

namespace {

/// Gives `put` the value `e` × factor: a number, or an expression rewritten by scale_expression().
template <class Put>
void put_scaled(const toml::node& e, const std::string& key, double factor, double length, const Put& put) {
  if (const auto x = e.value<double>())
    put(*x * factor);
  else if (const auto text = e.value<std::string>())
    put(scale_expression(*text, factor, length));
  else
    throw std::runtime_error("rescale_problem: " + key + " holds neither a number nor an expression");
}

/// Multiplies the value, or every value of the array, at `key` of `t` (absent: nothing) by `factor`; an
/// expression is rewritten for coordinates × `length` as well (scale_expression()).
void scale_key(toml::table& t, const std::string& key, double factor, double length = 1.0) {
  toml::node* n = t.get(key);
  if (!n || (factor == 1.0 && length == 1.0)) return;
  if (toml::array* a = n->as_array()) {
    toml::array scaled;
    for (const toml::node& e : *a) put_scaled(e, key, factor, length, [&](auto v) { scaled.push_back(v); });
    t.insert_or_assign(key, std::move(scaled));
  } else {
    put_scaled(*n, key, factor, length, [&](auto v) { t.insert_or_assign(key, v); });
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
void write_scaled_mesh(const std::string& in, const std::string& out, const MeshSettings& m, double length,
                       const std::vector<std::string>& gmsh_args) {
  std::vector<char*> argv{const_cast<char*>("gmsh")};
  for (const std::string& a : gmsh_args) argv.push_back(const_cast<char*>(a.c_str()));
  gmsh::initialize(static_cast<int>(argv.size()), argv.data(), false);
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

/// Replaces the mesh path of `t` by a scaled copy in `out_dir` (one per distinct source file and
/// mesh_parameters), meshed with its `mesh_parameters` (as Gmsh's -setnumber), which then leave the table.
void rescale_mesh_key(toml::table& t, const fs::path& base, const fs::path& out_dir, const MeshSettings& m,
                      double length, std::map<std::string, std::string>& written) {
  const auto name = t["mesh"].value<std::string>();
  if (!name) return;
  const fs::path src = fs::weakly_canonical(base / *name);
  std::vector<std::string> args;
  if (const toml::table* p = t["mesh_parameters"].as_table()) {
    for (const auto& [k, v] : *p) {
      std::ostringstream value;
      value.precision(17);
      value << v.value<double>().value_or(0.0);
      args.insert(args.end(), {"-setnumber", std::string(k.str()), value.str()});
    }
  }
  std::string key = src.string();
  for (const std::string& a : args) key += " " + a;
  auto [it, fresh] = written.try_emplace(key, "");
  if (fresh) {
    it->second = "mesh" + std::to_string(written.size()) + "_" + src.stem().string() + ".msh";
    write_scaled_mesh(src.string(), (out_dir / it->second).string(), m, length, args);
  }
  t.insert_or_assign("mesh", it->second);
  t.erase("mesh_parameters");
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
  if (toml::table* steps = root["steps"].as_table(); steps && variant.step_count > 0)
    steps->insert_or_assign("count", variant.step_count);
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

std::string scale_expression(const std::string& text, double factor, double length) {
  std::ostringstream out;
  out.precision(17);
  out << factor << "*(";
  const auto is_name = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < text.size();) {
    if (!is_name(text[i])) {
      out << text[i++];
      continue;
    }
    // A number (with its exponent: "2e-3") or a name, whole.
    std::size_t j = i;
    if (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.') {
      while (j < text.size() && (is_name(text[j]) || text[j] == '.' ||
                                 ((text[j] == '-' || text[j] == '+') && (text[j - 1] == 'e' || text[j - 1] == 'E'))))
        ++j;
    } else {
      while (j < text.size() && is_name(text[j])) ++j;
    }
    const std::string token = text.substr(i, j - i);
    if (token == "x" || token == "y" || token == "z")
      out << "(" << token << "/" << length << ")";
    else
      out << token;
    i = j;
  }
  out << ")";
  return out.str();
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
    // One material table, or one per region ([[body.material]]).
    const auto scale_material = [&](toml::table& mat) {
      for (const char* k : {"E", "mu", "lambda", "c1", "c2", "kappa"}) scale_key(mat, k, S);
    };
    if (toml::table* mat = body["material"].as_table()) scale_material(*mat);
    for_each_table(body, "material", scale_material);
    for_each_table(body, "dirichlet", [&](toml::table& d) {
      for (const char* k : {"ux", "uy", "uz"}) scale_key(d, k, L, L);
    });
    // A resultant or point force: [force] in 3D, [force / length] (per unit thickness) in 2D.
    const double F = m.dim == 3 ? S * L * L : S * L;
    for_each_table(body, "traction", [&](toml::table& d) {
      scale_key(d, "traction", S, L);
      scale_key(d, "total_force", F);
    });
    for_each_table(body, "point_load", [&](toml::table& d) { scale_key(d, "force", F); });
    for_each_table(body, "pressure", [&](toml::table& d) { scale_key(d, "pressure", S, L); });
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
