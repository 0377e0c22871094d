// The allocation and lock counters of realtime_tests (no_allocation_test.cpp replaces the
// allocation functions and pthread_mutex_lock for the whole executable): what a Guard's thread
// calls while the Guard lives is counted.
#pragma once

#include <atomic>

extern constinit thread_local bool t_guarded;
extern std::atomic<long> g_allocator_calls;
extern std::atomic<long> g_mutex_locks;

// Counts allocator and lock calls on this thread while alive.
class Guard {
  public:
    Guard() { t_guarded = true; }
    ~Guard() { t_guarded = false; }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
};

inline void reset_counts() {
    g_allocator_calls = 0;
    g_mutex_locks = 0;
}
