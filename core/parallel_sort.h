#pragma once
// A sort on the run's OpenMP threads: libstdc++'s parallel mode (a multiway merge sort, from
// 1 000 elements) where the standard library has it, std::sort elsewhere. For orders without
// ties only: every correct sort then gives the same sequence, whatever the thread count.
#if __has_include(<parallel/algorithm>)
#include <parallel/algorithm>
#define FCVT_GNU_PARALLEL_SORT 1
#endif
#include <algorithm>

namespace fieldcvt {

template <class Iterator, class Less>
void parallelSort(Iterator first, Iterator last, Less less)
{
#ifdef FCVT_GNU_PARALLEL_SORT
    __gnu_parallel::sort(first, last, less);
#else
    std::sort(first, last, less);
#endif
}

}  // namespace fieldcvt
