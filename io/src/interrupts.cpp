#include "antslam/io/interrupts.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <mutex>
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

[[noreturn]] void watch(sigset_t signals) {
  int signal_number = 0;
  while (sigwait(&signals, &signal_number) != 0) {
  }
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

}  // namespace antslam::io
