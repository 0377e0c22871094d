// Counts allocator calls and mutex locks made on a thread while a Guard is alive on it
// (allocation_counter.cpp replaces the allocation functions and pthread_mutex_lock of the
// executable it is linked into): the real-time tests' proof that process() never allocates
// or locks.
#pragma once

#include <atomic>

namespace tactus::test {

extern constinit thread_local bool t_guarded;
extern std::atomic<long> g_allocator_calls;
extern std::atomic<long> g_mutex_locks;

void reset_counts();

// Counts allocator and lock calls on this thread while alive.
class Guard {
  public:
    Guard() { t_guarded = true; }
    ~Guard() { t_guarded = false; }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
};

// Keeps the compiler from optimising an allocation away.
inline void escape(const void* pointer) {
    asm volatile("" : : "g"(pointer) : "memory");
}

}  // namespace tactus::test
