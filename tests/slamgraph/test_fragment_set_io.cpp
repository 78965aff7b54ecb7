// The fragment-set file: exact round trip, and every malformed input rejected with one line
// naming the file, the field and the problem.

#include <gtest/gtest.h>

#include <sstream>

#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

FragmentSet from_text(const std::string& text) {
  std::istringstream in(text);
  return read_fragment_set(in, "set.json");
}

void expect_pose_eq(const Pose2& a, const Pose2& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.theta, b.theta);
}

TEST(FragmentSetIo, RoundTripIsExact) {
  SynthSettings s = synth_preset("paper9");
  s.laps = 2;
  s.fragments = 12;
  s.correlation = 0.3;
  const FragmentSet set = synthesize(s);
  const std::string text = testing::fragment_set_text(set);
  const FragmentSet back = from_text(text);
  EXPECT_EQ(testing::fragment_set_text(back), text);
  EXPECT_EQ(back.name, set.name);
  ASSERT_EQ(back.fragments.size(), set.fragments.size());
  ASSERT_EQ(back.closures.size(), set.closures.size());
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Fragment &a = set.fragments[i], &b = back.fragments[i];
    expect_pose_eq(a.exit, b.exit);
    EXPECT_EQ(a.alignment->covariance(), b.alignment->covariance());
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t j = 0; j < a.samples.size(); ++j) expect_pose_eq(a.samples[j], b.samples[j]);
    ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
    EXPECT_EQ(a.trajectory.back().stamp, b.trajectory.back().stamp);
  }
  for (std::size_t c = 0; c < set.closures.size(); ++c) {
    EXPECT_EQ(set.closures[c].from, back.closures[c].from);
    EXPECT_EQ(set.closures[c].to, back.closures[c].to);
    expect_pose_eq(set.closures[c].hypothesis.mean(), back.closures[c].hypothesis.mean());
  }
  ASSERT_EQ(back.reference.size(), set.reference.size());
  expect_pose_eq(back.reference[5], set.reference[5]);
}

// A valid two-fragment document with one placeholder to break.
std::string document(
    const std::string& fragment1, const std::string& closure = "",
    const std::string& header = R"("format": "antslam-fragment-set", "version": 1)") {
  return "{" + header + R"(, "fragments": [{"exit": [1, 0, 0]}, )" +
         (fragment1.empty() ? R"({"exit": [0, 0, 0], "alignment": {"mean": [1, 0, 0],
           "covariance": [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]},
           "samples": [[1, 0, 0], [1.1, 0, 0]]})"
                            : fragment1) +
         R"(], "closures": [)" +
         (closure.empty() ? R"({"from": 0, "to": 1, "anchor": [0, 0, 0], "hypothesis":
           {"mean": [1, 0, 0], "covariance": [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]]}})"
                          : closure) +
         "]}";
}

std::string error_of(const std::string& text) {
  return testing::error_of([&] { from_text(text); });
}

TEST(FragmentSetIo, ReadsTheMinimalDocument) {
  const FragmentSet set = from_text(document(""));
  EXPECT_EQ(set.fragments.size(), 2U);
  EXPECT_EQ(set.fragments[1].samples.size(), 2U);
  EXPECT_EQ(set.closures[0].to, 1U);
}

