#pragma once
/// \file pad_geo.hpp
/// The 2D pad the frictional validation tests press and drag (symcontact-bench's pad-flat-2d and
/// pad-ball-2d): the rectangle [−½, ½] × [0, ¼] as Gmsh .geo text, its surface group "solid", its bottom
/// "bottom" and its top "top".

#include <string>

namespace symcontact::testing {

/// The pad's .geo with the characteristic length `mesh_size` at its corners; none (the problem file's
/// mesh_size decides) when `mesh_size` ≤ 0.
std::string pad_geo_2d(double mesh_size = 0.0);

}  // namespace symcontact::testing
