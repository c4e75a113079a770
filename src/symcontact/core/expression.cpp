#include "symcontact/core/expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>

#include <muParser.h>

namespace symcontact {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

/// "character 5 of \"x + w\": what".
std::string located(const std::string& text, int position, const std::string& what) {
  return "character " + std::to_string(position + 1) + " of " + quoted(text) + ": " + what;
}

/// Position of the first '=' that is an assignment (not part of ==, <=, >=, !=), or −1.
int assignment_position(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const bool after_comparison = i > 0 && std::string("=<>!").find(text[i - 1]) != std::string::npos;
    const bool before_equal = i + 1 < text.size() && text[i + 1] == '=';
    if (!after_comparison && !before_equal) return static_cast<int>(i);
    if (before_equal) ++i;
  }
  return -1;
}

/// Position of the first ',' outside every parenthesis, or −1.
int top_level_comma(const std::string& text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') ++depth;
    if (text[i] == ')') --depth;
    if (text[i] == ',' && depth <= 0) return static_cast<int>(i);
  }
  return -1;
}

/// muParser's message without its own "at position N" (ours says where), starting in lower case, and a
/// reminder of the variables when the fault is an unknown name.
std::string describe_fault(const mu::Parser::exception_type& e) {
  std::string m = std::regex_replace(e.GetMsg(), std::regex("\\s*(found )?at position -?[0-9]+\\.?$"), "");
  if (!m.empty() && m.back() == '.') m.pop_back();
  if (m.size() > 1 && std::isupper(static_cast<unsigned char>(m[0])) && std::islower(static_cast<unsigned char>(m[1])))
    m[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(m[0])));
  const std::string& token = e.GetToken();
  const bool is_name = !token.empty() && (std::isalpha(static_cast<unsigned char>(token[0])) || token[0] == '_');
  if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && is_name) m += " (the variables are x, y, z and t)";
  return m;
}

}  // namespace

ExpressionError::ExpressionError(std::string expression, int position, std::string message)
    : std::runtime_error(message), expression_(std::move(expression)), position_(position), message_(std::move(message)) {}

struct Expression::Impl {
  mu::Parser parser;
  mutable double x = 0.0, y = 0.0, z = 0.0, t = 0.0;  // the parser holds their addresses
};

Expression::Expression(const std::string& text) : text_(text), impl_(std::make_unique<Impl>()) {
  if (std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); }))
    throw ExpressionError(text, -1, "the expression is empty");
  if (const int p = assignment_position(text); p >= 0)
    throw ExpressionError(text, p, located(text, p, "'=' assigns to a variable (to compare, write ==)"));
  mu::Parser& parser = impl_->parser;
  try {
    parser.DefineVar("x", &impl_->x);
    parser.DefineVar("y", &impl_->y);
    parser.DefineVar("z", &impl_->z);
    parser.DefineVar("t", &impl_->t);
    parser.DefineConst("pi", std::acos(-1.0));
    parser.SetExpr(text);
    int results = 0;
    parser.Eval(results);  // parses: an unknown name or a syntax error throws here, not in SetExpr
    if (results != 1) {
      const int p = std::max(top_level_comma(text), 0);
      throw ExpressionError(text, p,
                            located(text, p, "expected one value, got a list of " + std::to_string(results)));
    }
  } catch (const mu::Parser::exception_type& e) {
    const int p = std::clamp(e.GetPos(), 0, static_cast<int>(text.size()));
    throw ExpressionError(text, p, located(text, p, describe_fault(e)));
  }
}

Expression::~Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;

double Expression::operator()(double x, double y, double z, double t) const {
  impl_->x = x;
  impl_->y = y;
  impl_->z = z;
  impl_->t = t;
  try {
    return impl_->parser.Eval();
  } catch (const mu::Parser::exception_type&) {
    return std::nan("");  // compiled expressions do not throw; should one, its value is undefined
  }
}

double Expression::at(const double* point, int dim, double t) const {
  return (*this)(point[0], dim > 1 ? point[1] : 0.0, dim > 2 ? point[2] : 0.0, t);
}

}  // namespace symcontact
