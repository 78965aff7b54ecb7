#pragma once
// Parallel backends run the ants of one iteration. A backend only has to offer
//   kind()                  which backend it is (backend_kind.hpp);
//   threads()               the number of threads it uses;
//   for_each(count, f)      calls f(i) once for every i in [0, count), in any order.
// Ants write only to their own slots and draw from their own random streams, so a run's result
// does not depend on the backend or on the thread count. OpenMP and TBB backends live in
// backend_omp.hpp / backend_tbb.hpp so that only code using them links their runtimes; a
// backend chosen by name comes from backend_factory.hpp.

#include <concepts>
#include <cstddef>
#include <functional>
#include <memory>
#include <utility>

#include "antslam/aco/backend_kind.hpp"

namespace antslam::aco {

template <class B>
concept Backend = requires(B& b, std::size_t count, void (*f)(std::size_t)) {
  { b.kind() } -> std::convertible_to<BackendKind>;
  { b.threads() } -> std::convertible_to<std::size_t>;
  b.for_each(count, f);
};

/// Runs everything on the calling thread.
struct SerialBackend {
  BackendKind kind() const { return BackendKind::serial; }
  std::size_t threads() const { return 1; }
  template <class F>
  void for_each(std::size_t count, F&& f) {
    for (std::size_t i = 0; i < count; ++i) f(i);
  }
};

/// Type-erased backend for choosing serial/OpenMP/TBB at run time (one indirect call per
/// for_each, i.e. per iteration phase; the per-ant work inside stays static).
class AnyBackend {
 public:
  AnyBackend() : AnyBackend(SerialBackend{}) {}

  template <Backend B>
  requires(!std::same_as<std::remove_cvref_t<B>, AnyBackend>)
      AnyBackend(B backend)  // NOLINT(google-explicit-constructor): implicit by design
      : self_(std::make_shared<Model<B>>(std::move(backend))) {}

  BackendKind kind() const { return self_->kind(); }
  std::size_t threads() const { return self_->threads(); }
  template <class F>
  void for_each(std::size_t count, F&& f) {
    self_->for_each(count, std::function<void(std::size_t)>(std::ref(f)));
  }

 private:
  struct Concept {
    virtual ~Concept() = default;
    virtual BackendKind kind() const = 0;
    virtual std::size_t threads() const = 0;
    virtual void for_each(std::size_t count, const std::function<void(std::size_t)>& f) = 0;
  };
  template <class B>
  struct Model final : Concept {
    explicit Model(B b) : backend(std::move(b)) {}
    BackendKind kind() const override { return backend.kind(); }
    std::size_t threads() const override { return backend.threads(); }
    void for_each(std::size_t count, const std::function<void(std::size_t)>& f) override {
      backend.for_each(count, f);
    }
    B backend;
  };
  std::shared_ptr<Concept> self_;
};

}  // namespace antslam::aco
