#include "symcontact/model/toml_parse.hpp"

#include <cstdint>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "symcontact/core/error.hpp"

namespace symcontact {

namespace {

constexpr char32_t kPlane15 = 0xF0000;  // shielded(c) = c + kPlane15 for c in U+0080 … U+FFFF

/// One code point decoded from UTF-8 (RFC 3629, section 3), or nothing for an ill-formed sequence:
/// a stray continuation byte, a truncated sequence, an overlong form, a surrogate, or above U+10FFFF.
struct Decoded {
  char32_t cp;
  std::size_t length;  ///< bytes
};

std::optional<Decoded> decode_utf8(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return Decoded{b0, 1};
  std::size_t length;
  char32_t cp, least;
  if ((b0 & 0xE0) == 0xC0) {
    length = 2, cp = b0 & 0x1F, least = 0x80;
  } else if ((b0 & 0xF0) == 0xE0) {
    length = 3, cp = b0 & 0x0F, least = 0x800;
  } else if ((b0 & 0xF8) == 0xF0) {
    length = 4, cp = b0 & 0x07, least = 0x10000;
  } else {
    return std::nullopt;
  }
  if (i + length > s.size()) return std::nullopt;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return std::nullopt;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  if (cp < least || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return std::nullopt;
  return Decoded{cp, length};
}

void append_utf8(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

std::string code_point_name(char32_t cp) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "U+%04X", static_cast<unsigned>(cp));
  return buffer;
}

/// Line and column (both from 1, columns counted in code points, as toml++ counts them) of byte `at`.
std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t at) {
  std::size_t line = 1, column = 1;
  for (std::size_t k = 0; k < at && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[k]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {line, column};
}

/// Byte offset of (line, column) in `text`, or npos when there is no such position.
std::size_t byte_at(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t l = 1, c = 1;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if ((static_cast<unsigned char>(text[k]) & 0xC0) == 0x80) continue;
    if (l == line && c == column) return k;
    if (text[k] == '\n') {
      ++l;
      c = 1;
    } else {
      ++c;
    }
  }
  return std::string_view::npos;
}

[[noreturn]] void fail_at(std::string_view text, std::size_t at, const std::string& file, const std::string& what) {
  const auto [line, column] = line_column(text, at);
  throw InputError(file, "", "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what);
}

bool is_shielded(char32_t cp) { return cp >= kPlane15 + 0x80 && cp <= kPlane15 + 0xFFFF; }

bool has_shielded(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::optional<Decoded> d = decode_utf8(s, i);
    if (d && is_shielded(d->cp)) return true;
    i += d ? d->length : 1;
  }
  return false;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// Step 3 on every string and key of `table`, recursively. A key that comes back equal to another
/// key of the same table (written once raw and once as an escape) is a duplicate key.
void unshield_node(toml::node& node, const std::string& file);

void unshield_table(toml::table& table, const std::string& file) {
  std::vector<toml::key> renamed;
  for (auto&& [key, value] : table) {
    unshield_node(value, file);
    if (has_shielded(key.str())) renamed.push_back(key);
  }
  for (const toml::key& old_key : renamed) {
    const std::string name = unshield_toml_text(old_key.str());
    if (table.contains(name)) {
      const toml::source_position where = old_key.source().begin;
      throw InputError(file, "",
                       "line " + std::to_string(where.line) + ", column " + std::to_string(where.column) +
                           ": the key \"" + name + "\" is defined twice in one table");
    }
    toml::node* value = table.get(old_key.str());
    value->visit([&](auto& v) { table.insert(toml::key(name, old_key.source()), std::move(v)); });
    table.erase(old_key.str());
  }
}

void unshield_node(toml::node& node, const std::string& file) {
  if (toml::value<std::string>* s = node.as_string()) {
    if (has_shielded(s->get())) s->get() = unshield_toml_text(s->get());
  } else if (toml::array* a = node.as_array()) {
    for (toml::node& element : *a) unshield_node(element, file);
  } else if (toml::table* t = node.as_table()) {
    unshield_table(*t, file);
  }
}

}  // namespace

std::string shield_toml_text(const std::string& text, const std::string& file) {
  std::string out;
  out.reserve(text.size() + text.size() / 2);
  std::size_t i = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {  // a byte order mark: toml++ skips it
    out += text.substr(0, 3);
    i = 3;
  }
  while (i < text.size()) {
    const unsigned char b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      out += text[i++];
      continue;
    }
    const std::optional<Decoded> d = decode_utf8(text, i);
    if (!d) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(b));
      fail_at(text, i, file,
              std::string("the byte ") + byte + " is not valid UTF-8 (the problem file must be UTF-8 encoded)");
    }
    if (d->cp >= kPlane15 && d->cp < kPlane15 + 0x10000) {
      fail_at(text, i, file,
              "the private-use character " + code_point_name(d->cp) +
                  " (plane 15) is not supported in problem files");
    }
    append_utf8(out, d->cp <= 0xFFFF ? d->cp + kPlane15 : d->cp);
    i += d->length;
  }
  return out;
}

std::string unshield_toml_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    // toml++'s escape of a character in a message: "\U000F" and four hex digits
    if (text.compare(i, 6, "\\U000F") == 0 && i + 10 <= text.size()) {
      int value = 0;
      for (std::size_t k = i + 6; k < i + 10 && value >= 0; ++k) {
        const int h = hex_value(text[k]);
        value = h < 0 ? -1 : value * 16 + h;
      }
      if (value >= 0x80) {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04X", static_cast<unsigned>(value));
        out += escape;
        i += 10;
        continue;
      }
    }
    const std::optional<Decoded> d = decode_utf8(text, i);
    if (d && is_shielded(d->cp)) {
      append_utf8(out, d->cp - kPlane15);
      i += d->length;
    } else {
      const std::size_t length = d ? d->length : 1;
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

toml::table parse_toml(const std::string& text, const std::string& file) {
  const std::string shielded = shield_toml_text(text, file);
  toml::table root;
  try {
    root = toml::parse(shielded, file);
  } catch (const toml::parse_error& e) {
    const toml::source_position where = e.source().begin;
    std::string message = "line " + std::to_string(where.line) + ", column " + std::to_string(where.column) +
                          ": " + unshield_toml_text(e.description());
    // Name a non-ASCII character at the error's position, with what TOML allows there.
    const std::size_t at = byte_at(text, where.line, where.column);
    if (at != std::string_view::npos && static_cast<unsigned char>(text[at]) >= 0x80) {
      const std::optional<Decoded> d = decode_utf8(text, at);
      if (d) {
        message += " (the character '" + text.substr(at, d->length) + "', " + code_point_name(d->cp) +
                   ": outside strings and comments TOML allows ASCII only; keys are written with "
                   "A-Z a-z 0-9 _ -, or quoted)";
      }
    }
    throw InputError(file, "", message);
  }
  unshield_table(root, file);
  return root;
}

}  // namespace symcontact
