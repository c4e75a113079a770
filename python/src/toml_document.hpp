#pragma once
/// \file toml_document.hpp
/// A problem file as an editable TOML document, addressed by key paths, and the conversions between
/// TOML values and Python objects.
///
/// Key paths name a value the way the reader's messages do, or with dots only:
///   "contact[0].mu" = "contact.0.mu",  "body[1].material.nu" = "body.1.material.nu",
///   "problem.mesh_size", "ipopt.tol", "steps.load_factors[2]".
/// A component is a table key (letters, digits, '_' and '-') or an array index (an integer, from 0).
/// Conversions: bool ↔ boolean, int ↔ integer, float ↔ floating point, str ↔ string, list/tuple ↔
/// array, dict ↔ table; numpy scalars and arrays are taken through their Python values (tolist()).

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

namespace symcontact::python {

/// One component of a key path: a table key or an array index.
using PathPart = std::variant<std::string, std::size_t>;

/// `path` split into its components; throws pybind11::key_error for an empty or malformed path.
std::vector<PathPart> split_key_path(const std::string& path);

/// The value at `path`, or nullptr when some component does not exist.
const toml::node* find_node(const toml::table& root, const std::vector<PathPart>& path);

/// Sets the value at `path` to `value`, creating missing tables on the way. An array index may be at
/// most the array's length (that length appends). Throws pybind11::key_error when the path goes
/// through a value that is neither a table nor an array, or with a key into an array, or an index
/// into a table, and pybind11::index_error for an index past the end.
void set_node(toml::table& root, const std::vector<PathPart>& path, std::unique_ptr<toml::node> value);

/// Removes the value at `path`; throws pybind11::key_error when there is none.
void remove_node(toml::table& root, const std::vector<PathPart>& path);

/// A Python object as a TOML value; throws pybind11::type_error for what TOML cannot hold (None, an
/// object of another type). A non-finite float is kept: the reader rejects it with its own message.
std::unique_ptr<toml::node> to_toml(const pybind11::handle& value, const std::string& path);

/// A TOML value as a Python object.
pybind11::object to_python(const toml::node& node);

}  // namespace symcontact::python
