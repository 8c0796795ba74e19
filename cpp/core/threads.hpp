// The OpenMP thread count and index, 1 and 0 in a build without OpenMP: per-thread copies of
// OpenCASCADE query objects (not thread-safe when shared) are indexed by them.
#pragma once
#include <exception>
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

}  // namespace hexlayer
