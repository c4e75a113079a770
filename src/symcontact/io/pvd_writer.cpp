#include "symcontact/io/pvd_writer.hpp"

#include <cmath>
#include <ostream>
#include <stdexcept>

#include "symcontact/io/atomic_file.hpp"
#include "symcontact/io/json_writer.hpp"
#include "symcontact/io/xml_escape.hpp"

namespace symcontact {


PvdCollection::PvdCollection(std::string path) : path_(std::move(path)) {}

void PvdCollection::add(double time, int part, const std::string& relative_file, const std::string& name) {
  if (!std::isfinite(time)) throw std::invalid_argument("PvdCollection " + path_ + ": time is not finite");
  if (part < 0) throw std::invalid_argument("PvdCollection " + path_ + ": part " + std::to_string(part) + " < 0");
  if (relative_file.empty()) throw std::invalid_argument("PvdCollection " + path_ + ": empty file name");
  entries_.push_back(Entry{time, part, relative_file, name});
}

void PvdCollection::write() const {
  write_file_atomically(path_, [&](std::ostream& os) {
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"Collection\" version=\"0.1\">\n"
       << "  <Collection>\n";
    for (const Entry& e : entries_) {
      os << "    <DataSet timestep=\"" << format_double(e.time) << "\" group=\"\" part=\"" << e.part
         << "\" file=\"" << xml_escape(e.file) << "\"";
      if (!e.name.empty()) os << " name=\"" << xml_escape(e.name) << "\"";
      os << "/>\n";
    }
    os << "  </Collection>\n"
       << "</VTKFile>\n";
  });
}

}  // namespace symcontact
