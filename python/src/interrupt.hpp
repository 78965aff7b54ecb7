#pragma once
// Long calls from Python: the work runs on a worker thread while the calling Python thread, with
// the GIL released, waits for it. Every 20 ms the Python thread takes the GIL and checks for
// signals (PyErr_CheckSignals), so that Ctrl-C is seen during any phase, and it runs the calls
// the worker hands over (the user's observers), so that Python code runs on the thread that
// called (where plotting libraries expect it). A KeyboardInterrupt, or an exception of a
// handed-over call or of a Python cost term, requests stop: the library ends the run at its
// next check (the colony after its iteration, NLopt at its next evaluation) and the Python
// error is raised; a KeyboardInterrupt as antslam.Interrupted (a KeyboardInterrupt) whose
// `result` is what the run had found (converted by to_python as the call's return value would
// be; the Python wrappers convert it further as they convert a return value). Exceptions of the
// work itself are raised as they are
// (std::invalid_argument as ValueError, std::runtime_error as RuntimeError, with the library's
// one-line message).

#include <pybind11/pybind11.h>

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <utility>

namespace antslam::python {

namespace py = pybind11;

/// The Python thread's side of a long call.
class PythonThread {
 public:
  /// From the worker: runs f on the Python thread with the GIL held and returns when it has run
  /// (at once, without running it, once stop was requested).
  void call(const std::function<void()>& f);
  /// From any thread holding the GIL: keeps the first error and requests stop.
  void fail(py::error_already_set error);
  /// The stop token the work must honour.
  std::stop_token stop_token() const { return source_.get_token(); }

  /// The Python thread's loop: serves calls and checks for signals until the worker finished.
  void serve();
  /// From the worker: it finished.
  void finish();
  /// The Python error that stopped the call, if any.
  const std::optional<py::error_already_set>& error() const { return error_; }

 private:
  /// Runs f with the GIL held; a Python error fails the call.
  void run_python(const std::function<void()>& f);

  std::stop_source source_;
  std::mutex mutex_;
  std::mutex calls_;  // one handed-over call at a time
  std::condition_variable changed_;
  const std::function<void()>* pending_ = nullptr;
  bool done_ = false;
  std::optional<py::error_already_set> error_;
};

/// Registers antslam._core.Interrupted, a KeyboardInterrupt with a `result` attribute.
void bind_interrupted(py::module_& m);

/// Raises antslam._core.Interrupted with `partial` as its result.
[[noreturn]] void raise_interrupted(py::object partial);

/// Converts a result to Python as pybind11 converts a return value.
struct CastToPython {
  template <class Result>
  py::object operator()(Result&& r) const {
    return py::cast(std::forward<Result>(r));
  }
};

/// Runs work(python) on a worker thread as described above and returns its result.
template <class Work, class ToPython = CastToPython>
auto run_interruptible(Work&& work, ToPython&& to_python = {}) {
  using Result = decltype(work(std::declval<PythonThread&>()));
  PythonThread python;
  std::optional<Result> result;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work(python));
      } catch (...) {
        failure = std::current_exception();
      }
      python.finish();
    });
    python.serve();
    worker.join();
  }
  if (python.error()) {
    if (result && python.error()->matches(PyExc_KeyboardInterrupt))
      raise_interrupted(to_python(std::move(*result)));
    throw *python.error();
  }
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

}  // namespace antslam::python
