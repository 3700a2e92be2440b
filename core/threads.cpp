#include "core/threads.hpp"

#include <omp.h>
#include <stdexcept>

namespace revsph {

void set_thread_count(int threads) {
  if (threads < 1) {
    throw std::invalid_argument("the thread count must be at least 1");
  }
  omp_set_num_threads(threads);
}

int thread_count() {
  return omp_get_max_threads();
}

} // namespace revsph
