// The JSON writer of the reports (app/io/json.hpp): member order, numbers, strings, the names of a
// report's statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "io/json.hpp"

namespace trirast {
namespace {

TEST(Json, MembersKeepTheirOrderAndASetKeyKeepsItsPlace) {
  Json j = Json::object();
  j.set("zeta", 1).set("alpha", "a").set("mid", true);
  j.set("zeta", 2);
  EXPECT_EQ(j.dump(), "{\n  \"zeta\": 2,\n  \"alpha\": \"a\",\n  \"mid\": true\n}\n");
  EXPECT_EQ(Json::object().dump(), "{}\n");
  EXPECT_EQ(Json::array().dump(), "[]\n");
  Json a = Json::array();
  a.push(Json::integer(1)).push(Json::object().set("x", -3));
  EXPECT_EQ(Json::object().set("list", a).dump(),
            "{\n  \"list\": [\n    1,\n    {\n      \"x\": -3\n    }\n  ]\n}\n");
}

TEST(Json, IntegersAsIntegersAndDoublesReadBackExactly) {
  Json j = Json::object();
  j.set("u", uint64_t(18446744073709551615ull))
      .set("i", int64_t(-9223372036854775807LL - 1))
      .set("whole", 4300.0)
      .set("zero", 0.0)
      .set("big", 1234567.0)
      .set("nan", std::nan(""))
      .set("inf", std::numeric_limits<double>::infinity());
  const std::string text = j.dump();
  for (const char* s : {"\"u\": 18446744073709551615", "\"i\": -9223372036854775808",
                        "\"whole\": 4300,", "\"zero\": 0,", "\"big\": 1234567,", "\"nan\": null",
                        "\"inf\": null"})
    EXPECT_NE(text.find(s), std::string::npos) << s << "\n" << text;
  for (const double v : {0.1, 1.0 / 3.0, 5e-324, 2.5e-7, 1e300, 0.0710269310446877, -12.75,
                         9007199254740993.0 * 4}) {
    const std::string dumped = Json::object().set("v", v).dump();
    const double back = nlohmann::json::parse(dumped)["v"].get<double>();
    EXPECT_EQ(std::memcmp(&back, &v, sizeof v), 0) << dumped;
  }
}

TEST(Json, StringsAreEscapedAndBytesThatAreNotUtf8Replaced) {
  const std::string text =
      Json::object().set("s", std::string("q\"b\\n\nt\t\x01 \xc3\xa9 \xff")).dump();
  EXPECT_EQ(text, "{\n  \"s\": \"q\\\"b\\\\n\\nt\\t\\u0001 \xc3\xa9 \xef\xbf\xbd\"\n}\n");
  EXPECT_EQ(nlohmann::json::parse(text)["s"], "q\"b\\n\nt\t\x01 \xc3\xa9 \xef\xbf\xbd");
  EXPECT_EQ(json_escape("a\"b"), "\"a\\\"b\"");
}

TEST(Json, LeafNamesNameArraysOfObjectsByTheirElements) {
  Json report = Json::object();
  report.set("triangles", Json::object().set("read", 2).set("culled", 0))
      .set("engines", Json::array()
                          .push(Json::object().set("pixels", 1).set("list", Json::array()))
                          .push(Json::object().set("pixels", 2).set("extra", 3)))
      .set("plain", Json::array().push(Json::integer(1)).push(Json::integer(2)))
      .set("empty", Json::object());
  std::vector<std::string> names;
  report.leaf_names(names);
  EXPECT_EQ(names, (std::vector<std::string>{"triangles.read", "triangles.culled",
                                             "engines[].pixels", "engines[].list",
                                             "engines[].extra", "plain"}));
}

}  // namespace
}  // namespace trirast
