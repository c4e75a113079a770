#include "symcontact/mesh/gmsh_io.hpp"

#include <gmsh.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "symcontact/core/error.hpp"
#include "symcontact/core/input_file.hpp"
#include "symcontact/mesh/geo_commands.hpp"
#include "symcontact/mesh/mesh_topology.hpp"
#include "symcontact/mesh/msh_validation.hpp"

namespace symcontact {

const MeshFile::Group* MeshFile::find(const std::string& name, int dim) const {
  for (const auto& g : groups)
    if (g.dim == dim && g.name == name) return &g;
  return nullptr;
}

namespace {

/// Initialises Gmsh for the lifetime of the object (Gmsh itself is a process-wide singleton).
class GmshInstance {
 public:
  /// `parameters` are passed as Gmsh's command line passes `-setnumber name value`.
  GmshInstance(bool verbose, const std::map<std::string, double>& parameters) {
    std::vector<std::string> args{"symcontact"};
    for (const auto& [name, value] : parameters) {
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", value);  // read back exactly by Gmsh's atof
      args.insert(args.end(), {"-setnumber", name, text});
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (parameters.empty())
      gmsh::initialize(0, nullptr, false);
    else
      gmsh::initialize(static_cast<int>(args.size()), argv.data(), false);
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::option::setNumber("General.Verbosity", verbose ? 5 : 1);
    // Gmsh's API throws its errors as std::string by default (General.AbortOnError = 2), also from
    // inside its OpenMP meshing loops, where no handler can catch them and the process aborts. With 0,
    // errors are only logged: the log is read after each call (throw_on_gmsh_errors()).
    gmsh::option::setNumber("General.AbortOnError", 0);
    gmsh::logger::start();
  }
  ~GmshInstance() {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
    }
  }
  GmshInstance(const GmshInstance&) = delete;
  GmshInstance& operator=(const GmshInstance&) = delete;
};

std::string describe_gmsh_error(const std::string& thrown) {
  std::string last;
  try {
    gmsh::logger::getLastError(last);
  } catch (...) {
  }
  return !thrown.empty() ? thrown : (!last.empty() ? last : std::string("unknown Gmsh error"));
}

/// Throws InputError(path) carrying the errors Gmsh has logged since Gmsh was initialised, if any
/// ("while meshing it: Error: The 1D mesh seems not to be forming a closed loop ...").
void throw_on_gmsh_errors(const std::string& path, const std::string& doing) {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  std::string errors;
  int count = 0;
  for (const std::string& line : log) {
    if (line.rfind("Error", 0) != 0) continue;
    if (++count <= 5) errors += (errors.empty() ? "" : "; ") + line;
  }
  if (count == 0) return;
  if (count > 5) errors += "; and " + std::to_string(count - 5) + " more";
  throw InputError(path, "", "Gmsh failed while " + doing + ": " + errors);
}

/// "1e-05", "4e+10", "5000000": short and readable (what a person typed, not 17 digits).
std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// The cells Gmsh makes of the predicted simplices under the .geo's own options, and how they are counted:
/// subdivision (Mesh.SubdivisionAlgorithm) splits each triangle into 3 quadrilaterals (1) and each
/// tetrahedron into 4 hexahedra (2); recombining every surface (Mesh.RecombineAll, 2D) pairs the triangles
/// off into about half as many quadrilaterals. Recombination asked for surface by surface is not seen:
/// those meshes are counted as triangles, about twice their cells.
struct PredictedCells {
  double count;
  std::string how;  ///< "triangles (2·A/h²" …, closed by the caller
};

double gmsh_number(const std::string& name) {
  double v = 0.0;
  gmsh::option::getNumber(name, v);
  return v;
}

PredictedCells predicted_cells(int dim, double simplices) {
  const std::string simplex = dim == 2 ? "triangles, 2·A/h²" : "tetrahedra, 6·V/h³";
  const int subdivision = static_cast<int>(gmsh_number("Mesh.SubdivisionAlgorithm"));
  if (dim == 2 && subdivision == 1) return {3 * simplices, "quadrilaterals (three per one of the " + simplex};
  if (dim == 3 && subdivision == 2) return {4 * simplices, "hexahedra (four per one of the " + simplex};
  if (dim == 2 && gmsh_number("Mesh.RecombineAll") != 0)
    return {simplices / 2, "quadrilaterals (one per two of the " + simplex};
  return {simplices, dim == 2 ? "triangles (2·A/h²" : "tetrahedra (6·V/h³"};
}

/// Refuses to mesh when the cells predicted over the model's bounding box (predicted_cell_count(), as the
/// .geo's options turn them into cells) exceed the limit.
void check_predicted_size(const std::string& path, const MeshReadOptions& opt) {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double extent[3] = {x1 - x0, y1 - y0, z1 - z0};
  const PredictedCells cells = predicted_cells(opt.dim, predicted_cell_count(opt.dim, extent, opt.mesh_size));
  if (!(cells.count > opt.max_predicted_cells)) return;  // also a NaN box (an empty model): Gmsh will say
  const std::string box = short_number(extent[0]) + " × " + short_number(extent[1]) +
                          (opt.dim == 3 ? " × " + short_number(extent[2]) : std::string());
  throw InputError(path, "",
                   opt.mesh_size_key + " = " + short_number(opt.mesh_size) + " would make about " +
                       short_number(cells.count) + " " + cells.how + " over the bounding box " + box +
                       "), more than the limit of " + short_number(opt.max_predicted_cells) +
                       " cells; use a larger mesh size, or pass --allow-large-mesh to mesh it anyway");
}

/// Gmsh's name of element type `type` ("Triangle 10", ...).
std::string gmsh_type_name(int type) {
  std::string name;
  int d, o, nn, np;
  std::vector<double> lc;
  gmsh::model::mesh::getElementProperties(type, name, d, o, nn, lc, np);
  return name;
}

/// Whether Gmsh has built pyramids in this process. Gmsh 4.8 keeps state across gmsh::finalize() that its
/// pyramid builder reads after it is freed once Gmsh is initialised again (an Eigen assertion aborts the
/// process, in RelocateVerticesOfPyramids()): a second .geo whose volumes are bounded by quadrilaterals is
/// refused instead (refuse_second_pyramid_meshing()).
std::atomic<bool> gmsh_built_pyramids{false};

/// Whether the current Gmsh model holds elements of `dim` whose type satisfies `pred`.
template <class Pred>
bool has_elements(int dim, Pred pred) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, dim, -1);
  for (int t : types) {
    CellType ct;
    if (from_gmsh_element_type(t, ct) && pred(ct)) return true;
  }
  return false;
}

