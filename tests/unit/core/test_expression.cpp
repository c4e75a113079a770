#include "symcontact/core/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

using namespace symcontact;

namespace {

/// The error compiling `text` throws (fails the test when it compiles).
ExpressionError error_of(const std::string& text) {
  try {
    Expression e(text);
  } catch (const ExpressionError& e) {
    return e;
  }
  ADD_FAILURE() << "\"" << text << "\" compiled";
  return ExpressionError(text, -2, "");
}

TEST(Expression, EvaluatesTheVariablesAndFunctions) {
  const Expression rotation("(cos(0.1*t)-1)*x - sin(0.1*t)*y");
  EXPECT_DOUBLE_EQ(rotation(2.0, 3.0, 0.0, 1.0), (std::cos(0.1) - 1) * 2.0 - std::sin(0.1) * 3.0);
  EXPECT_EQ(rotation(2.0, 3.0, 0.0, 0.0), 0.0);
  const Expression hydrostatic("1000 * 9.81 * (2 - y) * t");
  EXPECT_DOUBLE_EQ(hydrostatic(5.0, 0.5, 7.0, 0.5), 1000 * 9.81 * 1.5 * 0.5);
  EXPECT_EQ(Expression("z^2 + pi")(0, 0, 3, 0), 9 + std::acos(-1.0));  // pi to the last bit
  EXPECT_NEAR(Expression("_pi")(0, 0, 0, 0), std::acos(-1.0), 1e-11);     // muParser's own: 8e-13 short
  EXPECT_EQ(Expression("x < 0 ? -1 : 1")(-2, 0, 0, 0), -1.0);
  EXPECT_EQ(Expression("min(x, y)")(4, 3, 0, 0), 3.0);  // a comma inside parentheses is an argument list
  EXPECT_EQ(Expression("x == 1")(1, 0, 0, 0), 1.0);
}

TEST(Expression, AtFillsTheMissingCoordinatesWithZero) {
  Expression e("x + 10*y + 100*z + 1000*t");
  const double p[3] = {1, 2, 3};
  EXPECT_EQ(e.at(p, 2, 4), 1 + 20 + 4000.0);
  EXPECT_EQ(e.at(p, 3, 4), 1 + 20 + 300 + 4000.0);
  Expression moved = std::move(e);  // the variables move with it
  EXPECT_EQ(moved(1, 0, 0, 0), 1.0);
  EXPECT_EQ(moved.text(), "x + 10*y + 100*z + 1000*t");
}

TEST(Expression, NonFiniteValuesAreReturnedNotThrown) {
  EXPECT_TRUE(std::isinf(Expression("1/x")(0, 0, 0, 0)));
  EXPECT_TRUE(std::isnan(Expression("sqrt(x)")(-1, 0, 0, 0)));
}

TEST(Expression, AnUnknownNameGivesItsPositionAndTheVariables) {
  const ExpressionError e = error_of("x + w");
  EXPECT_EQ(e.position(), 4);
  EXPECT_EQ(e.message(), "character 5 of \"x + w\": unexpected token \"w\" (the variables are x, y, z and t)");
  EXPECT_EQ(error_of("foo(x)").position(), 0);
  EXPECT_NE(error_of("foo(x)").message().find("\"foo\""), std::string::npos);
}

TEST(Expression, SyntaxErrorsGiveTheirPosition) {
  EXPECT_EQ(error_of("2*x +").message(), "character 6 of \"2*x +\": unexpected end of expression");
  EXPECT_EQ(error_of("sin(x").position(), 5);
  EXPECT_NE(error_of("sin(x").message().find("issing parenthesis"), std::string::npos);
  EXPECT_EQ(error_of("x @ 2").position(), 2);
  EXPECT_EQ(error_of("x y").position(), 2);
  EXPECT_EQ(error_of("x y").message(), "character 3 of \"x y\": unexpected variable \"y\"");
}

TEST(Expression, ListsAssignmentsAndEmptyTextAreRefused) {
  EXPECT_EQ(error_of("2*t, 3").message(), "character 4 of \"2*t, 3\": expected one value, got a list of 2");
  EXPECT_EQ(error_of("x = 3").message(),
            "character 3 of \"x = 3\": '=' assigns to a variable (to compare, write ==)");
  EXPECT_NO_THROW(Expression("x >= 3 ? 1 : x != 2"));  // comparisons are not assignments
  EXPECT_EQ(error_of("  ").position(), -1);
  EXPECT_EQ(error_of("").message(), "the expression is empty");
}

}  // namespace
