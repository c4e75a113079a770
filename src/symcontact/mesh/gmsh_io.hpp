#pragma once
/// \file gmsh_io.hpp
/// Meshes from Gmsh: `.geo` files are meshed at run time through the Gmsh C++ API (with an optional
/// maximum element size), `.msh` files are read as they are; both at order 1 or 2 (Gmsh places P2
/// edge nodes on the CAD geometry of a `.geo`, and at edge midpoints for a `.msh`). Physical groups name
/// the bodies (groups of dimension `dim`), boundary parts (dimension dim − 1) and node sets (lower
/// dimensions). The Gmsh library is global state; these functions initialise and finalise it
/// around each call, so they are not re-entrant.

#include <string>
#include <vector>

#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

struct MeshReadOptions {
  int dim = 2;             ///< spatial dimension of the problem
  int order = 1;           ///< 1 or 2
  double mesh_size = 0.0;  ///< > 0: Mesh.MeshSizeMax for .geo meshing
  bool verbose = false;    ///< let Gmsh print its log
};

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
/// locates the fault), an unsupported element type, or a failed meshing.
MeshFile read_mesh_file(const std::string& path, const MeshReadOptions& options);

/// The mesh of one body: the cells of dimension `dim` in physical group `group` (all cells of that
/// dimension when `group` is empty), renumbered; lower-dimensional groups restricted to its nodes
/// (facet groups from dimension dim − 1, node groups from the rest). Cells are oriented, checked and
/// facets located; the mesh keeps the file's node and element tags for messages. Throws
/// InputError(file, key = `group_key`) when the group is absent or empty, and InputError(file, ...)
/// for a fault of the body's mesh: check_folds() on the cells as read, before they are oriented (a cell
/// folded over its neighbour), Mesh::check() (a non-finite coordinate, a degenerate element), check_topology() (coincident nodes that make a crack, a body in several pieces;
/// mesh_topology.hpp) and Mesh::locate_facets() (a group facet inside the body or off it).
Mesh extract_body(const MeshFile& file, int dim, const std::string& group, const std::string& group_key);

/// A rigid surface: the facets of group `group` (dimension dim − 1), with no cells. The mesh's cell_type is
/// the cell type whose facets these are; facets keep the orientation of the file. Throws InputError(file,
/// key = `group_key`) when the group is absent or holds no facets.
Mesh extract_surface(const MeshFile& file, int dim, const std::string& group, const std::string& group_key);

}  // namespace symcontact
