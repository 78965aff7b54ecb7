// antslam batch: many independent antslam command lines from one file, spread over the ranks of
// an MPI run (job j on rank j % ranks; in one process, one after the other). Each job runs
// in-process on its rank alone, as `antslam <line>` would: it writes its own outputs and its
// stdout is kept (printed by rank 0 in job order, or written to --log-dir). A failing job ends
// the rank's share (with --keep-going the rank goes on); once every rank has finished, the run
// fails with one line naming the job's line (and the rank).
// With --log-dir, each job's files are written as soon as it ends, with a mark that it finished
// (line-<line>.done: its command line); --resume skips the jobs marked finished with the same
// command line, so that a batch stopped by Ctrl-C, a wall-time limit or a crash goes on where it
// stopped. On one process, Ctrl-C stops the job under way as that command does (a tsp run keeps
// its best tour, marked partial; it is not marked finished) and no further job starts.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "antslam/dist/byte_stream.hpp"
#include "antslam/dist/command_world.hpp"
#include "antslam/dist/farm.hpp"
#include "antslam/dist/outcome.hpp"
#include "antslam/io/errors.hpp"
#include "antslam/io/interrupts.hpp"
#include "antslam/io/output_files.hpp"
#include "commands.hpp"

namespace antslam::cli {

namespace {

struct BatchOptions {
  std::string jobs;
  std::string log_dir;
  bool keep_going = false;
  bool resume = false;
};

/// What a job left: its stdout, and how it ended (its failure names the jobs file and line).
struct JobLog {
  std::string out;
  dist::Outcome outcome;
  bool skipped = false;  ///< --resume: finished by an earlier batch, not run
};

/// One line of the jobs file: an antslam command line, split at whitespace.
struct Job {
  std::size_t line = 0;
  std::vector<std::string> args;  ///< the subcommand and its arguments
  std::string text() const {
    std::string t;
    for (const std::string& a : args) t += (t.empty() ? "" : " ") + a;
    return t;
  }
};

/// Every job of the file: blank lines and lines starting with '#' skipped, a leading "antslam"
/// dropped.
std::vector<Job> read_jobs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw io::InputError(path + ": cannot open");
  std::vector<Job> jobs;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    Job job{number, {}};
    for (std::string w; words >> w;) job.args.push_back(w);
    if (job.args.empty() || job.args.front().starts_with('#')) continue;
    if (job.args.front() == "antslam") job.args.erase(job.args.begin());
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (job.args.empty()) throw io::InputError(where + "no command after 'antslam'");
    if (job.args.front() == "batch") throw io::InputError(where + "a batch cannot run a batch");
    jobs.push_back(std::move(job));
  }
  if (!in.eof()) throw io::InputError(path + ": read error");
  if (jobs.empty()) throw io::InputError(path + ": no job (one antslam command line per line)");
  return jobs;
}

/// Runs f with this process's stdout (file descriptor 1, so C stdio and std::cout alike) going
/// into a temporary file, and returns what it wrote.
template <class F>
std::string capture_stdout(F&& f) {
  std::FILE* file = std::tmpfile();
  if (file == nullptr)
    throw io::OutputError("batch: cannot create a temporary file for a job's output");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closer(file, &std::fclose);
  std::cout.flush();
  std::fflush(stdout);
  const int saved = ::dup(STDOUT_FILENO);
  if (saved < 0 || ::dup2(::fileno(file), STDOUT_FILENO) < 0)
    throw io::OutputError("batch: cannot redirect a job's output");
  struct Restore {
    int saved;
    ~Restore() {
      std::cout.flush();
      std::fflush(stdout);
      ::dup2(saved, STDOUT_FILENO);
      ::close(saved);
    }
  };
  {
    const Restore restore{saved};
    f();
  }
  std::rewind(file);
  std::string text;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
  return text;
}

/// Throws the failure as an error of its kind (so that it keeps its exit status).
[[noreturn]] void throw_as(const io::Failure& failure) {
  const std::string& message = failure.message;
  switch (failure.status) {
    case io::ExitStatus::usage:
      throw io::UsageError(message);
    case io::ExitStatus::input:
      throw io::InputError(message);
    default:
      throw io::OutputError(message);
  }
}

