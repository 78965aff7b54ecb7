// The synthetic generator: ground truth consistent with the model, noise of the stated size,
// presets, several loops, reproducibility.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "antslam/slamgraph/fragment_set_io.hpp"
#include "antslam/slamgraph/synth.hpp"
#include "support.hpp"

namespace antslam::slam {
namespace {

TEST(Synth, PresetsHaveThePapersSizes) {
  for (const auto& [name, n] : {std::pair{"paper9", 9U}, {"paper15", 15U}, {"paper24", 24U}}) {
    const FragmentSet set = synthesize(synth_preset(name));
    EXPECT_EQ(set.fragments.size(), n);
    EXPECT_EQ(set.fragments[1].samples.size(), 20U);
    EXPECT_EQ(set.closures.size(), 1U);  // one loop, as in the paper
    EXPECT_EQ(set.closures[0].from, 0U);
    EXPECT_EQ(set.closures[0].to, n - 1);
  }
  EXPECT_THROW(synth_preset("paper10"), std::invalid_argument);
}

// Without noise the ground truth is a perfect map: every term of eq. (10) is zero.
TEST(Synth, NoiseFreeGroundTruthHasZeroWeight) {
  for (std::size_t laps : {1U, 3U}) {
    SynthSettings s = synth_preset("paper15");
    s.laps = laps;
    s.fragments = 15 * laps;
    s.noise_free = true;
    const FragmentSet set = synthesize(s);
    const Scores truth = score(set, relative_alignments(set.reference));
    EXPECT_NEAR(truth.weight, 0.0, 1e-12);
    EXPECT_NEAR(truth.chi2, 0.0, 1e-12);
    // Eq. (4): the exit of fragment i is the alignment of fragment i + 1.
    for (std::size_t i = 0; i + 1 < set.fragments.size(); ++i)
      EXPECT_EQ(set.fragments[i].exit.x, set.fragments[i + 1].alignment->mean().x);
  }
}

// The scan matcher's error is drawn from Sigma: the mean squared Mahalanobis distance of the
// alignment means from the truth is chi^2_3, mean 3. Samples are drawn around the means.
TEST(Synth, NoiseHasTheStatedSize) {
  SynthSettings s;
  s.fragments = 400;
  s.samples = 10;
  s.loop_length_m = 2000.0;
  s.correlation = 0.3;
  const FragmentSet set = synthesize(s);
  const std::vector<Pose2> truth = relative_alignments(set.reference);
  double mean_truth = 0.0, mean_samples = 0.0;
  for (std::size_t i = 1; i < set.fragments.size(); ++i) {
    const Gaussian2& g = *set.fragments[i].alignment;
    mean_truth += g.mahalanobis_squared(truth[i - 1]);
    for (const Pose2& p : set.fragments[i].samples) mean_samples += g.mahalanobis_squared(p);
  }
  mean_truth /= 399.0;
  mean_samples /= 3990.0;
  EXPECT_NEAR(mean_truth, 3.0, 0.5);
  EXPECT_NEAR(mean_samples, 3.0, 0.2);
  EXPECT_NEAR(set.fragments[5].alignment->covariance()(0, 2), 0.3 * s.sigma_xy * s.sigma_theta,
              1e-15);
}

TEST(Synth, SeveralLapsCloseSeveralLoops) {
  SynthSettings s = synth_preset("paper9");
  s.laps = 2;
  s.fragments = 18;
  const FragmentSet set = synthesize(s);
  EXPECT_GT(set.closures.size(), 5U);
  for (const LoopClosure& c : set.closures) {
    EXPECT_LT(c.from + 1, c.to);
    const Pose2 d = between(set.reference[c.from], set.reference[c.to]);
    if (!(c.from == 0 && c.to == 17)) {
      EXPECT_LT(std::hypot(d.x, d.y), s.revisit_radius_m);
    }
  }
  EXPECT_NO_THROW(validate(set));
}

TEST(Synth, SameSeedSameSetOtherSeedOtherSet) {
  const SynthSettings s = synth_preset("paper9");
  SynthSettings other = s;
  other.seed = 2;
  EXPECT_EQ(testing::fragment_set_text(synthesize(s)), testing::fragment_set_text(synthesize(s)));
  EXPECT_NE(testing::fragment_set_text(synthesize(s)),
            testing::fragment_set_text(synthesize(other)));
}

/// Same structure and numbers up to libm rounding (the files were written on one platform).
void expect_same_set(const FragmentSet& a, const FragmentSet& b) {
  const auto near = [](const Pose2& p, const Pose2& q) {
    return std::abs(p.x - q.x) < 1e-9 && std::abs(p.y - q.y) < 1e-9 &&
           std::abs(wrap_angle(p.theta - q.theta)) < 1e-9;
  };
  ASSERT_EQ(a.fragments.size(), b.fragments.size());
  ASSERT_EQ(a.closures.size(), b.closures.size());
  for (std::size_t i = 1; i < a.fragments.size(); ++i) {
    ASSERT_EQ(a.fragments[i].samples.size(), b.fragments[i].samples.size());
    for (std::size_t j = 0; j < a.fragments[i].samples.size(); ++j)
      EXPECT_TRUE(near(a.fragments[i].samples[j], b.fragments[i].samples[j])) << i << " " << j;
    EXPECT_TRUE(near(a.fragments[i].alignment->mean(), b.fragments[i].alignment->mean()));
  }
  for (std::size_t c = 0; c < a.closures.size(); ++c) {
    EXPECT_EQ(a.closures[c].to, b.closures[c].to);
    EXPECT_TRUE(near(a.closures[c].hypothesis.mean(), b.closures[c].hypothesis.mean()));
  }
}

// data/fragment-sets ships the presets (synth seed 1) and a two-lap set; they load, validate
// and are what the generator writes today (data/fragment-sets/README.md).
TEST(Synth, ShippedExamplesMatchTheGenerator) {
  for (const char* name : {"paper9", "paper15", "paper24"}) {
    SCOPED_TRACE(name);
    expect_same_set(
        read_fragment_set_file(std::string(ANTSLAM_DATA_DIR) + "/fragment-sets/" + name + ".json"),
        synthesize(synth_preset(name)));
  }
  SynthSettings laps = synth_preset("paper15");
  laps.laps = 2;
  laps.fragments = 30;
  const FragmentSet shipped =
      read_fragment_set_file(ANTSLAM_DATA_DIR "/fragment-sets/paper15-2laps.json");
  expect_same_set(shipped, synthesize(laps));
  EXPECT_EQ(shipped.closures.size(), 16U);
}

TEST(Synth, RejectsNonsenseSettings) {
  SynthSettings s;
  s.fragments = 1;
  EXPECT_THROW(synthesize(s), std::invalid_argument);
  s = {};
  s.sigma_theta = 0.0;
  EXPECT_THROW(synthesize(s), std::invalid_argument);
  s = {};
  s.correlation = -0.7;
  EXPECT_THROW(synthesize(s), std::invalid_argument);
  s = {};
  s.loop_length_m = std::nan("");
  EXPECT_THROW(synthesize(s), std::invalid_argument);
}

}  // namespace
}  // namespace antslam::slam
