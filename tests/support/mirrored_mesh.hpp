#pragma once
/// \file mirrored_mesh.hpp
/// Test helper for self-contact by symmetry (VALIDATION.md, V7): the mesh of a half model and its
/// mirror image, node for node, written as one Gmsh MSH 2.2 file. The full model's solution is then the
/// exact mirror of the half model's (same nodes, same cells), so the two can be compared to round-off.

#include <string>

#include "symcontact/mesh/gmsh_io.hpp"

namespace symcontact::testing {

/// Writes `half` and its reflection about the plane x[axis] = 0 to `path` (MSH 2.2 ASCII). Nodes with
/// x[axis] == 0 exactly are shared by both halves (the half must be meshed so that its cut lies on the
/// plane). Every physical group keeps its name and holds both halves, except `cut_group`: its lines
/// (facets) become interior, so it is written as a node group (physical points of its nodes) with the
/// same name. Cells keep their file tags' order; the mirrored cells have reversed orientation, which
/// extract_body() corrects. Linear cells only (Line2, Tri3, Tet4), which is what the V7 tests use.
void write_mirrored_msh(const MeshFile& half, int axis, const std::string& cut_group, const std::string& path);

}  // namespace symcontact::testing
