// The OpenMP thread count and index, 1 and 0 in a build without OpenMP: per-thread copies of
// OpenCASCADE query objects (not thread-safe when shared) are indexed by them.
#pragma once
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

}  // namespace hexlayer
