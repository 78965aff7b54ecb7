// io/interrupts.hpp: while a StopOnInterrupt lives, the first signal requests a stop on its
// token and the second ends the process; without one, the first ends it. Each case runs in a
// child process (a death test), since the watcher owns the process's signals.

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"

namespace antslam::io {
namespace {

/// Waits (at most 10 s) until `token` is stopped: whether it was.
bool stopped_soon(const std::stop_token& token) {
  for (int i = 0; i < 1000 && !token.stop_requested(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return token.stop_requested();
}

TEST(InterruptsDeathTest, TheFirstSignalRequestsAStopAndTheProcessGoesOn) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto stop_then_exit = [] {
    handle_interrupts();
    StopOnInterrupt stop;
    if (stop.signal() != 0 || stop.token().stop_requested()) std::_Exit(10);
    ::kill(::getpid(), SIGTERM);
    if (!stopped_soon(stop.token())) std::_Exit(11);
    if (stop.signal() != SIGTERM) std::_Exit(12);
    std::_Exit(0);  // still alive: the signal only asked for a stop
  };
  EXPECT_EXIT(stop_then_exit(), ::testing::ExitedWithCode(0),
              "antslam: Terminated: stopping at the next safe point");
}

TEST(InterruptsDeathTest, TheSecondSignalEndsTheProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto two_signals = [] {
    handle_interrupts();
    StopOnInterrupt stop;
    ::kill(::getpid(), SIGINT);
    if (!stopped_soon(stop.token())) std::_Exit(11);
    ::kill(::getpid(), SIGINT);
    std::this_thread::sleep_for(std::chrono::seconds(10));  // the watcher ends the process first
    std::_Exit(0);
  };
  EXPECT_EXIT(two_signals(), ::testing::KilledBySignal(SIGINT),
              "antslam: interrupted \\(Interrupt\\); temporary files removed");
}

TEST(InterruptsDeathTest, AfterTheStopOnInterruptEndsASignalEndsTheProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto after_scope = [] {
    handle_interrupts();
    { const StopOnInterrupt stop; }
    ::kill(::getpid(), SIGHUP);
    std::this_thread::sleep_for(std::chrono::seconds(10));
    std::_Exit(0);
  };
  EXPECT_EXIT(after_scope(), ::testing::KilledBySignal(SIGHUP), "antslam: interrupted");
}

TEST(Interrupts, OneStopOnInterruptAtATime) {
  const StopOnInterrupt first;
  EXPECT_THROW(StopOnInterrupt second, std::logic_error);
}

TEST(Interrupts, InterruptedSaysTheSignalAndWhatWasKeptAndExitsWithIt) {
  const Failure f = failure_of(std::make_exception_ptr(Interrupted(SIGINT, "kept the best tour")));
  EXPECT_EQ(f.message, "interrupted (Interrupt); kept the best tour");
  EXPECT_EQ(f.signal, SIGINT);
  EXPECT_EQ(signal_name(SIGINT), "SIGINT");
  EXPECT_EQ(signal_name(SIGTERM), "SIGTERM");
  EXPECT_EQ(signal_name(SIGHUP), "SIGHUP");
  EXPECT_EQ(signal_name(SIGUSR1), "signal " + std::to_string(SIGUSR1));
}

}  // namespace
}  // namespace antslam::io
