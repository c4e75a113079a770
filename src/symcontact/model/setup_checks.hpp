#pragma once
/// \file setup_checks.hpp
/// Checks of a built model that need its geometry and its contacts together, run before anything is solved
/// (by `symcontact run` before the output folder is made, and by `symcontact check`). Each refuses the problem
/// with InputError (exit 2) naming the problem file and the key:
///
/// 1. **Meshed obstacle facing away** (key contact[i].obstacle): the facets of a rigid meshed obstacle must
///    have their normal towards the body (contact_surface.hpp). Each node of surface a whose closest point on
///    the obstacle is inside a facet is in front (signed distance along that facet's normal > 0) or behind
///    (< 0); the problem is refused when more nodes are behind than in front (the body lies on the side the
///    facets turn away from, so the contact search would never see it).
/// 2. **Rigid motions left free** (key body[i]): the rigid motions of each body (2D: translations x, y and
///    the rotation about z; 3D: translations x, y, z and rotations about x, y, z, about the body's centroid)
///    that no Dirichlet condition of the body holds and no contact resists. A Dirichlet DOF resists a motion
///    whose displacement has a component at it; a frictionless contact resists only along the outward normals
///    of the body's contact surface (reference configuration, all its nodes: it may count motions as held
///    that only the surface's far part would stop); a contact with Tresca or Coulomb friction resists every
///    motion of its nodes. Free motions are the null space of the resulting Gram matrix (eigenvalues below
///    1e-9 × the largest, the motions scaled to the body's size). Such a body's stiffness is singular (a block
///    on a frictionless plane under a vertical load may slide in x at no cost), so the solve cannot converge.
/// 3. **Overlap at the start** (key contact[i]): find_penetrations() (contact/penetration.hpp) at u = 0: a
///    node of a contact surface deeper than 25 % of the local element size inside the other body of its pair,
///    or behind an analytic obstacle.
/// Folded and inverted cells are refused when the mesh is read (mesh_topology.hpp, check_folds()).

#include "symcontact/model/model.hpp"

namespace symcontact {

/// Runs the checks above; throws InputError(spec.file, key, message) at the first failure.
void check_setup(const Model& model);

}  // namespace symcontact
