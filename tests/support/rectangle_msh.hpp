#pragma once
/// \file rectangle_msh.hpp
/// A small structured mesh file for tests that read meshes the way the program does: the rectangle
/// [0, width] × [0, height] of rectangle_mesh() (mesh/structured.hpp: nx × ny squares, two triangles
/// each) written as Gmsh MSH 2.2, with its facet groups "left", "right", "bottom", "top", its node groups
/// "corner_ll", "corner_lr" and the surface group `surface`.

#include <filesystem>
#include <string>

namespace symcontact::testing {

/// Writes the mesh to `path` and returns `path`.
std::filesystem::path write_rectangle_msh(const std::filesystem::path& path, double width, double height, int nx,
                                          int ny, const std::string& surface = "block");

}  // namespace symcontact::testing
