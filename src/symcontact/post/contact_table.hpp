#pragma once
/// \file contact_table.hpp
/// The node-by-node contact table of one pair and load step: what `contact_<pair>_<step>.csv` holds
/// (run.hpp) and what the Python module returns (python/), built once here so that both say the same.
///
/// One row per node of each side (side a's nodes, then side b's), columns in this order:
///   side ("a" | "b"), surface ("<body>.<group>"), node (1-based body node number),
///   then the numeric columns `numeric_names`: x y [z] (current position), x_ref y_ref [z_ref],
///   gap, pressure, current_pressure, tx ty [tz] (tangential traction), fx fy [fz] (nodal force of
///   the pair), fn_x fn_y [fn_z] (its normal part), slip_x slip_y [slip_z] (slip increment of the step),
///   accumulated_slip (Σ over steps of |slip increment|), ux uy [uz], and in 2D t_tangential,
///   slip_tangential (signed along the surface tangent τ),
///   then status: "open", "stick" (in contact, frictional side), "contact" (in contact, no friction on
///   this side) or "slip".
/// Undefined values (no projection, no friction on this side) are NaN.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/core/types.hpp"
#include "symcontact/post/contact_results.hpp"

namespace symcontact {

struct ContactTable {
  std::string pair;                         ///< the pair's name
  std::vector<std::string> side;            ///< per row: "a" or "b"
  std::vector<std::string> surface;         ///< per row
  std::vector<Index> node;                  ///< per row, 1-based
  std::vector<std::string> numeric_names;   ///< the numeric columns, in CSV order
  Eigen::MatrixXd numeric;                  ///< rows × numeric_names.size()
  std::vector<std::string> status;          ///< per row

  Index rows() const { return static_cast<Index>(side.size()); }
};

/// The table of `result` (its sides' surfaces indexed in `surfaces`), with `accumulated[side][k]` the
/// accumulated slip of node k of each side (a side without an entry, or without friction, gets NaN).
ContactTable contact_table(const std::vector<ContactSurface>& surfaces, int dim, const ContactPairResult& result,
                           const std::vector<Eigen::VectorXd>& accumulated);

}  // namespace symcontact
