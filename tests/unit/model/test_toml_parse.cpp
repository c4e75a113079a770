// Tests of the guarded TOML parser (src/symcontact/model/toml_parse.hpp): toml++ 3.3 never sees a
// character in the BMP above ASCII (where its white-space test has undefined behaviour), and what comes
// back is what the file said. Messages of the problem reader are tested in test_problem_reader.cpp.

#include "symcontact/model/toml_parse.hpp"

#include <gtest/gtest.h>

#include <string>

#include "symcontact/core/error.hpp"

namespace symcontact {
namespace {

/// UTF-8 of one code point (written here, not taken from the code under test).
std::string utf8(char32_t c) {
  std::string s;
  if (c < 0x80) {
    s += static_cast<char>(c);
  } else if (c < 0x800) {
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    s += static_cast<char>(0xE0 | (c >> 12));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    s += static_cast<char>(0xF0 | (c >> 18));
    s += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    s += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (c & 0x3F));
  }
  return s;
}

TEST(TomlParse, ShieldLeavesNoBmpCharacterAboveAsciiAndUnshieldRestoresEveryOne) {
  std::string text = "# every code point of the BMP above ASCII, surrogates excepted\n";
  for (char32_t c = 0x80; c <= 0xFFFF; ++c) {
    if (c >= 0xD800 && c <= 0xDFFF) continue;
    text += utf8(c);
    if (c % 64 == 0) text += '\n';
  }
  text += utf8(0x1F600) + utf8(0x10FFFF);  // beyond the BMP: passed through
  const std::string shielded = shield_toml_text(text, "f.toml");
  std::size_t lines_in = 0, lines_out = 0;
  for (const char b : text) lines_in += b == '\n';
  for (std::size_t i = 0; i < shielded.size(); ++i) {
    const auto b = static_cast<unsigned char>(shielded[i]);
    lines_out += b == '\n';
    // No lead byte of a 2- or 3-byte sequence: every non-ASCII character is beyond U+FFFF.
    ASSERT_FALSE(b >= 0xC0 && b < 0xF0) << "byte " << i;
  }
  EXPECT_EQ(lines_out, lines_in);
  EXPECT_EQ(unshield_toml_text(shielded), text);
}

TEST(TomlParse, ByteOrderMarkIsKept) {
  const std::string text = "\xEF\xBB\xBF" "a = \"\xC3\xA9\"\n";
  const std::string shielded = shield_toml_text(text, "f.toml");
  EXPECT_EQ(shielded.substr(0, 3), "\xEF\xBB\xBF");
  EXPECT_EQ(*parse_toml(text, "f.toml")["a"].value<std::string>(), "\xC3\xA9");
}

TEST(TomlParse, MessagesNameTheOriginalCharacter) {
  // toml++ writes a character it shows in a message as "\U000F03BD" (shielded) or as itself.
  EXPECT_EQ(unshield_toml_text("saw '\\U000F03BD' and '" + utf8(0xF03BD) + "'"),
            "saw '\\u03BD' and '" + utf8(0x3BD) + "'");
  EXPECT_EQ(unshield_toml_text("saw '\\U0001F600'"), "saw '\\U0001F600'");  // not shielded: unchanged
}

TEST(TomlParse, StringsAndKeysComeBackAtEveryDepth) {
  const std::string nu = utf8(0x3BD), zhe = utf8(0x436);
  const toml::table t = parse_toml("[\"" + nu + "\"]\nlist = [\"" + zhe + "\", ['" + nu + "'], {\"" + zhe +
                                       "\" = \"" + nu + "\"}]\n",
                                   "f.toml");
  const toml::array& list = *t[nu]["list"].as_array();
  EXPECT_EQ(*list[0].value<std::string>(), zhe);
  EXPECT_EQ(*list[1].as_array()->get(0)->value<std::string>(), nu);
  EXPECT_EQ(*list[2].as_table()->get(zhe)->value<std::string>(), nu);
}

TEST(TomlParse, SyntaxErrorsKeepTheFilesLineAndColumn) {
  // Shielding turns 2-byte characters into 4-byte ones; positions are still counted in the file's characters.
  try {
    parse_toml("a = \"" + utf8(0xE9) + utf8(0xE9) + "\"\nb = = 1\n", "f.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "f.toml");
    EXPECT_EQ(e.message().rfind("line 2, column 5: ", 0), 0u) << e.message();
  }
}

}  // namespace
}  // namespace symcontact
