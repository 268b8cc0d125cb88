#include "allocation_counter.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>

// ThreadSanitizer's runtime defines operator new and delete itself, in archives the driver links
// whole and ahead of every object file, so a replacement here would never be called (the
// counter counted nothing under TSan). There the runtime's allocation hook counts instead: every
// heap allocation, malloc included, a stricter count than operator new's.
#if defined(__SANITIZE_THREAD__)
#define INTERPLAY_COUNT_BY_HOOK 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define INTERPLAY_COUNT_BY_HOOK 1
#endif
#endif
#ifdef INTERPLAY_COUNT_BY_HOOK
#include <sanitizer/allocator_interface.h>
#endif

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};

void count() {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
}

#ifdef INTERPLAY_COUNT_BY_HOOK
void onAllocation(const volatile void*, std::size_t) { count(); }
void onFree(const volatile void*) {}
[[maybe_unused]] const int hookInstalled = __sanitizer_install_malloc_and_free_hooks(onAllocation, onFree);
#else
void* allocate(std::size_t size) {
    count();
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* allocateAligned(std::size_t size, std::align_val_t alignment) {
    count();
    const auto align = static_cast<std::size_t>(alignment);
    const std::size_t rounded = (std::max<std::size_t>(size, 1) + align - 1) / align * align;
    if (void* p = std::aligned_alloc(align, rounded)) return p;
    throw std::bad_alloc();
}
#endif

}  // namespace

namespace test_support {

void startCountingAllocations() {
    allocations = 0;
    counting = true;
}

std::size_t stopCountingAllocations() {
    counting = false;
    return allocations.load();
}

}  // namespace test_support

#ifndef INTERPLAY_COUNT_BY_HOOK

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, std::align_val_t alignment) { return allocateAligned(size, alignment); }
void* operator new[](std::size_t size, std::align_val_t alignment) { return allocateAligned(size, alignment); }
// The nothrow forms too: std::stable_sort's temporary buffer uses them, and without these a
// sanitizer runtime's own nothrow new would hand out memory that the delete below frees with free().
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    count();
    return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    try {
        return allocateAligned(size, alignment);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t& tag) noexcept {
    return operator new(size, alignment, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
#endif  // INTERPLAY_COUNT_BY_HOOK
