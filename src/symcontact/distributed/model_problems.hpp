#pragma once
/// \file model_problems.hpp
/// The model problems of the distributed path's tests and benchmark. On a linear-elastic unit square (plane
/// strain) or unit cube, structured simplex mesh of n divisions per side, E = 1, ν = 0.3:
///
/// - clamped_block_system: clamped at its bottom (y = 0, resp. z = 0), its top moved by 0.01 along x, a
///   downward nodal load of 10⁻³ on every node;
/// - block_on_ball_system: its top moved down by `depth` (every component fixed), no load, pressed onto a
///   rigid ball (2D: disc) of radius R whose top touches the centre of the block's bottom face — a Hertz
///   contact when the contact zone is small against the block. One constraint per bottom node along the
///   vertical: u_z ≥ l = −(R − √(R² − r²)), r the node's distance from the centre of the bottom face (the
///   small-displacement gap along the vertical; R must exceed the half-diagonal of the face);
/// - block_on_plane_system: its top moved down by `depth` and along x by `shift` (every component fixed), on
///   the rigid plane y = 0 (3D: z = 0) that its bottom rests on, with regularised Tresca friction of
///   threshold τ and regularisation length α at the bottom nodes (g_j = τ × the node's lumped area). Once
///   every node slides (|slip| ≫ α), the friction force on the bottom is τ × its area, 1, along −x.
///
/// And the Hertz sphere of VALIDATION.md, V2 (hertz_sphere_system), as examples/hertz_3d/sphere_on_plane.toml
/// states it: the quarter sphere of sphere_on_plane.geo meshed at size h near the contact point, E = 1,
/// ν = 0.3, the pressure 0.01/π on its cut z = 1, u_x = 0 on symmetry_x and u_y = 0 on symmetry_y, on the
/// rigid plane z = 0: one constraint per node of the contact surface, z + u_z ≥ 0 (exact for a plane).
///
/// Part `part` of `parts` (an MPI rank of the ranks) assembles the stiffness of its contiguous range of
/// cells only (in the mesh's order), its share of K; the mesh, the load, the fixed DOFs and the constraints
/// are whole on every part.

#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

struct BlockSystem {
  Mesh mesh;
  SparseMatrix K_lower;  ///< lower triangle of the part's share of the stiffness (dof = dim·node + comp)
  VectorXd f;
  std::vector<Index> fixed;
  VectorXd fixed_values;
};

BlockSystem clamped_block_system(int dim, int divisions, int part = 0, int parts = 1);

struct ObstacleSystem {
  BlockSystem block;
  NodalConstraints contact;
};

ObstacleSystem block_on_ball_system(int dim, int divisions, double radius, double depth, int part = 0,
                                    int parts = 1);

ObstacleSystem block_on_plane_system(int dim, int divisions, double depth, double shift, double tau, double alpha,
                                     int part = 0, int parts = 1);

/// sphere_geo: the path of examples/hertz_3d/sphere_on_plane.geo; a wrapper setting h is written into
/// work_dir and meshed by Gmsh.
ObstacleSystem hertz_sphere_system(const std::string& sphere_geo, double h, const std::string& work_dir,
                                   int part = 0, int parts = 1);

/// The load the sphere's model carries: −Σ f_z, the resultant of the pressure on the meshed cut (a polygon
/// slightly inside the quarter disk).
double vertical_load(const BlockSystem& s);

/// The lumped measure of every node on the facets of group `surface` (3D triangles: a third of each one's
/// area; 2D segments: half of each one's length); zero off the surface.
VectorXd lumped_measures(const Mesh& mesh, const std::string& surface);

/// Nodal contact pressures λ_j / A_j, A_j the lumped measure of node p_j on the facets of group `surface`
/// (a node on a symmetry plane has half its area and half its force).
VectorXd nodal_pressures(const Mesh& mesh, const std::string& surface, const NodalConstraints& c,
                         const VectorXd& lambda);

}  // namespace symcontact
