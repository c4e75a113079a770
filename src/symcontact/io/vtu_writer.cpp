#include "symcontact/io/vtu_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <stdexcept>

#include "symcontact/io/atomic_file.hpp"
#include "symcontact/io/json_writer.hpp"
#include "symcontact/io/xml_escape.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

namespace {

bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// A contiguous run of bytes for the appended section.
struct Block {
  const void* data;
  std::uint64_t bytes;
};

void check_finite(const Eigen::MatrixXd& m, const std::string& what) {
  for (Index j = 0; j < m.cols(); ++j) {
    for (Index i = 0; i < m.rows(); ++i) {
      if (!std::isfinite(m(i, j))) {
        throw std::invalid_argument("VtuWriter: " + what + " has the non-finite value " + format_double(m(i, j)) +
                                    " (component " + std::to_string(i) + ", entry " + std::to_string(j) +
                                    "); ASCII VTU cannot hold it, use VtuEncoding::kBinaryAppended");
      }
    }
  }
}

Eigen::MatrixXd pad_to_3d(const Eigen::MatrixXd& points) {
  if (points.rows() < 1 || points.rows() > 3) {
    throw std::invalid_argument("VtuWriter: points must have 1 to 3 rows (coordinates), got " +
                                std::to_string(points.rows()));
  }
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(3, points.cols());
  p.topRows(points.rows()) = points;
  return p;
}

}  // namespace

VtuWriter::VtuWriter(const Mesh& mesh) : points_(pad_to_3d(mesh.x)) {
  for (const CellBlock& b : mesh.cell_blocks)
    append_cells(b.type, mesh.cell(b.begin),
                 static_cast<std::size_t>(mesh.cell_offsets[b.end] - mesh.cell_offsets[b.begin]));
}

VtuWriter::VtuWriter(const Eigen::MatrixXd& points, CellType type, std::vector<Index> connectivity)
    : points_(pad_to_3d(points)) {
  append_cells(type, connectivity.data(), connectivity.size());
}

void VtuWriter::append_cells(CellType type, const Index* connectivity, std::size_t entries) {
  const auto npc = static_cast<std::size_t>(cell_num_nodes(type));
  if (entries % npc != 0) {
    throw std::invalid_argument("VtuWriter: connectivity has " + std::to_string(entries) +
                                " entries, not a multiple of the " + std::to_string(npc) + " nodes of a " +
                                cell_name(type) + " cell");
  }
  const Index n = points_.cols();
  for (std::size_t k = 0; k < entries; ++k) {
    if (connectivity[k] < 0 || connectivity[k] >= n) {
      throw std::invalid_argument("VtuWriter: connectivity of cell " + std::to_string(num_cells() + Index(k / npc)) +
                                  " holds node " + std::to_string(connectivity[k]) + ", outside [0, " +
                                  std::to_string(n) + ")");
    }
  }
  const int* order = vtk_node_order(type);
  const auto nvtk = static_cast<std::size_t>(vtk_num_nodes(type));
  for (std::size_t c = 0; c < entries; c += npc) {
    for (std::size_t k = 0; k < nvtk; ++k) connectivity_.push_back(connectivity[c + static_cast<std::size_t>(order[k])]);
    offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
    types_.push_back(static_cast<std::uint8_t>(vtk_cell_type(type)));
  }
  per_line_ = std::max(per_line_, npc);
}

void VtuWriter::add(std::vector<Array>& arrays, const char* where, Index count, const std::string& name,
                    const Eigen::MatrixXd& values, const std::vector<std::string>& component_names) {
  const std::string label = std::string(where) + " array '" + name + "'";
  if (name.empty()) throw std::invalid_argument(std::string("VtuWriter: ") + where + " array with an empty name");
  for (const Array& a : arrays) {
    if (a.name == name) throw std::invalid_argument("VtuWriter: " + label + " added twice");
  }
  if (values.rows() < 1 || values.cols() != count) {
    throw std::invalid_argument("VtuWriter: " + label + " is " + std::to_string(values.rows()) + " x " +
                                std::to_string(values.cols()) + ", expected ncomp x " + std::to_string(count) +
                                " with ncomp >= 1");
  }
  if (!component_names.empty() && static_cast<Index>(component_names.size()) != values.rows()) {
    throw std::invalid_argument("VtuWriter: " + label + " has " + std::to_string(values.rows()) +
                                " components but " + std::to_string(component_names.size()) + " component names");
  }
  arrays.push_back(Array{name, values, component_names});
}

