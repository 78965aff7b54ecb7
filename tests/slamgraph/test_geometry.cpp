#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "antslam/slamgraph/fragment_set.hpp"
#include "antslam/slamgraph/gaussian2.hpp"
#include "antslam/slamgraph/pose2.hpp"

namespace antslam::slam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Pose2, WrapAngle) {
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-3 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(kPi), -kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(0.3 + 8 * kPi), 0.3, 1e-12);
}

TEST(Pose2, ComposeByHand) {
  const Pose2 a{1.0, 2.0, kPi / 2};
  const Pose2 b{3.0, 0.5, 0.25};
  const Pose2 c = a * b;  // rotate b's translation by 90 deg: (3, 0.5) -> (-0.5, 3)
  EXPECT_NEAR(c.x, 0.5, 1e-12);
  EXPECT_NEAR(c.y, 5.0, 1e-12);
  EXPECT_NEAR(c.theta, kPi / 2 + 0.25, 1e-12);
}

TEST(Pose2, InverseAndBetween) {
  const Pose2 a{1.0, -2.0, 2.5};
  const Pose2 b{-0.3, 4.0, -2.9};
  const Pose2 id = a * a.inverse();
  EXPECT_NEAR(id.x, 0.0, 1e-12);
  EXPECT_NEAR(id.y, 0.0, 1e-12);
  EXPECT_NEAR(id.theta, 0.0, 1e-12);
  const Pose2 back = a * between(a, b);
  EXPECT_NEAR(back.x, b.x, 1e-12);
  EXPECT_NEAR(back.y, b.y, 1e-12);
  EXPECT_NEAR(wrap_angle(back.theta - b.theta), 0.0, 1e-12);
}

TEST(Gaussian2, ValueIsPeakNormalised) {
  Eigen::Matrix3d cov = Eigen::Vector3d(0.04, 0.09, 0.01).asDiagonal();
  const Gaussian2 g(Pose2{1.0, 2.0, 0.5}, cov);
  EXPECT_DOUBLE_EQ(g.value(Pose2{1.0, 2.0, 0.5}), 1.0);
  // r = (0.2, -0.3, 0.1): r^T Sigma^-1 r = 1 + 1 + 1 = 3
  EXPECT_NEAR(g.mahalanobis_squared(Pose2{1.2, 1.7, 0.6}), 3.0, 1e-12);
  EXPECT_NEAR(g.value(Pose2{1.2, 1.7, 0.6}), std::exp(-1.5), 1e-12);
}

TEST(Gaussian2, ResidualWrapsTheAngle) {
  const Gaussian2 g(Pose2{0.0, 0.0, kPi - 0.05}, Eigen::Matrix3d::Identity());
  EXPECT_NEAR(g.residual(Pose2{0.0, 0.0, -kPi + 0.05}).z(), 0.1, 1e-12);
}

