#pragma once
/// \file problem.hpp
/// A problem as the Python module holds it: the TOML document, the name that messages give it and the
/// folder its mesh paths are resolved against, and the ProblemSpec the reader made of it. Every change
/// goes through the reader again (read_problem_table(), check_ipopt_section()), so an invalid value
/// raises the InputError, message and key the command line would print for the same file; the document
/// is then left as it was.

#include <string>

#include <toml++/toml.h>

#include "symcontact/model/problem_spec.hpp"
#include "toml_document.hpp"

namespace symcontact::python {

class Problem {
 public:
  /// The file at `path`, read and checked as `symcontact run` does (read_problem_file()).
  static Problem from_file(const std::string& path);
  /// TOML text; `name` stands for the file in messages and in summary.json "problem"; relative mesh
  /// paths are resolved against `base_dir` ("" : the current folder).
  static Problem from_string(const std::string& text, const std::string& base_dir, const std::string& name);

  pybind11::object get(const std::string& key_path) const;
  bool contains(const std::string& key_path) const;
  void set(const std::string& key_path, const pybind11::handle& value);
  void remove(const std::string& key_path);
  /// Several changes, key path → value (None: remove the key), validated once after all of them: for
  /// changes that are only valid together (steps.load_factors and every `factors` array, a friction law
  /// and its coefficient). All or nothing.
  void update(const pybind11::dict& changes);

  /// The document as TOML text (toml++'s formatting: keys sorted, comments dropped).
  std::string toml_text() const;
  pybind11::object as_dict() const { return to_python(doc_); }
  const ProblemSpec& spec() const { return spec_; }
  const std::string& name() const { return name_; }
  const std::string& base_dir() const { return base_dir_; }

 private:
  Problem(toml::table doc, std::string name, std::string base_dir);
  /// Reads doc_ into spec_ (throws InputError).
  void validate();
  /// Applies `change` to the document and validates it, restoring the document when either throws.
  template <class Change>
  void change_and_validate(Change&& change);

  toml::table doc_;
  std::string name_;
  std::string base_dir_;
  ProblemSpec spec_;
};

}  // namespace symcontact::python
