// Replaces every global allocation function (operator new/delete in all forms; malloc, calloc,
// realloc, free, aligned_alloc, posix_memalign, memalign, valloc, pvalloc, forwarding to glibc's
// __libc_* functions) and pthread_mutex_lock for the executable it is linked into, and counts
// the calls made on a thread while an AllocationGuard (allocation_counter.hpp) is alive there.
// Libraries the executable loads (a plugin through dlopen) call these too.
#include "support/allocation_counter.hpp"

#include <dlfcn.h>
#include <pthread.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <new>

extern "C" {
void* __libc_malloc(size_t size);
void* __libc_calloc(size_t count, size_t size);
void* __libc_realloc(void* pointer, size_t size);
void __libc_free(void* pointer);
void* __libc_memalign(size_t alignment, size_t size);
void* __libc_valloc(size_t size);
void* __libc_pvalloc(size_t size);
}

namespace tactus::test {

constinit thread_local bool t_guarded = false;
std::atomic<long> g_allocator_calls{0};
std::atomic<long> g_mutex_locks{0};

void reset_counts() {
    g_allocator_calls = 0;
    g_mutex_locks = 0;
}

}  // namespace tactus::test

namespace {

using tactus::test::g_allocator_calls;
using tactus::test::g_mutex_locks;
using tactus::test::t_guarded;

inline void note_allocator_call() {
    if (t_guarded) g_allocator_calls.fetch_add(1, std::memory_order_relaxed);
}

void* allocate_or_throw(size_t size) {
    note_allocator_call();
    if (void* p = __libc_malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* allocate_aligned_or_throw(size_t size, std::align_val_t alignment) {
    note_allocator_call();
    if (void* p = __libc_memalign(static_cast<size_t>(alignment), size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void release(void* pointer) {
    note_allocator_call();
    __libc_free(pointer);
}

using LockFunction = int (*)(pthread_mutex_t*);
std::atomic<LockFunction> g_real_lock{nullptr};

}  // namespace

// ---- C allocation functions ----
extern "C" {
void* malloc(size_t size) noexcept {
    note_allocator_call();
    return __libc_malloc(size);
}
void* calloc(size_t count, size_t size) noexcept {
    note_allocator_call();
    return __libc_calloc(count, size);
}
void* realloc(void* pointer, size_t size) noexcept {
    note_allocator_call();
    return __libc_realloc(pointer, size);
}
void free(void* pointer) noexcept {
    note_allocator_call();
    __libc_free(pointer);
}
void* aligned_alloc(size_t alignment, size_t size) noexcept {
    note_allocator_call();
    return __libc_memalign(alignment, size);
}
void* memalign(size_t alignment, size_t size) noexcept {
    note_allocator_call();
    return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, size_t alignment, size_t size) noexcept {
    note_allocator_call();
    if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
    void* p = __libc_memalign(alignment, size);
    if (!p) return ENOMEM;
    *out = p;
    return 0;
}
void* valloc(size_t size) noexcept {
    note_allocator_call();
    return __libc_valloc(size);
}
void* pvalloc(size_t size) noexcept {
    note_allocator_call();
    return __libc_pvalloc(size);
}

int pthread_mutex_lock(pthread_mutex_t* mutex) noexcept {
    if (t_guarded) g_mutex_locks.fetch_add(1, std::memory_order_relaxed);
    LockFunction real = g_real_lock.load(std::memory_order_acquire);
    if (!real) {
        real = reinterpret_cast<LockFunction>(dlsym(RTLD_NEXT, "pthread_mutex_lock"));
        g_real_lock.store(real, std::memory_order_release);
    }
    return real(mutex);
}
}

// ---- C++ allocation functions, every replaceable form ----
void* operator new(size_t size) {
    return allocate_or_throw(size);
}
void* operator new[](size_t size) {
    return allocate_or_throw(size);
}
void* operator new(size_t size, const std::nothrow_t&) noexcept {
    note_allocator_call();
    return __libc_malloc(size == 0 ? 1 : size);
}
void* operator new[](size_t size, const std::nothrow_t&) noexcept {
    note_allocator_call();
    return __libc_malloc(size == 0 ? 1 : size);
}
void* operator new(size_t size, std::align_val_t alignment) {
    return allocate_aligned_or_throw(size, alignment);
}
void* operator new[](size_t size, std::align_val_t alignment) {
    return allocate_aligned_or_throw(size, alignment);
}
void* operator new(size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    note_allocator_call();
    return __libc_memalign(static_cast<size_t>(alignment), size == 0 ? 1 : size);
}
void* operator new[](size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    note_allocator_call();
    return __libc_memalign(static_cast<size_t>(alignment), size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept {
    release(p);
}
void operator delete[](void* p) noexcept {
    release(p);
}
void operator delete(void* p, size_t) noexcept {
    release(p);
}
void operator delete[](void* p, size_t) noexcept {
    release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
