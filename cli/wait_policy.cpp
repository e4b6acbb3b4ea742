#include "wait_policy.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace fieldcvt::cli {

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

bool spinningFits(int others, int threads, int cores)
{
    if (others < 0 || threads < 1 || cores < 1) return false;
    return others + threads <= cores;
}

bool threadsMaySpinNow(int threads, int cores)
{
    for (int look = 0; look < 5; ++look) {
        if (look > 0) usleep(1000);
        int others = -1;
        if (FILE* f = std::fopen("/proc/loadavg", "r")) {
            char line[256] = {0};
            if (std::fgets(line, sizeof line, f)) others = otherRunnableTasks(line);
            std::fclose(f);
        }
        if (others < 0) return false;  // no load to read: sleep
        if (spinningFits(others, threads, cores)) return true;
    }
    return false;
}

int requestedThreads(int argc, char** argv, int cores)
{
    int threads = 0;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::strcmp(argv[i], "--threads") == 0) threads = std::atoi(argv[i + 1]);
    return threads > 0 ? threads : cores;
}

}  // namespace fieldcvt::cli
