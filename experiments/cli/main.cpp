// antslam: the command-line entry point and its error boundary. Every failure ends the program
// with one line "antslam: error: ..." on stderr and the exit status of its kind (cli/errors.hpp,
// README "Exit status"); SIGINT and SIGTERM remove temporary files first (cli/interrupts.hpp).

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "cli/errors.hpp"
#include "cli/interrupts.hpp"
#include "commands.hpp"
#include "dist/communicator.hpp"

int main(int argc, char** argv) {
  using antslam::cli::ExitStatus;
  antslam::cli::handle_interrupts();
  antslam::dist::MpiSession mpi(argc, argv);
  CLI::App app{"antslam: ant colony optimization for SLAM map optimization and the TSP"};
  antslam::cli::Failure failure;
  try {
    antslam::cli::add_commands(app);
    app.parse(argc, argv);
    return static_cast<int>(ExitStatus::ok);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    failure = {antslam::cli::one_line(e.what()), ExitStatus::usage};
  } catch (...) {
    failure = antslam::cli::failure_of(std::current_exception());
  }
  std::fprintf(stderr, "antslam: error: %s\n", failure.message.c_str());
  return static_cast<int>(failure.status);
}
