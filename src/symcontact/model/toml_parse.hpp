#pragma once
/// \file toml_parse.hpp
/// TOML text → toml::table, safe for any input with the toml++ of Debian 12 (3.3.0).
///
/// toml++ 3.3.0 has undefined behaviour on ordinary text: `is_non_ascii_horizontal_whitespace()`
/// reaches `__builtin_unreachable()` for most code points from U+00A1 to U+0499 (Latin-1, Latin
/// Extended, Greek, Cyrillic: "ν = 0.3" is enough) and from U+FC06 to U+FEFE, wherever the parser asks
/// "is this white space?" — outside strings, inside a value it is recording for a message, after a
/// line-ending backslash in a multi-line string (upstream marzer/tomlplusplus issues #190 and #295,
/// fixed after 3.3 by pull request #305). Where the parser asks cannot be predicted reliably from outside
/// (fuzzing finds such places all over the grammar), so this parser never shows toml++ such a character:
///
/// 1. **shield**: the text is checked to be UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing
///    above U+10FFFF) and every code point c in U+0080 … U+FFFF is written as c + U+F0000 (plane 15,
///    private use). toml++ answers "not white space" for anything above U+FEFF at once. The number of
///    code points does not change, so the lines and columns toml++ reports are those of the file, and
///    neither does what TOML makes of the text: a non-ASCII, non-control character is allowed in
///    strings and comments and nowhere else, before and after. A leading byte order mark is kept.
/// 2. **parse** with toml++.
/// 3. **unshield** every string value and every key of the result, and toml++'s error messages
///    (which print a character as "\U000F03BD" or as itself), mapping plane 15 back to the BMP.
///
/// A file that contains plane-15 characters itself (U+F0000 … U+FFFFF) is refused: they would come
/// back as other characters. (So is an escape "\U000Fxxxx" in a basic string, for the same reason.)
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace symcontact {

/// Parses `text` (the contents of `file`, which names the file in messages). Throws
/// InputError(file, "", "line L, column C: …") for text that is not UTF-8, for plane-15 characters, for
/// a TOML syntax error (toml++'s description, with the offending non-ASCII character named and how
/// keys are written when that is the cause), and for two keys of one table that differ only in how a
/// non-ASCII character is written (raw and escaped).
toml::table parse_toml(const std::string& text, const std::string& file);

/// Step 1 alone (exposed for tests): the shielded text. Throws as parse_toml() for bad UTF-8.
std::string shield_toml_text(const std::string& text, const std::string& file);

/// Step 3 on one string (exposed for tests): plane-15 characters back to the BMP, and the escapes
/// "\U000Fxxxx" toml++ writes in messages back to "\uxxxx".
std::string unshield_toml_text(std::string_view text);

}  // namespace symcontact
