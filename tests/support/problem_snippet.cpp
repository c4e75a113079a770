#include "support/problem_snippet.hpp"

#include <gtest/gtest.h>

#include "support/temp_folder.hpp"

namespace symcontact::testing {

std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  std::string s = text;
  const std::size_t at = s.find(from);
  if (at == std::string::npos) ADD_FAILURE() << "test bug: \"" << from << "\" is not in the base file";
  else s.replace(at, from.size(), to);
  return s;
}

ProblemSnippet ProblemSnippet::replaced(const std::string& from, const std::string& to) const {
  return ProblemSnippet(testing::replaced(text_, from, to));
}

ProblemSnippet ProblemSnippet::after(const std::string& line, const std::string& lines) const {
  return replaced(line, line + lines);
}

ProblemSnippet ProblemSnippet::in_3d() const { return replaced("dimension = 2", "dimension = 3"); }

std::string body_toml(const std::string& name, const std::string& mesh, const std::string& group,
                      const std::string& material, const std::string& tables) {
  std::string t = "[[body]]\nname = \"" + name + "\"\nmesh = \"" + mesh + "\"\n";
  if (!group.empty()) t += "group = \"" + group + "\"\n";
  return t + "material = { " + material + " }\n" + tables;
}

std::string dirichlet_toml(const std::string& boundary, const std::string& components) {
  return "[[body.dirichlet]]\nboundary = \"" + boundary + "\"\n" + components;
}

ProblemSnippet clamped_block(const std::string& material) {
  return ProblemSnippet("[problem]\ndimension = 2\n[steps]\nload_factors = [0.5, 1.0]\n" +
                        body_toml("block", "block.msh", "block", material,
                                  dirichlet_toml("bottom", "ux = 0.0\nuy = 0.0\n")));
}

std::optional<InputError> input_error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

void expect_input_error_case(const std::function<void()>& read, const InputErrorCase& c, const std::string& file) {
  const std::optional<InputError> e = input_error_of(read);
  if (!e.has_value()) {
    ADD_FAILURE() << "no error for:\n" << c.text;
    return;
  }
  EXPECT_EQ(e->file(), file);
  EXPECT_EQ(e->key(), c.key) << e->what();
  EXPECT_NE(e->message().find(c.fragment), std::string::npos)
      << "message: " << e->message() << "\nexpected to contain: " << c.fragment;
}

void write_placeholders(const std::filesystem::path& folder, std::initializer_list<const char*> names) {
  for (const char* name : names) write_text(folder / name, "// placeholder\n");
}

}  // namespace symcontact::testing
