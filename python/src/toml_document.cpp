#include "toml_document.hpp"

#include <cctype>
#include <sstream>

namespace py = pybind11;

namespace symcontact::python {

namespace {

bool is_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

[[noreturn]] void bad_path(const std::string& path, const std::string& why) {
  throw py::key_error("key path '" + path + "': " + why);
}

std::string describe(const std::vector<PathPart>& path, std::size_t upto) {
  std::string s;
  for (std::size_t i = 0; i < upto && i < path.size(); ++i) {
    if (const auto* key = std::get_if<std::string>(&path[i]))
      s += (s.empty() ? "" : ".") + *key;
    else
      s += "[" + std::to_string(std::get<std::size_t>(path[i])) + "]";
  }
  return s.empty() ? "the document" : s;
}

/// Moves the concrete value held by `value` into `place(concrete&&)`.
template <class Place>
void move_into(std::unique_ptr<toml::node>& value, Place&& place) {
  value->visit([&](auto& concrete) { place(std::move(concrete)); });
}

}  // namespace

std::vector<PathPart> split_key_path(const std::string& path) {
  std::vector<PathPart> parts;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos) bad_path(path, "a '[' without its ']'");
      const std::string index = path.substr(i + 1, close - i - 1);
      if (!all_digits(index)) bad_path(path, "expected an index from 0 between [ and ], got '" + index + "'");
      parts.emplace_back(static_cast<std::size_t>(std::stoull(index)));
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    std::size_t end = i;
    while (end < path.size() && is_key_char(path[end])) ++end;
    const std::string key = path.substr(i, end - i);
    if (key.empty()) bad_path(path, "expected a key (letters, digits, '_', '-') at character " + std::to_string(i + 1));
    if (all_digits(key) && !parts.empty())
      parts.emplace_back(static_cast<std::size_t>(std::stoull(key)));
    else
      parts.emplace_back(key);
    i = end;
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size()) bad_path(path, "ends with '.'");
    } else if (i < path.size() && path[i] != '[') {
      bad_path(path, std::string("unexpected character '") + path[i] + "'");
    }
  }
  if (parts.empty()) bad_path(path, "empty");
  return parts;
}

const toml::node* find_node(const toml::table& root, const std::vector<PathPart>& path) {
  const toml::node* node = &root;
  for (const PathPart& part : path) {
    if (const auto* key = std::get_if<std::string>(&part)) {
      const toml::table* t = node->as_table();
      node = t ? t->get(*key) : nullptr;
    } else {
      const toml::array* a = node->as_array();
      node = a ? a->get(std::get<std::size_t>(part)) : nullptr;
    }
    if (!node) return nullptr;
  }
  return node;
}

namespace {

/// The container that holds path.back(), creating missing tables on the way.
toml::node* parent_for_set(toml::table& root, const std::vector<PathPart>& path) {
  toml::node* node = &root;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    toml::node* next = nullptr;
    if (const auto* key = std::get_if<std::string>(&path[i])) {
      toml::table* t = node->as_table();
      if (!t) bad_path(describe(path, path.size()), describe(path, i) + " is not a table");
      next = t->get(*key);
      if (!next) next = &t->insert_or_assign(*key, toml::table{}).first->second;
    } else {
      toml::array* a = node->as_array();
      if (!a) bad_path(describe(path, path.size()), describe(path, i) + " is not an array");
      next = a->get(std::get<std::size_t>(path[i]));
      if (!next) throw py::index_error(describe(path, i + 1) + ": no such element (the array has " +
                                       std::to_string(a->size()) + ")");
    }
    node = next;
  }
  return node;
}

}  // namespace

