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
// Only blocks of kLargeBlockBytes and more, each a mapping of its own
// (setUpLargeBlocks sets glibc's mapping threshold there) placed on a 2 MiB
// boundary: every 2 MiB of it can be one huge page. Smaller blocks share
// pages with others and are left as they are. This is the program's
// choice, not the libraries': they allocate with whatever operator new the
// program that links them has.
//
// Measured on that VM (docs/benchmarks.md): 1000 x 1000 `tsf gen` 12.6 ->
// 5.1-5.6 s and 862 -> 817 MB peak; page faults 590 000 -> 11 000.
//
// The heap's first 64 MiB is asked for huge pages as well, and every
// thread allocates from it (one arena): a 100 x 100 model's arrays are all
// below 4 MiB, and its checks' workers each grew an arena of their own,
// page by page (7 600 faults; 1 100 with the heap on huge pages and shared;
// 0.27 -> 0.21 s on that VM). The workers allocate outside their loops, so
// one arena costs them no waiting (malloc and free were 0.4 % of a
// 1000 x 1000 run's profile with it).
//
// Replacing the throwing operator new (and new[]) is enough: libstdc++'s
// nothrow and array forms call it, and its operator delete frees what
// malloc returned, as this operator new's blocks are.
#include "app/large_blocks.h"

#include <cstdlib>
#include <new>

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

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

namespace {
constexpr std::size_t kLargeBlockBytes = std::size_t(4) << 20;
// The heap's part kept on huge pages and never given back (bytes).
constexpr std::size_t kHeapOnHugePagesBytes = std::size_t(64) << 20;
}  // namespace

#ifndef TSF_SANITIZER_ALLOCATES
namespace {

constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

// A large block starts on a huge page's boundary and ends on one, and is
// advised as a whole: every 2 MiB of it can then be one huge page. (A block
// from plain malloc starts just past its header, so its first and last
// 2 MiB would fault page by page: about 512 faults a block, most of those
// left on a 1000 x 1000 model.) The rounding is address space; only the
// pages written are backed.
void* allocateLarge(std::size_t n) {
    const std::size_t rounded = (n + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    void* p = nullptr;
    if (rounded < n || ::posix_memalign(&p, kHugePageBytes, rounded) != 0) return nullptr;
    ::madvise(p, rounded, MADV_HUGEPAGE);  // a failure is only a lost hint
    return p;
}

void* allocate(std::size_t n) {
    if (n == 0) n = 1;
    for (;;) {
        // posix_memalign's blocks are freed by free(), as operator delete does.
        if (void* p = n >= kLargeBlockBytes ? allocateLarge(n) : std::malloc(n)) return p;
        std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

// The heap grown at once by kHeapOnHugePagesBytes (glibc's top pad: each
// growth by at least that much, and so much kept when it shrinks) and the
// new part advised as huge pages. The advice holds for that range of
// addresses only: later growth is plain pages, while the blocks that make
// a large model large take the path above.
void adviseHeapHugePages() {
    ::mallopt(M_ARENA_MAX, 1);
    ::mallopt(M_TOP_PAD, int(kHeapOnHugePagesBytes));
    const auto before = reinterpret_cast<std::uintptr_t>(::sbrk(0));
    void* volatile grow = std::malloc(std::size_t(1) << 20);  // volatile: a malloc and free pair may be elided
    std::free(grow);
    // Read after the free: freeing may have given back the block's own pages.
    const auto after = reinterpret_cast<std::uintptr_t>(::sbrk(0));
    const std::uintptr_t lo = (before + kHugePageBytes - 1) & ~std::uintptr_t(kHugePageBytes - 1);
    const std::uintptr_t hi = after & ~std::uintptr_t(kHugePageBytes - 1);
    if (before != std::uintptr_t(-1) && hi > lo)
        ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);  // a failure is only a lost hint
}

}  // namespace
#endif

namespace tsf::cli {

void setUpLargeBlocks() {
    // Large blocks mapped on their own (on huge pages, above) and unmapped
    // when freed; the heap keeps the small ones, its top given back only
    // past 64 MiB free (glibc's default gives back past 128 KiB, and the
    // pages then fault again).
    ::mallopt(M_MMAP_THRESHOLD, int(kLargeBlockBytes));
    ::mallopt(M_TRIM_THRESHOLD, int(kHeapOnHugePagesBytes));
#ifndef TSF_SANITIZER_ALLOCATES
    adviseHeapHugePages();
#endif
}

}  // namespace tsf::cli

#ifndef TSF_SANITIZER_ALLOCATES
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
#endif