/// After pyramids in this process, meshes the surfaces first and refuses a 3D mesh with quadrilateral faces,
/// where Gmsh would build pyramids again (gmsh_built_pyramids).
void refuse_second_pyramid_meshing(const std::string& path, const MeshReadOptions& opt) {
  if (!gmsh_built_pyramids || opt.dim != 3) return;
  gmsh::model::mesh::generate(2);
  throw_on_gmsh_errors(path, "meshing the geometry");
  if (has_elements(2, [](CellType t) { return cell_shape(t) == CellShape::kTensor; }))
    throw InputError(path, "", "Gmsh 4.8 cannot build pyramids twice in one process, and a .geo meshed before "
                                "in this run already made some; mesh this file to a .msh once (gmsh -3 -order " +
                                    std::to_string(opt.order) + " " + path + ") and use the .msh");
}

/// The meshes of the .geo files that built pyramids in this process, by geo_read_key(): read again (a
/// Python script building several models of one hex-dominant body) they are taken from here, as Gmsh
/// cannot build them a second time (gmsh_built_pyramids).
std::mutex pyramid_meshes_mutex;
std::map<std::string, MeshFile> pyramid_meshes;

/// What a .geo's mesh depends on: its path, its text and the reading options (not the text of the files it
/// includes).
std::string geo_read_key(const std::string& path, const MeshReadOptions& o) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream key;
  key << path << '\n' << in.rdbuf() << '\n' << o.dim << ' ' << o.order << ' ' << std::hexfloat << o.mesh_size << ' '
      << o.max_predicted_cells << ' ' << static_cast<int>(o.geo_commands);
  for (const auto& [name, value] : o.geo_parameters) key << ' ' << name << '=' << value;
  return key.str();
}