void VtuWriter::write(const std::string& path) const {
  const bool ascii = encoding_ == VtuEncoding::kAscii;
  if (ascii) {
    check_finite(points_, "Points");
    for (const Array& a : point_data_) check_finite(a.values, "point data array '" + a.name + "'");
    for (const Array& a : cell_data_) check_finite(a.values, "cell data array '" + a.name + "'");
  }

  static_assert(sizeof(Index) == sizeof(std::int64_t), "connectivity is written as Int64");

  // Appended blocks in the order their DataArray headers are written.
  std::vector<Block> blocks;
  std::uint64_t next_offset = 0;
  auto format_attr = [&](const void* data, std::uint64_t bytes) -> std::string {
    if (ascii) return "format=\"ascii\"";
    std::string s = "format=\"appended\" offset=\"" + std::to_string(next_offset) + "\"";
    blocks.push_back(Block{data, bytes});
    next_offset += sizeof(std::uint64_t) + bytes;
    return s;
  };

  write_file_atomically(path, [&](std::ostream& os) {
    const char* indent = "          ";
    auto matrix_array = [&](const Eigen::MatrixXd& m, const std::string& name_attr,
                            const std::vector<std::string>& component_names) {
      os << "        <DataArray type=\"Float64\"" << name_attr << " NumberOfComponents=\"" << m.rows() << "\"";
      for (std::size_t k = 0; k < component_names.size(); ++k) {
        os << " ComponentName" << k << "=\"" << xml_escape(component_names[k]) << "\"";
      }
      os << " " << format_attr(m.data(), static_cast<std::uint64_t>(m.size()) * sizeof(double));
      if (!ascii) {
        os << "/>\n";
        return;
      }
      os << ">\n";
      for (Index j = 0; j < m.cols(); ++j) {
        os << indent;
        for (Index i = 0; i < m.rows(); ++i) os << (i ? " " : "") << format_double(m(i, j));
        os << '\n';
      }
      os << "        </DataArray>\n";
    };
    // Integer arrays, `per_line` values to a line.
    auto int_array = [&](const char* type, const char* name, const auto& v, std::size_t per_line) {
      using T = typename std::decay_t<decltype(v)>::value_type;
      os << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" "
         << format_attr(v.data(), static_cast<std::uint64_t>(v.size() * sizeof(T)));
      if (!ascii) {
        os << "/>\n";
        return;
      }
      os << ">\n";
      for (std::size_t k = 0; k < v.size(); ++k) {
        os << (k % per_line == 0 ? indent : " ") << static_cast<long long>(v[k]);
        if (k % per_line == per_line - 1 || k + 1 == v.size()) os << '\n';
      }
      os << "        </DataArray>\n";
    };
    auto data_section = [&](const char* tag, const std::vector<Array>& arrays) {
      os << "      <" << tag << ">\n";
      for (const Array& a : arrays) matrix_array(a.values, " Name=\"" + xml_escape(a.name) + "\"", a.component_names);
      os << "      </" << tag << ">\n";
    };

    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
       << (host_is_little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
       << "  <UnstructuredGrid>\n"
       << "    <Piece NumberOfPoints=\"" << num_points() << "\" NumberOfCells=\"" << num_cells() << "\">\n";
    data_section("PointData", point_data_);
    data_section("CellData", cell_data_);
    os << "      <Points>\n";
    matrix_array(points_, " Name=\"Points\"", {});
    os << "      </Points>\n"
       << "      <Cells>\n";
    int_array("Int64", "connectivity", connectivity_, per_line_);
    int_array("Int64", "offsets", offsets_, 10);
    int_array("UInt8", "types", types_, 20);
    os << "      </Cells>\n"
       << "    </Piece>\n"
       << "  </UnstructuredGrid>\n";
    if (!ascii) {
      os << "  <AppendedData encoding=\"raw\">\n   _";
      for (const Block& b : blocks) {
        os.write(reinterpret_cast<const char*>(&b.bytes), sizeof(b.bytes));
        if (b.bytes > 0) os.write(static_cast<const char*>(b.data), static_cast<std::streamsize>(b.bytes));
      }
      os << "\n  </AppendedData>\n";
    }
    os << "</VTKFile>\n";
  });
}

VtuWriter VtuWriter::piece(const std::vector<Index>& cells, std::vector<Index>& points_used) const {
  for (const Index c : cells)
    if (c < 0 || c >= num_cells())
      throw std::invalid_argument("VtuWriter: piece with cell " + std::to_string(c) + " outside [0, " +
                                  std::to_string(num_cells()) + ")");
  auto cell_end = [&](Index c) { return static_cast<std::size_t>(offsets_[static_cast<std::size_t>(c)]); };
  auto cell_begin = [&](Index c) { return c == 0 ? std::size_t{0} : cell_end(c - 1); };
  std::vector<Index> local(static_cast<std::size_t>(num_points()), -1);
  for (const Index c : cells)
    for (std::size_t k = cell_begin(c); k < cell_end(c); ++k) local[static_cast<std::size_t>(connectivity_[k])] = 0;
  points_used.clear();
  for (Index p = 0; p < num_points(); ++p)
    if (local[static_cast<std::size_t>(p)] == 0) {
      local[static_cast<std::size_t>(p)] = static_cast<Index>(points_used.size());
      points_used.push_back(p);
    }
  VtuWriter w;
  w.encoding_ = encoding_;
  w.per_line_ = per_line_;
  w.points_.resize(3, static_cast<Index>(points_used.size()));
  for (std::size_t j = 0; j < points_used.size(); ++j) w.points_.col(static_cast<Index>(j)) = points_.col(points_used[j]);
  for (const Index c : cells) {
    for (std::size_t k = cell_begin(c); k < cell_end(c); ++k)
      w.connectivity_.push_back(local[static_cast<std::size_t>(connectivity_[k])]);
    w.offsets_.push_back(static_cast<std::int64_t>(w.connectivity_.size()));
    w.types_.push_back(types_[static_cast<std::size_t>(c)]);
  }
  for (const Array& a : point_data_) {
    Eigen::MatrixXd v(a.values.rows(), static_cast<Index>(points_used.size()));
    for (std::size_t j = 0; j < points_used.size(); ++j) v.col(static_cast<Index>(j)) = a.values.col(points_used[j]);
    w.point_data_.push_back(Array{a.name, std::move(v), a.component_names});
  }
  for (const Array& a : cell_data_) {
    Eigen::MatrixXd v(a.values.rows(), static_cast<Index>(cells.size()));
    for (std::size_t j = 0; j < cells.size(); ++j) v.col(static_cast<Index>(j)) = a.values.col(cells[j]);
    w.cell_data_.push_back(Array{a.name, std::move(v), a.component_names});
  }
  return w;
}

Eigen::MatrixXd VtuWriter::cell_centres() const {
  Eigen::MatrixXd centres = Eigen::MatrixXd::Zero(3, num_cells());
  std::size_t begin = 0;
  for (Index c = 0; c < num_cells(); ++c) {
    const auto end = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(c)]);
    for (std::size_t k = begin; k < end; ++k) centres.col(c) += points_.col(connectivity_[k]);
    if (end > begin) centres.col(c) /= static_cast<double>(end - begin);
    begin = end;
  }
  return centres;
}

