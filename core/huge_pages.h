#pragma once
// Transparent huge pages for the run's memory, asked for in-process so that the MeshLab filter
// gets them as the CLI does (issue 31 item 5). Where the kernel gives huge pages only on request
// (Debian's default, THP "madvise"), the hot loops' random reads over the surface, the cells and
// the neighbour lists miss the TLB far less in 2 MB pages: whole commands 5-10 % faster
// (docs/measurements.md, "Huge pages in-process"). The output does not depend on it.

namespace fieldcvt {

//! Marks the process's anonymous private memory of at least one 2 MB page (the heap, malloc's
//! arenas and mapped blocks, their reserved parts) with madvise(MADV_HUGEPAGE): pages touched
//! after the call come as huge pages where 2 MB of a mapping are still untouched. remesh() calls
//! it before each stage, so that what the last stage added is covered. Returns the bytes marked;
//! 0 where the kernel has no such advice or /proc/self/maps cannot be read.
long long adviseHugePages();

//! While alive, malloc keeps room to grow: the heap grows by at least 64 MiB at a time
//! (M_TOP_PAD) and blocks up to 32 MiB come from it rather than from their own mappings
//! (M_MMAP_THRESHOLD), so the memory a stage is about to use is mostly mapped, untouched, when
//! adviseHugePages() marks it. Nested scopes are allowed; the outermost gives back glibc's
//! default top pad (128 KiB) when it ends (the threshold stays at 32 MiB, the largest glibc's own
//! dynamic threshold reaches). Marks the memory there is when it starts.
class HugePageHeap {
public:
    HugePageHeap();
    ~HugePageHeap();
    HugePageHeap(const HugePageHeap&) = delete;
    HugePageHeap& operator=(const HugePageHeap&) = delete;
};

}  // namespace fieldcvt
