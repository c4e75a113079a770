#pragma once
/// \file linear_elastic_energy.hpp
/// Strain energy of one linear-elastic body, E(u) = ½ a(u, u) = ½ uᵀ K u (talk eq. 4–5).
/// Element stiffnesses are recomputed at every call (no per-cell storage). Each cell has its own law:
/// materials[cell_material[c]] (one law for all cells when cell_material is empty). The materials' model
/// (LinearElastic::model, the same for all) chooses the kinematics: axisymmetric adds the hoop strain and
/// integrates over the whole ring (elastic_kernel.hpp).

#include <string>
#include <vector>

#include "symcontact/energy/cell_materials.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/fem/shape_functions.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

class LinearElasticEnergy : public EnergyTerm {
 public:
  /// `label` names the body in messages. Throws InputError(key = "<label>: cell N") if an element's
  /// isoparametric map is inverted or degenerate at a quadrature point.
  LinearElasticEnergy(const Mesh& mesh, const DofMap& dofs, int body, const LinearElastic& material,
                      std::string label);
  /// A body of several materials: `materials` non-empty; `cell_material` empty or one index into
  /// `materials` per cell of `mesh`.
  LinearElasticEnergy(const Mesh& mesh, const DofMap& dofs, int body, std::vector<LinearElastic> materials,
                      std::vector<int> cell_material, std::string label);
  std::string name() const override { return "elastic(" + label_ + ")"; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override { return true; }

 private:
  /// Calls f(c, dofs, K_e) for every cell c, with K_e the D·NN square element stiffness.
  template <class F>
  void for_each_cell(F&& f) const;

  const Mesh& mesh_;
  Index offset_;
  CellMaterials<LinearElastic> materials_;
  std::string label_;
  std::vector<Tabulation> tabs_;  ///< one per cell block of the mesh
};

}  // namespace symcontact
