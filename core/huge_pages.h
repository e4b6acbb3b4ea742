#pragma once
// Transparent huge pages for the run's memory, asked for in-process so that the MeshLab filter
// gets them as the CLI does. Where the kernel gives huge pages only on request
// (Debian's default, THP "madvise"), the hot loops' random reads over the surface, the cells and
// the neighbour lists miss the TLB far less in 2 MB pages: whole commands 5-10 % faster
// (docs/measurements.md, "Huge pages in-process"). The output does not depend on it.

#include <cstddef>

namespace fieldcvt {

//! Marks the process's anonymous private memory of at least one 2 MB page (the heap, malloc's
//! arenas and mapped blocks, their reserved parts; adjacent mappings as one range, so that a
//! part under 2 MB between two others is marked too) with madvise(MADV_HUGEPAGE): pages touched
//! after the call come as huge pages where 2 MB of a mapping are still untouched. remesh() calls
//! it before each stage (through adviseNewHugePages), so that what the last stage added is
//! covered. Returns the bytes marked; 0 where the kernel has no such advice or /proc/self/maps
//! cannot be read.
long long adviseHugePages();

//! adviseHugePages(), but only when malloc holds at least 2 MB more memory from the system
//! (heap, arenas, mapped blocks: mallinfo2) than when it last marked; returns -1 when it
//! skipped (never where the allocator reports nothing to mallinfo2, e.g. AddressSanitizer's).
//! Reading /proc/self/maps costs up to a millisecond inside MeshLab, paid before each stage
//! (docs/tuning.md, "Huge pages and free memory").
long long adviseNewHugePages();

//! Gives the free memory inside malloc's heap back to the system when it holds at least `atLeast`
//! bytes free below its top (the room kept at the top stays: HugePageHeap's pad, marked) (glibc's mallinfo2 and malloc_trim; nothing elsewhere): blocks under the 32 MiB
//! mapping threshold (HugePageHeap) that a stage freed would otherwise stay resident while the
//! next stages allocate more (docs/tuning.md, "Memory of the diagram"). remesh() calls it before
//! each stage. Returns whether it trimmed.
bool releaseFreeMemory(std::size_t atLeast = std::size_t(32) << 20);

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
