#include "support/rectangle_msh.hpp"

#include <iomanip>
#include <sstream>
#include <vector>

#include "support/temp_folder.hpp"
#include "symcontact/mesh/structured.hpp"

namespace symcontact::testing {

std::filesystem::path write_rectangle_msh(const std::filesystem::path& path, double width, double height, int nx,
                                          int ny, const std::string& surface) {
  const Mesh m = rectangle_mesh(0.0, 0.0, width, height, nx, ny);
  std::ostringstream os;
  os << std::setprecision(17);
  // Physical groups: tag 1 the surface, then the facet groups, then the node groups.
  std::vector<std::string> elements;  // "type 2 phys phys nodes…" (tags follow the order)
  const auto element = [&](int type, int phys, const Index* nodes, int count) {
    std::string e = std::to_string(type) + " 2 " + std::to_string(phys) + " " + std::to_string(phys);
    for (int k = 0; k < count; ++k) e += " " + std::to_string(nodes[k] + 1);
    elements.push_back(e);
  };
  std::ostringstream names;
  int phys = 1;
  names << "2 " << phys << " \"" << surface << "\"\n";
  for (Index c = 0; c < m.num_cells(); ++c) element(2, phys, m.cell(c), 3);
  for (const auto& [name, group] : m.facet_groups) {
    names << "1 " << ++phys << " \"" << name << "\"\n";
    for (std::size_t f = 0; f < group.facets.size(); f += 2) element(1, phys, &group.facets[f], 2);
  }
  for (const auto& [name, nodes] : m.node_groups) {
    names << "0 " << ++phys << " \"" << name << "\"\n";
    for (const Index& n : nodes) element(15, phys, &n, 1);
  }
  os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << phys << "\n" << names.str()
     << "$EndPhysicalNames\n$Nodes\n" << m.num_nodes() << "\n";
  for (Index a = 0; a < m.num_nodes(); ++a) os << a + 1 << " " << m.x(0, a) << " " << m.x(1, a) << " 0\n";
  os << "$EndNodes\n$Elements\n" << elements.size() << "\n";
  for (std::size_t k = 0; k < elements.size(); ++k) os << k + 1 << " " << elements[k] << "\n";
  os << "$EndElements\n";
  write_text(path, os.str());
  return path;
}

}  // namespace symcontact::testing
