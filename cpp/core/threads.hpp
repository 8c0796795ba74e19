// The OpenMP thread count and index, 1 and 0 in a build without OpenMP: per-thread copies of
// OpenCASCADE query objects (not thread-safe when shared) are indexed by them.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <functional>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace hexlayer {

inline int threadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

inline int threadIndex() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

// An exception thrown in an OpenMP loop's body cannot leave the parallel region: the runtime calls std::terminate, an
// abort that takes FreeCAD down with it (seen: OpenCASCADE's line-face intersector throwing Standard_NullObject on a
// B-spline face while the tets were classified). Each body runs in `run`, which keeps the first exception thrown
// (any type: OpenCASCADE's Standard_Failure is not a std::exception) and lets the loop finish; `rethrow`, after the
// loop, throws it where the caller can catch it.
class ParallelErrors {
 public:
  template <class Body>
  void run(Body&& body) noexcept {
    try {
      body();
    } catch (...) {
#pragma omp critical(hexlayer_parallel_errors)
      if (!first_) first_ = std::current_exception();
    }
  }
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::exception_ptr first_;
};

// Runs jobs that do not depend on each other side by side: as OpenMP tasks of the enclosing parallel region (a job's
// own parallel loops then run on its thread alone), or of a region of their own; the first job on this thread. After
// all have run, throws the exception of the first job, in their order, that threw one (the same whatever finished
// first). [in] jobs.
inline void sideBySide(const std::vector<std::function<void()>>& jobs) {
  std::vector<std::exception_ptr> failed(jobs.size());
  auto runOne = [&](std::size_t k) {
    try {
      jobs[k]();
    } catch (...) {
      failed[k] = std::current_exception();
    }
  };
  auto runAll = [&] {
    for (std::size_t k = 1; k < jobs.size(); ++k) {
#pragma omp task default(shared) firstprivate(k)
      runOne(k);
    }
    if (!jobs.empty()) runOne(0);
#pragma omp taskwait
  };
#ifdef _OPENMP
  if (omp_in_parallel()) {
    runAll();
  } else {
#pragma omp parallel
#pragma omp single
    runAll();
  }
#else
  runAll();
#endif
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

// What body(i) gives for each i in [0, n), the items found independently of each other side by side, joined in the
// order of i: the same on any number of threads. [in] n; [in] body(i): a vector of items. Returns them all.
template <class Body>
auto joinedInOrder(int n, Body body) {
  std::vector<decltype(body(0))> each(static_cast<std::size_t>(std::max(n, 0)));
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < n; ++i) errors.run([&] { each[i] = body(i); });
  errors.rethrow();
  decltype(body(0)) all;
  for (auto& items : each) all.insert(all.end(), items.begin(), items.end());
  return all;
}

}  // namespace hexlayer
