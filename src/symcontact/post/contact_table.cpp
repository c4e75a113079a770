#include "symcontact/post/contact_table.hpp"

#include <cmath>

namespace symcontact {

namespace {

std::vector<std::string> numeric_column_names(int dim) {
  const char* xyz[] = {"x", "y", "z"};
  std::vector<std::string> names;
  const auto per_axis = [&](const std::string& prefix, const std::string& suffix) {
    for (int i = 0; i < dim; ++i) names.push_back(prefix + xyz[i] + suffix);
  };
  per_axis("", "");
  per_axis("", "_ref");
  names.insert(names.end(), {"gap", "pressure", "current_pressure"});
  per_axis("t", "");
  per_axis("f", "");
  per_axis("fn_", "");
  per_axis("slip_", "");
  names.push_back("accumulated_slip");
  per_axis("u", "");
  if (dim == 2) names.insert(names.end(), {"t_tangential", "slip_tangential"});
  return names;
}

}  // namespace

ContactTable contact_table(const std::vector<ContactSurface>& surfaces, int dim, const ContactPairResult& result,
                           const std::vector<Eigen::VectorXd>& accumulated) {
  ContactTable t;
  t.pair = result.name;
  t.numeric_names = numeric_column_names(dim);
  Index rows = 0;
  for (const auto& sr : result.sides) rows += surfaces[sr.surface].num_nodes();
  t.numeric.resize(rows, static_cast<Index>(t.numeric_names.size()));
  static const char* status[] = {"open", "contact", "slip"};
  Index row = 0;
  for (std::size_t side = 0; side < result.sides.size(); ++side) {
    const auto& sr = result.sides[side];
    const ContactSurface& s = surfaces[sr.surface];
    // A side has friction when its slip is defined somewhere (NaN off the friction side).
    const bool friction = std::isfinite(sr.slip.maxCoeff()) || sr.slip.array().isFinite().any();
    for (Index k = 0; k < s.num_nodes(); ++k, ++row) {
      t.side.push_back(side == 0 ? "a" : "b");
      t.surface.push_back(s.name);
      t.node.push_back(s.nodes[k] + 1);
      Index c = 0;
      const auto put = [&](double v) { t.numeric(row, c++) = v; };
      for (int i = 0; i < dim; ++i) put(sr.x(i, k));
      for (int i = 0; i < dim; ++i) put(sr.X(i, k));
      put(sr.gap[k]);
      put(sr.pressure[k]);
      put(sr.current_pressure[k]);
      for (int i = 0; i < dim; ++i) put(sr.tangential(i, k));
      for (int i = 0; i < dim; ++i) put(sr.force(i, k));
      for (int i = 0; i < dim; ++i) put(sr.normal_part(i, k));
      for (int i = 0; i < dim; ++i) put(sr.slip(i, k));
      const bool has_acc = side < accumulated.size() && accumulated[side].size() > k && friction;
      put(has_acc ? accumulated[side][k] : std::nan(""));
      for (int i = 0; i < dim; ++i) put(sr.displacement(i, k));
      if (dim == 2) {
        put(sr.tangential_along[k]);
        put(sr.slip_along[k]);
      }
      const int st = sr.status[k];
      t.status.push_back(st == 1 && friction ? "stick" : status[st]);
    }
  }
  return t;
}

}  // namespace symcontact
