#include "symcontact/solvers/geometry_diagnostics.hpp"

#include <set>
#include <sstream>
#include <string>

namespace symcontact {

void warn_pairs_without_points(const ContactSet& contacts, const ContactLinearization& lin, const Logger& log) {
  for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
    std::size_t n = 0;
    for (int f = 0; f < static_cast<int>(contacts.families().size()); ++f)
      if (contacts.families()[f].pair == p) n += lin.points[f].size();
    if (n == 0)
      log.warning("contact '" + contacts.pairs[p].name +
                  "': no point of its surfaces faces the opposite side within the search distance " +
                  std::to_string(contacts.pairs[p].search_distance) +
                  " (a meshed obstacle's facets must be oriented with their normal towards the body)");
  }
}

void log_geometry_change(const VectorXd& du, const DofMap& dofs, const ContactLinearization& lin,
                         const std::vector<int>& prev_family, const std::vector<Index>& prev_node, const Logger& log) {
  std::ostringstream s;
  Index d = 0;
  const double m = du.size() ? du.cwiseAbs().maxCoeff(&d) : 0.0;
  int body = 0;
  while (body + 1 < dofs.num_bodies() && d >= dofs.offset(body + 1)) ++body;
  s << "    largest change " << m << " at body " << body << " node " << (d - dofs.offset(body)) / dofs.dim()
    << " component " << (d - dofs.offset(body)) % dofs.dim();
  if (!prev_family.empty()) {
    std::set<std::pair<int, Index>> before, now;
    for (std::size_t r = 0; r < prev_family.size(); ++r) before.insert({prev_family[r], prev_node[r]});
    for (std::size_t r = 0; r < lin.row_family.size(); ++r) now.insert({lin.row_family[r], lin.row_node[r]});
    s << "; rows added:";
    for (const auto& fr : now)
      if (!before.count(fr)) s << " " << fr.first << ":" << fr.second;
    s << "; removed:";
    for (const auto& fr : before)
      if (!now.count(fr)) s << " " << fr.first << ":" << fr.second;
  }
  log.debug(s.str());
}

}  // namespace symcontact
