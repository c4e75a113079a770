#include "support/mirrored_mesh.hpp"

#include <fstream>
#include <iomanip>
#include <set>
#include <stdexcept>
#include <vector>

namespace symcontact::testing {

namespace {
int gmsh_type(CellType t) {
  switch (t) {
    case CellType::kLine2: return 1;
    case CellType::kTri3: return 2;
    case CellType::kTet4: return 4;
    default: throw std::invalid_argument("write_mirrored_msh: linear cells only");
  }
}
}  // namespace

void write_mirrored_msh(const MeshFile& half, int axis, const std::string& cut_group, const std::string& path) {
  const Index n = half.x.cols();
  // Mirror node numbers: nodes on the plane are shared.
  std::vector<Index> mirror(n);
  Index next = n;
  for (Index a = 0; a < n; ++a) mirror[a] = half.x(axis, a) == 0.0 ? a : next++;
  std::ofstream os(path);
  os << std::setprecision(17);
  os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << half.groups.size() << "\n";
  for (std::size_t g = 0; g < half.groups.size(); ++g) {
    const int dim = half.groups[g].name == cut_group ? 0 : half.groups[g].dim;
    os << dim << " " << g + 1 << " \"" << half.groups[g].name << "\"\n";
  }
  os << "$EndPhysicalNames\n$Nodes\n" << next << "\n";
  for (Index a = 0; a < n; ++a) os << a + 1 << " " << half.x(0, a) << " " << half.x(1, a) << " " << half.x(2, a) << "\n";
  for (Index a = 0; a < n; ++a) {
    if (mirror[a] == a) continue;
    Eigen::Vector3d y = half.x.col(a);
    y[axis] = -y[axis];
    os << mirror[a] + 1 << " " << y[0] << " " << y[1] << " " << y[2] << "\n";
  }
  os << "$EndNodes\n";
  // Elements: each group's cells, then their mirror images; the cut group as points.
  std::vector<std::string> lines;
  for (std::size_t g = 0; g < half.groups.size(); ++g) {
    const MeshFile::Group& group = half.groups[g];
    const std::string tags = " 2 " + std::to_string(g + 1) + " " + std::to_string(g + 1);
    if (group.name == cut_group) {
      std::set<Index> nodes;
      for (const auto& b : group.blocks) nodes.insert(b.nodes.begin(), b.nodes.end());
      for (Index a : nodes) lines.push_back("15" + tags + " " + std::to_string(a + 1));
      continue;
    }
    for (const auto& b : group.blocks) {
      const int npc = cell_num_nodes(b.type);
      const std::string type = std::to_string(gmsh_type(b.type));
      for (int side = 0; side < 2; ++side)
        for (std::size_t c = 0; c < b.nodes.size() / npc; ++c) {
          std::string l = type + tags;
          for (int k = 0; k < npc; ++k) {
            const Index a = b.nodes[c * npc + k];
            l += " " + std::to_string((side == 0 ? a : mirror[a]) + 1);
          }
          lines.push_back(l);
        }
    }
  }
  os << "$Elements\n" << lines.size() << "\n";
  for (std::size_t k = 0; k < lines.size(); ++k) os << k + 1 << " " << lines[k] << "\n";
  os << "$EndElements\n";
  if (!os) throw std::runtime_error("write_mirrored_msh: cannot write " + path);
}

}  // namespace symcontact::testing
