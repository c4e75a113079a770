#include "symcontact/mesh/geo_commands.hpp"

#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string_view>
#include <utility>

#include "symcontact/core/error.hpp"
#include "symcontact/core/input_file.hpp"

namespace symcontact {

namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 5> kRunsPrograms = {"SystemCall", "System", "NonBlockingSystemCall",
                                                           "OnelabRun", "Shell"};
constexpr int kMaxIncludeDepth = 16;

const std::string kHint =
    "Gmsh commands that run other programs are refused in .geo files (they would run while the file is "
    "read, even by `symcontact check`); pass --allow-geo-commands if you trust this file";

/// A token of the .geo text: an identifier, a string literal (its contents) or one other character.
struct Token {
  enum Kind { kIdentifier, kString, kOther, kEnd } kind = kEnd;
  std::string text;
  int line = 1;
};

/// Gmsh's lexical rules, enough to find identifiers outside comments and strings.
class Lexer {
 public:
  explicit Lexer(std::string text) : s_(std::move(text)) {}

  Token next() {
    skip_space_and_comments();
    Token t;
    t.line = line_;
    if (i_ >= s_.size()) return t;
    const char c = s_[i_];
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = i_;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      t.kind = Token::kIdentifier;
      t.text = s_.substr(start, i_ - start);
    } else if (c == '"') {
      ++i_;
      t.kind = Token::kString;
      while (i_ < s_.size() && s_[i_] != '"') {
        if (s_[i_] == '\\' && i_ + 1 < s_.size()) ++i_;
        if (s_[i_] == '\n') ++line_;
        t.text += s_[i_++];
      }
      ++i_;
    } else {
      t.kind = Token::kOther;
      t.text = std::string(1, c);
      ++i_;
    }
    return t;
  }

 private:
  void skip_space_and_comments() {
    while (i_ < s_.size()) {
      if (s_[i_] == '\n') {
        ++line_;
        ++i_;
      } else if (std::isspace(static_cast<unsigned char>(s_[i_]))) {
        ++i_;
      } else if (s_.compare(i_, 2, "//") == 0) {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
      } else if (s_.compare(i_, 2, "/*") == 0) {
        i_ += 2;
        while (i_ < s_.size() && s_.compare(i_, 2, "*/") != 0) line_ += s_[i_++] == '\n' ? 1 : 0;
        i_ += 2;
      } else {
        return;
      }
    }
  }

  std::string s_;
  std::size_t i_ = 0;
  int line_ = 1;
};

std::string read_geo_text(const std::string& path) {
  if (const std::string problem = input_file_problem(path); !problem.empty())
    throw InputError(path, "", "cannot read the .geo file: it " + problem);
  std::ifstream in(path, std::ios::binary);
  return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The .geo file that `Include "f"` or `Merge "f"` (token `t`, file name token `name`) reads as .geo text,
/// or "" when it merges another kind of file (a mesh, a CAD file).
std::string included_geo(const std::string& path, const Token& t, const Token& name, int depth) {
  const fs::path included = fs::path(path).parent_path() / name.text;
  if (t.text != "Include" && included.extension() != ".geo") return "";
  if (depth >= kMaxIncludeDepth)
    throw InputError(path, "line " + std::to_string(t.line),
                     "more than " + std::to_string(kMaxIncludeDepth) + " nested Include/Merge of .geo files");
  return included.string();
}

/// The file name token after Include or Merge (skipping an opening parenthesis).
Token include_name(Lexer& lex) {
  Token name = lex.next();
  while (name.kind == Token::kOther && name.text == "(") name = lex.next();
  return name;
}

void scan(const std::string& path, int depth) {
  Lexer lex(read_geo_text(path));
  for (Token t = lex.next(); t.kind != Token::kEnd; t = lex.next()) {
    if (t.kind != Token::kIdentifier) continue;
    for (std::string_view command : kRunsPrograms)
      if (t.text == command)
        throw InputError(path, "line " + std::to_string(t.line),
                         "the command '" + t.text + "' runs another program. " + kHint);
    if (t.text != "Include" && t.text != "Merge") continue;
    const Token name = include_name(lex);
    if (name.kind != Token::kString)
      throw InputError(path, "line " + std::to_string(t.line),
                       "'" + t.text + "' with a computed file name cannot be checked for commands that run " +
                           "other programs. " + kHint);
    if (const std::string geo = included_geo(path, t, name, depth); !geo.empty()) scan(geo, depth + 1);
  }
}

/// Adds the names declared in the brackets of one `DefineConstant[ ... ]` (the lexer just past the
/// keyword): identifiers directly inside the brackets (not inside a `{...}` or `(...)` of options) and
/// followed by `=`.
void read_define_constant(Lexer& lex, std::set<std::string>& names) {
  Token t = lex.next();
  if (t.kind != Token::kOther || t.text != "[") return;
  int depth = 0;  // of (), {} and [] inside the outer brackets
  Token previous;
  for (t = lex.next(); t.kind != Token::kEnd; previous = t, t = lex.next()) {
    if (t.kind == Token::kOther && (t.text == "(" || t.text == "{" || t.text == "[")) ++depth;
    if (t.kind == Token::kOther && (t.text == ")" || t.text == "}" || t.text == "]")) {
      if (depth-- == 0) return;
    }
    if (depth == 0 && t.kind == Token::kOther && t.text == "=" && previous.kind == Token::kIdentifier)
      names.insert(previous.text);
  }
}

void collect_constants(const std::string& path, int depth, std::set<std::string>& names) {
  Lexer lex(read_geo_text(path));
  for (Token t = lex.next(); t.kind != Token::kEnd; t = lex.next()) {
    if (t.kind != Token::kIdentifier) continue;
    if (t.text == "DefineConstant") read_define_constant(lex, names);
    if (t.text != "Include" && t.text != "Merge") continue;
    const Token name = include_name(lex);
    if (name.kind != Token::kString) continue;  // a computed name cannot be followed
    if (const std::string geo = included_geo(path, t, name, depth); !geo.empty())
      collect_constants(geo, depth + 1, names);
  }
}

}  // namespace

void check_geo_commands(const std::string& path) { scan(path, 0); }

std::set<std::string> geo_defined_constants(const std::string& path) {
  std::set<std::string> names;
  collect_constants(path, 0, names);
  return names;
}

bool is_geo_identifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

}  // namespace symcontact