TEST(FragmentSetIo, RejectsMalformedInputWithOneClearLine) {
  const std::string cov = R"("covariance": [[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.001]])";
  const auto fragment = [&](const std::string& alignment, const std::string& samples) {
    return R"({"exit": [0, 0, 0], "alignment": )" + alignment + R"(, "samples": )" + samples + "}";
  };
  const std::string ok_alignment = R"({"mean": [1, 0, 0], )" + cov + "}";
  EXPECT_EQ(error_of("{\"format\": "),
            "set.json: JSON syntax error: parse error at line 1, column 12: syntax error while "
            "parsing value - unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(error_of(document("", "", R"("format": "g2o", "version": 1)")),
            "set.json: format: expected \"antslam-fragment-set\"");
  EXPECT_EQ(error_of(document("", "", R"("format": "antslam-fragment-set", "version": 2)")),
            "set.json: version: 2 is not supported (this build reads versions 1 to 1)");
  EXPECT_EQ(error_of(document("", "", R"("format": "antslam-fragment-set")")),
            "set.json: version: missing");
  EXPECT_EQ(error_of(document(R"({"exit": [0, 0, 0], "alignment": )" + ok_alignment + "}")),
            "set.json: fragments[1].samples: missing");
  EXPECT_EQ(error_of(document(fragment(ok_alignment, "[[1, 0, null]]"))),
            "set.json: fragments[1].samples[0][2]: expected a number");
  EXPECT_EQ(error_of(document(fragment(ok_alignment, "[[1, 0]]"))),
            "set.json: fragments[1].samples[0]: expected [x, y, theta]");
  EXPECT_EQ(error_of(document(fragment(ok_alignment, "[]"))),
            "set.json: fragments[1].samples: is empty");
  EXPECT_EQ(error_of(document(fragment(
                R"({"mean": [1, 0, 0], "covariance": [[0.01, 0, 0], [0, -0.01, 0], [0, 0, 1]]})",
                "[[1, 0, 0]]"))),
            "set.json: fragments[1].alignment.covariance: covariance is not positive definite");
  EXPECT_EQ(error_of(document(fragment(
                R"({"mean": [1, 0, 0], "covariance": [[0.01, 0.005, 0], [0, 0.01, 0], [0, 0, 1]]})",
                "[[1, 0, 0]]"))),
            "set.json: fragments[1].alignment.covariance: covariance is not symmetric");
  EXPECT_EQ(error_of(document(
                fragment(R"({"mean": [1, 0, 0], "covariance": [[1, 0, 0]]})", "[[1, 0, 0]]"))),
            "set.json: fragments[1].alignment.covariance: expected 3 elements, got 1");
  EXPECT_EQ(error_of(document(R"({"exit": [0, 0, 0], "sampels": []})")),
            "set.json: fragments[1]: unknown field 'sampels'");
  // Found by fuzzing (docs/fuzzing.md): a key with an escaped line break is named as JSON
  // writes it, so the message stays one line.
  EXPECT_EQ(error_of(document(R"({"exit": [0, 0, 0], "covari\nce": []})")),
            "set.json: fragments[1]: unknown field 'covari\\nce'");
  EXPECT_EQ(error_of(document("", R"({"from": 0, "to": 2, "anchor": [0, 0, 0],
                              "hypothesis": {"mean": [1, 0, 0], )" +
                                      cov + "}}")),
            "set.json: closures[0].to: 2 is not a fragment index");
  EXPECT_EQ(error_of(document("", R"({"from": 1, "to": 1, "anchor": [0, 0, 0],
                              "hypothesis": {"mean": [1, 0, 0], )" +
                                      cov + "}}")),
            "set.json: closures[0].from: must be smaller than `to`");
  EXPECT_EQ(error_of(document("", R"({"from": -1, "to": 1, "anchor": [0, 0, 0],
                              "hypothesis": {"mean": [1, 0, 0], )" +
                                      cov + "}}")),
            "set.json: closures[0].from: expected a non-negative integer");
}

TEST(FragmentSetIo, RejectsStructuralProblems) {
  EXPECT_EQ(error_of(R"({"format": "antslam-fragment-set", "version": 1, "fragments":
                     [{"exit": [0, 0, 0]}], "closures": []})"),
            "set.json: fragments: a fragment set needs at least 2 fragments, got 1");
  std::string no_closure = document("");
  no_closure = no_closure.substr(0, no_closure.find("\"closures\"")) + "\"closures\": []}";
  EXPECT_EQ(error_of(no_closure),
            "set.json: closures: a fragment set needs at least one loop closure");
  EXPECT_EQ(error_of(R"({"format": "antslam-fragment-set", "version": 1, "fragments":
                     [{"exit": [0, 0, 0], "samples": [[0, 0, 0]]}, {"exit": [0, 0, 0]}],
                     "closures": []})"),
            "set.json: fragments[0]: the first fragment is the world frame: no alignment or "
            "samples");
  std::string bad_reference = document("");
  bad_reference.insert(bad_reference.size() - 1, R"(, "reference": [[0, 0, 0]])");
  EXPECT_EQ(error_of(bad_reference), "set.json: reference: expected 2 elements, got 1");
  EXPECT_EQ(error_of("[1, 2]"), "set.json: expected a JSON object");
}

TEST(FragmentSetIo, MissingFileIsOneLine) {
  try {
    read_fragment_set_file("no/such/set.json");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no/such/set.json: cannot open");
  }
}

TEST(FragmentSetIo, WritingValidatesFirst) {
  FragmentSet set = testing::random_set(3, 2, 1, 1);
  set.fragments[2].samples.clear();
  std::ostringstream out;
  EXPECT_THROW(write_fragment_set(out, set), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
