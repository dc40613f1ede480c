// The tsf program's operator new: large blocks on transparent huge pages.
//
// Why: a model's arrays are large and short-lived (a 1000 x 1000 model's
// positions, triangles, column grid and check tables: hundreds of MB, each
// written once soon after it is allocated). Every 4 KiB page of them costs
// a page fault on first touch; on a virtual machine a fault is expensive
// (on the 2-core VM of docs/benchmarks.md the kernel's share was 4.6 s of a
// 10.9 s `tsf gen` at 1000 x 1000). A block asked for huge pages
// (madvise MADV_HUGEPAGE) faults once per 2 MiB. Linux honours the advice
// when /sys/kernel/mm/transparent_hugepage/enabled is "madvise" (a common
// default) or "always"; with "never", or elsewhere, it changes nothing.
//
// Only blocks of kLargeBlockBytes and more: glibc serves those with a
// mapping of their own (or from a freed region of the heap), and the kernel
// places a fresh mapping of 2 MiB or more on a 2 MiB boundary. Smaller
// blocks share pages with others and are left as they are. This is the
// program's choice, not the libraries': they allocate with whatever
// operator new the program that links them has.
//
// setUpLargeBlocks (main calls it first) keeps freed memory in the process
// for the next block rather than handing it back to the kernel at once,
// whose pages would fault again when the next stage asks for as much.
//
// Replacing the throwing operator new (and new[]) is enough: libstdc++'s
// nothrow and array forms call it, and its operator delete frees what
// malloc returned, as this operator new's blocks are.
#include "app/large_blocks.h"

#include <cstdint>
#include <cstdlib>
#include <new>

#include <malloc.h>
#include <sys/mman.h>

// Under a sanitizer the sanitizer's own operator new stays: it checks that
// what new allocated is freed by delete, which a malloc'd block is not.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define TSF_SANITIZER_ALLOCATES 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TSF_SANITIZER_ALLOCATES 1
#endif

#ifndef TSF_SANITIZER_ALLOCATES
namespace {

constexpr std::size_t kLargeBlockBytes = std::size_t(4) << 20;
constexpr std::uintptr_t kPageBytes = 4096;

void* allocate(std::size_t n) {
    if (n == 0) n = 1;
    for (;;) {
        if (void* p = std::malloc(n)) {
            if (n >= kLargeBlockBytes) {
                // Every page the block touches, its first one included:
                // malloc's header sits at the start of the block's own mapping,
                // and a first page left out would split that mapping and cost
                // the whole first 2 MiB its huge page. The advice only says how
                // to back the pages; a neighbour's page sharing it loses
                // nothing, and a failure is only a lost hint.
                const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p) & ~(kPageBytes - 1);
                const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + n + kPageBytes - 1) & ~(kPageBytes - 1);
                if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
            }
            return p;
        }
        std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

}  // namespace
#endif

namespace tsf::cli {

void setUpLargeBlocks() {
    // Blocks up to 32 MiB (glibc's largest threshold) from the heap, reused
    // once freed; the heap's top given back only past 1 GiB free. The peak
    // is where it was (the stages free before the next allocates); what
    // stays is memory the process had already touched.
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace tsf::cli

#ifndef TSF_SANITIZER_ALLOCATES
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
#endif
