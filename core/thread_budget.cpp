#include "thread_budget.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#include <unistd.h>
#endif

namespace fieldcvt {

int otherRunnableTasks(const std::string& loadavg)
{
    std::istringstream in(loadavg);
    double load1 = 0, load5 = 0, load15 = 0;
    std::string tasks;
    if (!(in >> load1 >> load5 >> load15 >> tasks)) return -1;
    const size_t slash = tasks.find('/');
    if (slash == std::string::npos || slash == 0) return -1;
    char* end = nullptr;
    const long runnable = std::strtol(tasks.c_str(), &end, 10);
    if (end != tasks.c_str() + slash || runnable < 1) return -1;
    return static_cast<int>(runnable - 1);
}

int threadsForLoad(int requested, int cores, int others)
{
    if (requested > 0) return requested;
    cores = std::max(cores, 1);
    if (others < 0) return cores;
    return std::clamp(cores - others, 1, cores);
}

int threadsForThisMachine(int requested)
{
    if (requested > 0) return requested;
    int cores = static_cast<int>(std::thread::hardware_concurrency());
#if defined(__linux__)
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) cores = CPU_COUNT(&set);
    int fewest = -1;
    for (int look = 0; look < 5; ++look) {
        if (look > 0) usleep(1000);
        int others = -1;
        if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
            char line[256] = {0};
            if (std::fgets(line, sizeof line, f)) others = otherRunnableTasks(line);
            std::fclose(f);
        }
        if (others < 0) break;
        fewest = fewest < 0 ? others : std::min(fewest, others);
        if (fewest == 0) break;  // every core is free
    }
    return threadsForLoad(requested, cores, fewest);
#else
    return threadsForLoad(requested, cores, -1);
#endif
}

int openMpThreads(int requested)
{
#ifdef _OPENMP
    return requested > 0 ? requested : omp_get_max_threads();
#else
    (void)requested;
    return 1;
#endif
}

}  // namespace fieldcvt
