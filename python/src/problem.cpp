#include "problem.hpp"

#include <sstream>

#include "symcontact/model/problem_reader.hpp"
#include "symcontact/model/toml_parse.hpp"

namespace py = pybind11;

namespace symcontact::python {

Problem::Problem(toml::table doc, std::string name, std::string base_dir)
    : doc_(std::move(doc)), name_(std::move(name)), base_dir_(std::move(base_dir)) {}

Problem Problem::from_file(const std::string& path) {
  // The steps of read_problem_file(), keeping the document.
  const std::string text = read_problem_text(path);
  Problem p(parse_toml(text, path), path, problem_folder(path));
  p.validate();
  return p;
}

Problem Problem::from_string(const std::string& text, const std::string& base_dir, const std::string& name) {
  Problem p(parse_toml(text, name), name, base_dir);
  p.validate();
  return p;
}

void Problem::validate() {
  ProblemSpec spec = read_problem_table(doc_, name_, base_dir_);
  check_ipopt_section(spec);
  spec_ = std::move(spec);
}

template <class Change>
void Problem::change_and_validate(Change&& change) {
  toml::table before = doc_;
  try {
    change();
    validate();
  } catch (...) {
    doc_ = std::move(before);
    throw;
  }
}

py::object Problem::get(const std::string& key_path) const {
  const toml::node* node = find_node(doc_, split_key_path(key_path));
  if (!node) throw py::key_error(key_path + ": not in the problem");
  return to_python(*node);
}

bool Problem::contains(const std::string& key_path) const {
  return find_node(doc_, split_key_path(key_path)) != nullptr;
}

void Problem::set(const std::string& key_path, const py::handle& value) {
  const std::vector<PathPart> path = split_key_path(key_path);
  std::unique_ptr<toml::node> node = to_toml(value, key_path);
  change_and_validate([&] { set_node(doc_, path, std::move(node)); });
}

void Problem::remove(const std::string& key_path) {
  const std::vector<PathPart> path = split_key_path(key_path);
  change_and_validate([&] { remove_node(doc_, path); });
}

void Problem::update(const py::dict& changes) {
  std::vector<std::pair<std::vector<PathPart>, std::unique_ptr<toml::node>>> edits;
  for (auto item : changes) {
    const std::string key = py::str(item.first);
    edits.emplace_back(split_key_path(key), item.second.is_none() ? nullptr : to_toml(item.second, key));
  }
  change_and_validate([&] {
    for (auto& [path, value] : edits) {
      if (value)
        set_node(doc_, path, std::move(value));
      else
        remove_node(doc_, path);
    }
  });
}

std::string Problem::toml_text() const {
  std::ostringstream os;
  os << doc_;
  return os.str();
}

}  // namespace symcontact::python
