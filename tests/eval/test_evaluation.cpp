#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "antslam/eval/alignment.hpp"
#include "antslam/eval/evaluation.hpp"
#include "antslam/eval/report.hpp"
#include "trajectories.hpp"

namespace antslam::eval {
namespace {

const std::filesystem::path kLaser = std::filesystem::path(ANTSLAM_DATA_DIR) / "laser";

/// The shipped Intel reference moved by a rigid transform, its stamps shifted by `shift` seconds
/// (some of its poses are only 5.3 ms apart: a shift over 2.6 ms pairs them with neighbours).
slam::Trajectory moved_intel_reference(double shift) {
  slam::Trajectory t =
      transformed(slam::read_tum_file(kLaser / "intel-subset.ref.tum"), {2.0, -1.0, 0.7});
  for (slam::StampedPose& p : t) p.stamp += shift;
  return t;
}

TEST(Evaluate, IntelReferenceAgainstAMovedCopyOfItself) {
  const slam::Trajectory reference = slam::read_tum_file(kLaser / "intel-subset.ref.tum");
  const slam::Trajectory estimate = moved_intel_reference(0.001);
  const Evaluation e = evaluate(estimate, reference, {});
  EXPECT_EQ(e.estimate_poses, 910U);
  EXPECT_EQ(e.associated, 910U);
  EXPECT_LT(e.ate.translation_m.rmse, 1e-6);
  EXPECT_LT(e.rpe.translation_m.max, 1e-6);
  EXPECT_EQ(e.rpe.translation_m.count, 909U);
  EXPECT_FALSE(e.relations);
  // Without alignment the error is the transform's displacement of each pose: never zero here.
  const Evaluation raw = evaluate(estimate, reference, {.max_dt = 0.02, .align = false, .rpe = {}});
  EXPECT_GT(raw.ate.translation_m.min, 0.1);
  EXPECT_DOUBLE_EQ(raw.rpe.translation_m.rmse, e.rpe.translation_m.rmse);  // RPE ignores it
  // A tolerance below the 1 ms shift associates nothing.
  EXPECT_THROW(evaluate(estimate, reference, {.max_dt = 0.0005, .align = true, .rpe = {}}),
               std::invalid_argument);
}

TEST(Evaluate, IntelRelationsMatchAnIndependentCount) {
  const slam::Trajectory reference = slam::read_tum_file(kLaser / "intel-subset.ref.tum");
  const std::vector<Relation> relations = read_relations_file(kLaser / "intel.relations");
  ASSERT_EQ(relations.size(), 2984U);
  for (const double tolerance : {0.0, 0.001, 0.02}) {
    // Linear scan: relations with both stamps within the tolerance of some reference pose.
    const auto present = [&](double stamp) {
      for (const slam::StampedPose& p : reference)
        if (std::abs(p.stamp - stamp) <= tolerance) return true;
      return false;
    };
    std::size_t expected = 0;
    for (const Relation& r : relations) expected += present(r.stamp1) && present(r.stamp2);
    EvaluationSettings settings;
    settings.relations_max_dt = tolerance;
    const Evaluation e = evaluate(reference, reference, settings, relations);
    ASSERT_TRUE(e.relations);
    EXPECT_EQ(e.relations->used, expected) << tolerance;
    EXPECT_EQ(e.relations->used + e.relations->skipped, relations.size());
  }
  const Evaluation e = evaluate(reference, reference, {}, relations);
  EXPECT_EQ(e.relations->used, 97U);  // data/README.md: "about 90" share exact stamps
  // A rigid transform of the estimate does not change the relations metric.
  const Evaluation moved = evaluate(moved_intel_reference(0.0), reference, {}, relations);
  EXPECT_EQ(moved.relations->used, e.relations->used);
  EXPECT_NEAR(moved.relations->translation_m.mean, e.relations->translation_m.mean, 1e-9);
  EXPECT_NEAR(moved.relations->rotation_deg.std, e.relations->rotation_deg.std, 1e-7);
}

TEST(Evaluate, NoAssociationNamesBothTimeRanges) {
  const slam::Trajectory a = testing::make_trajectory({{1.0, 0, 0, 0}, {2.0, 1, 0, 0}});
  const slam::Trajectory b = testing::make_trajectory({{10.0, 0, 0, 0}});
  try {
    evaluate(a, b, {});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "no estimated pose has a reference pose within max_dt = 0.02 s (estimate: 2 "
                 "poses, 1.000000 .. 2.000000 s; reference: 1 poses, 10.000000 .. 10.000000 s)");
  }
}

TEST(Report, JsonAndTableCarryTheResults) {
  const slam::Trajectory reference = testing::spiral(20);
  slam::Trajectory estimate = reference;
  for (slam::StampedPose& p : estimate) p.pose.x += 0.25;
  const Evaluation e = evaluate(
      estimate, reference, {.max_dt = 0.02, .align = false, .rpe = {.frames = 1, .metres = 2.0}});
  const nlohmann::json json = to_json(e);
  EXPECT_DOUBLE_EQ(json["ate"]["translation_m"]["rmse"].get<double>(), 0.25);
  EXPECT_EQ(json["ate"]["translation_m"]["count"].get<std::size_t>(), 20U);
  EXPECT_TRUE(json["alignment"].is_null());
  EXPECT_DOUBLE_EQ(json["rpe"]["step"]["metres"].get<double>(), 2.0);
  EXPECT_EQ(json["poses"]["associated"].get<std::size_t>(), 20U);
  EXPECT_FALSE(json.contains("relations"));
  std::ostringstream table;
  print_table(table, e);
  EXPECT_NE(table.str().find("ATE translation (m)        0.2500     0.2500"), std::string::npos)
      << table.str();
  EXPECT_NE(table.str().find("alignment: none"), std::string::npos);
  EXPECT_NE(table.str().find("RPE step: 2 m"), std::string::npos);
}

TEST(FramesError, ZeroForARigidlyMovedCopyAndByHandForOneShiftedPose) {
  const std::vector<slam::Pose2> reference{{0, 0, 0}, {2, 0, 0.5}, {2, 2, 1.5}, {0, 2, 3}};
  std::vector<slam::Pose2> moved;
  for (const slam::Pose2& p : reference) moved.push_back(slam::Pose2{1, -3, 0.4} * p);
  const slam::TrajectoryError zero = frames_error(moved, reference);
  EXPECT_NEAR(zero.rmse_m, 0.0, 1e-9);
  EXPECT_NEAR(zero.rmse_deg, 0.0, 1e-6);
  EXPECT_EQ(zero.poses, 4U);
  // The square stretched symmetrically along x: the best rigid alignment is the identity (the
  // centroid and the rotation stay), and every pose is 0.1 m off.
  std::vector<slam::Pose2> apart = reference;
  apart[0].x -= 0.1;
  apart[1].x += 0.1;
  apart[2].x += 0.1;
  apart[3].x -= 0.1;
  const slam::TrajectoryError e = frames_error(apart, reference);
  EXPECT_NEAR(e.rmse_m, 0.1, 1e-9);
  EXPECT_NEAR(e.max_m, 0.1, 1e-9);
  EXPECT_THROW(frames_error(apart, std::vector<slam::Pose2>(3)), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::eval
