#pragma once
// How many OpenMP threads a run takes: one per core that no other task holds. Idle OpenMP
// threads spin at barriers (libgomp's default); where another task wants the same core, a
// spinning thread holds it while the thread with work waits for a time slice, at every barrier
// (docs/tuning.md, "Thread budget"). The output does not depend on the thread count.
#include <string>

namespace fieldcvt {

//! The tasks runnable right now besides the reader, from the text of /proc/loadavg ("0.10 0.20
//! 0.30 R/T PID": R counts the running and runnable tasks, the reader included); -1 when the
//! text is not in that form.
int otherRunnableTasks(const std::string& loadavg);

//! Threads for `requested` on `cores` cores while `others` other tasks are runnable: a count
//! asked for (> 0) as it is; 0 (one per free core) the cores the others leave, at least 1; all
//! cores when the load is unknown (others < 0).
int threadsForLoad(int requested, int cores, int others);

//! threadsForLoad on this machine now: the cores this process may run on, and the fewest other
//! runnable tasks of up to 5 looks at /proc/loadavg 1 ms apart (a process that started this
//! one, or a short job, is often runnable at the first look; a competing busy task at every one).
int threadsForThisMachine(int requested);

//! A parameter's thread count for an OpenMP loop: `requested` (> 0) as it is, else OpenMP's
//! default (1 without OpenMP).
int openMpThreads(int requested);

}  // namespace fieldcvt
