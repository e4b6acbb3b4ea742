// `fcvt`: field-aligned CVT remeshing from the command line. Every failure ends as exactly one
// line "fcvt: error: <message>" on stderr: exit code 2 for usage errors, 1 for the rest.
#include "arguments.h"
#include "commands.h"
#include "errors.h"
#include "wait_policy.h"

#include <malloc.h>
#include <sched.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace {

const char* const usage =
    "Usage: fcvt <command> [options]\n"
    "\n"
    "Field-aligned CVT isotropic remeshing of triangle meshes (PLY, OBJ, OFF, STL).\n"
    "\n"
    "Commands:\n"
    "  remesh IN OUT --vertices N [options]   remesh IN into OUT with about N vertices\n"
    "  field IN OUT.ply [options]             the 6-RoSy direction field of IN and its singularities\n"
    "  compare IN --vertices N [options]      CVT vs FCVT on IN, one row per method (paper's Table 2)\n"
    "  metrics MESH [--ref INPUT] [--json]    quality metrics and topology of a mesh\n"
    "  convert IN OUT                         IN in OUT's format (by extension), after remesh's input checks\n"
    "\n"
    "Options:\n"
    "  -h, --help     show this help; 'fcvt <command> --help' shows a command's options\n"
    "  --version      print the version\n"
    "\n"
    "Exit status: 0 success, 1 runtime error, 2 usage error.\n";

//! One line, whatever the exception text holds.
void printError(std::string message)
{
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "fcvt: error: %s\n", fieldcvt::escapeControlCharacters(message).c_str());
}

int run(const std::vector<std::string>& args)
{
    using namespace fieldcvt::cli;
    if (args.empty()) throw UsageError("no command given (try 'fcvt --help')");
    const std::string& command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(usage, stdout);
        return 0;
    }
    if (command == "--version") {
        std::printf("fcvt %s\n", FCVT_VERSION);
        return 0;
    }
    if (command == "remesh") return runRemesh(rest);
    if (command == "metrics") return runMetrics(rest);
    if (command == "field") return runField(rest);
    if (command == "compare") return runCompare(rest);
    if (command == "convert") return runConvert(rest);
    throw UsageError("unknown command '" + command + "' (try 'fcvt --help')");
}

//! The settings the C library and libgomp read as they load, before main: set here, then the
//! same program runs again (a variable the user set is kept).
//! - GLIBC_TUNABLES=glibc.malloc.hugetlb=1: the heap in transparent huge pages where the kernel
//!   offers them on request (Debian's default, "madvise"): bunny 5000 11 400 -> 2 800 minor page
//!   faults; whole commands, medians of 7 alternating (issue 12, 2 threads): mask 4000 1.07 ->
//!   0.94 s, fandisk 5000 1.13 -> 1.03 s, fertility 7000 1.21 -> 1.10 s, bunny 5000 1.27 ->
//!   1.23 s, nefertiti 10000 2.16 -> 2.11 s, torus 1000 the same.
//! - How idle OpenMP threads wait. On a machine with a free core per thread they spin up to
//!   libgomp's default count (GOMP_SPINCOUNT 300 000), then sleep: a sleeping thread takes ~0.2 ms
//!   to wake on these virtual machines, at every parallel region and barrier (medians of 7 / 5:
//!   torus 1000 0.31 s sleeping against 0.28 s spinning, bunny 5000 1.38 against 1.30-1.33 s).
//!   Where other tasks are runnable as the command starts (5 looks, 1 ms apart) they sleep at once
//!   (OMP_WAIT_POLICY=PASSIVE, spin count 0): a spinning thread holds its core while the one with
//!   work waits for a time slice at every barrier (the same machine with one busy process beside:
//!   torus 0.38 s sleeping against 0.58-1.07 s spinning, bunny 2.2 against 2.9-4.8 s; in an
//!   earlier, busier run torus 3.4 against 14.8 s). The outputs are the same bytes either way.
void chooseRuntimeSettings(int argc, char** argv)
{
    using namespace fieldcvt::cli;
    bool changed = false;
    if (!std::getenv("GLIBC_TUNABLES")) changed = setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) == 0;
    if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT")) {
        cpu_set_t set;
        const int cores = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
        const bool spin = threadsMaySpinNow(requestedThreads(argc, argv, cores), cores);
        // The spin count written out (libgomp's default) so that the run below does not decide again.
        changed = (spin ? setenv("GOMP_SPINCOUNT", "300000", 1) : setenv("OMP_WAIT_POLICY", "PASSIVE", 1)) == 0 || changed;
    }
    if (changed) execv("/proc/self/exe", argv);  // returns only on failure: go on as we are
}

//! The heap grows and shrinks by 64 MB at a time instead of glibc's 128 kB: the optimisation
//! allocates and frees buffers of a few hundred kB to a few MB every evaluation, and each
//! shrink returned pages that the next evaluation faulted in again, zeroed by the kernel.
//! Measured (issue 12, bunny 5000, 2 threads, 5 alternating whole commands): 15 900 minor page
//! faults and a median of 1.58 s against 11 100 and 1.48 s. A process-wide setting, so the CLI
//! makes it and the MeshLab plugin (a guest in MeshLab's process) does not.
void keepHeapPadding() { mallopt(M_TOP_PAD, 64 << 20); }

}  // namespace

int main(int argc, char** argv)
{
    chooseRuntimeSettings(argc, argv);
    keepHeapPadding();
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const fieldcvt::cli::UsageError& e) {
        printError(e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        printError("out of memory");
        return 1;
    } catch (const std::exception& e) {
        printError(e.what());
        return 1;
    } catch (...) {
        printError("unexpected internal error");
        return 1;
    }
}
