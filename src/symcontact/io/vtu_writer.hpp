#pragma once
/// \file vtu_writer.hpp
/// Writes one piece of a VTK XML UnstructuredGrid (.vtu) file: points, cells of one type, and point
/// and cell data arrays. Used for the bodies (volume cells) and for contact surfaces (line and
/// triangle facets).
///
/// File layout (VTK file formats, "UnstructuredGrid"): Points as Float64 × 3 (coordinates of lower
/// dimension padded with zeros); Cells as Int64 connectivity and offsets and UInt8 types; data arrays
/// as Float64 with NumberOfComponents = rows of the matrix given. Cells are written in VTK node order:
/// our ordering is Gmsh's (cell_type.hpp), and node k of a VTK cell is our node vtk_node_order(t)[k]
/// (for Tet10 the last two edge nodes swap).
///
/// Data conventions for callers: vectors (displacement, force) as 3 components (pad 2D with a zero
/// z so ParaView can warp by them); symmetric tensors (stress, strain) as 6 components in ParaView's
/// order XX, YY, ZZ, XY, YZ, XZ (2D: XX, YY, 0 or the plane value, XY, 0, 0).
///
/// A parallel VTU (.pvtu, "PUnstructuredGrid") names several such files, its pieces, that ParaView reads as one
/// grid: piece() cuts a range of cells out of a writer, write_parallel() writes the .pvtu that lists the pieces
/// with their arrays (the same names and components in every piece).
///
/// Encodings: kAscii writes every value in the shortest text that reads back to the same double
/// (format_double); NaN or inf cannot be written that way and make write() throw. kBinaryAppended
/// writes raw little- or big-endian bytes (the host's, declared in byte_order) in one AppendedData
/// block with UInt64 block-size headers; it is smaller, faster and keeps NaN and inf.

#include <cstdint>
#include <string>
#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

struct Mesh;

enum class VtuEncoding { kAscii, kBinaryAppended };

class VtuWriter {
 public:
  /// The geometry of `mesh`: mesh.x (dim × n) as points, its cells block by block (of one or more types).
  /// The mesh is copied; it need not outlive the writer.
  explicit VtuWriter(const Mesh& mesh);

  /// Raw geometry: `points` is d × n with d in 1..3 (padded to 3 with zeros), `connectivity` holds
  /// num_cells × cell_num_nodes(type) node indices in our (Gmsh) ordering, cell after cell.
  /// Throws std::invalid_argument if d is out of range, the connectivity length is not a multiple of
  /// the nodes per cell, or an index is outside [0, n). Zero cells (an empty contact surface) is allowed.
  VtuWriter(const Eigen::MatrixXd& points, CellType type, std::vector<Index> connectivity);

  Index num_points() const { return points_.cols(); }
  Index num_cells() const { return static_cast<Index>(offsets_.size()); }

  void set_encoding(VtuEncoding e) { encoding_ = e; }  ///< default kAscii
  VtuEncoding encoding() const { return encoding_; }

  /// Adds a point data array; `values` is ncomp × num_points() (column j = point j), ncomp >= 1.
  /// A column vector (VectorXd, or any expression with one column at compile time) is instead a
  /// scalar array with one value per point. `component_names`, if not empty, has ncomp entries,
  /// written as ComponentName0.. (ParaView shows them in place of 0, 1, 2). Throws
  /// std::invalid_argument naming the array when the shape is wrong, the name is empty, or an array
  /// of that name was already added to point data. The values are copied.
  template <class Derived>
  void add_point_data(const std::string& name, const Eigen::MatrixBase<Derived>& values,
                      const std::vector<std::string>& component_names = {}) {
    if constexpr (Derived::ColsAtCompileTime == 1) {
      add(point_data_, "point data", num_points(), name, values.transpose(), component_names);
    } else {
      add(point_data_, "point data", num_points(), name, values, component_names);
    }
  }
  /// Adds a cell data array; `values` is ncomp × num_cells() (or a column vector: one scalar per
  /// cell). Same rules as add_point_data().
  template <class Derived>
  void add_cell_data(const std::string& name, const Eigen::MatrixBase<Derived>& values,
                     const std::vector<std::string>& component_names = {}) {
    if constexpr (Derived::ColsAtCompileTime == 1) {
      add(cell_data_, "cell data", num_cells(), name, values.transpose(), component_names);
    } else {
      add(cell_data_, "cell data", num_cells(), name, values, component_names);
    }
  }

  /// Writes the file atomically (write_file_atomically()); the folder must exist. Throws
  /// std::runtime_error if the file cannot be written, std::invalid_argument (naming the array)
  /// if the encoding is kAscii and an array holds a non-finite value.
  void write(const std::string& path) const;

  /// The cells `cells` (indices here, in that order) with the points they use, in increasing order of their
  /// index here (their indices, to `points_used`), and every data array restricted to those points and cells:
  /// one piece of a parallel VTU. No cells give a piece of no cells and no points. Throws
  /// std::invalid_argument for an index outside [0, num_cells()).
  VtuWriter piece(const std::vector<Index>& cells, std::vector<Index>& points_used) const;

  /// The mean of each cell's points, 3 × num_cells().
  Eigen::MatrixXd cell_centres() const;

  /// Writes the .pvtu at `path` (atomically) naming `pieces`, files relative to its folder, each written by a
  /// writer with this one's arrays (piece() of the same writer, with the same arrays added to each).
  void write_parallel(const std::string& path, const std::vector<std::string>& pieces) const;

 private:
  VtuWriter() = default;
  struct Array {
    std::string name;
    Eigen::MatrixXd values;  ///< ncomp × count
    std::vector<std::string> component_names;
  };
  void add(std::vector<Array>& arrays, const char* where, Index count, const std::string& name,
           const Eigen::MatrixXd& values, const std::vector<std::string>& component_names);

  /// Appends cells of one type (`entries` node indices in our ordering, cell after cell), checking them.
  void append_cells(CellType type, const Index* connectivity, std::size_t entries);

  Eigen::MatrixXd points_;            ///< 3 × n
  std::vector<Index> connectivity_;   ///< in VTK node order
  std::vector<std::int64_t> offsets_; ///< end of each cell's nodes in connectivity_
  std::vector<std::uint8_t> types_;   ///< VTK cell type of each cell
  std::size_t per_line_ = 1;          ///< connectivity entries per line in ASCII: the largest cell's nodes
  std::vector<Array> point_data_, cell_data_;
  VtuEncoding encoding_ = VtuEncoding::kAscii;
};

}  // namespace symcontact
