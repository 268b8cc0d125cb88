#pragma once
// The allocator of a step's large arrays (the solver's batches, the contact records). Two things
// make a world's first step of a large scene cheaper (pyramid20 on this project's 2-core VM:
// 105-140 ms, most of it page faults, against 12 for a later step; 45-70 ms with both):
// - Growing the vector leaves new elements default-initialised (for trivial types: unwritten), so
//   the threads that fill them in parallel write, and fault in, their pages first; the caller no
//   longer zeroes megabytes one page after another before that.
// - Arrays of kHugePageBytes or more start on such a boundary and are offered to the kernel for
//   transparent huge pages: one fault each 2 MiB, not each 4 KiB. In Linux's "madvise" THP mode
//   (Debian's) only advised memory gets them; where THP is off the advice changes nothing.

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

#include <stdlib.h>  // posix_memalign
#include <sys/mman.h>

namespace simcore {

template <class T>
class LargeArrayAllocator : public std::allocator<T> {
public:
    static constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

    template <class U>
    struct rebind {
        using other = LargeArrayAllocator<U>;
    };
    LargeArrayAllocator() = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (!huge(n)) return std::allocator<T>::allocate(n);
        void* memory = nullptr;
        if (posix_memalign(&memory, kHugePageBytes, n * sizeof(T)) != 0) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
        madvise(memory, n * sizeof(T), MADV_HUGEPAGE);  // advice only: without THP the pages stay small
#endif
        return static_cast<T*>(memory);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (huge(n))
            std::free(p);
        else
            std::allocator<T>::deallocate(p, n);
    }

    // Default-initialises where a vector would value-initialise (resize(n), emplace_back()); with
    // arguments, std::allocator_traits constructs as usual.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }

private:
    static bool huge(std::size_t n) { return n >= kHugePageBytes / sizeof(T); }
};

template <class T, class U>
bool operator==(const LargeArrayAllocator<T>&, const LargeArrayAllocator<U>&) noexcept {
    return true;
}

}  // namespace simcore
