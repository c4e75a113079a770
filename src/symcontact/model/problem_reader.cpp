#include "symcontact/model/problem_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "symcontact/core/error.hpp"
#include "symcontact/core/expression.hpp"
#include "symcontact/core/input_file.hpp"
#include "symcontact/mesh/geo_commands.hpp"
#include "symcontact/model/toml_parse.hpp"

namespace symcontact {

namespace {

namespace fs = std::filesystem;

using KeyList = std::initializer_list<std::string_view>;

// ---- formatting ---------------------------------------------------------------------------------

/// Shortest decimal form of `x` that reads back exactly ("0.3", not "0.29999999999999999").
std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::ostringstream os;
  if (x == std::trunc(x) && std::abs(x) < 1e15) {  // whole numbers in full: "10", not "1e+01"
    os << std::fixed;
    os.precision(0);
    os << x;
    return os.str();
  }
  for (int precision = 1; precision <= 17; ++precision) {
    os.str("");
    os.precision(precision);
    os << x;
    if (std::strtod(os.str().c_str(), nullptr) == x) break;
  }
  return os.str();
}

std::string in_quotes(std::string_view s) { return "\"" + std::string(s) + "\""; }

std::string join(KeyList items, std::string_view separator) {
  std::string s;
  for (std::string_view item : items) {
    if (!s.empty()) s += separator;
    s += item;
  }
  return s;
}

/// "a string (\"abc\")", "an integer (4)", "a table", ...: what the user actually wrote.
std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string (" + in_quotes(*node.value<std::string>()) + ")";
    case toml::node_type::integer:
      return "an integer (" + std::to_string(*node.value<std::int64_t>()) + ")";
    case toml::node_type::floating_point:
    {
      std::string x = format_number(*node.value<double>());
      if (x.find_first_of(".eni") == std::string::npos) x += ".0";  // 2.0, not 2
      return "a floating-point number (" + x + ")";
    }
    case toml::node_type::boolean:
      return std::string("a boolean (") + (*node.value<bool>() ? "true" : "false") + ")";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

/// Levenshtein distance, for "did you mean" hints on misspelt keys.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool valid_name(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

std::string child(const std::string& path, std::string_view name) {
  return path.empty() ? std::string(name) : path + "." + std::string(name);
}

std::string indexed(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

// ---- the reader ---------------------------------------------------------------------------------

/// Walks the parsed document. Every accessor takes the TOML path of the value (for messages).
class Reader {
 public:
  Reader(std::string file, std::string base_dir) : file_(std::move(file)), base_dir_(std::move(base_dir)) {}

  ProblemSpec read(const toml::table& root) const {
    ProblemSpec spec;
    spec.file = file_;
    check_keys(root, "", {"title", "problem", "steps", "output", "body", "contact", "contact_solver", "ipopt"});
    if (const toml::node* n = root.get("title")) spec.title = as_string(*n, "title");

    read_problem(root, spec);
    read_steps(root, spec);
    read_output(root, spec);

    const toml::node* bodies = root.get("body");
    if (!bodies) fail("body", "missing required array of tables [[body]] (at least one body)");
    const toml::array& list = as_table_array(*bodies, "body", "[[body]]");
    if (list.empty()) fail("body", "expected at least one [[body]], got an empty array");
    for (std::size_t i = 0; i < list.size(); ++i) {
      spec.bodies.push_back(read_body(*list[i].as_table(), indexed("body", i), spec));
      for (std::size_t j = 0; j < i; ++j) {
        if (spec.bodies[j].name == spec.bodies[i].name) {
          fail(spec.bodies[i].key + ".name", "duplicate body name " + in_quotes(spec.bodies[i].name) +
                                                 " (already used by " + spec.bodies[j].key + ")");
        }
      }
    }

    read_contacts(root, spec);
    check_held(spec);
    read_contact_solver(root, spec);
    read_ipopt(root, spec);
    return spec;
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(file_, key, message);
  }

  // ---- structure ----

  /// Every key of `table` must be in `allowed`; the message lists them (and suggests a near miss).
  void check_keys(const toml::table& table, const std::string& path, KeyList allowed) const {
    for (auto&& [key, value] : table) {
      (void)value;
      const std::string_view name = key.str();
      if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
      std::string message = "unknown key " + in_quotes(name);
      std::string_view best;
      std::size_t best_distance = 3;  // suggest only near misses (distance <= 2)
      for (std::string_view candidate : allowed) {
        const std::size_t d = edit_distance(name, candidate);
        if (d < best_distance && d < std::max(name.size(), candidate.size())) {
          best_distance = d;
          best = candidate;
        }
      }
      if (!best.empty()) message += " (did you mean " + in_quotes(best) + "?)";
      message += "; allowed keys " + (path.empty() ? std::string("at the top level") : "in " + path) + ": " +
                 join(allowed, ", ");
      fail(child(path, name), message);
    }
  }

  const toml::table& as_table(const toml::node& node, const std::string& key) const {
    if (!node.is_table()) fail(key, "expected a table, got " + describe(node));
    return *node.as_table();
  }

  /// An array whose elements are all tables (written [[name]] or name = [{...}, ...]).
  const toml::array& as_table_array(const toml::node& node, const std::string& key, const std::string& header) const {
    if (!node.is_array()) fail(key, "expected an array of tables (" + header + "), got " + describe(node));
    const toml::array& array = *node.as_array();
    for (std::size_t i = 0; i < array.size(); ++i) {
      if (!array[i].is_table()) fail(indexed(key, i), "expected a table, got " + describe(array[i]));
    }
    return array;
  }

  // ---- scalars ----

  std::string as_string(const toml::node& node, const std::string& key) const {
    if (!node.is_string()) fail(key, "expected a string, got " + describe(node));
    return *node.value<std::string>();
  }

  std::string as_nonempty_string(const toml::node& node, const std::string& key) const {
    std::string s = as_string(node, key);
    if (s.empty()) fail(key, "expected a non-empty string, got \"\"");
    return s;
  }

  bool as_bool(const toml::node& node, const std::string& key) const {
    if (!node.is_boolean()) fail(key, "expected a boolean (true or false), got " + describe(node));
    return *node.value<bool>();
  }

  std::int64_t as_integer(const toml::node& node, const std::string& key) const {
    if (!node.is_integer()) fail(key, "expected an integer, got " + describe(node));
    return *node.value<std::int64_t>();
  }

  /// A finite number; integers are accepted.
  double as_number(const toml::node& node, const std::string& key) const {
    double x = 0.0;
    if (node.is_integer()) {
      x = static_cast<double>(*node.value<std::int64_t>());
    } else if (node.is_floating_point()) {
      x = *node.value<double>();
    } else {
      fail(key, "expected a number, got " + describe(node));
    }
    if (!std::isfinite(x)) fail(key, "expected a finite number, got " + format_number(x));
    return x;
  }

  std::vector<double> as_number_array(const toml::node& node, const std::string& key) const {
    if (!node.is_array()) fail(key, "expected an array of numbers, got " + describe(node));
    const toml::array& array = *node.as_array();
    std::vector<double> values;
    values.reserve(array.size());
    for (std::size_t i = 0; i < array.size(); ++i) values.push_back(as_number(array[i], indexed(key, i)));
    return values;
  }

  /// A vector with one component per space dimension.
  std::vector<double> as_vector(const toml::node& node, const std::string& key, int dim) const {
    std::vector<double> v = as_number_array(node, key);
    if (v.size() != static_cast<std::size_t>(dim)) {
      fail(key, "expected " + std::to_string(dim) + " components (problem.dimension = " + std::to_string(dim) +
                    "), got " + std::to_string(v.size()));
    }
    return v;
  }

  /// A number (scaled by the load factor) or a string holding an expression of x, y, z, t (evaluated as
  /// written), compiled here so that a fault is reported with the file and the key.
  LoadValue as_load_value(const toml::node& node, const std::string& key) const {
    LoadValue v;
    if (!node.is_string()) {
      if (!node.is_number()) fail(key, "expected a number or an expression of x, y, z, t (a string), got " + describe(node));
      v.number = as_number(node, key);
      return v;
    }
    v.expression = *node.value<std::string>();
    try {
      Expression compiled(v.expression);
    } catch (const ExpressionError& e) {
      fail(key, "expected a number or an expression of x, y, z, t; " + e.message());
    }
    return v;
  }

  /// A vector with one component per space dimension, each a number or an expression (as_load_value).
  std::vector<LoadValue> as_load_vector(const toml::node& node, const std::string& key, int dim) const {
    if (!node.is_array())
      fail(key, "expected an array of " + std::to_string(dim) + " numbers or expressions, got " + describe(node));
    const toml::array& array = *node.as_array();
    if (array.size() != static_cast<std::size_t>(dim)) {
      fail(key, "expected " + std::to_string(dim) + " components (problem.dimension = " + std::to_string(dim) +
                    "), got " + std::to_string(array.size()));
    }
    std::vector<LoadValue> v;
    for (std::size_t i = 0; i < array.size(); ++i) v.push_back(as_load_value(array[i], indexed(key, i)));
    return v;
  }

  /// Per-step multipliers: an array of one entry per load step, or a load curve (curve_factors).
  std::vector<double> as_factors(const toml::node& node, const std::string& key, const ProblemSpec& spec) const {
    const std::size_t steps = spec.load_factors.size();
    if (node.is_table()) return curve_factors(*node.as_table(), key, steps);
    std::vector<double> f = as_number_array(node, key);
    if (f.size() != steps) {
      fail(key, "expected " + std::to_string(steps) + " entries (one per load step, as in steps.load_factors), got " +
                    std::to_string(f.size()) + " (or a load curve: { at = [step numbers], values = [factors] })");
    }
    return f;
  }

  /// A load curve { at = [k0, k1, ...], values = [v0, v1, ...] }: the factor is piecewise linear in the
  /// step number k (k = 0 is the unloaded start), through the points (k_i, v_i); k_i are integers,
  /// strictly increasing, from 0 up to at least the number of steps. Returns the factors of steps 1..n.
  std::vector<double> curve_factors(const toml::table& t, const std::string& key, std::size_t steps) const {
    check_keys(t, key, {"at", "values"});
    const toml::node* at_node = t.get("at");
    const toml::node* values_node = t.get("values");
    if (!at_node || !values_node) fail(key, "a load curve needs both 'at' (step numbers) and 'values'");
    const std::vector<double> at = as_number_array(*at_node, child(key, "at"));
    const std::vector<double> v = as_number_array(*values_node, child(key, "values"));
    if (at.size() != v.size() || at.size() < 2)
      fail(key, "expected 'at' and 'values' of the same length, at least 2; got " + std::to_string(at.size()) + " and " +
                    std::to_string(v.size()));
    for (std::size_t i = 0; i < at.size(); ++i) {
      if (at[i] != std::floor(at[i]) || (i == 0 && at[i] != 0.0) || (i > 0 && at[i] <= at[i - 1]))
        fail(indexed(child(key, "at"), i), "expected whole step numbers, strictly increasing from 0, got " +
                                               format_number(at[i]));
    }
    if (at.back() < static_cast<double>(steps))
      fail(child(key, "at"), "the curve ends at step " + format_number(at.back()) + ", before the last load step " +
                                 std::to_string(steps));
    std::vector<double> f(steps);
    std::size_t seg = 0;
    for (std::size_t k = 1; k <= steps; ++k) {
      while (at[seg + 1] < static_cast<double>(k)) ++seg;
      f[k - 1] = v[seg] + (static_cast<double>(k) - at[seg]) * (v[seg + 1] - v[seg]) / (at[seg + 1] - at[seg]);
    }
    return f;
  }

  /// A count: an integer in [1, INT_MAX] (iteration limits).
  int as_count(const toml::node& node, const std::string& key) const {
    const std::int64_t i = as_integer(node, key);
    if (i < 1 || i > std::numeric_limits<int>::max()) {
      fail(key, "expected an integer in [1, " + std::to_string(std::numeric_limits<int>::max()) + "], got " +
                    std::to_string(i));
    }
    return static_cast<int>(i);
  }

  const toml::node& required(const toml::table& table, const std::string& path, std::string_view name,
                             const std::string& what) const {
    const toml::node* node = table.get(name);
    if (!node) fail(child(path, name), "missing required key (expected " + what + ")");
    return *node;
  }

  /// `boundary`: the (non-empty) name of a physical group; its existence is checked with the mesh.
  std::string boundary(const toml::table& t, const std::string& path) const {
    return as_nonempty_string(required(t, path, "boundary", "the name of a physical group"), child(path, "boundary"));
  }

  // ---- sections ----

  void read_problem(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("problem");
    if (!node) fail("problem", "missing required table [problem] (with at least dimension = 2 or 3)");
    const toml::table& t = as_table(*node, "problem");
    check_keys(t, "problem", {"dimension", "model", "order", "mesh_size"});

    const std::int64_t dim = as_integer(required(t, "problem", "dimension", "2 or 3"), "problem.dimension");
    if (dim != 2 && dim != 3) fail("problem.dimension", "expected 2 or 3, got " + std::to_string(dim));
    spec.dim = static_cast<int>(dim);

    spec.model = spec.dim == 2 ? AnalysisModel::kPlaneStrain : AnalysisModel::kThreeD;
    if (const toml::node* n = t.get("model")) {
      const std::string model = as_string(*n, "problem.model");
      if (spec.dim == 2 && model == "plane_strain") {
        spec.model = AnalysisModel::kPlaneStrain;
      } else if (spec.dim == 2 && model == "plane_stress") {
        spec.model = AnalysisModel::kPlaneStress;
      } else if (spec.dim == 2 && model == "axisymmetric") {
        spec.model = AnalysisModel::kAxisymmetric;
      } else if (spec.dim == 3 && model == "3d") {
        spec.model = AnalysisModel::kThreeD;
      } else if (spec.dim == 2) {
        fail("problem.model",
             "expected \"plane_strain\", \"plane_stress\" or \"axisymmetric\" (problem.dimension = 2), got " +
                 in_quotes(model));
      } else {
        fail("problem.model", "expected \"3d\" (problem.dimension = 3), got " + in_quotes(model));
      }
    }

    if (const toml::node* n = t.get("order")) {
      const std::int64_t order = as_integer(*n, "problem.order");
      if (order != 1 && order != 2) fail("problem.order", "expected 1 or 2, got " + std::to_string(order));
      spec.order = static_cast<int>(order);
    }

    if (const toml::node* n = t.get("mesh_size")) {
      spec.mesh_size = as_number(*n, "problem.mesh_size");
      if (!(spec.mesh_size > 0.0)) {
        fail("problem.mesh_size", "expected a number > 0, got " + format_number(spec.mesh_size));
      }
    }
  }

  void read_steps(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("steps");
    if (!node) return;
    const toml::table& t = as_table(*node, "steps");
    check_keys(t, "steps", {"count", "load_factors"});
    const toml::node* count = t.get("count");
    const toml::node* n = t.get("load_factors");
    if (count) {
      const std::int64_t c = as_integer(*count, "steps.count");
      if (c < 1 || c > 1000000) fail("steps.count", "expected a number of load steps in [1, 1000000], got " + std::to_string(c));
      // Without load_factors: a linear ramp k/count.
      spec.load_factors.resize(static_cast<std::size_t>(c));
      for (std::int64_t k = 1; k <= c; ++k) spec.load_factors[k - 1] = static_cast<double>(k) / static_cast<double>(c);
      if (n) spec.load_factors = as_factors(*n, "steps.load_factors", spec);
      return;
    }
    if (n) {
      if (n->is_table()) fail("steps.load_factors", "a load curve needs steps.count (the number of load steps)");
      spec.load_factors = as_number_array(*n, "steps.load_factors");
      if (spec.load_factors.empty()) {
        fail("steps.load_factors", "expected at least one load factor, got an empty array");
      }
    }
  }

  void read_output(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("output");
    if (!node) return;
    const toml::table& t = as_table(*node, "output");
    check_keys(t, "output", {"vtu", "summary"});
    if (const toml::node* n = t.get("vtu")) spec.output.vtu = as_bool(*n, "output.vtu");
    if (const toml::node* n = t.get("summary")) spec.output.summary = as_bool(*n, "output.summary");
  }

  BodySpec read_body(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path,
               {"name", "mesh", "mesh_parameters", "group", "body_force", "body_force_factors", "material", "dirichlet",
                "traction", "pressure", "point_load"});
    BodySpec body;
    body.key = path;

    const std::string name_key = child(path, "name");
    body.name = as_string(required(t, path, "name", "a string of letters, digits, '_' and '-'"), name_key);
    if (!valid_name(body.name)) {
      fail(name_key, "expected a non-empty name of letters, digits, '_' and '-', got " + in_quotes(body.name));
    }

    read_mesh(t, path, body.mesh_file, body.mesh_path);
    if (const toml::node* n = t.get("mesh_parameters")) {
      body.mesh_parameters = read_mesh_parameters(*n, child(path, "mesh_parameters"), body);
    }

    if (const toml::node* n = t.get("group")) body.group = as_nonempty_string(*n, child(path, "group"));

    if (const toml::node* n = t.get("body_force")) body.body_force = as_vector(*n, child(path, "body_force"), spec.dim);
    if (const toml::node* n = t.get("body_force_factors")) {
      const std::string key = child(path, "body_force_factors");
      if (body.body_force.empty()) {
        fail(key, "body_force_factors given without body_force (expected a body_force vector too)");
      }
      body.body_force_factors = as_factors(*n, key, spec);
    }

    body.materials = read_materials(required(t, path, "material", "a table [body.material]"), child(path, "material"),
                                    spec);

    read_list(t, path, "dirichlet", body.dirichlet, &Reader::read_dirichlet, spec);
    read_list(t, path, "traction", body.tractions, &Reader::read_traction, spec);
    read_list(t, path, "pressure", body.pressures, &Reader::read_pressure, spec);
    read_list(t, path, "point_load", body.point_loads, &Reader::read_point_load, spec);
    return body;
  }

  /// The array of tables [[body.<name>]] of a body, if present, each read by `read_one`.
  template <class Item>
  void read_list(const toml::table& t, const std::string& path, std::string_view name, std::vector<Item>& out,
                 Item (Reader::*read_one)(const toml::table&, const std::string&, const ProblemSpec&) const,
                 const ProblemSpec& spec) const {
    const toml::node* n = t.get(name);
    if (!n) return;
    const std::string key = child(path, name);
    const toml::array& list = as_table_array(*n, key, "[[body." + std::string(name) + "]]");
    for (std::size_t i = 0; i < list.size(); ++i) out.push_back((this->*read_one)(*list[i].as_table(), indexed(key, i), spec));
  }

  /// mesh: a .geo or .msh file, relative to the problem file's folder, that must exist. Sets
  /// `mesh_file` (as written) and `mesh_path` (resolved).
  void read_mesh(const toml::table& t, const std::string& path, std::string& mesh_file, std::string& mesh_path) const {
    const std::string key = child(path, "mesh");
    mesh_file = as_nonempty_string(required(t, path, "mesh", "the path of a .geo or .msh file"), key);
    const fs::path written(mesh_file);
    const std::string extension = written.extension().string();
    if (extension != ".geo" && extension != ".msh") {
      fail(key, "expected a Gmsh .geo or .msh file, got " + in_quotes(mesh_file) + " (extension " +
                    (extension.empty() ? std::string("missing") : in_quotes(extension)) + ")");
    }
    const fs::path resolved = (written.is_absolute() ? written : fs::path(base_dir_) / written).lexically_normal();
    mesh_path = resolved.string();
    const std::string problem = input_file_problem(mesh_path);
    if (problem == "does not exist") {
      fail(key, "mesh file " + in_quotes(mesh_path) + " does not exist (relative paths are resolved against " +
                    "the problem file's folder)");
    }
    if (!problem.empty()) fail(key, "mesh file " + in_quotes(mesh_path) + " " + problem);
  }

  /// mesh_parameters = { name = value, ... }: numbers handed to the body's .geo as Gmsh's `-setnumber`
  /// (gmsh_io.hpp). Each name must be a Gmsh identifier declared by DefineConstant in the .geo (or a file
  /// it includes; geo_commands.hpp), each value a finite number; a .msh mesh takes none.
  std::map<std::string, double> read_mesh_parameters(const toml::node& node, const std::string& key,
                                                     const BodySpec& body) const {
    const toml::table& t = as_table(node, key);
    if (fs::path(body.mesh_file).extension() != ".geo") {
      fail(key, "mesh parameters are passed to a .geo file when it is meshed, but mesh " + in_quotes(body.mesh_file) +
                    " is a .msh file (remove mesh_parameters, or mesh the .geo)");
    }
    std::set<std::string> declared;
    try {
      declared = geo_defined_constants(body.mesh_path);
    } catch (const InputError& e) {
      fail(child(body.key, "mesh"), e.file() + (e.key().empty() ? "" : ": " + e.key()) + ": " + e.message());
    }
    std::string declared_list;
    for (const std::string& d : declared) declared_list += (declared_list.empty() ? "" : ", ") + d;
    std::map<std::string, double> parameters;
    for (auto&& [name_key, value] : t) {
      const std::string name(name_key.str());
      const std::string parameter_key = child(key, name);
      if (!is_geo_identifier(name)) {
        fail(parameter_key, "expected a Gmsh variable name (a letter or '_', then letters, digits and '_'), got " +
                                in_quotes(name));
      }
      parameters[name] = as_number(value, parameter_key);
      if (!declared.count(name)) {
        fail(parameter_key, "mesh " + in_quotes(body.mesh_file) + " declares no DefineConstant[ " + name +
                                " = ... ]: only such constants take a value from outside the file (a plain "
                                "assignment would replace it); constants it declares: " +
                                (declared_list.empty() ? std::string("none") : declared_list));
      }
    }
    return parameters;
  }

  /// material: one table [body.material] (the whole body, or the group it names), or an array of tables
  /// [[body.material]], each with the physical group of cells it fills. Groups must differ, and the models
  /// must be all linear elastic or all hyperelastic (one body is solved by one of the two formulations).
  std::vector<MaterialSpec> read_materials(const toml::node& node, const std::string& key,
                                           const ProblemSpec& spec) const {
    if (node.is_table()) return {read_material_in_group(*node.as_table(), key, spec, false)};
    if (!node.is_array()) {
      fail(key, "expected a table [body.material], or an array of tables [[body.material]] each with a group, got " +
                    describe(node));
    }
    const toml::array& list = as_table_array(node, key, "[[body.material]]");
    if (list.empty()) fail(key, "expected at least one [[body.material]], got an empty array");
    std::vector<MaterialSpec> materials;
    for (std::size_t i = 0; i < list.size(); ++i) {
      materials.push_back(read_material_in_group(*list[i].as_table(), indexed(key, i), spec, true));
      const MaterialSpec& m = materials.back();
      for (std::size_t j = 0; j < i; ++j) {
        if (materials[j].group == m.group) {
          fail(child(m.key, "group"),
               "group " + in_quotes(m.group) + " already has a material (" + materials[j].key + ")");
        }
        if ((materials[j].model == "linear_elastic") != (m.model == "linear_elastic")) {
          fail(child(m.key, "model"), "model " + in_quotes(m.model) + " in a body whose " + materials[j].key + " is " +
                                          in_quotes(materials[j].model) +
                                          ": the materials of one body must be all \"linear_elastic\" or all "
                                          "hyperelastic (use two bodies bonded by a shared mesh otherwise)");
        }
      }
    }
    return materials;
  }

  /// One material table with its optional `group` (required when `group_required`, in a list).
  MaterialSpec read_material_in_group(const toml::table& t, const std::string& path, const ProblemSpec& spec,
                                      bool group_required) const {
    std::string group;
    if (const toml::node* n = t.get("group")) {
      group = as_nonempty_string(*n, child(path, "group"));
    } else if (group_required) {
      fail(child(path, "group"), "missing required key (expected the physical group of cells this material fills; "
                                 "every [[body.material]] of a list names one)");
    }
    MaterialSpec material = read_material(t, path, spec);
    material.group = group;
    return material;
  }

  /// [body.material] (its optional `group` read by the caller): model "linear_elastic" (E, nu), "neo_hookean" (E, nu | mu, lambda) or
  /// "mooney_rivlin" (E, nu | c1, c2, kappa); exactly one parameter set. Hyperelastic models need plane
  /// strain or 3D. With the model's own constants, young/poisson get the small-strain equivalent.
  MaterialSpec read_material(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    MaterialSpec material;
    material.key = path;
    const std::string model_key = child(path, "model");
    if (const toml::node* n = t.get("model")) {
      material.model = as_string(*n, model_key);
      if (material.model != "linear_elastic" && material.model != "neo_hookean" && material.model != "mooney_rivlin") {
        fail(model_key, "expected \"linear_elastic\", \"neo_hookean\" or \"mooney_rivlin\", got " +
                            in_quotes(material.model));
      }
    }
    if (material.model == "linear_elastic") {
      // A hyperelastic constant without its model: say which model it belongs to.
      for (std::string_view k : {"mu", "lambda", "c1", "c2", "kappa"}) {
        if (!t.get(k)) continue;
        const bool neo_key = k == "mu" || k == "lambda";
        fail(child(path, k), "unknown key " + in_quotes(k) + " for model \"linear_elastic\" (" +
                                 (neo_key ? "mu, lambda are constants of model = \"neo_hookean\""
                                          : "c1, c2, kappa are constants of model = \"mooney_rivlin\"") +
                                 "); allowed keys in " + path + ": model, E, nu, group");
      }
      check_keys(t, path, {"model", "E", "nu", "group"});
      read_young_poisson(t, path, material);
      return material;
    }
    if (spec.model == AnalysisModel::kPlaneStress) {
      fail(model_key, "the hyperelastic model " + in_quotes(material.model) +
                          " needs problem.model = \"plane_strain\" or \"axisymmetric\" (or dimension = 3), got "
                          "\"plane_stress\"");
    }
    const bool neo = material.model == "neo_hookean";
    const std::vector<std::string_view> own =
        neo ? std::vector<std::string_view>{"mu", "lambda"} : std::vector<std::string_view>{"c1", "c2", "kappa"};
    if (neo) {
      check_keys(t, path, {"model", "E", "nu", "mu", "lambda", "group"});
    } else {
      check_keys(t, path, {"model", "E", "nu", "c1", "c2", "kappa", "group"});
    }
    // Exactly one parameter set: (E, nu) or the model's own constants.
    const std::string_view given_young = t.get("E") ? "E" : t.get("nu") ? "nu" : "";
    std::string_view given_own;
    std::string own_list;
    for (std::string_view k : own) {
      if (given_own.empty() && t.get(k)) given_own = k;
      own_list += (own_list.empty() ? "" : ", ") + std::string(k);
    }
    if (!given_young.empty() && !given_own.empty()) {
      fail(child(path, given_own), "give either E, nu or " + own_list + " for " + in_quotes(material.model) +
                                       ", not both (" + std::string(given_young) + " is also given)");
    }
    if (given_own.empty()) {
      if (given_young.empty()) {
        fail(path, "missing material parameters (expected E, nu or " + own_list + " for " +
                       in_quotes(material.model) + ")");
      }
      read_young_poisson(t, path, material);
      return material;
    }
    material.own_constants = true;
    auto constant = [&](std::string_view name, const std::string& what) {
      return as_number(required(t, path, name, what), child(path, name));
    };
    double mu = 0.0, lambda = 0.0;  // small-strain equivalents
    if (neo) {
      material.mu = constant("mu", "the shear modulus, a number > 0");
      if (!(material.mu > 0.0)) fail(child(path, "mu"), "expected a number > 0, got " + format_number(material.mu));
      material.lambda = constant("lambda", "the Lame constant, a number > -2 mu / 3");
      if (!(material.lambda + 2.0 * material.mu / 3.0 > 0.0)) {
        fail(child(path, "lambda"), "expected a number > -2 mu / 3 = " + format_number(-2.0 * material.mu / 3.0) +
                                        " (a positive bulk modulus lambda + 2 mu / 3), got " +
                                        format_number(material.lambda));
      }
      mu = material.mu;
      lambda = material.lambda;
    } else {
      material.c1 = constant("c1", "a number >= 0");
      if (!(material.c1 >= 0.0)) fail(child(path, "c1"), "expected a number >= 0, got " + format_number(material.c1));
      material.c2 = constant("c2", "a number >= 0");
      if (!(material.c2 >= 0.0)) fail(child(path, "c2"), "expected a number >= 0, got " + format_number(material.c2));
      if (!(material.c1 + material.c2 > 0.0)) {
        fail(child(path, "c2"), "expected c1 + c2 > 0 (the shear modulus is 2 (c1 + c2)), got c1 = c2 = 0");
      }
      material.kappa = constant("kappa", "the bulk modulus, a number > 0");
      if (!(material.kappa > 0.0)) {
        fail(child(path, "kappa"), "expected a number > 0, got " + format_number(material.kappa));
      }
      mu = 2.0 * (material.c1 + material.c2);
      lambda = material.kappa - 2.0 * mu / 3.0;
    }
    material.young = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
    material.poisson = lambda / (2.0 * (lambda + mu));
    return material;
  }

  void read_young_poisson(const toml::table& t, const std::string& path, MaterialSpec& material) const {
    const std::string e_key = child(path, "E");
    material.young = as_number(required(t, path, "E", "Young's modulus, a number > 0"), e_key);
    if (!(material.young > 0.0)) fail(e_key, "expected a number > 0, got " + format_number(material.young));

    const std::string nu_key = child(path, "nu");
    material.poisson = as_number(required(t, path, "nu", "Poisson's ratio, a number in (-1, 0.5)"), nu_key);
    if (!(material.poisson > -1.0 && material.poisson < 0.5)) {
      fail(nu_key, "expected a number in (-1, 0.5), got " + format_number(material.poisson));
    }
  }

  DirichletSpec read_dirichlet(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path, {"boundary", "ux", "uy", "uz", "factors"});
    DirichletSpec d;
    d.key = path;
    d.group = boundary(t, path);
    constexpr std::string_view components[3] = {"ux", "uy", "uz"};
    bool any = false;
    for (int i = 0; i < 3; ++i) {
      const toml::node* n = t.get(components[i]);
      if (!n) continue;
      const std::string key = child(path, components[i]);
      if (i >= spec.dim) fail(key, "uz is only allowed in 3D (problem.dimension = 3), got problem.dimension = 2");
      d.value[i] = as_load_value(*n, key);
      any = true;
    }
    if (!any) {
      fail(path, std::string("expected at least one imposed component (") + (spec.dim == 3 ? "ux, uy, uz" : "ux, uy") +
                     "), got none");
    }
    if (const toml::node* n = t.get("factors")) d.factors = as_factors(*n, child(path, "factors"), spec);
    return d;
  }

