#include "symcontact/io/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace symcontact {
namespace {

TEST(JsonWriter, Scalars) {
  EXPECT_EQ(Json().dump(), "null");
  EXPECT_EQ(Json(nullptr).dump(), "null");
  EXPECT_EQ(Json(true).dump(), "true");
  EXPECT_EQ(Json(false).dump(), "false");
  EXPECT_EQ(Json(3).dump(), "3");
  EXPECT_EQ(Json(-12L).dump(), "-12");
  EXPECT_EQ(Json(std::size_t{7}).dump(), "7");
  EXPECT_EQ(Json("abc").dump(), "\"abc\"");
  EXPECT_EQ(Json(std::string("x y")).dump(), "\"x y\"");
}

TEST(JsonWriter, Numbers) {
  EXPECT_EQ(Json(3.0).dump(), "3");
  EXPECT_EQ(Json(-0.0).dump(), "0");
  EXPECT_EQ(Json(0.1).dump(), "0.1");
  EXPECT_EQ(Json(-2.5).dump(), "-2.5");
  EXPECT_EQ(Json(1e-7).dump(), "1e-07");
  EXPECT_EQ(Json(9007199254740992.0).dump(), "9007199254740992");  // 2^53: still an integer
  EXPECT_EQ(Json(1e300).dump(), "1e+300");
  EXPECT_EQ(Json(std::numeric_limits<double>::quiet_NaN()).dump(), "null");
  EXPECT_EQ(Json(std::numeric_limits<double>::infinity()).dump(), "null");
  EXPECT_EQ(Json(-std::numeric_limits<double>::infinity()).dump(), "null");
}

TEST(JsonWriter, NumbersRoundTrip) {
  const double values[] = {1.0 / 3.0, 2.0 / 3.0, std::acos(-1.0), 1e-310, std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::min(), 123456789.123456789, -4.9406564584124654e-324};
  for (const double v : values) {
    const std::string s = format_double(v);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), v) << s;
  }
  EXPECT_EQ(format_double(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_double(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(JsonWriter, StringEscapes) {
  EXPECT_EQ(Json("a\"b\\c").dump(), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(Json("\b\f\n\r\t").dump(), "\"\\b\\f\\n\\r\\t\"");
  EXPECT_EQ(Json(std::string("\x01\x1f", 2)).dump(), "\"\\u0001\\u001f\"");
  EXPECT_EQ(Json(std::string("nul\0x", 5)).dump(), "\"nul\\u0000x\"");
  EXPECT_EQ(Json("/ \x7f").dump(), "\"/ \x7f\"");
  EXPECT_EQ(Json("\xce\xbc=0.3 \xe2\x9c\x93").dump(), "\"\xce\xbc=0.3 \xe2\x9c\x93\"");  // UTF-8 unchanged
}

TEST(JsonWriter, EmptyContainers) {
  EXPECT_EQ(Json::object().dump(), "{}");
  EXPECT_EQ(Json::array().dump(), "[]");
  EXPECT_EQ(Json(std::vector<double>{}).dump(), "[]");
  Json j = Json::object();
  j["a"] = Json::array();
  j["b"] = Json::object();
  EXPECT_EQ(j.dump(), "{\n  \"a\": [],\n  \"b\": {}\n}");
}

TEST(JsonWriter, NestedIndented) {
  Json j = Json::object();
  j["name"] = "hertz";
  j["steps"] = 12;
  j["gap"] = std::vector<double>{0.0, 1e-3};
  j["solver"]["iterations"] = 31;
  j["solver"]["converged"] = true;
  Json list = Json::array();
  list.push_back(Json(1));
  list.push_back(Json("two"));
  list.push_back(Json());
  j["list"] = list;
  EXPECT_EQ(j.dump(),
            "{\n"
            "  \"name\": \"hertz\",\n"
            "  \"steps\": 12,\n"
            "  \"gap\": [\n"
            "    0,\n"
            "    0.001\n"
            "  ],\n"
            "  \"solver\": {\n"
            "    \"iterations\": 31,\n"
            "    \"converged\": true\n"
            "  },\n"
            "  \"list\": [\n"
            "    1,\n"
            "    \"two\",\n"
            "    null\n"
            "  ]\n"
            "}");
  EXPECT_EQ(j.dump(-1),
            "{\"name\":\"hertz\",\"steps\":12,\"gap\":[0,0.001],\"solver\":{\"iterations\":31,\"converged\":true},"
            "\"list\":[1,\"two\",null]}");
  EXPECT_EQ(j.dump(0), "{\n\"name\": \"hertz\",\n\"steps\": 12,\n\"gap\": [\n0,\n0.001\n],\n\"solver\": {\n"
                       "\"iterations\": 31,\n\"converged\": true\n},\n\"list\": [\n1,\n\"two\",\nnull\n]\n}");
}

TEST(JsonWriter, KeysKeepInsertionOrderAndReassign) {
  Json j;
  j["z"] = 1;
  j["a"] = 2;
  j["z"] = "again";  // existing key: replaced in place
  EXPECT_EQ(j.dump(-1), "{\"z\":\"again\",\"a\":2}");
  EXPECT_EQ(j.size(), 2u);
  EXPECT_TRUE(j.contains("a"));
  EXPECT_FALSE(j.contains("b"));
  EXPECT_EQ(j.at("a").dump(), "2");
  EXPECT_THROW(j.at("b"), std::out_of_range);
  EXPECT_EQ(Json::object().dump(-1), "{}");
  Json key_escape;
  key_escape["a\"b"] = 0.5;
  EXPECT_EQ(key_escape.dump(-1), "{\"a\\\"b\":0.5}");
}

TEST(JsonWriter, TypeMisuseThrows) {
  Json arr = Json::array();
  EXPECT_THROW(arr["k"], std::logic_error);
  Json obj = Json::object();
  EXPECT_THROW(obj.push_back(Json(1)), std::logic_error);
  Json num(1.5);
  EXPECT_THROW(num["k"], std::logic_error);
  Json null_to_array;
  null_to_array.push_back(Json(2.5));
  EXPECT_EQ(null_to_array.dump(-1), "[2.5]");
}

}  // namespace
}  // namespace symcontact