/// Runs one job on this rank alone, as the antslam program runs its command line. A failure
/// names the job's line; it is thrown, or with `keep_going` returned.
JobLog run_job(const Job& job, const std::string& jobs_file, bool keep_going) {
  const dist::SingleProcessScope alone;
  std::vector<std::string> args{"antslam"};
  args.insert(args.end(), job.args.begin(), job.args.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  try {
    return {capture_stdout([&] {
              CLI::App app{"antslam"};
              add_commands(app);
              try {
                app.parse(static_cast<int>(argv.size()), argv.data());
              } catch (const CLI::Success& e) {
                app.exit(e);  // --help
              } catch (const CLI::ParseError& e) {
                throw io::UsageError(io::one_line(e.what()));
              }
            }),
            {}};
  } catch (const io::Interrupted&) {
    throw;  // the batch stops (run below)
  } catch (...) {
    io::Failure failure = io::failure_of(std::current_exception());
    failure.message = jobs_file + ":" + std::to_string(job.line) + ": " + failure.message;
    if (!keep_going) throw_as(failure);
    return {{}, dist::outcome_of(failure)};
  }
}

std::filesystem::path log_path(const BatchOptions& o, const Job& job, const char* extension) {
  return std::filesystem::path(o.log_dir) / ("line-" + std::to_string(job.line) + extension);
}

/// The files a job leaves in --log-dir, written together by the process that ran it as soon as
/// it ends: its stdout (.out), and either its error line (.err, a failed job with --keep-going)
/// or the mark that it finished (.done: its command line); a stale .err or .done is removed.
void write_job_logs(const BatchOptions& o, const Job& job, const JobLog& log) {
  io::OutputFiles files(true);
  const std::filesystem::path out = files.add(log_path(o, job, ".out"));
  const std::filesystem::path err = files.add(log_path(o, job, ".err"));
  const std::filesystem::path done = files.add(log_path(o, job, ".done"));
  files.write(out, log.out);
  if (log.outcome.failed)
    files.write(err, "antslam: error: " + log.outcome.message + "\n");
  else
    files.write(done, job.text() + "\n");
  files.commit();
}

/// --resume: whether an earlier batch marked the job finished with the same command line.
bool finished_before(const BatchOptions& o, const Job& job) {
  std::ifstream in(log_path(o, job, ".done"));
  std::string line;
  return in && std::getline(in, line) && line == job.text();
}

void run(const BatchOptions& o) {
  if (o.resume && o.log_dir.empty())
    throw io::UsageError("--resume needs --log-dir (where the finished jobs are marked)");
  const std::vector<Job> jobs = read_jobs(o.jobs);
  if (!o.log_dir.empty()) {  // every log file can be written, checked before the first job
    io::OutputFiles check(false);
    for (const Job& job : jobs)
      for (const char* extension : {".out", ".err", ".done"})
        check.add(log_path(o, job, extension));
  }
  dist::Communicator& world = dist::command_world();
  std::size_t finished = 0;  // on this process, now or before (--resume): for the interrupted line
  const Job* under_way = nullptr;
  const std::vector<JobLog> logs = [&] {
    try {
      return dist::farm<JobLog>(
          world, jobs.size(),
          [&](std::span<const std::size_t> share) {
            std::vector<JobLog> out;
            for (const std::size_t j : share) {
              if (o.resume && finished_before(o, jobs[j])) {
                out.push_back({{}, {}, true});
                ++finished;
                continue;
              }
              under_way = &jobs[j];
              if (!o.log_dir.empty())  // no longer finished, until it finishes again
                std::filesystem::remove(log_path(o, jobs[j], ".done"));
              out.push_back(run_job(jobs[j], o.jobs, o.keep_going));
              if (!o.log_dir.empty()) write_job_logs(o, jobs[j], out.back());
              ++finished;
            }
            return out;
          },
          [](dist::ByteWriter& out, const JobLog& log) {
            out.text(log.out);
            dist::write(out, log.outcome);
            out.value(static_cast<std::uint8_t>(log.skipped));
          },
          [](dist::ByteReader& in) {
            JobLog log{in.text(), {}};
            log.outcome = dist::read_outcome(in);
            log.skipped = in.value<std::uint8_t>() != 0;
            return log;
          });
    } catch (const io::Interrupted& e) {  // one process: the job under way kept what it could
      throw io::Interrupted(
          e.signal(), std::to_string(finished) + " of " + std::to_string(jobs.size()) +
                          " jobs finished; " + o.jobs + ":" + std::to_string(under_way->line) +
                          " stopped and " + e.kept() +
                          (o.log_dir.empty() ? std::string() : "; --resume runs the others"));
    }
  }();
  std::vector<std::size_t> failed;
  std::size_t skipped = 0;
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    if (logs[j].outcome.failed) failed.push_back(j);
    if (logs[j].skipped) ++skipped;
  }
  if (o.log_dir.empty()) {
    for (std::size_t j = 0; j < jobs.size(); ++j)
      std::printf("== %s:%zu: %s\n%s", o.jobs.c_str(), jobs[j].line, jobs[j].text().c_str(),
                  logs[j].out.c_str());
  } else {
    const std::string before =
        skipped == 0 ? "" : " (" + std::to_string(skipped) + " finished before, skipped)";
    std::printf("%zu jobs done%s; their output in %s/line-<line>.out\n", jobs.size(),
                before.c_str(), o.log_dir.c_str());
  }
  if (failed.empty()) return;
  // --keep-going: every rank holds every job's outcome, so every rank stops here alike, naming
  // the first failed job and the rank that ran it.
  dist::Outcome first = logs[failed.front()].outcome;
  if (failed.size() > 1)
    first.message += " (and " + std::to_string(failed.size() - 1) + " more failed job" +
                     (failed.size() > 2 ? "s" : "") + ")";
  throw dist::RankFailure(failed.front() % world.size(), first);
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto o = std::make_shared<BatchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "batch", "Run the antslam command lines of a file (under mpirun: job j on rank j % ranks)");
  cmd->add_option("jobs", o->jobs,
                  "one antslam command line per line, words split at whitespace (no quoting); "
                  "blank lines and lines starting with # are skipped")
      ->required();
  cmd->add_option("--log-dir", o->log_dir,
                  "write each job's stdout to DIR/line-<line>.out instead of printing them all "
                  "in job order");
  cmd->add_flag("--resume", o->resume,
                "skip the jobs an earlier batch finished (DIR/line-<line>.done holds the same "
                "command line); needs --log-dir");
  cmd->add_flag("--keep-going", o->keep_going,
                "run every job even after a failure (with --log-dir, a failed job's error line "
                "goes to DIR/line-<line>.err); the batch still fails, naming the first failed "
                "job");
  cmd->callback([o] { run(*o); });
}

}  // namespace antslam::cli
