#include "antslam/io/interrupts.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace antslam::io {

namespace {

/// Held while temporary paths are created, removed or moved into place, and by the watcher
/// while it cleans up: an interrupt waits for those steps to finish.
std::recursive_mutex& registry_mutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

std::vector<std::filesystem::path>& registry() {
  static std::vector<std::filesystem::path> paths;
  return paths;
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}

/// The StopOnInterrupt alive, if any, and the signal that requested its stop.
struct GracefulStop {
  std::mutex mutex;
  std::stop_source* source = nullptr;
  std::atomic<int> signal{0};
};

GracefulStop& graceful_stop() {
  static GracefulStop state;
  return state;
}

/// Requests the stop of the StopOnInterrupt alive if it has none yet: whether it did.
bool request_graceful_stop(int signal_number) {
  GracefulStop& g = graceful_stop();
  const std::lock_guard lock(g.mutex);
  if (g.source == nullptr || g.signal.load() != 0) return false;
  g.signal.store(signal_number);
  g.source->request_stop();
  std::fprintf(stderr,
               "\nantslam: %s: stopping at the next safe point to keep what was found "
               "(again to abort)\n",
               strsignal(signal_number));
  std::fflush(stderr);
  return true;
}

[[noreturn]] void end_process(int signal_number) {
  const std::lock_guard lock(registry_mutex());  // never released: the process ends here
  for (const std::filesystem::path& path : registry()) {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::fprintf(stderr, "\nantslam: interrupted (%s); temporary files removed\n",
               strsignal(signal_number));
  std::fflush(stderr);
  std::signal(signal_number, SIG_DFL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, signal_number);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  raise(signal_number);
  _exit(128 + signal_number);  // not reached: the default action ends the process
}

[[noreturn]] void watch(sigset_t signals) {
  for (;;) {
    int signal_number = 0;
    if (sigwait(&signals, &signal_number) != 0) continue;
    if (!request_graceful_stop(signal_number)) end_process(signal_number);
  }
}

}  // namespace

void handle_interrupts() {
  const sigset_t signals = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(watch, signals).detach();
}

void create_temporary(const std::filesystem::path& path, const std::function<void()>& create) {
  const std::lock_guard lock(registry_mutex());
  registry().push_back(path);
  try {
    create();
  } catch (...) {
    registry().pop_back();
    throw;
  }
}

void remove_temporary(const std::filesystem::path& path) {
  const std::lock_guard lock(registry_mutex());
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
  std::erase(registry(), path);
}

void without_interrupts(const std::function<void()>& f) {
  const std::lock_guard lock(registry_mutex());
  f();
}

StopOnInterrupt::StopOnInterrupt() {
  GracefulStop& g = graceful_stop();
  const std::lock_guard lock(g.mutex);
  if (g.source != nullptr) throw std::logic_error("StopOnInterrupt: one is alive already");
  g.source = &source_;
  g.signal.store(0);
}

StopOnInterrupt::~StopOnInterrupt() {
  GracefulStop& g = graceful_stop();
  const std::lock_guard lock(g.mutex);
  g.source = nullptr;
}

int StopOnInterrupt::signal() const { return graceful_stop().signal.load(); }

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "signal " + std::to_string(signal);
  }
}

Interrupted::Interrupted(int signal, const std::string& kept)
    : std::runtime_error("interrupted (" + std::string(strsignal(signal)) + "); " + kept),
      signal_(signal),
      kept_(kept) {}

}  // namespace antslam::io
