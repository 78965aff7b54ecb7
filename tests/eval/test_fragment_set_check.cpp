// A fragment set checked against a reference: alignment and closure errors by hand, precision
// and recall of the closures on a square loop.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "antslam/eval/fragment_set_check.hpp"

namespace antslam::eval {
namespace {

constexpr double kPi = std::numbers::pi;

/// A 3 m x 3 m square driven counter-clockwise, one pose a metre (12 poses, stamps 0..11),
/// cut into 6 fragments of 2 scans; alignments and closures are the truth unless changed.
class SquareLoop : public ::testing::Test {
 protected:
  slam::Trajectory reference;
  slam::FragmentSet set;

  void SetUp() override {
    const double xs[] = {0, 1, 2, 3, 3, 3, 3, 2, 1, 0, 0, 0};
    const double ys[] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 2, 1};
    const double headings[] = {0,   0,   0,   kPi / 2,  kPi / 2,  kPi / 2,
                               kPi, kPi, kPi, -kPi / 2, -kPi / 2, -kPi / 2};
    for (int k = 0; k < 12; ++k)
      reference.push_back({static_cast<double>(k), slam::Pose2{xs[k], ys[k], headings[k]}});
    for (std::size_t i = 0; i < 6; ++i) {
      slam::Fragment f;
      const slam::Pose2 frame = reference[2 * i].pose;
      for (std::size_t k = 2 * i; k < 2 * i + 2; ++k)
        f.trajectory.push_back({reference[k].stamp, slam::between(frame, reference[k].pose)});
      if (i > 0)
        f.alignment = slam::Gaussian2(slam::between(reference[2 * i - 2].pose, frame),
                                      Eigen::Matrix3d::Identity() * 0.01);
      set.fragments.push_back(f);
    }
  }

  slam::Pose2 truth(std::size_t a, std::size_t b, const slam::Pose2& anchor) const {
    return slam::between(reference[2 * a].pose, reference[2 * b].pose) * anchor;
  }
};

TEST_F(SquareLoop, TrueAlignmentsAndClosuresAreCorrect) {
  const slam::Pose2 anchor{0.5, 0.0, 0.0};
  set.closures.push_back(
      {0, 5, anchor, slam::Gaussian2(truth(0, 5, anchor), Eigen::Matrix3d::Identity() * 0.01)});
  const FragmentSetCheck c = check_fragment_set(set, reference);
  ASSERT_EQ(c.alignments.size(), 5U);
  for (const GaussianCheck& a : c.alignments) {
    EXPECT_TRUE(a.has_reference);
    EXPECT_NEAR(a.translation_error, 0.0, 1e-12);
    EXPECT_TRUE(a.correct);
  }
  EXPECT_EQ(c.checked_closures, 1U);
  EXPECT_EQ(c.correct_closures, 1U);
  // Only fragment 5 (poses (0, 2), (0, 1)) comes within 1 m of an earlier fragment >= 3 back:
  // fragment 0 at (0, 0).
  EXPECT_EQ(c.revisits, 1U);
  EXPECT_EQ(c.revisits_closed, 1U);
  EXPECT_DOUBLE_EQ(*c.precision(), 1.0);
  EXPECT_DOUBLE_EQ(*c.recall(), 1.0);
}

TEST_F(SquareLoop, ErrorsAreMeasuredAgainstTheTruth) {
  // Alignment 2 off by 0.5 m along its own x (std 0.1 m: 5 sigma).
  const slam::Pose2 true_alignment = set.fragments[2].alignment->mean();
  set.fragments[2].alignment = slam::Gaussian2(true_alignment * slam::Pose2{0.5, 0.0, 0.0},
                                               Eigen::Matrix3d::Identity() * 0.01);
  // A closure (1, 4) 0.2 m and 5 deg off: wrong by the rotation only; (0, 5) 0.4 m off.
  const slam::Pose2 anchor{1.0, 0.0, 0.0};
  const slam::Pose2 h14 = truth(1, 4, anchor);
  set.closures.push_back({1, 4, anchor,
                          slam::Gaussian2(slam::Pose2{h14.x + 0.2, h14.y, h14.theta + 0.0873},
                                          Eigen::Matrix3d::Identity() * 0.01)});
  const slam::Pose2 h05 = truth(0, 5, anchor);
  set.closures.push_back({0, 5, anchor,
                          slam::Gaussian2(slam::Pose2{h05.x, h05.y - 0.4, h05.theta},
                                          Eigen::Matrix3d::Identity() * 0.04)});
  const FragmentSetCheck c = check_fragment_set(set, reference);
  EXPECT_NEAR(c.alignments[1].translation_error, 0.5, 1e-12);
  EXPECT_NEAR(c.alignments[1].mahalanobis, 5.0, 1e-9);
  EXPECT_FALSE(c.alignments[1].correct);
  EXPECT_NEAR(c.closures[0].translation_error, 0.2, 1e-12);
  EXPECT_NEAR(c.closures[0].rotation_error, 0.0873, 1e-12);
  EXPECT_FALSE(c.closures[0].correct);
  EXPECT_NEAR(c.closures[1].translation_error, 0.4, 1e-12);
  EXPECT_NEAR(c.closures[1].mahalanobis, 2.0, 1e-9);  // 0.4 m at 0.2 m std
  EXPECT_FALSE(c.closures[1].correct);
  EXPECT_EQ(c.correct_closures, 0U);
  EXPECT_DOUBLE_EQ(*c.precision(), 0.0);
  EXPECT_DOUBLE_EQ(*c.recall(), 0.0);
  const nlohmann::json j = to_json(c);
  EXPECT_EQ(j["alignments_beyond_3_sigma"], 1);
  EXPECT_NEAR(j["closures"][0]["rotation_error_deg"].get<double>(), 5.0, 0.01);
}

TEST_F(SquareLoop, FramesWithoutReferenceAreNotJudged) {
  reference.erase(reference.begin() + 10);  // fragment 5's first scan
  const slam::Pose2 anchor;
  set.closures.push_back(
      {0, 5, anchor, slam::Gaussian2(slam::Pose2{9, 9, 0}, Eigen::Matrix3d::Identity())});
  const FragmentSetCheck c = check_fragment_set(set, reference);
  EXPECT_FALSE(c.closures[0].has_reference);
  EXPECT_FALSE(c.alignments[4].has_reference);
  EXPECT_EQ(c.checked_closures, 0U);
  EXPECT_FALSE(c.precision().has_value());
  EXPECT_EQ(c.revisits, 1U);  // fragment 5's second scan (0, 1) still revisits fragment 0
}

TEST_F(SquareLoop, AFragmentWithoutTrajectoryIsAnError) {
  set.fragments[3].trajectory.clear();
  EXPECT_THROW(check_fragment_set(set, reference), std::invalid_argument);
  FragmentSetCheckSettings bad;
  bad.max_translation = -1.0;
  set.fragments[3].trajectory.push_back({6.0, slam::Pose2{}});
  EXPECT_THROW(check_fragment_set(set, reference, bad), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::eval
