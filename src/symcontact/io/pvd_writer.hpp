#pragma once
/// \file pvd_writer.hpp
/// A ParaView collection (.pvd) that ties the .vtu files of a run together over time and bodies.
///
/// Each entry is one file at one time for one part (a body, or a contact surface):
///     <DataSet timestep="0.5" group="" part="1" file="out/body1_000003.vtu" name="punch"/>
/// ParaView opens the .pvd as one time series; the parts at a time form a multiblock dataset
/// (block k = part k). The `name` attribute labels the block in readers that know it (VTK 9
/// collection readers); other readers ignore it.

#include <cstddef>
#include <string>
#include <vector>

namespace symcontact {

class PvdCollection {
 public:
  /// A collection to be written to `path` (nothing is written until write()).
  explicit PvdCollection(std::string path);

  const std::string& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }

  /// Adds the file `relative_file`, given relative to the folder of path() (as ParaView resolves it),
  /// for part `part` at time `time`. `name` labels the part (leave empty for none). Throws
  /// std::invalid_argument if time is not finite, part < 0 or relative_file is empty.
  /// Entries are written in the order they were added.
  void add(double time, int part, const std::string& relative_file, const std::string& name = "");

  /// (Re)writes the whole collection atomically (write_file_atomically()), so the file on disk is a
  /// valid collection after every step, even if the run is killed. Call after each step's files are
  /// written, so the collection never names a file that does not exist yet.
  void write() const;

 private:
  struct Entry {
    double time;
    int part;
    std::string file, name;
  };
  std::string path_;
  std::vector<Entry> entries_;
};

}  // namespace symcontact