TEST(Gaussian2, InformationFactorIsUpperAndWhitens) {
  Eigen::Matrix3d cov;
  cov << 0.5, 0.2, 0.05, 0.2, 0.3, -0.02, 0.05, -0.02, 0.1;
  const Gaussian2 g(Pose2{}, cov);
  const Eigen::Matrix3d& u = g.information_factor();
  EXPECT_NEAR((u.transpose() * u - g.information()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(u(1, 0), 0.0, 0.0);
  EXPECT_NEAR(u(2, 0), 0.0, 0.0);
  const Pose2 p{0.3, -0.2, 0.1};
  EXPECT_NEAR((u * g.residual(p)).squaredNorm(), g.mahalanobis_squared(p), 1e-12);
}

TEST(Gaussian2, SamplesHaveTheRightMoments) {
  Eigen::Matrix3d cov;
  cov << 0.5, 0.2, 0.05, 0.2, 0.3, -0.02, 0.05, -0.02, 0.1;
  const Gaussian2 g(Pose2{1.0, -1.0, 0.2}, cov);
  aco::Rng rng(4);
  const int n = 100000;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r = g.residual(g.sample(rng));
    mean += r;
    second += r * r.transpose();
  }
  mean /= n;
  second /= n;
  EXPECT_LT(mean.norm(), 0.01);
  EXPECT_LT((second - cov).cwiseAbs().maxCoeff(), 0.01);
}

TEST(Gaussian2, RejectsBadCovariances) {
  Eigen::Matrix3d asym = Eigen::Matrix3d::Identity();
  asym(0, 1) = 0.5;
  EXPECT_THROW(Gaussian2(Pose2{}, asym), std::invalid_argument);
  Eigen::Matrix3d indefinite = Eigen::Matrix3d::Identity();
  indefinite(2, 2) = -1.0;
  EXPECT_THROW(Gaussian2(Pose2{}, indefinite), std::invalid_argument);
  Eigen::Matrix3d nan = Eigen::Matrix3d::Identity();
  nan(1, 1) = std::nan("");
  EXPECT_THROW(Gaussian2(Pose2{}, nan), std::invalid_argument);
  EXPECT_THROW(Gaussian2(Pose2{0, std::nan(""), 0}, Eigen::Matrix3d::Identity()),
               std::invalid_argument);
}

// Three fragments, one sample each, hand-computed chain and weight.
TEST(FragmentSet, Eq8AndEq10ByHand) {
  FragmentSet set;
  set.fragments.resize(3);
  const Eigen::Matrix3d unit = Eigen::Matrix3d::Identity();
  set.fragments[0].exit = Pose2{2.0, 0.0, kPi / 2};
  set.fragments[1].alignment = Gaussian2(Pose2{2.0, 0.0, kPi / 2}, unit);
  set.fragments[1].samples = {Pose2{2.0, 0.0, kPi / 2}, Pose2{2.0, 1.0, kPi / 2}};
  set.fragments[1].exit = Pose2{2.0, 0.0, kPi / 2};
  set.fragments[2].alignment = Gaussian2(Pose2{2.0, 0.0, kPi / 2}, unit);
  set.fragments[2].samples = {Pose2{2.0, 0.0, kPi / 2}};
  set.fragments[2].exit = Pose2{1.0, 0.0, 0.0};
  LoopClosure closure;
  closure.from = 0;
  closure.to = 2;
  closure.anchor = set.fragments[2].exit;
  closure.hypothesis = Gaussian2(Pose2{2.0, 1.0, kPi}, unit);
  set.closures = {closure};
  validate(set);

  const std::vector<std::uint32_t> choice{0, 0};
  const auto frames = world_frames(set, choice);
  EXPECT_NEAR(frames[1].x, 2.0, 1e-12);
  EXPECT_NEAR(frames[2].x, 2.0, 1e-12);
  EXPECT_NEAR(frames[2].y, 2.0, 1e-12);
  EXPECT_NEAR(std::abs(frames[2].theta), kPi, 1e-12);
  // W T_{E_3} = F_3 * E_3 = (2 - 1, 2, pi) = (1, 2, pi); H = (2, 1, pi): r = (-1, 1, 0), m^2 = 2
  EXPECT_NEAR(path_weight(set, choice), 0.0 + 0.0 + (1.0 - std::exp(-1.0)), 1e-12);

  // Sample 1 of fragment 2 is off its mean by (0, 1, 0): alignment term 1 - e^-0.5, and it
  // moves F_2 to (2, 1, pi/2), F_3 to (2, 3, pi), E_3 to (1, 3, pi): r = (-1, 2, 0), m^2 = 5.
  const std::vector<std::uint32_t> other{1, 0};
  EXPECT_NEAR(path_weight(set, other), (1.0 - std::exp(-0.5)) + (1.0 - std::exp(-2.5)), 1e-12);
}

TEST(FragmentSet, ValidateNamesTheProblem) {
  FragmentSet set;
  set.fragments.resize(2);
  try {
    validate(set);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "fragments[1].alignment is missing");
  }
}

}  // namespace
}  // namespace antslam::slam
