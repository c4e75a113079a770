#include "symcontact/io/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace symcontact {

Json::Json(const std::vector<double>& values) : type_(Type::kArray) {
  items_.reserve(values.size());
  for (double v : values) items_.emplace_back(v);
}

Json Json::object() {
  Json j;
  j.type_ = Type::kObject;
  return j;
}

Json Json::array() {
  Json j;
  j.type_ = Type::kArray;
  return j;
}

Json& Json::operator[](const std::string& key) {
  if (type_ == Type::kNull) type_ = Type::kObject;
  if (type_ != Type::kObject) throw std::logic_error("Json: operator[](\"" + key + "\") on a value that is not an object");
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (keys_[i] == key) return items_[i];
  }
  keys_.push_back(key);
  items_.emplace_back();
  return items_.back();
}

const Json& Json::at(const std::string& key) const {
  if (type_ == Type::kObject) {
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      if (keys_[i] == key) return items_[i];
    }
  }
  throw std::out_of_range("Json: no member \"" + key + "\"");
}

bool Json::contains(const std::string& key) const {
  if (type_ != Type::kObject) return false;
  for (const std::string& k : keys_) {
    if (k == key) return true;
  }
  return false;
}

void Json::push_back(Json value) {
  if (type_ == Type::kNull) type_ = Type::kArray;
  if (type_ != Type::kArray) throw std::logic_error("Json: push_back on a value that is not an array");
  items_.push_back(std::move(value));
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out;
}

void Json::dump_to(std::string& out, int indent, int depth) const {
  switch (type_) {
    case Type::kNull: out += "null"; return;
    case Type::kBool: out += bool_ ? "true" : "false"; return;
    case Type::kNumber: out += std::isfinite(number_) ? format_double(number_) : "null"; return;
    case Type::kString: out += json_quote(string_); return;
    case Type::kArray:
    case Type::kObject: break;
  }
  const bool is_obj = type_ == Type::kObject;
  const char open = is_obj ? '{' : '[';
  const char close = is_obj ? '}' : ']';
  out += open;
  if (items_.empty()) {
    out += close;
    return;
  }
  auto newline = [&](int level) {
    if (indent < 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(level), ' ');
  };
  for (std::size_t i = 0; i < items_.size(); ++i) {
    if (i > 0) out += ',';
    newline(depth + 1);
    if (is_obj) {
      out += json_quote(keys_[i]);
      out += indent < 0 ? ":" : ": ";
    }
    items_[i].dump_to(out, indent, depth + 1);
  }
  newline(depth);
  out += close;
}

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  constexpr double kMaxExactInteger = 9007199254740992.0;  // 2^53
  if (v == std::trunc(v) && std::fabs(v) <= kMaxExactInteger) {
    return std::to_string(static_cast<long long>(v));
  }
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);  // shortest round trip
  return std::string(buf, r.ptr);
}

std::string json_quote(const std::string& s) {
  std::string out;
  out.reserve(s.size() + 2);
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", static_cast<unsigned>(c));
          out += buf;
        } else {
          out += ch;  // ASCII and UTF-8 bytes pass through
        }
    }
  }
  out += '"';
  return out;
}

}  // namespace symcontact
