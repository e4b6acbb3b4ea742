#pragma once
// Two serial jobs at once on two threads (internal to the remesh stages).
#include <omp.h>

#include <exception>

namespace fieldcvt {

// `first` on the calling thread and `second` on another one at the same time (when `together`
// and there are threads; else one after the other), for two serial jobs that do not depend on
// each other. An exception of either is rethrown once both are done (first's if both throw).
template <class First, class Second>
void sideBySide(bool together, First&& first, Second&& second)
{
    std::exception_ptr failures[2];
#pragma omp parallel num_threads(2) if (together && omp_get_max_threads() > 1)
    {
        const int thread = omp_get_thread_num();
        const bool alone = omp_get_num_threads() == 1;
        try {
            if (thread == 0) first();
        } catch (...) {
            failures[0] = std::current_exception();
        }
        try {
            if (thread == 1 || (alone && !failures[0])) second();
        } catch (...) {
            failures[1] = std::current_exception();
        }
    }
    for (const std::exception_ptr& failure : failures)
        if (failure) std::rethrow_exception(failure);
}

}  // namespace fieldcvt
