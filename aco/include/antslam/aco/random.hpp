#pragma once
// Random streams. Every random choice of a run flows from the user's seed: each ant of each
// iteration draws from its own stream, derived from (seed, iteration, ant), so that results do
// not depend on how ants are spread over threads.

#include <cstdint>
#include <limits>

namespace antslam::aco {

/// One step of SplitMix64 (Steele, Lea & Flood 2014); used to expand and mix seeds.
constexpr std::uint64_t splitmix64(std::uint64_t& state) noexcept {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31U);
}

/// Mixes up to three words into one well-spread 64-bit seed.
constexpr std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b = 0,
                                 std::uint64_t c = 0) noexcept {
  std::uint64_t s = a;
  std::uint64_t h = splitmix64(s);
  s = h ^ b;
  h = splitmix64(s);
  s = h ^ c;
  return splitmix64(s);
}

/// xoshiro256++ (Blackman & Vigna 2019). Satisfies std::uniform_random_bit_generator.
class Rng {
 public:
  using result_type = std::uint64_t;

  explicit constexpr Rng(std::uint64_t seed = 0) noexcept {
    for (auto& word : s_) word = splitmix64(seed);
  }

  static constexpr result_type min() noexcept { return 0; }
  static constexpr result_type max() noexcept { return std::numeric_limits<result_type>::max(); }

  constexpr result_type operator()() noexcept {
    const std::uint64_t result = rotl(s_[0] + s_[3], 23) + s_[0];
    const std::uint64_t t = s_[1] << 17U;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform double in [0, 1) with 53 random bits.
  constexpr double uniform() noexcept { return static_cast<double>((*this)() >> 11U) * 0x1.0p-53; }

  /// Uniform integer in [0, n), n > 0, without bias (Lemire 2019).
  constexpr std::uint32_t below(std::uint32_t n) noexcept {
    std::uint64_t m = ((*this)() >> 32U) * n;
    auto low = static_cast<std::uint32_t>(m);
    if (low < n) {
      const std::uint32_t threshold = static_cast<std::uint32_t>(-n) % n;
      while (low < threshold) {
        m = ((*this)() >> 32U) * n;
        low = static_cast<std::uint32_t>(m);
      }
    }
    return static_cast<std::uint32_t>(m >> 32U);
  }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) noexcept {
    return (x << k) | (x >> (64 - k));
  }
  std::uint64_t s_[4]{};
};

/// The stream of ant `ant` in iteration `iteration` of a run seeded with `seed`.
constexpr Rng ant_stream(std::uint64_t seed, std::uint64_t iteration, std::uint64_t ant) noexcept {
  return Rng(mix_seed(seed, iteration, ant));
}

}  // namespace antslam::aco