std::optional<MeshFile> remembered_pyramid_mesh(const std::string& key) {
  const std::lock_guard<std::mutex> lock(pyramid_meshes_mutex);
  const auto it = pyramid_meshes.find(key);
  if (it == pyramid_meshes.end()) return std::nullopt;
  return it->second;
}

void remember_pyramid_mesh(const std::string& key, const MeshFile& f) {
  bool pyramids = false;
  for (const MeshFile::Block& b : f.all_cells) pyramids = pyramids || cell_shape(b.type) == CellShape::kPyramid;
  if (!pyramids) return;
  const std::lock_guard<std::mutex> lock(pyramid_meshes_mutex);
  pyramid_meshes.emplace(key, f);
}

MeshFile read_with_gmsh(const std::string& path, const MeshReadOptions& opt, bool is_geo) {
  gmsh::open(path);
  throw_on_gmsh_errors(path, "reading the file");
  if (is_geo) {
    if (opt.mesh_size > 0) {
      if (opt.max_predicted_cells > 0) check_predicted_size(path, opt);
      gmsh::option::setNumber("Mesh.MeshSizeMax", opt.mesh_size);
    }
    refuse_second_pyramid_meshing(path, opt);
    gmsh::model::mesh::generate(opt.dim);
    throw_on_gmsh_errors(path, "meshing the geometry");
    if (has_elements(3, [](CellType t) { return cell_shape(t) == CellShape::kPyramid; })) gmsh_built_pyramids = true;
  }
  // Raise or lower the element order when the file's differs from the problem's.
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, opt.dim, -1);
    bool need = false;
    for (int t : types) {
      CellType ct;
      if (from_gmsh_element_type(t, ct) && cell_order(ct) != opt.order) need = true;
    }
    if (need) {
      gmsh::model::mesh::setOrder(opt.order);
      throw_on_gmsh_errors(path, "changing the element order");
    }
  }

  MeshFile f;
  f.path = path;
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, param;
  gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, true, false);
  if (node_tags.empty()) throw InputError(path, "", "the mesh has no nodes");
  // Number nodes by increasing tag: Gmsh returns them in an order that can change from run to run,
  // and results must not (same input, same numbering, same output).
  std::vector<std::size_t> order(node_tags.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return node_tags[a] < node_tags[b]; });
  std::unordered_map<std::size_t, Index> index_of;
  index_of.reserve(node_tags.size());
  f.x.resize(3, static_cast<Index>(node_tags.size()));
  f.node_tags.resize(node_tags.size());
  for (std::size_t j = 0; j < order.size(); ++j) {
    const std::size_t k = order[j];
    index_of[node_tags[k]] = static_cast<Index>(j);
    f.node_tags[j] = static_cast<Index>(node_tags[k]);
    for (int i = 0; i < 3; ++i) f.x(i, static_cast<Index>(j)) = coords[3 * k + i];
  }

  auto read_blocks = [&](int dim, int entity, std::vector<MeshFile::Block>& out) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
    for (std::size_t b = 0; b < types.size(); ++b) {
      CellType ct;
      if (!from_gmsh_element_type(types[b], ct))
        throw InputError(path, "", "unsupported element type '" + gmsh_type_name(types[b]) +
                                       "': symcontact uses triangles and quadrilaterals in 2D, tetrahedra, "
                                       "hexahedra, prisms and pyramids in 3D, of order 1 or 2 (not order 3 and "
                                       "above)");
      MeshFile::Block blk{ct, {}, {}};
      blk.nodes.reserve(nodes[b].size());
      blk.tags.assign(tags[b].begin(), tags[b].end());
      for (std::size_t t : nodes[b]) {
        auto it = index_of.find(t);
        if (it == index_of.end())
          throw InputError(path, "", "an element refers to node " + std::to_string(t) + ", which is not defined");
        blk.nodes.push_back(it->second);
      }
      out.push_back(std::move(blk));
    }
  };

  read_blocks(opt.dim, -1, f.all_cells);
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, -1);
  for (const auto& [dim, tag] : groups) {
    MeshFile::Group g;
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    if (g.name.empty()) g.name = std::to_string(tag);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int e : entities) read_blocks(dim, e, g.blocks);
    f.groups.push_back(std::move(g));
  }
  return f;
}