  /// [[body.traction]]: `traction` (t) or `total_force` (F, the resultant), exactly one of the two.
  TractionSpec read_traction(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path, {"boundary", "traction", "total_force", "factors"});
    TractionSpec s;
    s.key = path;
    s.group = boundary(t, path);
    const toml::node* traction = t.get("traction");
    const toml::node* total = t.get("total_force");
    const std::string numbers = std::to_string(spec.dim) + " numbers";
    if (traction && total) {
      fail(child(path, "total_force"), "expected either traction or total_force (one of the two), got both");
    }
    if (!traction && !total) {
      fail(path, "missing required key traction or total_force (expected " + numbers +
                     ": the traction, or the resultant force on the boundary), got neither");
    }
    s.input = total ? TractionInput::kTotalForce : TractionInput::kTraction;
    if (total) {
      for (double f : as_vector(*total, child(path, "total_force"), spec.dim)) s.traction.push_back(LoadValue{f, {}});
    } else {
      s.traction = as_load_vector(*traction, child(path, "traction"), spec.dim);
    }
    if (const toml::node* n = t.get("factors")) s.factors = as_factors(*n, child(path, "factors"), spec);
    return s;
  }

  /// [[body.point_load]]: `force` at every node of the physical point group `group` (checked with the mesh).
  PointLoadSpec read_point_load(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path, {"group", "force", "factors"});
    PointLoadSpec s;
    s.key = path;
    s.group = as_nonempty_string(required(t, path, "group", "the name of a physical point group"), child(path, "group"));
    s.force = as_vector(required(t, path, "force", std::to_string(spec.dim) + " numbers"), child(path, "force"),
                        spec.dim);
    if (const toml::node* n = t.get("factors")) s.factors = as_factors(*n, child(path, "factors"), spec);
    return s;
  }

  PressureSpec read_pressure(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path, {"boundary", "pressure", "factors"});
    PressureSpec s;
    s.key = path;
    s.group = boundary(t, path);
    s.pressure = as_load_value(required(t, path, "pressure", "a number or an expression"), child(path, "pressure"));
    if (const toml::node* n = t.get("factors")) s.factors = as_factors(*n, child(path, "factors"), spec);
    return s;
  }

  /// Every body must be held: by a [[body.dirichlet]] of its own, by a [[contact]] with an obstacle,
  /// or by a [[contact]] with another body that is held (transitively). A body held by nothing is free
  /// to move rigidly whatever the loads, and the solve could only fail: an input error, found before
  /// any mesh is read. (This needs no mesh; a body whose Dirichlet conditions leave some rigid motion
  /// free, such as uy alone, is found by the solve: SolveError.)
  void check_held(const ProblemSpec& spec) const {
    const std::size_t n = spec.bodies.size();
    auto index_of = [&](const std::string& name) {
      for (std::size_t i = 0; i < n; ++i)
        if (spec.bodies[i].name == name) return i;
      return n;
    };
    std::vector<bool> held(n, false), in_pair(n, false);
    for (std::size_t i = 0; i < n; ++i) held[i] = !spec.bodies[i].dirichlet.empty();
    for (const ContactSpec& c : spec.contacts) {
      const std::size_t a = index_of(c.body_a);
      const std::size_t b = c.obstacle ? n : index_of(c.body_b);
      if (a < n && c.obstacle) held[a] = true;
      if (a < n && b < n && a != b) in_pair[a] = in_pair[b] = true;
    }
    for (bool changed = true; changed;) {  // a contact with a held body holds
      changed = false;
      for (const ContactSpec& c : spec.contacts) {
        const std::size_t a = index_of(c.body_a);
        const std::size_t b = c.obstacle ? n : index_of(c.body_b);
        if (a < n && b < n && held[a] != held[b]) {
          held[a] = held[b] = true;
          changed = true;
        }
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (held[i]) continue;
      const BodySpec& body = spec.bodies[i];
      fail(body.key, "body " + in_quotes(body.name) + " has no [[body.dirichlet]] and " +
                         (in_pair[i] ? "its [[contact]] pairs link it only to bodies that nothing holds either (no "
                                       "Dirichlet condition, no obstacle among them)"
                                     : "is in no [[contact]] with another body or an obstacle") +
                         ": nothing holds it against rigid motion (expected a Dirichlet condition on it or on a body "
                         "it is in contact with, or a contact with an obstacle)");
    }
  }

  // ---- contact ----

  /// [[contact]]: optional; surfaces name declared bodies, names are unique.
  void read_contacts(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("contact");
    if (!node) return;
    const toml::array& list = as_table_array(*node, "contact", "[[contact]]");
    for (std::size_t i = 0; i < list.size(); ++i) {
      spec.contacts.push_back(read_contact(*list[i].as_table(), indexed("contact", i), i, spec));
    }
    // Checked once all are read: an explicit name may take the default name of another contact.
    for (std::size_t i = 0; i < spec.contacts.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (spec.contacts[j].name == spec.contacts[i].name) {
          fail(spec.contacts[i].key + ".name", "duplicate contact name " + in_quotes(spec.contacts[i].name) +
                                                   " (already used by " + spec.contacts[j].key + ")");
        }
      }
    }
  }

  ContactSpec read_contact(const toml::table& t, const std::string& path, std::size_t index,
                           const ProblemSpec& spec) const {
    check_keys(t, path,
               {"name", "a", "b", "obstacle", "mode", "slave", "search_distance", "friction", "mu", "tau", "alpha",
                "geometry"});
    ContactSpec c;
    c.key = path;

    c.name = "contact" + std::to_string(index);
    if (const toml::node* n = t.get("name")) {
      const std::string key = child(path, "name");
      c.name = as_string(*n, key);
      if (!valid_name(c.name)) {
        fail(key, "expected a non-empty name of letters, digits, '_' and '-', got " + in_quotes(c.name));
      }
    }

    surface(required(t, path, "a", "a surface \"<body>.<boundary>\""), child(path, "a"), spec, c.body_a,
            c.boundary_a);

    const toml::node* b = t.get("b");
    const toml::node* obstacle = t.get("obstacle");
    if (b && obstacle) {
      fail(path, "expected either b (another surface) or [contact.obstacle] (a rigid obstacle), got both");
    }
    if (!b && !obstacle) {
      fail(path, "missing the opposite surface (expected b = \"<body>.<boundary>\" or a table "
                 "[contact.obstacle])");
    }
    if (b) surface(*b, child(path, "b"), spec, c.body_b, c.boundary_b);
    if (obstacle) {
      const std::string key = child(path, "obstacle");
      c.obstacle = read_obstacle(as_table(*obstacle, key), key, spec);
    }

    if (const toml::node* n = t.get("mode")) {
      const std::string key = child(path, "mode");
      c.mode = as_string(*n, key);
      if (c.mode != "symmetric" && c.mode != "one-pass") {
        fail(key, "expected \"symmetric\" or \"one-pass\", got " + in_quotes(c.mode));
      }
    }

    if (const toml::node* n = t.get("slave")) {
      const std::string key = child(path, "slave");
      c.slave = as_string(*n, key);
      if (c.slave != "a" && c.slave != "b") fail(key, "expected \"a\" or \"b\", got " + in_quotes(c.slave));
      if (c.mode != "one-pass") {
        fail(key, "slave is only used with mode = \"one-pass\", got mode = " + in_quotes(c.mode) +
                      " (the symmetric mode writes the constraints from both surfaces in turn, so there is no "
                      "slave to choose)");
      }
      if (c.obstacle && c.slave != "a") {
        fail(key, "expected \"a\" with an obstacle (the rigid obstacle has no unknowns to constrain), got " +
                      in_quotes(c.slave));
      }
    }

    if (const toml::node* n = t.get("search_distance")) {
      const std::string key = child(path, "search_distance");
      c.search_distance = as_number(*n, key);
      if (!(c.search_distance > 0.0)) fail(key, "expected a number > 0, got " + format_number(c.search_distance));
    }

    if (const toml::node* n = t.get("geometry")) {
      const std::string key = child(path, "geometry");
      const std::string g = as_string(*n, key);
      if (g != "current" && g != "reference") fail(key, "expected \"current\" or \"reference\", got " + in_quotes(g));
      c.geometry = g == "reference" ? ContactGeometry::kReference : ContactGeometry::kCurrent;
    }

    read_friction(t, path, c);
    return c;
  }

  /// friction, mu, tau, alpha of a [[contact]]: `mu` belongs to "coulomb", `tau` to "tresca", `alpha` to
  /// both; a key of another law is an error naming its law. With an obstacle too (the obstacle is fixed).
  void read_friction(const toml::table& t, const std::string& path, ContactSpec& c) const {
    const toml::node* friction = t.get("friction");
    if (friction) {
      const std::string key = child(path, "friction");
      c.friction = as_string(*friction, key);
      if (c.friction != "none" && c.friction != "tresca" && c.friction != "coulomb") {
        fail(key, "expected \"none\", \"tresca\" or \"coulomb\", got " + in_quotes(c.friction));
      }
    }
    const bool tresca = c.friction == "tresca";
    const bool coulomb = c.friction == "coulomb";
    const std::string got = "got friction = " + in_quotes(c.friction) + (friction ? "" : " (the default)");
    if (t.get("mu") && !coulomb) {
      fail(child(path, "mu"), "mu (the friction coefficient) is only used with friction = \"coulomb\", " + got);
    }
    if (t.get("tau") && !tresca) {
      fail(child(path, "tau"), "tau (the sliding threshold) is only used with friction = \"tresca\", " + got);
    }
    if (t.get("alpha") && !tresca && !coulomb) {
      fail(child(path, "alpha"),
           "alpha (the regularisation of the slip) is only used with friction = \"tresca\" or \"coulomb\", " + got);
    }

    if (coulomb) {
      const std::string key = child(path, "mu");
      c.mu = as_number(required(t, path, "mu", "the friction coefficient, a number >= 0, with friction = \"coulomb\""),
                       key);
      if (!(c.mu >= 0.0)) fail(key, "expected a number >= 0, got " + format_number(c.mu));
    }
    if (tresca) {
      const std::string key = child(path, "tau");
      c.tau = as_number(required(t, path, "tau", "the sliding threshold, a number >= 0, with friction = \"tresca\""),
                        key);
      if (!(c.tau >= 0.0)) fail(key, "expected a number >= 0, got " + format_number(c.tau));
    }
    if (const toml::node* n = t.get("alpha")) {
      const std::string key = child(path, "alpha");
      c.alpha = as_number(*n, key);
      if (!(c.alpha > 0.0)) fail(key, "expected a number > 0, got " + format_number(c.alpha));
    }
  }

  /// A contact surface "<body>.<boundary>", split at the first dot (body names have none). The body
  /// must be declared; the boundary group is checked when the meshes are loaded.
  void surface(const toml::node& node, const std::string& key, const ProblemSpec& spec, std::string& body,
               std::string& group) const {
    const std::string s = as_string(node, key);
    const std::size_t dot = s.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == s.size()) {
      fail(key, "expected \"<body>.<boundary>\" (a body name, a dot, a physical group of its boundary), got " +
                    in_quotes(s));
    }
    body = s.substr(0, dot);
    group = s.substr(dot + 1);
    std::string names;
    for (const BodySpec& declared : spec.bodies) {
      if (declared.name == body) return;
      names += (names.empty() ? "" : ", ") + declared.name;
    }
    fail(key, "unknown body " + in_quotes(body) + " in " + in_quotes(s) + "; declared bodies: " + names);
  }

  /// [contact.obstacle]: the keys allowed depend on `type`.
  ObstacleSpec read_obstacle(const toml::table& t, const std::string& path, const ProblemSpec& spec) const {
    check_keys(t, path, {"type", "point", "normal", "center", "radius", "inside", "mesh", "boundary"});
    ObstacleSpec o;
    o.key = path;

    const std::string type_key = child(path, "type");
    o.type = as_string(required(t, path, "type", "\"plane\", \"circle\", \"sphere\" or \"mesh\""), type_key);
    // Named lists, so that their arrays live as long as `keys` (an initializer_list does not own them).
    const KeyList plane_keys = {"type", "point", "normal"};
    const KeyList round_keys = {"type", "center", "radius", "inside"};
    const KeyList mesh_keys = {"type", "mesh", "boundary"};
    KeyList keys;
    if (o.type == "plane") {
      keys = plane_keys;
    } else if (o.type == "circle" || o.type == "sphere") {
      const bool is_circle = o.type == "circle";
      if (spec.dim != (is_circle ? 2 : 3)) {
        fail(type_key, in_quotes(o.type) + " is only allowed in " + (is_circle ? "2D" : "3D") +
                           " (problem.dimension = " + (is_circle ? "2" : "3") + "), got problem.dimension = " +
                           std::to_string(spec.dim) + "; use " + (is_circle ? "\"sphere\"" : "\"circle\"") +
                           " in " + (is_circle ? "3D" : "2D"));
      }
      keys = round_keys;
    } else if (o.type == "mesh") {
      keys = mesh_keys;
    } else {
      fail(type_key, std::string("expected \"plane\", \"circle\" (2D), \"sphere\" (3D) or \"mesh\", got ") +
                         in_quotes(o.type));
    }
    for (auto&& [key, value] : t) {
      (void)value;
      const std::string_view name = key.str();
      if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
        fail(child(path, name), "key " + in_quotes(name) + " does not belong to an obstacle of type " +
                                    in_quotes(o.type) + "; keys of this type: " + join(keys, ", "));
      }
    }

    const std::string vector_what = std::to_string(spec.dim) + " numbers";
    if (o.type == "plane") {
      o.point = as_vector(required(t, path, "point", vector_what), child(path, "point"), spec.dim);
      const std::string normal_key = child(path, "normal");
      o.normal = as_vector(required(t, path, "normal", vector_what + ", nonzero"), normal_key, spec.dim);
      if (std::all_of(o.normal.begin(), o.normal.end(), [](double x) { return x == 0.0; })) {
        fail(normal_key, "expected a nonzero vector, got the zero vector");
      }
    } else if (o.type == "mesh") {
      read_mesh(t, path, o.mesh_file, o.mesh_path);
      o.boundary = boundary(t, path);
    } else {
      o.center = as_vector(required(t, path, "center", vector_what), child(path, "center"), spec.dim);
      const std::string radius_key = child(path, "radius");
      o.radius = as_number(required(t, path, "radius", "a number > 0"), radius_key);
      if (!(o.radius > 0.0)) fail(radius_key, "expected a number > 0, got " + format_number(o.radius));
      if (const toml::node* n = t.get("inside")) o.inside = as_bool(*n, child(path, "inside"));
    }
    return o;
  }

  /// [contact_solver] linear_solver.
  void read_linear_solver(const toml::table& t, ProblemSpec& spec) const {
    const toml::node* n = t.get("linear_solver");
    if (!n) return;
    const std::string key = "contact_solver.linear_solver";
    const std::string v = as_string(*n, key);
    const std::map<std::string, LinearSolverChoice> choices = {{"automatic", LinearSolverChoice::kAutomatic},
                                                               {"direct", LinearSolverChoice::kDirect},
                                                               {"iterative", LinearSolverChoice::kIterative}};
    const auto it = choices.find(v);
    if (it == choices.end()) fail(key, "expected \"automatic\", \"direct\" or \"iterative\", got \"" + v + "\"");
    spec.linear_solver = it->second;
  }

  /// [contact_solver] `name`, one of the names `parse` knows (`expected` lists them for the message), into `out`.
  template <class Choice>
  void read_choice(const toml::table& t, const char* name, std::optional<Choice> (*parse)(const std::string&),
                   const std::string& expected, Choice& out) const {
    const toml::node* n = t.get(name);
    if (!n) return;
    const std::string key = std::string("contact_solver.") + name;
    const std::string v = as_string(*n, key);
    const std::optional<Choice> choice = parse(v);
    if (!choice) fail(key, "expected " + expected + ", got \"" + v + "\"");
    out = *choice;
  }

  void read_contact_solver(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("contact_solver");
    if (!node) return;
    const toml::table& t = as_table(*node, "contact_solver");
    for (const char* replaced : {"dual_solve", "dual_optimizer"})
      if (t.get(replaced))
        fail(std::string("contact_solver.") + replaced,
             "replaced by subproblem_solver = \"dual_interior_point\" (the default), \"dual_ipopt\" (dual_optimizer = "
             "\"ipopt\") or \"primal_ipopt\" (dual_solve = false)");
    check_keys(t, "contact_solver",
               {"geometry_tolerance", "max_geometry_iterations", "coulomb_tolerance", "converge_past_tolerance",
                "max_coulomb_iterations", "coulomb_update", "static_condensation", "subproblem_solver", "warm_start",
                "ipopt_problem", "max_step_cuts", "linear_solver"});
    read_linear_solver(t, spec);
    FrictionalOptions& f = spec.contact_solver.friction;
    ContactSolveOptions& s = f.contact;
    if (const toml::node* n = t.get("geometry_tolerance")) {
      const std::string key = "contact_solver.geometry_tolerance";
      s.geometry_tolerance = as_number(*n, key);
      if (!(s.geometry_tolerance > 0.0)) fail(key, "expected a number > 0, got " + format_number(s.geometry_tolerance));
    }
    if (const toml::node* n = t.get("max_geometry_iterations")) {
      s.max_geometry_iterations = as_count(*n, "contact_solver.max_geometry_iterations");
    }
    if (const toml::node* n = t.get("coulomb_tolerance")) {
      const std::string key = "contact_solver.coulomb_tolerance";
      f.coulomb_tolerance = as_number(*n, key);
      if (!(f.coulomb_tolerance > 0.0)) fail(key, "expected a number > 0, got " + format_number(f.coulomb_tolerance));
    }
    if (const toml::node* n = t.get("converge_past_tolerance"))
      f.converge_past_tolerance = as_bool(*n, "contact_solver.converge_past_tolerance");
    if (const toml::node* n = t.get("max_coulomb_iterations")) {
      f.max_coulomb_iterations = as_count(*n, "contact_solver.max_coulomb_iterations");
    }
    read_choice(t, "coulomb_update", parse_coulomb_update, "\"inside_optimizer\" or \"between_solves\"",
                f.coulomb_update);
    if (const toml::node* n = t.get("static_condensation"))
      s.static_condensation = as_bool(*n, "contact_solver.static_condensation");
    read_choice(t, "subproblem_solver", parse_subproblem_solver,
                "\"dual_interior_point\", \"dual_ipopt\", \"primal_ipopt\" or \"primal_interior_point\"",
                s.subproblem_solver);
    read_choice(t, "warm_start", parse_warm_start, "\"active_set\" or \"interior_point\"", s.warm_start);
    read_choice(t, "ipopt_problem", parse_ipopt_problem, "\"automatic\", \"condensed\" or \"uncondensed\"",
                s.ipopt_problem);
    if (const toml::node* n = t.get("max_step_cuts")) {
      const std::string key = "contact_solver.max_step_cuts";
      const std::int64_t c = as_integer(*n, key);
      // 2^-20 of a step is already far below any useful increment.
      if (c < 0 || c > 20) fail(key, "expected an integer in [0, 20], got " + std::to_string(c));
      spec.contact_solver.max_step_cuts = static_cast<int>(c);
    }
  }

  /// [ipopt]: any option, passed to IPOPT as it is, sorted by the TOML type of its value. Names, types
  /// and ranges are checked by read_problem_file() (check_ipopt_section()).
  void read_ipopt(const toml::table& root, ProblemSpec& spec) const {
    const toml::node* node = root.get("ipopt");
    if (!node) return;
    const toml::table& t = as_table(*node, "ipopt");
    IpoptOptions& s = spec.contact_solver.friction.contact.ipopt;
    for (auto&& [k, value] : t) {
      const std::string name(k.str());
      const std::string key = child("ipopt", name);
      if (value.is_string()) {
        s.string_options[name] = *value.value<std::string>();
      } else if (value.is_integer()) {
        const std::int64_t i = *value.value<std::int64_t>();
        if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
          fail(key, "expected an integer that fits in an int (IPOPT integer option), got " + std::to_string(i));
        }
        s.integer_options[name] = static_cast<int>(i);
      } else if (value.is_floating_point()) {
        s.numeric_options[name] = as_number(value, key);
      } else {
        fail(key, "expected a string, an integer or a floating-point number (an IPOPT option value), got " +
                      describe(value));
      }
    }
  }

  std::string file_;
  std::string base_dir_;
};


}  // namespace

ProblemSpec parse_problem(const std::string& toml_text, const std::string& file_name, const std::string& base_dir) {
  return read_problem_table(parse_toml(toml_text, file_name), file_name, base_dir);
}

ProblemSpec read_problem_table(const toml::table& root, const std::string& file_name, const std::string& base_dir) {
  return Reader(file_name, base_dir).read(root);
}

std::string read_problem_text(const std::string& path) {
  // Only a regular file of bounded size: a FIFO would block, /dev/zero would never end.
  if (const std::string problem = input_file_problem(path, kMaxProblemFileBytes); !problem.empty())
    throw InputError(path, "", "cannot open the problem file: it " + problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the problem file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "error while reading the problem file");
  return text.str();
}

std::string problem_folder(const std::string& path) {
  std::error_code ec;
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  const fs::path absolute = fs::absolute(folder, ec);
  return (ec ? folder : absolute).lexically_normal().string();
}

}  // namespace symcontact
