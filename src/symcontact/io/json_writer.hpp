#pragma once
/// \file json_writer.hpp
/// A small JSON value for writing result summaries (no parser). Objects keep their keys in insertion
/// order, so files are stable and diff well.
///
///     Json j = Json::object();
///     j["name"] = "hertz";
///     j["steps"] = 12;
///     j["gap"] = std::vector<double>{0.0, 1e-3};
///     j["solver"]["iterations"] = 31;   // a null value becomes an object on operator[]
///     write_file_atomically(path, [&](std::ostream& os) { os << j.dump() << '\n'; });
///
/// Numbers are doubles. They are printed in the shortest form that reads back to the same double;
/// whole numbers of magnitude at most 2^53 print without a fraction or exponent ("3", "-12"), and
/// NaN and ±inf print as null (JSON has no non-finite numbers). Integers beyond 2^53 in magnitude
/// lose precision. Strings are UTF-8 and are passed through unchanged except for the escapes JSON
/// requires: \" \\ \b \f \n \r \t, and \u00XX for other control characters below 0x20.

#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace symcontact {

class Json {
 public:
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };

  Json() = default;  ///< null
  Json(std::nullptr_t) {}
  Json(bool b) : type_(Type::kBool), bool_(b) {}
  Json(double v) : type_(Type::kNumber), number_(v) {}
  /// Any integer type except bool (int, long, Index, std::size_t, ...), stored as a double.
  template <class T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>, int> = 0>
  Json(T v) : type_(Type::kNumber), number_(static_cast<double>(v)) {}
  Json(const char* s) : type_(Type::kString), string_(s) {}
  Json(std::string s) : type_(Type::kString), string_(std::move(s)) {}
  /// An array of numbers.
  Json(const std::vector<double>& values);

  static Json object();  ///< an empty object {}
  static Json array();   ///< an empty array []

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::kNull; }
  bool is_object() const { return type_ == Type::kObject; }
  bool is_array() const { return type_ == Type::kArray; }
  /// Elements of an array or members of an object; 0 for other values.
  std::size_t size() const { return items_.size(); }

  /// The member `key` of an object, inserted as null at the end if absent. A null value first becomes
  /// an empty object. Throws std::logic_error for other types. Lookup is linear in the number of keys.
  Json& operator[](const std::string& key);
  /// The member `key`; throws std::out_of_range if absent or if this is not an object.
  const Json& at(const std::string& key) const;
  bool contains(const std::string& key) const;

  /// Appends to an array (a null value first becomes an empty array). Throws std::logic_error for
  /// other types.
  void push_back(Json value);

  /// The JSON text. indent >= 0: one element or member per line, nested `indent` spaces deeper per
  /// level, "key": value; empty arrays and objects print as [] and {}. indent < 0: one line, no spaces.
  /// No trailing newline.
  std::string dump(int indent = 2) const;

 private:
  void dump_to(std::string& out, int indent, int depth) const;

  Type type_ = Type::kNull;
  bool bool_ = false;
  double number_ = 0.0;
  std::string string_;
  std::vector<std::string> keys_;  ///< object keys, parallel to items_
  std::vector<Json> items_;        ///< array elements or object values
};

/// The shortest decimal text that reads back (strtod) to exactly `v`, with whole numbers of magnitude
/// up to 2^53 printed as integers ("3", not "3.0" or "3e+00"). Non-finite values give "nan", "inf" or
/// "-inf" (callers writing formats without them must handle those first). Locale-independent.
std::string format_double(double v);

/// `s` as a quoted JSON string literal, escaped as described in the file comment.
std::string json_quote(const std::string& s);

}  // namespace symcontact
