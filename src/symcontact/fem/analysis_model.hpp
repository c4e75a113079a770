#pragma once
/// \file analysis_model.hpp
/// The kinematic model of a computation: 2D plane strain, 2D plane stress, 2D axisymmetric, or 3D.
///
/// Axisymmetric: the mesh is the (r, z) section of a body of revolution, r = x ≥ 0, z = y; the
/// displacement (u_r, u_z) has no hoop component, and the hoop strain is ε_θθ = u_r / r (Zienkiewicz &
/// Taylor, The Finite Element Method, vol. 1, 6th ed. 2005, §5.2). Every integral over the body or its
/// boundary is over the whole ring, dV = 2π r dA and dS = 2π r ds, so energies, loads, reactions and contact
/// forces are those of the full 360° body (as Abaqus reports them); a point load is a line load on a
/// circle, given by its total force.

namespace symcontact {

enum class AnalysisModel { kPlaneStrain, kPlaneStress, kAxisymmetric, kThreeD };

/// The factor of the volume or surface element at a point at radius r = x of a 2D section: 2π r under
/// kAxisymmetric, 1 otherwise (per unit thickness in plane strain and plane stress; 3D as it is).
inline double section_measure(AnalysisModel model, double r) {
  constexpr double kTwoPi = 6.283185307179586477;
  return model == AnalysisModel::kAxisymmetric ? kTwoPi * r : 1.0;
}

/// What the energies report of a cell whose map is inverted or degenerate at a quadrature point, or (in an
/// axisymmetric model) reaches r ≤ 0 there.
inline const char* bad_cell_message(AnalysisModel model) {
  return model == AnalysisModel::kAxisymmetric
             ? "inverted or degenerate element, or one reaching r = x <= 0 (an axisymmetric section lies in "
               "x >= 0)"
             : "inverted or degenerate element (Jacobian determinant <= 0 inside the cell)";
}

}  // namespace symcontact
