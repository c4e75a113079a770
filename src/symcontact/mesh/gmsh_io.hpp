#pragma once
/// \file gmsh_io.hpp
/// Meshes from Gmsh: `.geo` files are meshed at run time through the Gmsh C++ API (with an optional
/// maximum element size), `.msh` files are read as they are; both at order 1 or 2 (Gmsh places P2
/// edge nodes on the CAD geometry of a `.geo`, and at edge midpoints for a `.msh`). Physical groups name
/// the bodies (groups of dimension `dim`), boundary parts (dimension dim − 1) and node sets (lower
/// dimensions). The Gmsh library is global state; these functions initialise and finalise it
/// around each call, so they are not re-entrant.

#include <map>
#include <string>
#include <vector>

#include "symcontact/mesh/mesh.hpp"
#include "symcontact/mesh/mesh_topology.hpp"

namespace symcontact {

/// The default limit on the predicted number of cells of a .geo meshed with a given size.
constexpr double kDefaultMaxPredictedCells = 5e6;

/// Whether a .geo may use the Gmsh commands that run other programs (geo_commands.hpp).
enum class GeoCommands { kRefuse, kAllow };

struct MeshReadOptions {
  int dim = 2;             ///< spatial dimension of the problem
  int order = 1;           ///< 1 or 2
  double mesh_size = 0.0;  ///< > 0: Mesh.MeshSizeMax for .geo meshing
  /// Where mesh_size comes from, for messages ("--mesh-size", "problem.mesh_size").
  std::string mesh_size_key = "mesh_size";
  /// With mesh_size > 0, a .geo is meshed only when the predicted cell count (predicted_cell_count())
  /// is at most this; 0 or less: no limit.
  double max_predicted_cells = kDefaultMaxPredictedCells;
  GeoCommands geo_commands = GeoCommands::kRefuse;
  /// Numbers given to a .geo before it is parsed, as Gmsh's command-line `-setnumber name value` does:
  /// they replace the values of `DefineConstant[ name = ... ]` (geo_defined_constants()). Names must be
  /// Gmsh identifiers and values finite (the problem reader checks both); ignored for a .msh file.
  std::map<std::string, double> geo_parameters;
  bool verbose = false;    ///< let Gmsh print its log
};

/// A lower estimate of the number of cells of a mesh of maximum size h over a box of extents
/// `extent` (x, y, z): with elements of edge h, an equilateral triangle covers √3/4·h² ≈ 0.43·h² and a
/// regular tetrahedron h³/(6√2) ≈ 0.12·h³, so a full box holds about 2.3·A/h² triangles and 8.5·V/h³
/// tetrahedra; the estimate uses 2·A/h² (2D, A = Δx·Δy) and 6·V/h³ (3D, V = Δx·Δy·Δz), a little
/// below, because the geometry does not fill its bounding box.
double predicted_cell_count(int dim, const double extent[3], double h);

/// Everything read from one file. Node coordinates are 3 × N (z = 0 in 2D); connectivities index them.
struct MeshFile {
  struct Block {
    CellType type;
    std::vector<Index> nodes;  ///< compact node indices, cell after cell
    std::vector<Index> tags;   ///< the file's element tags, one per cell (for messages)
  };
  struct Group {
    int dim = 0;
    int tag = 0;
    std::string name;          ///< the physical name, or the tag as text when unnamed
    std::vector<Block> blocks;
  };
  std::string path;
  Eigen::MatrixXd x;
  std::vector<Index> node_tags;  ///< the file's tag of each node (increasing: nodes are numbered by tag)
  std::vector<Block> all_cells;  ///< every element of dimension `dim`, in or out of physical groups
  std::vector<Group> groups;
  const Group* find(const std::string& name, int dim) const;
};

/// Reads or meshes `path`. A `.msh` file is first checked by validate_msh_file() (msh_validation.hpp:
/// ASCII MSH 2.x or 4.1, sound structure), so that Gmsh never parses a malformed one. Throws
/// InputError(file = path) for a missing or malformed file (key "line L" when the structural check
/// locates the fault), a path that is not a regular file (input_file.hpp), an unsupported element type,
/// a .geo running other programs (geo_commands.hpp, unless options.geo_commands allows it), a mesh size
/// whose predicted cell count is above options.max_predicted_cells, or a failed meshing (the message
/// carries Gmsh's own error messages).
MeshFile read_mesh_file(const std::string& path, const MeshReadOptions& options);

/// The mesh of one body: the cells of dimension `dim` in physical group `group` (all cells of that
/// dimension when `group` is empty), renumbered; groups of dimension `dim` restricted to its cells
/// (Mesh::cell_groups, matched by element tag), lower-dimensional groups restricted to its nodes
/// (facet groups from dimension dim − 1, node groups from the rest). Cells are oriented, checked and
/// facets located; the mesh keeps the file's node and element tags for messages. Throws
/// InputError(file, key = `group_key`) when the group is absent or empty, and InputError(file, ...)
/// for a fault of the body's mesh: check_folds() on the cells as read, before they are oriented (a cell
/// folded over its neighbour), Mesh::check() (a non-finite coordinate, a degenerate element), check_topology() (coincident nodes that make a crack, a body in several pieces,
/// unless `allow` declares them: mesh_topology.hpp) and Mesh::locate_facets() (a group facet that is a facet of no
/// cell; a group inside the body becomes a node group, Mesh::interior_facet_groups).
Mesh extract_body(const MeshFile& file, int dim, const std::string& group, const std::string& group_key,
                  const TopologyAllowances& allow = {});

/// A rigid surface: the facets of group `group` (dimension dim − 1), with no cells. Its one (empty) cell block has
/// the cell type whose facets these are; facets keep the orientation of the file. Throws InputError(file,
/// key = `group_key`) when the group is absent or holds no facets.
Mesh extract_surface(const MeshFile& file, int dim, const std::string& group, const std::string& group_key);

}  // namespace symcontact
