// Farming runs over ranks (dist/farm.hpp): which runs a rank does, results in run order on every
// rank whatever rank ran them, and a failure on one rank reported on all of them with the
// lowest failed rank. Several ranks are threads of this process with a real all_gather (every
// rank waits until all have contributed), so the same code paths run as under MPI.

#include <gtest/gtest.h>

#include <condition_variable>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "antslam/dist/command_world.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/io/errors.hpp"

namespace antslam::cli {
namespace {

using Bytes = std::vector<std::byte>;

/// What the ranks of ThreadRanks share: the contributions of the all_gather in progress.
struct Exchange {
  std::mutex mutex;
  std::condition_variable done;
  std::vector<Bytes> contributions;
  std::vector<Bytes> result;
  std::size_t arrived = 0;
  std::size_t round = 0;
};

/// Rank `rank` of `size` ranks that run as threads of one process.
class ThreadRank final : public dist::Communicator {
 public:
  ThreadRank(std::size_t rank, std::size_t size, Exchange& exchange)
      : rank_(rank), size_(size), exchange_(&exchange) {}
  std::size_t rank() const override { return rank_; }
  std::size_t size() const override { return size_; }
  std::vector<Bytes> all_gather(std::span<const std::byte> mine) override {
    std::unique_lock lock(exchange_->mutex);
    exchange_->contributions.resize(size_);
    exchange_->contributions[rank_].assign(mine.begin(), mine.end());
    const std::size_t round = exchange_->round;
    if (++exchange_->arrived == size_) {
      exchange_->result = exchange_->contributions;
      exchange_->arrived = 0;
      ++exchange_->round;
      exchange_->done.notify_all();
    } else {
      exchange_->done.wait(lock, [&] { return exchange_->round != round; });
    }
    return exchange_->result;
  }

 private:
  std::size_t rank_, size_;
  Exchange* exchange_;
};

/// Runs body(communicator) on `size` thread ranks; returns what each rank returned.
template <class R, class F>
std::vector<R> on_ranks(std::size_t size, F body) {
  Exchange exchange;
  std::vector<R> results(size);
  std::vector<std::thread> threads;
  for (std::size_t r = 0; r < size; ++r)
    threads.emplace_back([&, r] {
      ThreadRank comm(r, size, exchange);
      results[r] = body(comm);
    });
  for (std::thread& t : threads) t.join();
  return results;
}

/// A run's result: its index and the rank that ran it.
struct Ran {
  std::size_t index = 0;
  std::size_t rank = 0;
};

std::vector<Ran> farm_indices(dist::Communicator& comm, std::size_t count) {
  return dist::farm<Ran>(
      comm, count,
      [&](std::span<const std::size_t> share) {
        std::vector<Ran> out;
        for (const std::size_t i : share) out.push_back({i, comm.rank()});
        return out;
      },
      [](dist::ByteWriter& out, const Ran& r) { out.value(r); },
      [](dist::ByteReader& in) { return in.value<Ran>(); });
}

TEST(Farm, RunIGoesToRankIModuloRanks) {
  EXPECT_EQ(dist::share_of(7, 0, 3), (std::vector<std::size_t>{0, 3, 6}));
  EXPECT_EQ(dist::share_of(7, 1, 3), (std::vector<std::size_t>{1, 4}));
  EXPECT_EQ(dist::share_of(7, 2, 3), (std::vector<std::size_t>{2, 5}));
  EXPECT_EQ(dist::share_of(2, 2, 3), std::vector<std::size_t>{});  // more ranks than runs
  EXPECT_EQ(dist::share_of(4, 0, 1), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_THROW(dist::share_of(4, 3, 3), std::invalid_argument);
}

TEST(Farm, ASingleProcessRunsEveryRunInOrder) {
  dist::SingleProcess single;
  const std::vector<Ran> ran = farm_indices(single, 5);
  ASSERT_EQ(ran.size(), 5U);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(ran[i].index, i);
  // Its failure passes unchanged, with its own type.
  EXPECT_THROW(dist::farm<int>(
                   single, 3,
                   [](std::span<const std::size_t>) -> std::vector<int> {
                     throw io::InputError("x.json: bad");
                   },
                   [](dist::ByteWriter&, int) {}, [](dist::ByteReader&) { return 0; }),
               io::InputError);
}

TEST(Farm, EveryRankGetsEveryResultInRunOrder) {
  for (const std::size_t size : {2U, 3U, 4U}) {
    const auto per_rank = on_ranks<std::vector<Ran>>(
        size, [](dist::Communicator& comm) { return farm_indices(comm, 7); });
    for (std::size_t r = 0; r < size; ++r) {
      ASSERT_EQ(per_rank[r].size(), 7U);
      for (std::size_t i = 0; i < 7; ++i) {
        EXPECT_EQ(per_rank[r][i].index, i) << size << " ranks";
        EXPECT_EQ(per_rank[r][i].rank, i % size) << size << " ranks";
      }
    }
  }
}

TEST(Farm, AFailureOnOneRankStopsEveryRankWithTheLowestFailedRank) {
  const auto per_rank = on_ranks<std::string>(3, [](dist::Communicator& comm) -> std::string {
    try {
      dist::farm<int>(
          comm, 6,
          [&](std::span<const std::size_t> share) {
            if (comm.rank() == 1) throw io::InputError("x.json: bad");
            if (comm.rank() == 2) throw std::bad_alloc();
            return std::vector<int>(share.size(), 1);
          },
          [](dist::ByteWriter& out, int v) { out.value(v); },
          [](dist::ByteReader& in) { return in.value<int>(); });
    } catch (const dist::RankFailure& e) {
      return std::to_string(e.rank()) + " " + std::to_string(e.status()) + " " + e.what();
    }
    return "no failure";
  });
  for (const std::string& seen : per_rank) EXPECT_EQ(seen, "1 1 rank 1: x.json: bad");
}

TEST(Farm, ABatchJobRunsOnItsRankAlone) {
  EXPECT_EQ(&dist::command_world(), &dist::world());
  {
    const dist::SingleProcessScope alone;
    EXPECT_EQ(dist::command_world().size(), 1U);
    EXPECT_TRUE(dist::command_world().is_root());
    EXPECT_THROW(dist::SingleProcessScope{}, std::logic_error);
  }
  EXPECT_EQ(&dist::command_world(), &dist::world());
}

}  // namespace
}  // namespace antslam::cli
