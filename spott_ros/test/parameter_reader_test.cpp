#include "spott_ros/parameter_reader.h"

#include <cmath>

#include <gtest/gtest.h>

namespace spott_ros {
namespace {

using XmlRpc::XmlRpcValue;

// {rate_hz: 20, window: {resolution_m: 0.1, cells: 70}, name: "x", flag: true}
XmlRpcValue Sample() {
  XmlRpcValue v;
  v["rate_hz"] = 20;
  v["window"]["resolution_m"] = 0.1;
  v["window"]["cells"] = 70;
  v["name"] = std::string("x");
  v["flag"] = true;
  return v;
}

TEST(ParameterReader, ReadsTypedValuesAndAcceptsIntegersAsNumbers) {
  ParameterReader r(Sample());
  double rate = 0, resolution = 0;
  int cells = 0;
  std::string name;
  bool flag = false;
  r.Get("rate_hz", rate, "Hz");
  r.Get("window/resolution_m", resolution, "m");
  r.Get("window/cells", cells);
  r.Get("name", name);
  r.Get("flag", flag);
  EXPECT_DOUBLE_EQ(rate, 20.0);
  EXPECT_DOUBLE_EQ(resolution, 0.1);
  EXPECT_EQ(cells, 70);
  EXPECT_EQ(name, "x");
  EXPECT_TRUE(flag);
  EXPECT_TRUE(r.Finish().empty());
}

TEST(ParameterReader, AbsentKeysKeepTheirDefaults) {
  ParameterReader r(XmlRpcValue{});
  double d = 1.5;
  int i = 3;
  r.Get("missing_m", d);
  r.Get("section/missing", i);
  EXPECT_DOUBLE_EQ(d, 1.5);
  EXPECT_EQ(i, 3);
  EXPECT_TRUE(r.Finish().empty());
}

TEST(ParameterReader, EveryUnknownKeyIsRefusedByItsFullName) {
  XmlRpcValue v = Sample();
  v["window"]["resoluton_m"] = 0.2;  // misspelt
  v["extra"] = 1;
  ParameterReader r(v);
  double rate = 0, resolution = 0;
  int cells = 0;
  std::string name;
  bool flag = false;
  r.Get("rate_hz", rate);
  r.Get("window/resolution_m", resolution);
  r.Get("window/cells", cells);
  r.Get("name", name);
  r.Get("flag", flag);
  const auto problems = r.Finish();
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "~extra is not a parameter of this node");
  EXPECT_EQ(problems[1], "~window/resoluton_m is not a parameter of this node");
}

TEST(ParameterReader, WrongTypesAreAllReportedAtOnceAndKeepDefaults) {
  XmlRpcValue v;
  v["rate_hz"] = std::string("fast");
  v["cells"] = 1.5;
  v["flag"] = 1;
  ParameterReader r(v);
  double rate = 10;
  int cells = 7;
  bool flag = false;
  r.Get("rate_hz", rate, "Hz");
  r.Get("cells", cells);
  r.Get("flag", flag);
  const auto problems = r.Finish();
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_EQ(problems[0], "~rate_hz must be a number (Hz), not a string");
  EXPECT_EQ(problems[1], "~cells must be an integer, not a number");
  EXPECT_EQ(problems[2], "~flag must be true or false, not an integer");
  EXPECT_DOUBLE_EQ(rate, 10);
  EXPECT_EQ(cells, 7);
}

TEST(ParameterReader, ASectionWhereAValueIsExpectedIsAWrongType) {
  XmlRpcValue v;
  v["window"]["x"] = 1;
  ParameterReader r(v);
  double w = 0;
  r.Get("window", w);
  const auto problems = r.Finish();
  ASSERT_FALSE(problems.empty());
  EXPECT_EQ(problems[0], "~window must be a number, not a section");
}

TEST(ParameterReader, KeysListsASectionAndAcceptMarksItKnown) {
  XmlRpcValue v;
  v["sources"]["planner"]["priority"] = 10;
  v["sources"]["reflex"]["priority"] = 100;
  v["faults"]["a"] = 1;
  ParameterReader r(v);
  const auto keys = r.Keys("sources");
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0], "planner");
  EXPECT_EQ(keys[1], "reflex");
  int p = 0;
  r.Get("sources/planner/priority", p);
  r.Get("sources/reflex/priority", p);
  r.Accept("faults");
  EXPECT_TRUE(r.Finish().empty());
}

TEST(ParameterReader, ListsOfNumbersAndStrings) {
  XmlRpcValue v;
  v["xs"][0] = 1;
  v["xs"][1] = 2.5;
  v["names"][0] = std::string("a");
  v["bad"][0] = std::string("a");
  ParameterReader r(v);
  std::vector<double> xs, bad;
  std::vector<std::string> names;
  r.Get("xs", xs);
  r.Get("names", names);
  r.Get("bad", bad);
  EXPECT_EQ(xs, (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(names, (std::vector<std::string>{"a"}));
  const auto problems = r.Finish();
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "~bad[0] must be a finite number, not a string");
}

TEST(ParameterReader, DegreesAreStoredInRadians) {
  XmlRpcValue v;
  v["angle_deg"] = 90;
  ParameterReader r(v);
  double a = 0;
  r.GetDegrees("angle_deg", a);
  EXPECT_NEAR(a, M_PI / 2, 1e-12);
}

TEST(ParameterReader, DegreesThatOverflowInRadiansAreRefused) {
  // markov_localization_parameters_fuzz: active_run/estimate_jump_deg 7.19e307 became inf rad.
  XmlRpcValue v;
  v["angle_deg"] = 7.1929766191987718e+307;
  ParameterReader r(v);
  double a = 0.5;
  r.GetDegrees("angle_deg", a);
  EXPECT_EQ(a, 0.5) << "the default is kept";
  const auto problems = r.Finish();
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "~angle_deg must be finite in radians too");
}

TEST(ParameterReader, RenamedKeysStillWorkWithADeprecationWarning) {
  XmlRpcValue v;
  v["resolution"] = 0.2;
  ParameterReader r(v);
  double res = 0.1;
  r.GetRenamed("resolution_m", "resolution", res, "m");
  EXPECT_DOUBLE_EQ(res, 0.2);
  EXPECT_TRUE(r.Finish().empty());
  ASSERT_EQ(r.Warnings().size(), 1u);
  EXPECT_EQ(r.Warnings()[0], "~resolution is deprecated: call it ~resolution_m");
}

TEST(ParameterReader, RequireAndFailNameTheKey) {
  ParameterReader r(XmlRpcValue{});
  r.Require(false, "rate_hz", "> 0", -1.0);
  r.Require(true, "ok", "fine", 1.0);
  r.Fail("window/resolution_m must be > 0");
  const auto problems = r.Finish();
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "~rate_hz must be > 0 (got -1)");
  EXPECT_EQ(problems[1], "~window/resolution_m must be > 0");
}

TEST(ParameterReader, NonFiniteNumbersAreRefused) {
  XmlRpcValue v;
  v["x_m"] = std::nan("");
  ParameterReader r(v);
  double x = 1;
  r.Get("x_m", x);
  EXPECT_DOUBLE_EQ(x, 1);
  ASSERT_EQ(r.Finish().size(), 1u);
}

}  // namespace
}  // namespace spott_ros
