// antslam: the command-line entry point and its error boundary. Every failure ends the program
// with one line "antslam: error: ..." on stderr and the exit status of its kind (io/errors.hpp,
// README "Exit status"); SIGINT and SIGTERM remove temporary files first (io/interrupts.hpp).
// Under an MPI launcher every rank runs the same command line: rank 0 alone prints (the other
// ranks' stdout goes to /dev/null) and writes outputs (io/output_files.hpp); a failure on any
// rank ends the run on every rank, and rank 0 prints "antslam: error: rank R: <message>" for the
// lowest failed rank R, every rank exiting with that failure's status.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "antslam/dist/communicator.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/outcome.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/version.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "suggestions.hpp"

namespace {

namespace io = antslam::io;

/// Parses and runs the command line: its failure, if it fails on this rank alone.
std::optional<io::Failure> run(int argc, char** argv) {
  CLI::App app{"antslam: ant colony optimization for SLAM map optimization and the TSP"};
  try {
    app.formatter(std::make_shared<antslam::cli::WrappingFormatter>());
    app.set_version_flag("--version", std::string("antslam ") + antslam::kVersion);
    antslam::cli::add_commands(app);
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::Success& e) {
    app.exit(e);  // --help, --version
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    return io::Failure{io::one_line(e.what() + antslam::cli::did_you_mean(app)),
                       io::ExitStatus::usage};
  } catch (const antslam::dist::RankFailure&) {
    throw;  // already known to every rank
  } catch (...) {
    return io::failure_of(std::current_exception());
  }
}

/// Under an MPI launcher, the end of a failed run: rank 0 prints the line, and every rank ends
/// MPI and exits with the status while interrupts are held back. The launcher ends the other
/// ranks as soon as one exits with an error; a rank ended that way would otherwise report an
/// interrupt (io/interrupts.hpp), and rank 0 could be ended before its line is out.
[[noreturn]] void end_failed_run(std::optional<antslam::dist::MpiSession>& session,
                                 const antslam::dist::RankFailure& failure) {
  io::without_interrupts([&] {
    if (antslam::dist::world().is_root())
      std::fprintf(stderr, "antslam: error: %s\n", failure.what());
    session.reset();
    std::fflush(nullptr);
    std::_Exit(failure.status());
  });
  std::_Exit(failure.status());  // not reached: io::without_interrupts runs its function
}

}  // namespace

int main(int argc, char** argv) {
  io::handle_interrupts();
  std::optional<antslam::dist::MpiSession> session(std::in_place, argc, argv);
  antslam::dist::Communicator& world = antslam::dist::world();
  if (!world.is_root() && std::freopen("/dev/null", "w", stdout) == nullptr)
    antslam::dist::MpiSession::abort_run(static_cast<int>(io::ExitStatus::runtime));
  std::optional<io::Failure> failure;
  try {
    failure = run(argc, argv);
  } catch (const antslam::dist::RankFailure& e) {
    // Every rank stopped at the same collective step with the same failure: no rank is left
    // waiting, so it is reported without the final gathering below.
    if (world.size() == 1) {
      std::fprintf(stderr, "antslam: error: %s\n", e.cause().c_str());
      return e.status();
    }
    end_failed_run(session, e);
  }
  if (world.size() == 1) {
    if (!failure) return 0;
    if (failure->signal != 0) {  // stopped at a safe point; the message says what was kept
      std::fprintf(stderr, "antslam: %s\n", failure->message.c_str());
      return 128 + failure->signal;
    }
    std::fprintf(stderr, "antslam: error: %s\n", failure->message.c_str());
    return static_cast<int>(failure->status);
  }
  // Every rank reaches this point, whether its command failed or not.
  antslam::dist::Outcome mine;
  if (failure) mine = antslam::dist::outcome_of(*failure);
  try {
    antslam::dist::gather_outcomes(world, mine);
  } catch (const antslam::dist::RankFailure& e) {
    end_failed_run(session, e);
  }
  return 0;
}
