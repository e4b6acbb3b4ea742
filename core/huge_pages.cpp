#include "huge_pages.h"

#include <malloc.h>
#include <sys/mman.h>

#include <algorithm>
#include <cinttypes>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace fieldcvt {

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

std::mutex heapMutex;
int heapScopes = 0;  // HugePageHeap scopes alive, guarded by heapMutex

//! One line of /proc/self/maps is anonymous private memory: the heap, or an unnamed mapping
//! (malloc's arenas and blocks, readable-writable or still reserved; "[anon:...]" where an allocator
//! names its mappings), never the stack or a file.
bool isAnonymousPrivate(const char* perms, unsigned long long inode, const char* name)
{
    if (inode != 0) return false;
    if (std::strcmp(perms, "rw-p") != 0 && std::strcmp(perms, "---p") != 0) return false;
    return *name == '\n' || *name == '\0' || std::strncmp(name, "[heap]", 6) == 0 || std::strncmp(name, "[anon:", 6) == 0;
}

}  // namespace

long long adviseHugePages()
{
#ifdef MADV_HUGEPAGE
    std::FILE* maps = std::fopen("/proc/self/maps", "r");
    if (!maps) return 0;
    long long marked = 0;
    // Adjacent anonymous mappings are marked as one range: the heap is often several mappings
    // (its parts marked earlier, the part it grew by since), and a part under 2 MB between them
    // would otherwise never be marked, nor merge with its neighbours into huge pages.
    std::uintptr_t runBegin = 0, runEnd = 0;
    auto markRun = [&] {
        const std::uintptr_t first = (runBegin + kHugePage - 1) & ~(kHugePage - 1);
        const std::uintptr_t last = runEnd & ~(kHugePage - 1);
        if (last > first && madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE) == 0)
            marked += static_cast<long long>(last - first);
    };
    char line[512];
    while (std::fgets(line, sizeof line, maps)) {
        // A mapped file's line names it by its path: most lines where libraries are many, skipped
        // before the parse (docs/tuning.md, "Huge pages and free memory").
        if (std::strchr(line, '/') != nullptr) continue;
        std::uintptr_t begin = 0, end = 0;
        char perms[8] = {}, device[16] = {};
        unsigned long long offset = 0, inode = 0;
        int nameAt = 0;
        if (std::sscanf(line, "%" SCNxPTR "-%" SCNxPTR " %7s %llx %15s %llu %n", &begin, &end, perms, &offset, device, &inode,
                        &nameAt) < 6)
            continue;
        if (!isAnonymousPrivate(perms, inode, line + nameAt)) continue;
        if (begin == runEnd && runEnd != 0) {
            runEnd = end;
            continue;
        }
        markRun();
        runBegin = begin, runEnd = end;
    }
    markRun();
    std::fclose(maps);
    return marked;
#else
    return 0;
#endif
}

long long adviseNewHugePages()
{
    static std::mutex mutex;
    static std::size_t markedAt = 0;  // what malloc held from the system at the last marking
    const struct mallinfo2 info = mallinfo2();
    const std::size_t held = info.arena + info.hblkhd;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (markedAt != 0 && held < markedAt + kHugePage) {
            markedAt = std::min(markedAt, held);  // given back (trimmed): growth counts from here
            return -1;
        }
        markedAt = held;
    }
    return adviseHugePages();
}

bool releaseFreeMemory(std::size_t atLeast)
{
#if defined(__GLIBC__)
    // Free memory inside the heap, not the room kept at its top (keepcost: HugePageHeap's 64 MiB
    // pad, already marked for huge pages); malloc_trim keeps that room as it is.
    const struct mallinfo2 info = mallinfo2();
    if (info.fordblks - std::min(info.fordblks, info.keepcost) < atLeast) return false;
    return malloc_trim(info.keepcost) != 0;
#else
    (void)atLeast;
    return false;
#endif
}

HugePageHeap::HugePageHeap()
{
    {
        const std::lock_guard<std::mutex> lock(heapMutex);
        if (heapScopes++ == 0) {
            mallopt(M_MMAP_THRESHOLD, 32 << 20);
            mallopt(M_TOP_PAD, 64 << 20);
            std::free(std::malloc(256 << 10));  // grows the heap now, by the new pad
        }
    }
    adviseHugePages();
}

HugePageHeap::~HugePageHeap()
{
    const std::lock_guard<std::mutex> lock(heapMutex);
    if (--heapScopes == 0) mallopt(M_TOP_PAD, 128 << 10);
}

}  // namespace fieldcvt
