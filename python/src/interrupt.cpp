#include "interrupt.hpp"

#include <chrono>

namespace antslam::python {

void bind_interrupted(py::module_& m) {
  PyObject* type = PyErr_NewExceptionWithDoc(
      "antslam._core.Interrupted",
      "Ctrl-C (or a KeyboardInterrupt raised by an observer) stopped a long call; `result` is "
      "what the run had found, of the type the call returns.",
      PyExc_KeyboardInterrupt, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.attr("Interrupted") = py::reinterpret_steal<py::object>(type);
}

void raise_interrupted(py::object partial) {
  const py::object type = py::module_::import("antslam._core").attr("Interrupted");
  py::object error = type("interrupted: what the run had found is in .result");
  error.attr("result") = std::move(partial);
  PyErr_SetObject(type.ptr(), error.ptr());
  throw py::error_already_set();
}

void PythonThread::call(const std::function<void()>& f) {
  const std::lock_guard one_at_a_time(calls_);
  std::unique_lock lock(mutex_);
  if (error_) return;
  pending_ = &f;
  changed_.notify_all();
  changed_.wait(lock, [&] { return pending_ == nullptr; });
}

void PythonThread::fail(py::error_already_set error) {
  const std::lock_guard lock(mutex_);
  if (!error_) error_ = std::move(error);
  source_.request_stop();
}

void PythonThread::finish() {
  const std::lock_guard lock(mutex_);
  done_ = true;
  changed_.notify_all();
}

void PythonThread::run_python(const std::function<void()>& f) {
  const py::gil_scoped_acquire gil;
  {
    const std::lock_guard lock(mutex_);
    if (error_) return;
  }
  try {
    f();
  } catch (py::error_already_set& e) {
    fail(std::move(e));
  }
}

void PythonThread::serve() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait_for(lock, std::chrono::milliseconds(20),
                      [&] { return done_ || pending_ != nullptr; });
    if (pending_ != nullptr) {
      const std::function<void()>* f = pending_;
      lock.unlock();
      run_python(*f);
      lock.lock();
      pending_ = nullptr;
      changed_.notify_all();
    }
    if (done_) return;
    lock.unlock();
    run_python([] {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    });
    lock.lock();
  }
}

}  // namespace antslam::python
