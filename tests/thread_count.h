#pragma once
// Runs a computation on a given OpenMP thread count and restores the caller's: the tests that
// check a result does not depend on the threads.
#include <omp.h>

namespace testthreads {

template <class F>
auto withThreadCount(int threads, F&& f)
{
    struct Restore {
        int saved = omp_get_max_threads();
        ~Restore() { omp_set_num_threads(saved); }
    } restore;
    omp_set_num_threads(threads);
    return f();
}

}  // namespace testthreads
