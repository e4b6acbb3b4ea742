#pragma once
// How the CLI's idle OpenMP threads wait (issue 12): spinning briefly when the machine has a core
// for each of them, sleeping at once when other work competes for the cores.
#include <string>

namespace fieldcvt::cli {

//! The tasks runnable right now besides the reader, from the text of /proc/loadavg ("0.10 0.20
//! 0.30 R/T PID": R counts the running and runnable tasks, the reader included); -1 when the
//! text is not in that form.
int otherRunnableTasks(const std::string& loadavg);

//! Whether idle threads may spin (libgomp's default: GOMP_SPINCOUNT 300 000, then sleep): only
//! when `threads` OpenMP threads and the `others` other runnable tasks fit on `cores` cores. An
//! unknown load (others < 0) sleeps.
bool spinningFits(int others, int threads, int cores);

//! Whether `threads` OpenMP threads may spin on this machine now: spinningFits with the
//! /proc/loadavg's runnable tasks, looked at up to 5 times 1 ms apart (the process that started
//! this one is often still runnable at the first look; a competing busy task is at every one).
//! False when the load cannot be read.
bool threadsMaySpinNow(int threads, int cores);

//! The OpenMP thread count a command line asks for: the value after "--threads" (0 or absent:
//! one per core).
int requestedThreads(int argc, char** argv, int cores);

}  // namespace fieldcvt::cli
