#pragma once
/// \file expression.hpp
/// A scalar expression of a point's reference coordinates x, y, z and the load factor t, written by the user
/// where the problem file takes a Dirichlet value, a pressure or a traction component (docs/loads.md,
/// "Expressions"). The one adapter to muParser (Debian libmuparser-dev): nothing else includes it.
///
/// The syntax is muParser's: + − * / ^, parentheses, comparisons and `c ? a : b`, the functions sin, cos,
/// tan, asin, acos, atan, sinh, cosh, tanh, asinh, acosh, atanh, log2, log10, log (= ln), exp, sqrt, sign,
/// rint, abs, min, max, sum, avg, and the constants pi (exact to the last bit, unlike muParser's own _pi of
/// Debian's 2.3.3, 8e-13 short) and _e. The variables are x, y, z and t; any other name is an error. An expression gives one value: ',' (several results) and '=' (assignment
/// to a variable) are refused.

#include <memory>
#include <stdexcept>
#include <string>

namespace symcontact {

/// An expression that cannot be compiled. what() is message().
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(std::string expression, int position, std::string message);
  const std::string& expression() const { return expression_; }
  /// 0-based character position in the expression where the fault was found (the end when it is missing
  /// something); −1 for an empty expression.
  int position() const { return position_; }
  /// "character 5 of \"x + w\": unexpected token \"w\" (the variables are x, y, z and t)": where (1-based)
  /// and what, for a message that names the file and the key before it.
  const std::string& message() const { return message_; }

 private:
  std::string expression_;
  int position_;
  std::string message_;
};

class Expression {
 public:
  /// Compiles `text`. Throws ExpressionError on an empty text, a syntax error, an unknown name, a list of
  /// several values or an assignment.
  explicit Expression(const std::string& text);
  ~Expression();
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

  /// The value at (x, y, z, t), as IEEE arithmetic gives it: NaN or ±inf are returned, not thrown (1/0 is
  /// inf, sqrt(−1) NaN). Not thread-safe on one object (the variables are the object's own).
  double operator()(double x, double y, double z, double t) const;
  /// The same at a point of `dim` ≤ 3 coordinates; the missing ones are 0.
  double at(const double* point, int dim, double t) const;
  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::string text_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace symcontact