void set_node(toml::table& root, const std::vector<PathPart>& path, std::unique_ptr<toml::node> value) {
  toml::node* parent = parent_for_set(root, path);
  const std::string where = describe(path, path.size());
  if (const auto* key = std::get_if<std::string>(&path.back())) {
    toml::table* t = parent->as_table();
    if (!t) bad_path(where, describe(path, path.size() - 1) + " is not a table");
    move_into(value, [&](auto&& v) { t->insert_or_assign(*key, std::move(v)); });
    return;
  }
  toml::array* a = parent->as_array();
  if (!a) bad_path(where, describe(path, path.size() - 1) + " is not an array");
  const std::size_t index = std::get<std::size_t>(path.back());
  if (index > a->size())
    throw py::index_error(where + ": past the end (the array has " + std::to_string(a->size()) + " elements)");
  if (index == a->size())
    move_into(value, [&](auto&& v) { a->push_back(std::move(v)); });
  else
    move_into(value, [&](auto&& v) { a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(index), std::move(v)); });
}

void remove_node(toml::table& root, const std::vector<PathPart>& path) {
  const std::string where = describe(path, path.size());
  std::vector<PathPart> parent_path(path.begin(), path.end() - 1);
  toml::node* parent = parent_path.empty() ? &root : const_cast<toml::node*>(find_node(root, parent_path));
  if (const auto* key = std::get_if<std::string>(&path.back())) {
    toml::table* t = parent ? parent->as_table() : nullptr;
    if (!t || !t->erase(*key)) throw py::key_error(where + ": not in the problem");
    return;
  }
  toml::array* a = parent ? parent->as_array() : nullptr;
  const std::size_t index = std::get<std::size_t>(path.back());
  if (!a || index >= a->size()) throw py::key_error(where + ": not in the problem");
  a->erase(a->cbegin() + static_cast<std::ptrdiff_t>(index));
}

std::unique_ptr<toml::node> to_toml(const py::handle& value, const std::string& path) {
  if (py::isinstance<py::bool_>(value)) return std::make_unique<toml::value<bool>>(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return std::make_unique<toml::value<std::int64_t>>(value.cast<std::int64_t>());
  if (py::isinstance<py::float_>(value)) return std::make_unique<toml::value<double>>(value.cast<double>());
  if (py::isinstance<py::str>(value)) return std::make_unique<toml::value<std::string>>(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    auto t = std::make_unique<toml::table>();
    for (auto item : value.cast<py::dict>()) {
      const std::string key = py::str(item.first);
      std::unique_ptr<toml::node> v = to_toml(item.second, path + "." + key);
      move_into(v, [&](auto&& c) { t->insert_or_assign(key, std::move(c)); });
    }
    return t;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    auto a = std::make_unique<toml::array>();
    std::size_t i = 0;
    for (auto item : value) {
      std::unique_ptr<toml::node> v = to_toml(item, path + "[" + std::to_string(i++) + "]");
      move_into(v, [&](auto&& c) { a->push_back(std::move(c)); });
    }
    return a;
  }
  if (py::hasattr(value, "tolist")) return to_toml(value.attr("tolist")(), path);  // numpy values
  throw py::type_error(path + ": a TOML value is a bool, int, float, str, list or dict, got " +
                       std::string(py::str(value.get_type().attr("__name__"))));
}

py::object to_python(const toml::node& node) {
  if (const auto* t = node.as_table()) {
    py::dict d;
    for (auto&& [key, v] : *t) d[py::str(std::string(key.str()))] = to_python(v);
    return d;
  }
  if (const auto* a = node.as_array()) {
    py::list l;
    for (const toml::node& v : *a) l.append(to_python(v));
    return l;
  }
  if (const auto* b = node.as_boolean()) return py::bool_(b->get());
  if (const auto* i = node.as_integer()) return py::int_(i->get());
  if (const auto* f = node.as_floating_point()) return py::float_(f->get());
  if (const auto* s = node.as_string()) return py::str(s->get());
  // Dates and times: their TOML text.
  std::ostringstream os;
  node.visit([&os](const auto& v) { os << v; });
  return py::str(os.str());
}

}  // namespace symcontact::python