/// Fills m.cell_groups: every group of dimension m.dim, restricted to the cells of m (matched by element tag).
void add_cell_groups(const MeshFile& file, Mesh& m) {
  std::unordered_map<Index, Index> cell_of_tag;
  for (std::size_t c = 0; c < m.cell_tags.size(); ++c) cell_of_tag[m.cell_tags[c]] = static_cast<Index>(c);
  for (const auto& g : file.groups) {
    if (g.dim != m.dim) continue;
    std::vector<Index> cells;
    for (const auto& b : g.blocks)
      for (Index tag : b.tags)
        if (auto it = cell_of_tag.find(tag); it != cell_of_tag.end()) cells.push_back(it->second);
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    if (!cells.empty()) m.cell_groups[g.name] = std::move(cells);
  }
}

}  // namespace

MeshFile read_mesh_file(const std::string& path, const MeshReadOptions& options) {
  namespace fs = std::filesystem;
  if (const std::string problem = input_file_problem(path); !problem.empty())
    throw InputError(path, "", "cannot read the mesh file: it " + problem);
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".geo" && ext != ".msh")
    throw InputError(path, "", "expected a Gmsh .geo or .msh file, got extension '" + ext + "'");
  if (options.order != 1 && options.order != 2) throw InputError(path, "", "element order must be 1 or 2");
  if (ext == ".geo" && options.geo_commands == GeoCommands::kRefuse) check_geo_commands(path);
  // Gmsh's own parser trusts the file's structure: check it first (msh_validation.hpp).
  if (ext == ".msh") validate_msh_file(path);
  const std::string key = ext == ".geo" ? geo_read_key(path, options) : std::string();
  if (ext == ".geo")
    if (std::optional<MeshFile> f = remembered_pyramid_mesh(key)) return *f;
  GmshInstance gmsh_instance(options.verbose, ext == ".geo" ? options.geo_parameters : std::map<std::string, double>{});
  try {
    MeshFile f = read_with_gmsh(path, options, ext == ".geo");
    if (ext == ".geo") remember_pyramid_mesh(key, f);
    return f;
  } catch (const InputError&) {
    throw;
  } catch (const std::string& s) {
    throw InputError(path, "", "Gmsh could not read or mesh the file: " + describe_gmsh_error(s));
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("Gmsh could not read or mesh the file: ") + e.what());
  } catch (...) {
    throw InputError(path, "", "Gmsh could not read or mesh the file: " + describe_gmsh_error(""));
  }
}

double predicted_cell_count(int dim, const double extent[3], double h) {
  double e[3] = {std::abs(extent[0]), std::abs(extent[1]), std::abs(extent[2])};
  std::sort(e, e + 3, std::greater<double>());  // a 2D geometry may lie in any coordinate plane
  return dim == 2 ? 2.0 * e[0] * e[1] / (h * h) : 6.0 * e[0] * e[1] * e[2] / (h * h * h);
}

