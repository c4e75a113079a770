#pragma once
/// \file problem_snippet.hpp
/// Input files for tests, each written as one edit of a base snippet, and the checks of the InputError a
/// bad one must raise.
///  - replaced(), ProblemSnippet: a problem file (or a mesh file) as text, and edited copies of it — a text
///    replaced, lines added after a given line, the 2D base turned 3D;
///  - body_toml(), dirichlet_toml(), clamped_block(): the [[body]] and [[body.dirichlet]] tables cases repeat;
///  - InputErrorCase, expect_input_error_case(): a table of bad inputs, each with the key its InputError must
///    name and a part of its message (the problem reader's and the .msh check's tables);
///  - write_placeholders(): empty files for the meshes a problem refers to (the reader checks existence
///    only).

#include <filesystem>
#include <functional>
#include <initializer_list>
#include <optional>
#include <ostream>
#include <string>

#include "symcontact/core/error.hpp"

namespace symcontact::testing {

/// `text` with the first occurrence of `from` replaced by `to`; a test failure when `from` is not in it.
std::string replaced(const std::string& text, const std::string& from, const std::string& to);

/// A problem file's text; every edit returns an edited copy, so that one base serves a table of cases.
class ProblemSnippet {
 public:
  explicit ProblemSnippet(std::string text) : text_(std::move(text)) {}

  const std::string& text() const { return text_; }
  operator const std::string&() const { return text_; }  // NOLINT: a snippet is its text

  /// The first `from` replaced by `to` (a test failure when absent).
  ProblemSnippet replaced(const std::string& from, const std::string& to) const;
  /// `lines` ("key = value\n" …) inserted after the first occurrence of `line` (a whole line, its "\n"
  /// included): keys added to the table `line` opens or belongs to.
  ProblemSnippet after(const std::string& line, const std::string& lines) const;
  /// `dimension = 2` made `dimension = 3`.
  ProblemSnippet in_3d() const;
  /// `more` appended (further tables).
  ProblemSnippet operator+(const std::string& more) const { return ProblemSnippet(text_ + more); }

 private:
  std::string text_;
};
/// `before` (top-level keys, tables) followed by the snippet.
inline ProblemSnippet operator+(const std::string& before, const ProblemSnippet& s) {
  return ProblemSnippet(before + s.text());
}

/// A [[body]] table: name, mesh, group (left out when empty), the inline material `{ material }`, then
/// `tables` (its [[body.dirichlet]], [[body.pressure]] …).
std::string body_toml(const std::string& name, const std::string& mesh, const std::string& group,
                      const std::string& material, const std::string& tables = "");
/// A [[body.dirichlet]] table on `boundary` with `components` ("ux = 0.0\nuy = 0.0\n").
std::string dirichlet_toml(const std::string& boundary, const std::string& components);

/// A 2D problem over the load steps 0.5 and 1 with one body "block" (mesh "block.msh", group "block",
/// material `material`) clamped at its bottom; tests add its further tables.
ProblemSnippet clamped_block(const std::string& material = "E = 1.0, nu = 0.3");

/// A bad input and what its InputError must say.
struct InputErrorCase {
  std::string name;      ///< test name suffix
  std::string text;      ///< the input file
  std::string key;       ///< expected InputError::key()
  std::string fragment;  ///< expected part of InputError::message()
};
inline void PrintTo(const InputErrorCase& c, std::ostream* os) { *os << c.name; }

/// The InputError `read` throws, or nothing.
std::optional<InputError> input_error_of(const std::function<void()>& read);
/// Expects `read` to throw an InputError naming `file`, the case's key and its message fragment.
void expect_input_error_case(const std::function<void()>& read, const InputErrorCase& c, const std::string& file);

/// Creates an empty placeholder file at each of `names` (relative to `folder`, sub-folders created).
void write_placeholders(const std::filesystem::path& folder, std::initializer_list<const char*> names);

}  // namespace symcontact::testing
