// Real-time safety of tactus~ inside a real Pd. Loaded twice into pd: preloaded (LD_PRELOAD), it
// replaces the allocator and pthread_mutex_lock and counts their calls made while the guard is
// on; as the external [perform_guard~ on|off] (the same file, found on Pd's path), it passes its
// signal through and turns the guard on or off in the DSP chain. The test patch wraps tactus~
// between the two (render_through.pd), so the counts are what tactus~'s perform routine did. At
// exit it prints "perform-guard: performs=N allocations=A locks=L" on stderr.
#include <dlfcn.h>
#include <m_pd.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

extern "C" {
void* __libc_malloc(size_t size);
void* __libc_calloc(size_t count, size_t size);
void* __libc_realloc(void* pointer, size_t size);
void __libc_free(void* pointer);
void* __libc_memalign(size_t alignment, size_t size);
}

namespace {

constinit thread_local bool t_guarded = false;
std::atomic<long> g_performs{0}, g_allocations{0}, g_locks{0};
int (*g_real_lock)(pthread_mutex_t*) = nullptr;

void note(std::atomic<long>& counter) {
    if (t_guarded) counter.fetch_add(1, std::memory_order_relaxed);
}

__attribute__((constructor)) void find_real_lock() {
    g_real_lock = reinterpret_cast<int (*)(pthread_mutex_t*)>(dlsym(RTLD_NEXT, "pthread_mutex_lock"));
}

__attribute__((destructor)) void report() {
    std::fprintf(stderr, "perform-guard: performs=%ld allocations=%ld locks=%ld\n",
                 g_performs.load(), g_allocations.load(), g_locks.load());
}

// [perform_guard~ on|off]
t_class* guard_class = nullptr;
struct Guard {
    t_object pd;
    t_float scalar_input;
    bool on;
};

t_int* perform(t_int* w) {
    const auto* guard = reinterpret_cast<const Guard*>(w[1]);
    const auto* in = reinterpret_cast<const t_sample*>(w[2]);
    auto* out = reinterpret_cast<t_sample*>(w[3]);
    const auto n = static_cast<int>(w[4]);
    if (in != out) std::copy_n(in, n, out);
    if (guard->on) g_performs.fetch_add(1, std::memory_order_relaxed);
    t_guarded = guard->on;
    return w + 5;
}

}  // namespace

extern "C" {

void* malloc(size_t size) {
    note(g_allocations);
    return __libc_malloc(size);
}
void* calloc(size_t count, size_t size) {
    note(g_allocations);
    return __libc_calloc(count, size);
}
void* realloc(void* pointer, size_t size) {
    note(g_allocations);
    return __libc_realloc(pointer, size);
}
void free(void* pointer) {
    note(g_allocations);
    __libc_free(pointer);
}
void* memalign(size_t alignment, size_t size) {
    note(g_allocations);
    return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) { return memalign(alignment, size); }
int posix_memalign(void** out, size_t alignment, size_t size) {
    *out = memalign(alignment, size);
    return *out ? 0 : ENOMEM;
}
int pthread_mutex_lock(pthread_mutex_t* mutex) {
    note(g_locks);
    return g_real_lock(mutex);
}

void perform_guard_tilde_setup() {
    guard_class = class_new(
        gensym("perform_guard~"),
        reinterpret_cast<t_newmethod>(+[](t_symbol* state) -> void* {
            auto* guard = reinterpret_cast<Guard*>(pd_new(guard_class));
            guard->scalar_input = 0;
            guard->on = std::strcmp(state->s_name, "on") == 0;
            outlet_new(&guard->pd, &s_signal);
            return guard;
        }),
        nullptr, sizeof(Guard), CLASS_DEFAULT, A_DEFSYMBOL, A_NULL);
    CLASS_MAINSIGNALIN(guard_class, Guard, scalar_input);
    class_addmethod(guard_class, reinterpret_cast<t_method>(+[](Guard* guard, t_signal** sp) {
                        dsp_add(perform, 4, guard, sp[0]->s_vec, sp[1]->s_vec,
                                static_cast<t_int>(sp[0]->s_n));
                    }),
                    gensym("dsp"), A_CANT, A_NULL);
}

}  // extern "C"