namespace {

/// Why a facet of group g is left out of the body although it lies on it, or "" where it is not: some of its
/// nodes are the body's and the others, outside the body's cells, all sit at the position of a body node. The
/// body's surface was then meshed with nodes of its own (duplicates: Gmsh's Geometry.AutoCoherence = 0
/// leaves them on the curves of extruded surfaces), and a contact surface or a load on the group would lose
/// part of its area without a word (Mesh::incomplete_groups). Facets of another body that shares nodes with
/// this one (a conforming interface) have their other nodes away from this body's, and facets wholly outside
/// it (a body in contact with coincident nodes) are that body's: both give "".
std::string duplicated_nodes(const MeshFile& file, const std::vector<Index>& local, const Mesh& m, const Index* facet,
                             std::size_t npf, std::unique_ptr<NodeGrid>& nodes) {
  Index outside = -1, twin = -1;
  bool any_inside = false;
  for (std::size_t a = 0; a < npf; ++a) {
    if (local[facet[a]] >= 0) {
      any_inside = true;
      continue;
    }
    if (!nodes) nodes = std::make_unique<NodeGrid>(m);
    const Index at = nodes->at(file.x.col(facet[a]).head(m.dim));
    if (at < 0) return "";
    if (outside < 0) outside = facet[a], twin = at;
  }
  if (!any_inside || outside < 0) return "";
  auto tag = [&](Index v, const std::vector<Index>& tags) {
    return std::to_string(v < static_cast<Index>(tags.size()) ? tags[v] : v + 1);
  };
  std::ostringstream e;
  e << "node " << tag(outside, file.node_tags) << " of one of its facets is not a node of the body's cells but sits "
    << "at the position of body node " << tag(twin, m.node_tags)
    << ": the mesh has duplicate nodes, and the group's facets on them are not the body's (in a .geo, "
       "Geometry.AutoCoherence = 0 makes them; remove that line, or add Coherence Mesh; after the mesh is made)";
  return e.str();
}

/// The facets of physical group g (of dimension dim − 1) whose nodes are all in the body (local: the body's
/// index of each node of the file, −1 outside), as a facet group of m of their type. A group holding facets
/// of two types (the triangles and quadrilaterals of prisms) becomes a node group, listed in
/// interior_facet_groups with the reason it cannot be a contact surface or a load. A facet partly in the body
/// through duplicate nodes puts the group in Mesh::incomplete_groups (duplicated_nodes()).
void add_facet_group(const MeshFile& file, const MeshFile::Group& g, const std::vector<Index>& local, Mesh& m) {
  std::unique_ptr<NodeGrid> coincident;
  std::map<CellType, FacetGroup> by_type;
  for (const auto& b : g.blocks) {
    bool facet_of_body = false;
    for (const CellBlock& cb : m.cell_blocks)
      for (int f = 0; f < cell_num_facets(cb.type); ++f) facet_of_body = facet_of_body || cell_facet_type(cb.type, f) == b.type;
    if (!facet_of_body) continue;
    const std::size_t npf = cell_num_nodes(b.type);
    FacetGroup& fg = by_type[b.type];
    fg.type = b.type;
    for (std::size_t k = 0; k + npf <= b.nodes.size(); k += npf) {
      bool inside = true;
      for (std::size_t a = 0; a < npf; ++a) inside = inside && local[b.nodes[k + a]] >= 0;
      if (!inside) {
        if (!m.incomplete_groups.count(g.name)) {
          std::string why = duplicated_nodes(file, local, m, &b.nodes[k], npf, coincident);
          if (!why.empty()) m.incomplete_groups[g.name] = std::move(why);
        }
        continue;
      }
      for (std::size_t a = 0; a < npf; ++a) fg.facets.push_back(local[b.nodes[k + a]]);
      if (k / npf < b.tags.size()) fg.tags.push_back(b.tags[k / npf]);
    }
  }
  for (auto it = by_type.begin(); it != by_type.end();)
    it = it->second.facets.empty() ? by_type.erase(it) : std::next(it);
  if (by_type.empty()) return;
  if (by_type.size() == 1) {
    FacetGroup& fg = by_type.begin()->second;
    if (fg.tags.size() * cell_num_nodes(*fg.type) != fg.facets.size()) fg.tags.clear();
    m.facet_groups[g.name] = std::move(fg);
    return;
  }
  std::vector<Index> nodes;
  std::string types;
  for (const auto& [t, fg] : by_type) {
    nodes.insert(nodes.end(), fg.facets.begin(), fg.facets.end());
    types += (types.empty() ? "" : " and ") + cell_name(t);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  m.node_groups[g.name] = std::move(nodes);
  m.node_group_dims[g.name] = m.dim - 1;
  m.interior_facet_groups[g.name] =
      "the group holds facets of two types (" + types + "): a contact surface or a load is made of facets of one "
      "type; make one physical group of each (a Dirichlet condition may hold its nodes)";
}

}  // namespace

Mesh extract_body(const MeshFile& file, int dim, const std::string& group, const std::string& group_key,
                  const TopologyAllowances& allow) {
  const std::vector<MeshFile::Block>* cells = &file.all_cells;
  if (!group.empty()) {
    const MeshFile::Group* g = file.find(group, dim);
    if (!g) {
      std::string known;
      for (const auto& h : file.groups)
        if (h.dim == dim) known += (known.empty() ? "" : ", ") + ("'" + h.name + "'");
      throw InputError(file.path, group_key,
                       "no physical group '" + group + "' of dimension " + std::to_string(dim) +
                           " in the mesh (groups of that dimension: " + (known.empty() ? "none" : known) + ")");
    }
    cells = &g->blocks;
  }
  Mesh m;
  m.dim = dim;
  const MeshFile::Block* first = nullptr;
  for (const auto& b : *cells) {
    if (cell_dim(b.type) != dim) continue;
    if (first && !compatible_cell_types(b.type, first->type))
      throw InputError(file.path, group_key,
                       "the body mixes element types that cannot share an edge or a face (" + cell_name(first->type) +
                           " and " + cell_name(b.type) + "): a body may mix cell types of one order whose "
                           "quadrilateral faces are of one type; make each part with its own type a body of "
                           "its own, or mesh all parts with one order");
    if (!first) first = &b;
  }
  if (!first)
    throw InputError(file.path, group_key,
                     "no " + std::to_string(dim) + "D elements in " + (group.empty() ? "the mesh" : "group '" + group + "'"));
  // Renumber the nodes used by the body's cells, in file order.
  std::vector<Index> local(file.x.cols(), -1);
  for (const auto& b : *cells)
    for (Index v : b.nodes) local[v] = 0;
  Index n = 0;
  for (auto& l : local)
    if (l == 0) l = n++;
  m.x.resize(dim, n);
  m.node_tags.resize(n);
  for (Index v = 0; v < file.x.cols(); ++v) {
    if (local[v] < 0) continue;
    m.x.col(local[v]) = file.x.col(v).head(dim);
    if (v < static_cast<Index>(file.node_tags.size())) m.node_tags[local[v]] = file.node_tags[v];
  }
  if (file.node_tags.size() != static_cast<std::size_t>(file.x.cols())) m.node_tags.clear();
  for (const auto& b : *cells) {
    if (cell_dim(b.type) != dim) continue;
    std::vector<Index> conn(b.nodes.size());
    for (std::size_t k = 0; k < conn.size(); ++k) conn[k] = local[b.nodes[k]];
    m.add_cells(b.type, conn.data(), static_cast<Index>(conn.size()) / cell_num_nodes(b.type));
    m.cell_tags.insert(m.cell_tags.end(), b.tags.begin(), b.tags.end());
  }
  add_cell_groups(file, m);
  // Lower-dimensional groups, restricted to this body.
  for (const auto& g : file.groups) {
    if (g.dim >= dim) continue;
    if (g.dim == dim - 1) {
      add_facet_group(file, g, local, m);
    } else {
      std::vector<Index> nodes;
      for (const auto& b : g.blocks)
        for (Index v : b.nodes)
          if (local[v] >= 0) nodes.push_back(local[v]);
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      if (!nodes.empty()) {
        m.node_groups[g.name] = std::move(nodes);
        m.node_group_dims[g.name] = g.dim;
      }
    }
  }
  try {
    check_folds(m);  // on the cells as read: orient_cells() would hide which one is folded
  } catch (const InputError& e) {
    throw e.in_file(file.path);
  }
  m.orient_cells();
  try {
    m.check();
    check_topology(m, allow);
    m.locate_facets();
  } catch (const InputError& e) {
    throw e.in_file(file.path);
  }
  return m;
}

Mesh extract_surface(const MeshFile& file, int dim, const std::string& group, const std::string& group_key) {
  const MeshFile::Group* g = file.find(group, dim - 1);
  if (!g) throw InputError(file.path, group_key, "no physical group '" + group + "' of dimension " + std::to_string(dim - 1));
  Mesh m;
  m.dim = dim;
  std::vector<Index> local(file.x.cols(), -1);
  Index n = 0;
  FacetGroup fg;
  bool have_type = false;
  for (const auto& b : g->blocks) {
    if (cell_dim(b.type) != dim - 1) continue;
    const CellType ct = cell_type_with_facet(b.type);
    if (have_type && ct != m.first_cell_type())
      throw InputError(file.path, group_key, "the surface mixes element types");
    m.set_cells(ct, {});
    have_type = true;
    for (Index v : b.nodes) {
      if (local[v] < 0) local[v] = n++;
      fg.facets.push_back(local[v]);
    }
  }
  if (!have_type) throw InputError(file.path, group_key, "group '" + group + "' holds no facets");
  m.x.resize(dim, n);
  for (Index v = 0; v < file.x.cols(); ++v)
    if (local[v] >= 0) m.x.col(local[v]) = file.x.col(v).head(dim);
  m.facet_groups[group] = std::move(fg);
  return m;
}

}  // namespace symcontact