void VtuWriter::write_parallel(const std::string& path, const std::vector<std::string>& pieces) const {
  write_file_atomically(path, [&](std::ostream& os) {
    auto header = [&](const std::string& name, Index components, const std::vector<std::string>& component_names) {
      os << "      <PDataArray type=\"Float64\" Name=\"" << xml_escape(name) << "\" NumberOfComponents=\"" << components
         << "\"";
      for (std::size_t k = 0; k < component_names.size(); ++k)
        os << " ComponentName" << k << "=\"" << xml_escape(component_names[k]) << "\"";
      os << "/>\n";
    };
    auto data_section = [&](const char* tag, const std::vector<Array>& arrays) {
      os << "    <" << tag << ">\n";
      for (const Array& a : arrays) header(a.name, a.values.rows(), a.component_names);
      os << "    </" << tag << ">\n";
    };
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\""
       << (host_is_little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
       << "  <PUnstructuredGrid GhostLevel=\"0\">\n";
    data_section("PPointData", point_data_);
    data_section("PCellData", cell_data_);
    os << "    <PPoints>\n";
    header("Points", 3, {});
    os << "    </PPoints>\n";
    for (const std::string& p : pieces) os << "    <Piece Source=\"" << xml_escape(p) << "\"/>\n";
    os << "  </PUnstructuredGrid>\n"
       << "</VTKFile>\n";
  });
}

}  // namespace symcontact
